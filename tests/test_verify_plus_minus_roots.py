"""Two roots written with ± (or ∓) after the equation they solve: judged as algebra on the text's
names as written, and a pair written again another way (`derive.lecture.restated`)."""
import kept_readings as kept

QUADRATIC = r"""# Steady precession

The component of the angular momentum along the axis is a constant of the motion,

$$L_a = I_\parallel(\omega + \Omega\cos\vartheta)$$

and the condition of steady precession is a quadratic in $\Omega$,

$$I_\perp\Omega^2\cos\vartheta - L_a\Omega + Mgh = 0$$

whose two roots are

$$\Omega = \frac{L_a \pm \sqrt{L_a^2 - 4MghI_\perp\cos\vartheta}}{2I_\perp\cos\vartheta}$$
"""

PAIR = r"""# A quadratic in alpha

A trial solution turns the equation of motion into a quadratic for its frequency, solved by the formula

$$\alpha = \frac{2 a \pm \sqrt{(2 a)^2 + 4 b^2}}{-2}$$

which tidies up to

$$\alpha = -a \mp \sqrt{a^2 + b^2}$$
"""


def _verdicts(text, start):
    line = next(k for k, row in enumerate(text.split("\n"), 1) if row.startswith(start))
    return [c.verdict for c in kept.by_line(text).get(line, [])]


def test_roots_with_plus_minus_solve_the_quadratic_before_with_a_name_held_as_written():
    # L_a is defined through Omega, but the text solves for Omega with L_a held: the roots are judged as written
    assert _verdicts(QUADRATIC, "$$\\Omega = \\frac{L_a \\pm") == ["holds"]


def test_roots_that_do_not_solve_the_quadratic_before_are_not_judged_by_it():
    text = QUADRATIC.replace("\\pm \\sqrt{L_a^2 - 4MghI_\\perp", "\\pm \\sqrt{L_a^2 - 2MghI_\\perp")
    assert "holds" not in _verdicts(text, "$$\\Omega = \\frac{L_a \\pm")
    assert not {"typo", "fails"} & set(_verdicts(text, "$$\\Omega = \\frac{L_a \\pm"))


def test_a_pair_of_roots_written_again_with_minus_plus_is_the_same_pair():
    assert _verdicts(PAIR, "$$\\alpha = -a") == ["holds"]


def test_a_pair_of_roots_written_again_differently_is_not_judged():
    text = PAIR.replace("-a \\mp \\sqrt{a^2 + b^2}", "-a \\mp \\sqrt{a^2 + 2 b^2}")
    verdicts = _verdicts(text, "$$\\alpha = -a")
    assert "holds" not in verdicts and not {"typo", "fails"} & set(verdicts)
