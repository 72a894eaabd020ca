"""A primed function the text defined, read as its derivative (derive/lecture/primed_functions.py).

A heavy top's notes name the effective potential ``U(\\theta) = ...`` and then write its slope,
``U'(\\theta) = ... = 0``, the condition for steady precession. The rewriting of U' is an identity
(the derivative of the text's own U), only the final ``= 0`` is a condition the text imposes. The
notes below are written for these tests.
"""
import kept_readings as kept

from derive.lecture import primed_functions

HEAD = """---
convention: z-x-z
angles: [\\phi, \\theta, \\psi]
---

A heavy symmetric top, $I_1 = I_2$ about the fixed point $O$, the centre of mass on the symmetry axis
at distance $l$ from $O$, mass $M$, $L_Z$ and $L_3$ the conserved angular momentum components along the
vertical and the symmetry axis. Its energy integral leaves one equation in the nutation angle, whose
angle-dependent part is the effective potential

$$
U(\\theta) = \\frac{(L_Z-L_3\\cos\\theta)^2}{2I_1\\sin^2\\theta}+\\frac{L_3^2}{2I_3}+Mgl\\cos\\theta
$$

A steady precession sits where the slope of $U$ vanishes:

"""
RIGHT = r"\frac{(L_3-L_Z\cos\theta)(L_Z-L_3\cos\theta)}{I_1\sin^3\theta} - Mgl\sin \theta"
SLIP = r"\frac{(L_3-L_Z\cos\theta)(L_Z-L_3\cos\theta)}{I_1\sin^2\theta} - Mgl\sin \theta"


def verdicts(display: str) -> list:
    start = HEAD.count("\n")
    return [c.verdict for c in kept.check_text(HEAD + display + "\n") if c.line > start]


def test_the_slope_of_the_texts_potential_holds_and_its_zero_stays_a_condition():
    got = verdicts(f"$$\nU'(\\theta) = {RIGHT} = 0\n$$")
    assert "holds" in got and not {"typo", "fails"} & set(got), got
    assert verdicts(f"$$\nU'(\\theta) = {RIGHT}\n$$") == ["holds"]


def test_a_slip_in_the_slope_of_the_texts_potential_is_flagged():
    got = verdicts(f"$$\nU'(\\theta) = {SLIP} = 0\n$$")
    assert {"typo", "fails"} & set(got), got
    got = verdicts(f"$$\nU'(\\theta) = {SLIP}\n$$")
    assert {"typo", "fails"} & set(got), got


def test_the_second_derivative_is_read_to_its_order():
    curvature = (r"\frac{L_3^2+L_Z^2-2L_3L_Z\cos\theta}{I_1\sin^2\theta} - "
                 r"\frac{%d\cos\theta(L_3-L_Z\cos\theta)(L_Z-L_3\cos\theta)}{I_1\sin^4\theta} - Mgl\cos\theta")
    assert verdicts(f"$$\nU''(\\theta) = {curvature % 3}\n$$") == ["holds"]
    assert verdicts(f"$$\nU''(\\theta) = {curvature % 2}\n$$")[0] in ("typo", "fails")


def test_a_prime_at_another_argument_or_of_an_undefined_function_is_not_read():
    assert not {"typo", "fails"} & set(verdicts(f"$$\nU'(\\theta_0) = {SLIP}\n$$"))
    assert not {"typo", "fails"} & set(verdicts(f"$$\nW'(\\theta) = {SLIP} = 0\n$$"))


def test_the_statement_shape_is_a_primed_function_at_an_argument():
    assert primed_functions.leads(r"U'(\theta) = 0")
    assert primed_functions.leads(r"V''_{\mathrm{eff}}(x) = 1")
    assert primed_functions.leads(r"\Phi' \left( \theta \right) = 1")
    assert not primed_functions.leads(r"U(\theta) = 1")
    assert not primed_functions.leads(r"x' = 1")


def test_beside_a_derivative_written_as_an_operator_in_the_angle_nothing_is_flagged():
    # the reader does not read d/dtheta as an operator: the correct form must not be called a slip
    got = verdicts("$$\nU'(\\theta) = \\frac{d}{d\\theta}\\left(\\frac{(L_Z-L_3\\cos\\theta)^2}{2I_1\\sin^2\\theta}"
                   "+Mgl\\cos\\theta\\right)\n$$")
    assert not {"typo", "fails"} & set(got), got
    assert primed_functions.operator_in_other_variable(r"\frac{\mathrm{d}}{\mathrm{d}\theta} U")
    assert not primed_functions.operator_in_other_variable(r"\frac{d}{dt} U + \frac{dU}{dt}")
