"""A chain with a member in the text's bold tensor (½ 𝛚·𝐈·𝛚 beside I₁ω₁² …) is read whole by the vector
reader, and the kinetic energy's gradient by a vector (dT/d𝛚 = 𝐋, ∂T/∂𝐋 = 𝛚) is read as that
vector; a slip in either is flagged, never passed."""
import kept_readings as kept

HEAD = "The body turns with angular velocity $\\boldsymbol\\omega$ about its centre of mass.\n\n"


def verdicts(display: str) -> list:
    return [c.verdict for c in kept.check_text(HEAD + "$$\n" + display + "\n$$\n")]


def test_the_energy_as_a_tensor_form_and_along_the_principal_axes_is_read_as_one_chain():
    chain = ("T = \\frac{1}{2} \\boldsymbol\\omega \\cdot \\mathbf{I} \\cdot \\boldsymbol\\omega =\n"
             "\\frac{1}{2} I_{1} \\omega_{1}^{2} + \\frac{1}{2} I_{2} \\omega_{2}^{2} + \\frac{1}{2} I_{3} \\omega_{3}^{2}")
    assert set(verdicts(chain)) == {"holds"}


def test_the_energy_chain_with_a_half_dropped_is_flagged():
    chain = ("T = \\frac{1}{2} \\boldsymbol\\omega \\cdot \\mathbf{I} \\cdot \\boldsymbol\\omega =\n"
             "\\frac{1}{2} I_{1} \\omega_{1}^{2} + I_{2} \\omega_{2}^{2} + \\frac{1}{2} I_{3} \\omega_{3}^{2}")
    found = verdicts(chain)
    assert found.count("holds") <= 1 and set(found) & {"typo", "fails"}     # T = ½ 𝛚·𝐈·𝛚 holds, the sum does not


def test_the_gradient_of_the_energy_by_the_angular_velocity_is_the_angular_momentum():
    assert set(verdicts("\\frac{dT}{d\\boldsymbol\\omega} = \\mathbf{I} \\cdot \\boldsymbol\\omega = \\mathbf{L}.")) \
        == {"holds"}
    assert verdicts("\\frac{\\partial T}{\\partial \\boldsymbol\\omega} = \\mathbf{L}") == ["holds"]


def test_the_gradient_of_the_energy_by_the_angular_momentum_is_the_angular_velocity():
    assert verdicts("\\frac{\\partial T}{\\partial \\mathbf{L}} = \\boldsymbol\\omega") == ["holds"]


def test_a_gradient_doubled_or_taken_for_the_angular_velocity_is_flagged():
    for wrong in ("\\frac{dT}{d\\boldsymbol\\omega} = 2 \\mathbf{I} \\cdot \\boldsymbol\\omega",
                  "\\frac{\\partial T}{\\partial \\boldsymbol\\omega} = \\boldsymbol\\omega"):
        found = verdicts(wrong)
        assert "holds" not in found and set(found) & {"typo", "fails"}, (wrong, found)
