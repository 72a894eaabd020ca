"""A bare momentum beside a sum over a body's points (derive/lecture/lone_point.py): the letter is the
body's own total there, not the lone point mass the vector model reads outside a sum, so the pair
is left unchecked instead of failed."""
import kept_readings as kept

MOMENTUM = "## Linear momentum\n\n$$\n\\vec{p}=m\\vec{v}\n$$\n\n"


def verdicts(text: str, start: str) -> list:
    return [c.verdict for c in kept.check_text(text) if c.latex.startswith(start)]


def test_the_rate_of_a_bodys_momentum_set_equal_to_the_sum_of_the_forces_is_not_failed():
    text = MOMENTUM + "$$\n\\vec{\\dot{p}}=\\sum_i\\vec{F}_i\n$$\n"
    assert "fails" not in verdicts(text, "\\vec{\\dot{p}}")


def test_a_chain_through_m_a_to_the_sum_of_the_forces_is_not_failed():
    text = MOMENTUM + "$$\n\\vec{\\dot{p}}=m\\vec{a}=\\sum_i\\vec{F}_i\n$$\n"
    assert set(verdicts(text, "\\vec{\\dot{p}}")) == {"unchecked"}


def test_a_sum_over_the_points_against_a_wrong_sum_still_fails():
    text = "$$\\vec{L} = \\sum_i m_i \\vec{r}_i \\times \\vec{v}_i = \\sum_i m_i \\vec{v}_i \\times \\vec{r}_i$$\n"
    assert "fails" in verdicts(text, "\\vec{L}") or "typo" in verdicts(text, "\\vec{L}")
