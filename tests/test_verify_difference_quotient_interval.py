"""A difference quotient over an interval beside one over the bare variable in the same statement:
``\\frac{\\Delta x}{\\Delta t} = R\\frac{\\Delta\\vartheta}{t}`` divides the second change by the time itself,
a typo for ``\\Delta t``; a relative change ``\\Delta t / t`` or a quotient alone is not judged so."""
import kept_readings as kept
from derive.lecture import delta_quotients

HEAD = "# Rolling\n\nA ball of radius $R$ rolls, turning by $\\Delta\\vartheta$ as it moves by $\\Delta x$.\n\n"


def _claims(formula):
    return kept.check_text(HEAD + "$$\n" + formula + "\n$$\n")


def test_a_change_over_the_bare_time_beside_one_over_its_interval_is_a_typo():
    [c] = [c for c in _claims("v = \\frac{\\Delta x}{\\Delta t} = R\\frac{\\Delta\\vartheta}{t} = R\\omega") if c.verdict != "unchecked"]
    assert c.verdict == "typo" and "\\Delta t" in c.why
    assert "R\\frac{\\Delta\\vartheta}{\\Delta t}" in c.correction


def test_a_space_set_after_the_delta_changes_nothing():
    for spaced in ("v = \\frac{\\Delta \\, x}{\\Delta \\, t} = R\\frac{\\Delta\\vartheta}{t}",
                   "v = \\frac{\\Delta x}{\\Delta t} = R\\frac{\\Delta \\; \\vartheta}{ t }"):
        assert delta_quotients.slip(spaced) is not None, spaced


def test_quotients_over_their_intervals_or_a_relative_change_are_not_flagged():
    for formula in ("v = \\frac{\\Delta x}{\\Delta t} = R\\frac{\\Delta\\vartheta}{\\Delta t} = R\\omega",
                    "\\frac{\\Delta t}{t} = \\frac{\\Delta x}{\\Delta t}",
                    "\\bar\\omega = \\frac{\\Delta\\vartheta}{t}"):
        assert delta_quotients.slip(formula) is None, formula
        assert all(c.verdict not in ("typo", "fails") for c in _claims(formula)), formula
