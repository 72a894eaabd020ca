"""A body's constant written ≈ 0 (derive/lecture/moments_small.py): judged by the value the text
gave it and the small quantities it states, never by a guess."""
import kept_readings as kept

FREE_BODY = (
    "A free rigid body with principal moments $I_1$, $I_2$, $I_3$ and no torque.\n\n"
    "$$I_1 = \\frac{1}{12} M (b^2 + c^2) \\qquad I_3 = \\frac{1}{12} M (a^2 + b^2)$$\n\n"
    "## Near the first axis\n\n"
    "The components $\\omega_2$ and $\\omega_3$ are small.\n\n"
)


def verdicts_at(text: str, latex: str) -> list:
    return [c.verdict for c in kept.check_text(text) if c.latex.strip() == latex]


def test_a_moment_the_text_gave_a_finite_value_is_not_approx_zero():
    text = FREE_BODY + "$$I_1 \\approx 0$$\n"
    assert verdicts_at(text, "I_1 \\approx 0") == ["fails"]


def test_a_moment_with_no_value_in_the_text_stays_unchecked():
    text = FREE_BODY + "$$I_2 \\approx 0$$\n"
    assert verdicts_at(text, "I_2 \\approx 0") == ["unchecked"]


def test_a_mislabelled_setting_gives_its_corrected_value():
    text = ("A free rigid body.\n\n$$I_1 = \\frac{1}{12} M (b^2 + c^2) \\qquad I_1 = \\frac{1}{12} M (c^2 + a^2) "
            "\\qquad I_3 = \\frac{1}{12} M (a^2 + b^2)$$\n\n## Near the second axis\n\n"
            "The components $\\omega_1$ and $\\omega_3$ are small.\n\n$$I_2 \\approx 0$$\n")
    assert verdicts_at(text, "I_2 \\approx 0") == ["fails"]


def test_a_moment_above_the_smallest_of_a_stated_ordering_is_not_approx_zero():
    text = ("A free rigid body.\n\n$$I_1 < I_2 < I_3$$\n\n$$I_2 \\approx 0$$\n\n$$I_1 \\approx 0$$\n")
    claims = kept.check_text(text)
    assert [c.verdict for c in claims if c.latex.strip() == "I_2 \\approx 0"] == ["fails"]
    assert [c.verdict for c in claims if c.latex.strip() == "I_1 \\approx 0"] == ["unchecked"]   # a thin rod
