"""The notes reader on angles and their rates written as functions of the time, θ(t), θ̇(t): the
argument (t) names what the quantity depends on, never a factor t, so the heavy top's Lagrangian
written with them holds as it does without them, and a slip in it is still flagged."""
import kept_readings as kept

verdicts, line_of = kept.verdicts_by_line, kept.line_of

LAGRANGIAN = ("L = \\frac{1}{2} I_1 (\\dot\\beta(t)^2 + \\dot\\alpha(t)^2 \\sin^2\\beta(t)) + \\frac{1}{2} I_3 "
              "(\\dot\\gamma(t) + \\dot\\alpha(t) \\cos\\beta(t))^2 - M g l \\cos\\beta(t)")


def test_the_lagrangian_in_angles_written_as_functions_of_the_time_holds():
    text = f"# Heavy top\n\n$$\n{LAGRANGIAN}\n$$\n"
    assert verdicts(text)[line_of(text, "$$\nL =")] == {"holds"}


def test_a_sign_slip_in_it_is_still_flagged():
    text = f"# Heavy top\n\n$$\n{LAGRANGIAN.replace('- M g l', '+ M g l')}\n$$\n"
    assert verdicts(text)[line_of(text, "$$\nL =")] & {"typo", "fails"}
