"""A lone new symbol before `= \\text{constant}` at the end of a chain (``p_\\psi = \\partial L/\\partial\\dot\\psi
= … = B_3 = \\text{constant}``) is the text's name for the chain's first member from there on: a
later formula in it is read."""
import kept_readings as kept

TOP = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n## Heavy symmetric top\n\n"
       "A symmetric top, $I_1 = I_2 \\neq I_3$, spins with its tip fixed; its center of mass is a distance $h$ "
       "from the tip, and the potential energy is $U = Mgh \\cos\\theta$.\n\n"
       "$$\nL = \\frac{1}{2} I_1 \\left( \\dot{\\phi}^2 \\sin^2 \\theta + \\dot{\\theta}^2\\right) + \\frac{1}{2} I_3 "
       "\\left( \\dot{\\phi} \\cos \\theta + \\dot{\\psi} \\right)^2 - Mgh \\cos \\theta\n$$\n\n"
       "The momentum conjugate to $\\psi$ is constant:\n\n"
       "$$\np_{\\psi} = \\frac{\\partial L}{ \\partial \\dot{\\psi}} = I_3 \\left( \\dot{\\phi} \\cos \\theta + "
       "\\dot{\\psi} \\right) = B_3 = \\text{ constant}\n$$\n\n")


def verdicts(text: str, start: str) -> list:
    return [c.verdict for c in kept.check_text(text) if c.latex.lstrip().startswith(start)]


def test_a_name_at_the_end_of_a_chain_is_read_later():
    text = TOP + "$$\n\\frac{1}{2} I_3 \\left( \\dot{\\phi} \\cos \\theta + \\dot{\\psi} \\right)^2 = \\frac{B^2_3}{2I_3}\n$$\n"
    assert set(verdicts(text, "\\frac{1}{2} I_3")) == {"holds"}


def test_a_slip_in_the_named_quantity_is_flagged():
    text = TOP + "$$\n\\frac{1}{2} I_3 \\left( \\dot{\\phi} \\cos \\theta + \\dot{\\psi} \\right)^2 = \\frac{B^2_3}{I_3}\n$$\n"
    assert set(verdicts(text, "\\frac{1}{2} I_3")) & {"typo", "fails"}


def test_a_symbol_inside_a_chain_is_no_name():
    text = TOP.replace("= B_3 = \\text{ constant}", "= B_3 + 1") + (
        "$$\n\\frac{1}{2} I_3 \\left( \\dot{\\phi} \\cos \\theta + \\dot{\\psi} \\right)^2 = \\frac{B^2_3}{2I_3}\n$$\n")
    assert "holds" not in verdicts(text, "\\frac{1}{2} I_3")
