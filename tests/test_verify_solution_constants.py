"""A general solution whose two constants multiply one function of the time: c₁ e^{κt} + c₂ e^{κt}
has one free constant, never the two a second-order equation's solution carries."""
import kept_readings as kept


def claims(*displays: str, prose: str = "") -> list:
    text = "# Solutions\n\n" + prose + "\n\n" + "".join(f"$$\n{d}\n$$\n\n" for d in displays)
    return kept.check_text(text)


def test_two_constants_beside_one_exponential_are_flagged():
    [c] = [c for c in claims("\\delta \\omega_1 = c_1 \\exp( \\kappa t ) + c_2 \\exp( \\kappa t )",
                             prose="With $\\kappa > 0$ the general solution is") if c.verdict != "unchecked"]
    assert c.verdict == "fails" and "c_1 + c_2" in c.why
    [c] = claims("x(t) = A_1 \\cos(\\omega t) + A_2 \\cos(\\omega t)")
    assert c.verdict == "fails"


def test_two_independent_solutions_are_not_flagged():
    for d in ("\\delta \\omega_1 = c_1 \\exp( \\kappa t ) + c_2 \\exp( -\\kappa t )",
              "\\delta \\omega_1 = c_1 \\cos( \\kappa t ) + c_2 \\sin( \\kappa t )",
              "x = c_1 e^{\\kappa t} + c_2 t e^{\\kappa t}",
              "x = c_1 e^{\\kappa t} + b_2 e^{\\kappa t}",
              "x = (c_1 + c_2) e^{\\kappa t}"):
        assert all(c.verdict not in ("fails", "typo") for c in claims(d)), d
