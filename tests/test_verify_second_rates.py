"""The rate of a body-frame angular velocity's rate, d/dt of ω̃̇ᵢ, is ω̃̈ᵢ (the text's own symbol
for it, or ``\\ddot{\\tilde\\omega}_i``), never zero: ω̃̇ᵢ is no constant."""
from kept_readings import check_text

HEAD = "---\ntitle: free body\n---\n# Euler's equations of a free body\n\nIn principal axes, with no torque:\n\n"


def _verdicts(display):
    return [c.verdict for c in check_text(HEAD + f"$$\n{display}\n$$\n")]


def test_the_rate_of_a_body_frame_angular_velocitys_rate_is_its_second_rate_not_zero():
    rate = r"\frac{d}{dt}\left(\dot{\tilde\omega}_1 + \tilde\omega_2\right) = "
    assert _verdicts(rate + r"\ddot{\tilde\omega}_1 + \dot{\tilde\omega}_2") == ["holds"]
    assert _verdicts(rate + r"\dot{\tilde\omega}_2") == ["fails"]
