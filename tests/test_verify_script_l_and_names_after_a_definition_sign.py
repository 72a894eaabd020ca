"""The notes reader on the heavy top's notes: the script letter ``\\ell`` is the letter l (the
distance of the centre of mass from the fixed point, set in script), and a definition sign with the text's one new
symbol on its right, ``p_\\psi \\equiv I_1 a``, defines that symbol (a = p_ψ/I₁) for the displays after it; and
``p_\\theta`` is the momentum conjugate to the tilt, ∂L/∂θ̇, as p_φ and p_ψ are those of the other two angles."""
import kept_readings as kept
from derive.lecture import texmacros

by_line, verdicts, line_of = kept.by_line, kept.verdicts_by_line, kept.line_of
TOP = ("# The heavy symmetric top\n\nA symmetric top, $I_1 = I_2$, with its centre of mass at the distance $\\ell$ "
       "from the fixed point on its axis, in the Euler angles $\\phi$, $\\theta$, $\\psi$ of the z-x-z sequence.\n\n")
T = "\\frac{1}{2} I_1 (\\dot\\theta^2 + \\dot\\phi^2\\sin^2\\theta) + \\frac{1}{2} I_3 (\\dot\\psi + \\dot\\phi\\cos\\theta)^2"
MOMENTA = ("$$p_\\psi = I_3(\\dot\\psi + \\dot\\phi\\cos\\theta), \\qquad "
           "p_\\phi = I_1\\dot\\phi\\sin^2\\theta + I_3(\\dot\\psi + \\dot\\phi\\cos\\theta)\\cos\\theta$$\n\n")


def test_the_script_letter_l_is_the_letter_l():
    assert texmacros.synonyms("Mg\\ell\\cos\\theta + \\ell_1") == "Mg l\\cos\\theta + l_1"
    assert texmacros.synonyms("\\ellipse") == "\\ellipse"        # another command's name is left alone


def test_a_lagrangian_with_the_script_l_is_read():
    text = TOP + f"The Lagrangian is\n\n$$L = {T} - Mg\\ell\\cos\\theta$$\n"
    assert verdicts(text)[line_of(text, "$$L")] == {"holds"}


def test_a_lagrangian_with_the_script_l_and_a_wrong_sign_is_not_taken_to_hold():
    text = TOP + f"The Lagrangian is\n\n$$L = {T} + Mg\\ell\\cos\\theta$$\n"
    assert "holds" not in verdicts(text)[line_of(text, "$$L")]


def test_a_symbol_named_after_a_definition_sign_is_used_in_the_displays_after_it():
    text = (TOP + f"The Lagrangian is\n\n$$L = {T} - Mg l\\cos\\theta$$\n\nIts conserved momenta are\n\n" + MOMENTA
            + "We define $p_\\psi \\equiv I_1 a$ and $p_\\phi \\equiv I_1 b$, so that\n\n"
            "$$\\dot\\phi = \\frac{b - a\\cos\\theta}{\\sin^2\\theta}$$\n")
    assert verdicts(text)[line_of(text, "$$\\dot\\phi")] == {"holds"}
    named = [c for c in by_line(text)[line_of(text, "We define")] if "I_1 a" in c.latex]
    assert named and named[0].kind == "new symbol" and named[0].verdict == "unchecked"


def test_a_wrong_formula_in_a_symbol_named_after_a_definition_sign_is_flagged():
    text = (TOP + f"The Lagrangian is\n\n$$L = {T} - Mg l\\cos\\theta$$\n\nIts conserved momenta are\n\n" + MOMENTA
            + "We define $p_\\psi \\equiv I_1 a$ and $p_\\phi \\equiv I_1 b$, so that\n\n"
            "$$\\dot\\phi = \\frac{b + a\\cos\\theta}{\\sin^2\\theta}$$\n")
    assert verdicts(text)[line_of(text, "$$\\dot\\phi")] & {"typo", "fails"}


def test_an_equals_sign_with_a_new_symbol_on_its_right_defines_nothing():
    text = (TOP + f"The Lagrangian is\n\n$$L = {T} - Mg l\\cos\\theta$$\n\nIts conserved momenta are\n\n" + MOMENTA
            + "We have $p_\\psi = I_1 a$ and $p_\\phi = I_1 b$, so that\n\n"
            "$$\\dot\\phi = \\frac{b - a\\cos\\theta}{\\sin^2\\theta}$$\n")
    assert "holds" not in verdicts(text)[line_of(text, "$$\\dot\\phi")]


def test_the_momentum_conjugate_to_the_tilt_is_the_derivative_of_the_lagrangian_by_its_rate():
    text = TOP + f"The Lagrangian is\n\n$$L = {T} - Mg l\\cos\\theta$$\n\nand the momentum conjugate to $\\theta$ is\n\n" \
        "$$p_\\theta = I_1\\dot\\theta$$\n"
    assert verdicts(text)[line_of(text, "$$p_\\theta")] == {"holds"}


def test_the_momentum_of_the_precession_named_for_the_tilt_is_flagged():
    text = TOP + f"The Lagrangian is\n\n$$L = {T} - Mg l\\cos\\theta$$\n\nand the momentum conjugate to $\\theta$ is\n\n" \
        "$$p_\\theta = (I_1\\sin^2\\theta + I_3\\cos^2\\theta)\\dot\\phi + I_3\\cos\\theta\\,\\dot\\psi$$\n"
    assert verdicts(text)[line_of(text, "$$p_\\theta")] & {"typo", "fails"}
