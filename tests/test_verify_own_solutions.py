"""A closed form a text gives for its own equation of motion (derive/lecture/text_motion.py), with
Jacobi's elliptic functions (derive/lecture/elliptic.py): put into the equation, for the variable,
for the angle it was defined by, or for the variable of a change."""
import sympy as sp

import kept_readings as kept
from derive.lecture.elliptic import JacobiCN, JacobiDN, JacobiSN

NUTATION = (
    "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Nutation\n\n"
    "With the substitution $u=\\cos\\theta$ the equation for $u$ reads\n\n"
    "$$\\dot{u}^2 = a(u-u_1)(u-u_2)(u-u_3)$$\n\n"
    "A new variable $v$ is introduced by\n\n$$u = u_1 + (u_2-u_1)\\sin^2v$$\n\n"
    "where\n\n$$k^2=\\frac{u_2-u_1}{u_3-u_1}$$\n\n"
)


def verdict_at(text: str, start: str) -> list:
    return verdicts_at(kept.check_text(text), start)


def verdicts_at(claims, start: str) -> list:
    return [c.verdict for c in claims if c.latex.startswith(start)]


def test_jacobis_functions_have_their_derivatives_and_values():
    x, m = sp.symbols("x m")
    assert sp.diff(JacobiSN(x, m), x) == JacobiCN(x, m) * JacobiDN(x, m)
    # sn² + cn² = 1 and dn² + m sn² = 1 at a numeric point
    at = {x: sp.Rational(7, 5), m: sp.Rational(1, 3)}
    assert abs(sp.N((JacobiSN(x, m) ** 2 + JacobiCN(x, m) ** 2 - 1).xreplace(at), 30)) < 1e-25
    assert abs(sp.N((JacobiDN(x, m) ** 2 + m * JacobiSN(x, m) ** 2 - 1).xreplace(at), 30)) < 1e-25


def test_an_elliptic_solution_of_the_texts_own_equation_holds():
    text = NUTATION + "$$u = u_1+(u_2-u_1)\\mathrm{sn}\\,^2 \\left(\\frac{\\sqrt{a(u_3-u_1)}}{2}t\\right)$$\n"
    assert verdict_at(text, "u = u_1+") == ["holds"]


def test_the_solution_written_for_the_angle_or_the_new_variable_holds():
    text = NUTATION + ("$$\\theta = \\arccos \\left[u_1+(u_2-u_1)\\mathrm{sn}\\,^2 \\left(\\frac{\\sqrt{a(u_3-u_1)}}{2}t"
                       "\\right)\\right]$$\n\n$$\\sin v = \\mathrm{sn}\\, \\left(\\frac{\\sqrt{a(u_3-u_1)}}{2}t\\right)$$\n")
    claims = kept.check_text(text)  # one reading of the text for both displays
    assert verdicts_at(claims, "\\theta = \\arccos") == ["holds"]
    assert verdicts_at(claims, "\\sin v") == ["holds"]


def test_a_solution_with_the_wrong_rate_is_not_taken_as_holding():
    text = NUTATION + "$$u = u_1+(u_2-u_1)\\mathrm{sn}\\,^2 \\left(\\sqrt{a(u_3-u_1)}\\,t\\right)$$\n"
    assert "holds" not in verdict_at(text, "u = u_1+")
