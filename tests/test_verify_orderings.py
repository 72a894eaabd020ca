"""Orderings a text states (``I_1 < I_2 < I_3``, ``-1 < u_1 < u_2 < 1 < u_3``) and the inequalities
they decide, with the text's own names (derive/lecture/motion.py, derive/lecture/context.py)."""
import kept_readings as kept

ROOTS = (
    "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# A cubic's roots\n\n"
    "The equation for $u$ is\n\n$$\\dot{u}^2 = a(u-u_1)(u-u_2)(u-u_3)$$\n\n"
    "and its roots lie in\n\n$$-1 < u_1<u_2<1<u_3$$\n\n"
    "A ratio of the gaps between them, named by its square after the text has used it:\n\n"
    "$$\\dot{v}^2 = \\frac{a(u_3-u_1)}{4}\\left(1-k^2\\sin^2v\\right)$$\n\n"
    "where\n\n$$k^2=\\frac{u_2-u_1}{u_3-u_1}$$\n\n"
)


def verdicts_at(text: str, latex: str) -> list:
    return [c.verdict for c in kept.check_text(text) if c.latex.strip() == latex]


def test_a_chain_with_numbers_is_an_ordering_of_its_symbols():
    text = ROOTS + "$$0\\le k^2\\le 1$$\n"
    assert verdicts_at(text, "-1 < u_1<u_2<1<u_3") == ["unchecked"]
    assert verdicts_at(text, "0\\le k^2\\le 1") == ["holds"]


def test_an_inequality_the_ordering_reverses_is_a_typo():
    claims = [c for c in kept.check_text(ROOTS + "$$k^2 > 1$$\n") if c.latex.strip() == "k^2 > 1"]
    assert [c.verdict for c in claims] == ["typo"]
    assert claims[0].correction.replace(" ", "") == "k^{2}<1"


def test_an_inequality_the_ordering_does_not_decide_stays_unchecked():
    assert verdicts_at(ROOTS + "$$u_1 + u_3 > 0$$\n", "u_1 + u_3 > 0") == ["unchecked"]


def test_a_display_that_opens_with_a_minus_and_its_own_inequality_is_no_continuation():
    text = ("# Roots\n\n$$G(u) = (1 - u^2) - u$$\n\nso the roots lie in\n\n$$-1 < u_1<u_2<1<u_3$$\n")
    assert [c.line for c in kept.check_text(text) if "u_1" in c.latex] == [7]


FUNCTION = ("# A cubic\n\nThe function is\n\n$$G(u) = (\\alpha-au)(1-u^2)-(\\beta-b u)^2$$\n\n"
            "and at the ends of the interval\n\n")


def test_a_plus_minus_on_the_left_states_the_formula_for_each_sign():
    claims = kept.check_text(FUNCTION + "$$G(\\pm 1) = -(\\beta \\mp b)^2$$\n")
    assert [(c.latex, c.verdict) for c in claims[1:]] == [
        ("G(+ 1) = -(\\beta - b)^2", "holds"), ("G(- 1) = -(\\beta + b)^2", "holds")]


def test_the_text_function_then_a_bound_is_two_claims_the_bound_undecided_without_an_ordering():
    claims = kept.check_text(FUNCTION + "$$G(-1) = -(\\beta + b)^2 < 0$$\n")
    assert [(c.latex, c.verdict) for c in claims[1:]] == [
        ("G(-1) = -(\\beta + b)^2", "holds"), ("-(\\beta + b)^2 < 0", "unchecked")]


def test_the_text_function_with_a_wrong_value_is_not_taken_as_holding():
    claims = kept.check_text(FUNCTION + "$$G(-1) = -(\\beta - b)^2$$\n")
    assert "holds" not in [c.verdict for c in claims]
