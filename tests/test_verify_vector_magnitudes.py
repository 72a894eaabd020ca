"""The magnitude of the body's angular momentum or angular velocity written on the vector itself:
``|\\mathbf{L}|``, ``\\mathbf{L}^2``, ``\\boldsymbol{\\omega}^2`` are the vector dotted with itself, a scalar,
never a vector (derive/lecture/latex_parser.py)."""
import kept_readings as kept

_HEAD = "A free symmetric body, $I_1 = I_2$, with angular momentum $\\mathbf{L}$.\n\n"
_SQUARE = "I_1^2\\omega_1^2 + I_1^2\\omega_2^2 + I_3^2\\omega_3^2"


def _judged(display):
    return [c for c in kept.check_text(_HEAD + "$$\n" + display + "\n$$\n") if c.line > 1]


def test_the_square_and_the_bars_of_the_angular_momentum_are_its_magnitude():
    for lhs in ("|\\mathbf{L}|^2", "\\mathbf{L}^2", "\\left|\\mathbf{L}\\right|^2"):
        assert [c.verdict for c in _judged(f"{lhs} = {_SQUARE}")] == ["holds"], lhs
    assert [c.verdict for c in _judged(f"|\\mathbf{{L}}| = \\sqrt{{{_SQUARE}}}")] == ["holds"]


def test_a_slip_in_the_magnitude_is_flagged_with_its_edit():
    judged = _judged("\\mathbf{L}^2 = I_1^2\\omega_1^2 + I_1^2\\omega_2^2 + I_3\\omega_3^2")
    assert [c.verdict for c in judged] == ["typo"] and "I_3^{2}" in judged[0].correction.replace(" ", "")


def test_the_angle_of_the_angular_momentum_to_the_symmetry_axis_divides_by_its_magnitude():
    head = "\\cos\\tau = \\frac{\\mathbf{L}\\cdot\\mathbf{e}_3}{|\\mathbf{L}|} = \\frac{I_3\\omega_3}{\\sqrt{I_1^2(\\omega_1^2 + \\omega_2^2) + "
    assert [c.verdict for c in _judged(head + "I_3^2\\omega_3^2}}")] == ["holds"]
    assert [c.verdict for c in _judged(head + "I_2^2\\omega_3}}")] == ["fails"]


def test_the_square_of_the_angular_velocity_is_its_components_squared():
    assert [c.verdict for c in _judged("\\boldsymbol{\\omega}^2 = \\omega_1^2 + \\omega_2^2 + \\omega_3^2")] == ["holds"]
