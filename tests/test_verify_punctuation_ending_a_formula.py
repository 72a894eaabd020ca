"""A full stop or a comma that ends a display's formula is the sentence's punctuation, spaced
(``\\, .``) or not, after a sized bracket too: every reader takes the formula without it (the
quaternion reader among them, which refused the whole display over it). A number's decimal point
is no punctuation."""
from __future__ import annotations

import pytest

import kept_readings as kept
from derive.lecture import source

SERIES = r"""# The exponential of a rotation vector

A rotation by the angle $\theta$ about the unit axis $\mathbf{u}$ is the rotation vector
$\mathbf{v} = \mathbf{u}\theta$; as a pure quaternion, $\mathbf{u}^2 = -1$, and its exponential is a unit
quaternion whose series splits into even and odd powers:

$$
e^\mathbf{v} = \Big(1 - \frac{\theta^2}{2!} + \frac{\theta^4}{4!} + \cdots\Big)
+ \Big(\mathbf{u}\theta - \frac{\mathbf{u}\theta^3}{3!} + \frac{\mathbf{u}\theta^5}{5!} + \cdots\Big)END
$$
"""


@pytest.mark.parametrize("end", ["", ".", ",", r" \, .", " ."])
def test_a_quaternion_series_ending_in_punctuation_is_read_without_it(end):
    claims = [c for c in kept.check_text(SERIES.replace("END", end)) if c.line >= 7]
    assert [c.verdict for c in claims] == ["holds"], [c.why for c in claims]


def test_a_slip_before_the_punctuation_is_flagged():
    slipped = SERIES.replace(r"\frac{\theta^4}{4!}", r"\frac{\theta^4}{3!}").replace("END", r" \, .")
    verdicts = [c.verdict for c in kept.check_text(slipped) if c.line >= 7]
    assert verdicts and all(v in ("typo", "fails") for v in verdicts), verdicts


def test_a_decimal_point_inside_a_number_stays():
    assert source.normalize(r"I_1 = 1.5").endswith("1.5")
    assert source.normalize(r"I_1 = 1.5.").endswith("1.5")
