"""The notes reader on the inertia tensor written as a plain I acting on the bold angular velocity
(``\\mathbf{L} = I\\boldsymbol{\\omega}``, ``T = \\frac{1}{2}\\boldsymbol{\\omega}\\cdot I\\boldsymbol{\\omega}``):
read by the grammar of vectors, as a bold 𝐈 is, in the body's principal axes beside I₁, I₂, I₃; a
slip in the principal-axis form is flagged and the I written with a subscript is not taken for it."""
import kept_readings as kept

HEAD = "# Energy\n\nThe inertia tensor $I$ about the fixed point, in principal axes:\n\n"
ENERGY = "$$T = \\frac{1}{2}\\boldsymbol{\\omega} \\cdot I \\boldsymbol{\\omega} = \\frac{1}{2}(I_1\\omega_1^2 + I_2\\omega_2^2 + I_3\\omega_3^2)$$\n"


def _verdicts(text):
    return {c.verdict for cs in kept.by_line(HEAD + text).values() for c in cs}


def test_the_energy_with_a_plain_inertia_tensor_holds_in_the_principal_axes():
    assert "holds" in _verdicts(ENERGY)
    assert not _verdicts(ENERGY) & {"fails", "typo"}


def test_a_slip_in_the_principal_axis_form_is_flagged():
    assert _verdicts(ENERGY.replace("I_2\\omega_2^2", "I_2\\omega_1^2")) & {"fails", "typo"}


def test_a_subscripted_i_before_omega_is_not_the_tensor():
    # I_1 ω (a moment times the vector) is no tensor: nothing here is read as the vector grammar's
    assert "holds" not in _verdicts("$$T = \\frac{1}{2}\\boldsymbol{\\omega} \\cdot I_1 \\boldsymbol{\\omega}$$\n")
