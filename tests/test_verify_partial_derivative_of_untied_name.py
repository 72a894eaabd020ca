"""A partial derivative of a name the text has not tied (∂Ω₃/∂ψ̇ with Ω₃ only set equal to a column
the reader does not take for its definition) is 0 only if Ω₃ is a constant, which the reader cannot
say: a flag resting on it is left unchecked, naming Ω₃; once the text defines the name, the claim is judged."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n# Euler's third equation from Lagrange's\n\n"
UNTIED = ("The body components:\n\n$$\n\\vec{\\Omega} =\n\\begin{pmatrix}\n\\Omega_1\\\\\n\\Omega_2\\\\\n\\Omega_3\n"
          "\\end{pmatrix}\n=\n\\begin{pmatrix}\n\\dot{\\varphi} \\sin{\\theta} \\sin{\\psi} + \\dot{\\theta} \\cos{\\psi} \\\\\n"
          "\\dot{\\varphi} \\sin{\\theta} \\cos{\\psi} - \\dot{\\theta} \\sin{\\psi} \\\\\n"
          "\\dot{\\varphi} \\cos{\\theta} + \\dot{\\psi}\n\\end{pmatrix}\n$$\n\n")
TIED = "The third component:\n\n$$ \\Omega_3 \\equiv \\dot{\\varphi} \\cos{\\theta} + \\dot{\\psi} $$\n\n"
CLAIM = "Its slope in the spin rate:\n\n$$ \\frac{\\partial \\Omega_3}{\\partial \\dot{\\psi}} = %s $$\n"


def _verdict(body):
    return [c.verdict for c in kept.check_text(HEAD + body) if "\\partial" in c.latex]


def test_a_partial_derivative_of_a_name_the_text_has_not_tied_is_not_judged():
    assert _verdict(UNTIED + CLAIM % "1") == ["unchecked"]
    assert _verdict(UNTIED + CLAIM % "2") == ["unchecked"]


def test_a_partial_derivative_of_a_name_the_text_defined_is_judged():
    assert _verdict(TIED + CLAIM % "1") == ["holds"]
    assert _verdict(TIED + CLAIM % "2")[0] in ("typo", "fails")


def test_a_constant_of_the_text_s_that_survives_the_derivative_is_still_a_constant():
    # m of ∂(m ψ̇²/2)/∂ψ̇ = m ψ̇: m stays in the value, the text's name for a constant factor
    body = "The spin's energy:\n\n$$ \\frac{\\partial}{\\partial \\dot{\\psi}} \\left( \\frac{1}{2} m \\dot{\\psi}^2 \\right) = %s $$\n"
    assert _verdict(body % "m \\dot{\\psi}") == ["holds"]
