"""An equation of the text's written again with a factor all its terms share divided out
(`derive.lecture.restated`): the same equation, whatever its names stand for."""
import kept_readings as kept
import sympy as sp

from derive.lecture import restated

STEP = r"""# Steady precession

The equation for the tilt gives

$$I_\perp\Omega^2\sin\vartheta\cos\vartheta - L_a\Omega\sin\vartheta + Mgh\sin\vartheta = 0$$

and, cancelling the factor $\sin\vartheta$ every term shares,

$$I_\perp\Omega^2\cos\vartheta - L_a\Omega + Mgh = 0$$
"""


def _verdicts(text, line):
    return [c.verdict for c in kept.by_line(text).get(line, [])]


def test_the_equation_with_the_shared_sine_divided_out_holds():
    assert _verdicts(STEP, 9) == ["holds"]


def test_an_equation_that_is_no_multiple_of_the_one_before_is_not_judged_by_it():
    text = STEP.replace("- L_a\\Omega + Mgh = 0", "+ L_a\\Omega + Mgh = 0")
    verdicts = _verdicts(text, 9)
    assert "holds" not in verdicts and not {"typo", "fails"} & set(verdicts)


def test_a_factor_that_is_a_sum_is_not_divided_out():
    text = STEP.replace("\\sin\\vartheta = 0", "(1 + \\sin\\vartheta) = 0").replace(
        "\\Omega^2\\sin\\vartheta\\cos", "\\Omega^2(1 + \\sin\\vartheta)\\cos").replace(
        "L_a\\Omega\\sin\\vartheta", "L_a\\Omega(1 + \\sin\\vartheta)")
    assert "holds" not in _verdicts(text, 9)


def test_the_shared_factor_is_read_off_the_terms_and_the_rest_must_be_a_number_times_the_new_equation():
    m, g, l, th, a = sp.symbols("m g l theta a")
    new = g * sp.sin(th) + l * a
    assert restated._divided(new, 2 * m * sp.cos(th) * new) == m * sp.cos(th)
    assert restated._divided(new, m * (g * sp.sin(th) - l * a)) is None      # not a multiple: a sign differs
    assert restated._divided(new, m * g * sp.sin(th) + l * a) is None        # no factor every term shares
