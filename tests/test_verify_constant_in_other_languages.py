"""A chain that says its quantity is constant in another language (``\\text{cte}``, ``\\text{constante}``,
``\\text{Konstante}``) and then gives the constant's value in an example (``= 172.80``): the quantity
before the constant is judged as an integral of the free body, the value is left aside."""
import kept_readings as kept

HEAD = ("## Free rotation\n\nThe body turns freely, with no torque, about its centre of mass; "
        "$I_1$, $I_2$, $I_3$ are its principal moments and $\\omega_i$ the body components of its angular velocity.\n\n")


def claims_at(text: str, start: str) -> list:
    return [c for c in kept.check_text(HEAD + text) if c.latex.lstrip().startswith(start)]


def test_a_spanish_constant_after_the_energy_is_an_integral_that_holds():
    got = claims_at("$$2 T = I_1 \\omega_1^2 + I_2 \\omega_2^2 + I_3 \\omega_3^2 = \\text{cte} = 172.80$$\n", "2 T")
    assert any(c.kind == "integral" and c.verdict == "holds" for c in got)
    assert not any(c.verdict in ("typo", "fails") for c in got)


def test_french_and_german_words_for_a_constant_are_read_as_one():
    for word in ("constante", "Konstante", "konst."):
        got = claims_at(f"$$L^2 = I_1^2 \\omega_1^2 + I_2^2 \\omega_2^2 + I_3^2 \\omega_3^2 = \\text{{{word}}}$$\n", "L^2")
        assert any(c.kind == "integral" and c.verdict == "holds" for c in got), word


def test_a_quantity_that_is_not_an_integral_gets_no_verdict_from_its_constant():
    got = claims_at("$$2 T = I_1 \\omega_1^2 + I_2 \\omega_2 + I_3 \\omega_3^2 = \\text{cte} = 172.80$$\n", "2 T")
    assert not any(c.kind == "integral" for c in got)
    assert not any(c.verdict == "holds" and c.kind == "integral" for c in got)


def test_the_constants_value_in_an_example_is_never_flagged():
    got = claims_at("$$2 T = I_1 \\omega_1^2 + I_2 \\omega_2^2 + I_3 \\omega_3^2 = \\text{cte} = 9.99$$\n", "2 T")
    assert not any(c.verdict in ("typo", "fails") for c in got)
