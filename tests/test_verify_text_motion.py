"""The text's own equation of motion in a variable of its own, carried through a change of
variable (`derive.lecture.text_motion`)."""
import pytest

import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n# Nutation of the heavy top\n\n"

REDUCTION = HEAD + r"""With $u = \cos\theta$ the nutation obeys, with the three roots of the cubic,

$$\dot{u}^2 = a(u-u_1)(u-u_2)(u-u_3)$$

A new variable $v$ is introduced by

$$u = u_1 + (u_2-u_1)\sin^2v$$

which turns the equation into

$$LEFT = RIGHT$$

where

$$k^2=\dfrac{u_2-u_1}{u_3-u_1}$$
"""

RIGHT = r"\frac{a(u_3-u_1)}{4}\left(1-k^2\sin^2v\right)"


def _claims(left, right=RIGHT):
    text = REDUCTION.replace("LEFT", left).replace("RIGHT", right)
    return {c.line: c for c in kept.check_text(text)}


def _equation(claims):
    (c,) = [c for c in claims.values() if c.latex.startswith(r"\dot{v}")]
    return c


def test_change_of_variable_is_not_a_claim():
    claims = _claims(r"\dot{v}^2")
    change = [c for c in claims.values() if c.latex.startswith("u = u_1")]
    assert [c.verdict for c in change] == ["unchecked"]
    assert change[0].kind == "change of variable"


def test_equation_carried_through_the_change_holds_with_a_name_defined_after_it():
    c = _equation(_claims(r"\dot{v}^2"))
    assert c.verdict == "holds", c.why


def test_dropped_square_on_the_new_variable_is_a_typo_with_the_square_restored():
    c = _equation(_claims(r"\dot{v}"))
    assert c.verdict == "typo", c.why
    assert c.correction == r"\dot{v}^2 = " + RIGHT


@pytest.mark.parametrize("right", [r"\frac{a(u_3-u_1)}{2}\left(1-k^2\sin^2v\right)",
                                   r"\frac{a(u_3-u_1)}{4}\left(1+k^2\sin^2v\right)"])
def test_wrong_factor_after_the_change_fails(right):
    c = _equation(_claims(r"\dot{v}^2", right))
    assert c.verdict == "fails", c.why
    assert c.correction.startswith(r"\dot{v}^2 =") and "u_{3}" in c.correction


def test_name_never_defined_leaves_the_equation_unchecked():
    text = REDUCTION.replace("LEFT", r"\dot{v}^2").replace("RIGHT", RIGHT.replace("k^2", "q^2"))
    (c,) = [c for c in kept.check_text(text) if c.latex.startswith(r"\dot{v}")]
    assert c.verdict == "unchecked"
    assert "never defines" in c.why


CUBIC = HEAD + r"""With $u = \cos\theta$ the nutation obeys

$$\dot{u}^2 = (\alpha-au)(1-u^2)-(\beta-b u)^2$$

and, with the roots of the cubic on the right,

$$\dot{u}^2 = FACTORED$$
"""


def _factored(factored):
    (c,) = [c for c in kept.check_text(CUBIC.replace("FACTORED", factored))
            if c.latex.startswith(r"\dot{u}^2 = ") and "u_1" in c.latex]
    return c


def test_equation_by_its_named_roots_holds_with_the_leading_coefficient():
    c = _factored("a(u-u_1)(u-u_2)(u-u_3)")
    assert c.verdict == "holds", c.why


@pytest.mark.parametrize("factored", ["2a(u-u_1)(u-u_2)(u-u_3)", "-a(u-u_1)(u-u_2)(u-u_3)", "a(u-u_1)(u-u_2)"])
def test_equation_by_its_named_roots_fails_with_another_degree_or_leading_coefficient(factored):
    assert _factored(factored).verdict == "fails"


def test_equation_of_a_variable_is_kept_for_its_section_only():
    text = CUBIC.replace("FACTORED", "2a(u-u_1)(u-u_2)(u-u_3)").replace(
        "and, with the roots", "# Another body\n\nWith $u = \\cos\\theta$ and, with the roots")
    (c,) = [c for c in kept.check_text(text) if c.latex.startswith(r"\dot{u}^2 = ") and "u_1" in c.latex]
    assert c.verdict == "unchecked"


FUNCTION = HEAD + r"""The text names the right side

$$G(u) = (\alpha-au)(1-u^2)-(\beta-bu)^2$$

and evaluates it where the precession stops:

$$G\left(\frac{\beta}{b}\right) = VALUE$$
"""


def _at(value):
    (c,) = [c for c in kept.check_text(FUNCTION.replace("VALUE", value)) if c.latex.startswith("G\\left")]
    return c


def test_function_of_the_text_at_an_argument_holds_with_its_definition():
    c = _at(r"\left(\alpha-\frac{a\beta}{b}\right)\left(1-\frac{\beta^2}{b^2}\right)")
    assert c.verdict == "holds", c.why


def test_function_of_the_text_at_an_argument_is_never_flagged_by_that_reading():
    c = _at(r"\left(\alpha+\frac{a\beta}{b}\right)\left(1-\frac{\beta^2}{b^2}\right)")
    assert c.verdict not in ("holds", "typo", "fails")


SLIDING = ("# A block sliding to rest\n\nFriction slows the block at a steady rate:\n\n$$\n\\frac{dv}{dt} = -\\mu g\n$$\n\n"
           "so its speed falls in time:\n\n$$\nSPEED\n$$\n")


def _speed(speed):
    return [c for c in kept.check_text(SLIDING.replace("SPEED", speed)) if c.line == 11]


def test_a_constant_rates_integral_without_the_time_is_a_typo_with_the_time_restored():
    (claim,) = _speed("v = v(0) - \\mu g")
    assert (claim.kind, claim.verdict) == ("solution", "typo")
    assert claim.correction == "v = v(0) - \\mu g t"


def test_a_constant_rates_integral_with_another_rate_fails_and_with_the_time_holds():
    assert [c.verdict for c in _speed("v = v(0) - 2 \\mu g")] == ["fails"]
    assert [c.verdict for c in _speed("v = v(0) - \\mu g t")] == ["holds"]
