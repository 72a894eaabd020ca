"""The notes reader on a partial derivative in a vector, Landau's ∂L/∂𝛀 = 𝐌 or ∂U/∂𝐫 = −𝐅: a gradient in
the vector, which the scalar partial of a name would read as zero (the name holding no such symbol), so
it is left unread rather than judged; a partial in a scalar rate is read as before."""
import kept_readings as kept

verdicts, line_of = kept.verdicts_by_line, kept.line_of


def test_a_lagrangians_gradient_in_the_angular_velocity_is_not_judged_a_slip():
    text = "# Notes\n\nFor the rotation:\n\n$$\n\\frac{\\partial L}{\\partial \\vec{\\Omega}}=\\vec{M}\n$$\n"
    assert "fails" not in verdicts(text)[line_of(text, "$$")]


def test_a_bold_position_in_the_denominator_is_not_read_as_a_scalar_variable():
    text = "# Notes\n\nThe force:\n\n$$\n\\frac{\\partial U}{\\partial \\mathbf{r}}=-\\mathbf{F}\n$$\n"
    assert verdicts(text)[line_of(text, "$$")] <= {"unchecked"}


def test_a_partial_in_a_scalar_rate_is_still_read():
    text = ("# The heavy symmetric top\n\nIts Lagrangian:\n\n$$\nL = \\frac{I_1}{2}(\\dot\\theta^2 + \\dot\\phi^2\\sin^2\\theta)"
            " + \\frac{I_3}{2}(\\dot\\psi + \\dot\\phi\\cos\\theta)^2 - M g l\\cos\\theta\n$$\n\nand the momentum of the spin:"
            "\n\n$$\n\\frac{\\partial L}{\\partial \\dot\\psi} = I_3(\\dot\\psi + \\dot\\phi\\cos\\theta)\n$$\n")
    assert verdicts(text)[line_of(text, "$$\n\\frac{\\partial L}")] == {"holds"}
