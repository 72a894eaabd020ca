"""A column of one letter's components written over lines, boxed and after the vector's own name, as a
notebook writes it (``\\boxed{\\vec{\\Omega} = [Ω₁; Ω₂; Ω₃] = […]}``) after "the components of the
angular velocity:", names the letter as a one-line column would; a text that writes the rate of φ as
``\\dot{\\varphi}`` and never ``\\phi`` has φ for its first angle. The components so named, the
derivation's steps in them are judged: ∂Ω₃/∂ψ̇, and a chain ``A = B = 0`` whose first two members are
the same expression (a step), read as the equation B = 0."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n# Euler's equations from Lagrange's\n\n"
SAID = "Projecting the rates on the body axes gives the components of the angular velocity:\n\n"
UNSAID = "Projecting the rates on the body axes gives three rows:\n\n"
COLUMN = ("$$\n\\boxed{\n\\vec{\\Omega} =\n\\begin{pmatrix}\n\\Omega_1\\\\\n\\Omega_2\\\\\n\\Omega_3\\\\\n\\end{pmatrix}\n=\n"
          "\\begin{pmatrix}\n\\dot{\\varphi} \\sin{\\theta} \\sin{\\psi} + \\dot{\\theta} \\cos{\\psi} \\\\\n"
          "\\dot{\\varphi} \\sin{\\theta} \\cos{\\psi} - \\dot{\\theta} \\sin{\\psi} \\\\\n"
          "\\dot{\\varphi} \\cos{\\theta} + \\dot{\\psi}\n\\end{pmatrix}\n}\n$$\n\n")
SLOPE = "Its slope in the spin rate:\n\n$$ \\frac{\\partial \\Omega_3}{\\partial \\dot{\\psi}} = %s $$\n\n"
STEP = ("The equation for the spin:\n\n$$\n\\frac{d}{d t} \\left( I_3 \\Omega_3 \\right) - \\left[ I_1 \\Omega_1 \\Omega_2"
        " + I_2 \\Omega_2 (-\\Omega_1) \\right] = %s = 0\n$$\n")


def _verdicts(body, mark):
    return [c.verdict for c in kept.check_text(HEAD + body) if mark in c.latex]


def test_a_boxed_column_over_lines_names_the_components_so_their_slope_is_judged():
    assert _verdicts(SAID + COLUMN + SLOPE % "1", "\\partial") == ["holds"]
    assert _verdicts(SAID + COLUMN + SLOPE % "2", "\\partial")[0] in ("typo", "fails")


def test_without_the_sentence_the_components_stay_unnamed_and_unflagged():
    assert _verdicts(UNSAID + COLUMN + SLOPE % "2", "\\partial") == ["unchecked"]


def test_a_step_then_zero_is_read_as_euler_s_equation():
    held = _verdicts(SAID + COLUMN + STEP % "I_3 \\dot{\\Omega}_3 - (I_1 - I_2) \\Omega_1 \\Omega_2", "I_3 \\Omega_3")
    assert held and set(held) == {"holds"}
    # the same expression twice, then a 0 that is no equation of motion: unread, never flagged
    odd = _verdicts(SAID + COLUMN + "$$ I_3 \\dot{\\Omega}_3 = I_3 \\dot{\\Omega}_3 = 0 $$\n", "I_3 \\dot")
    assert "typo" not in odd and "fails" not in odd
