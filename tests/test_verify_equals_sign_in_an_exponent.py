"""The notes reader on an equals sign typed inside a bracket of an exponential's exponent: the statement is no
formula as written and fails; an argument of a function (ω(t = 0)), a sum's limit and a power of anything but
e are left alone."""
import kept_readings as kept
from derive.lecture.exponent_relations import relations

line_of = kept.line_of
PROSE = "# Notes\n\nThe phases the two turns about z give the element between the states m' and m:\n\n"


def test_an_equals_sign_inside_a_bracket_of_an_exponent_of_e_fails():
    text = PROSE + "$$\nd = e^{-i(\\alpha = \\gamma)/2} \\sin\\frac{\\beta}{2}\n$$\n"
    claims = [c for c in kept.check_text(text) if c.line == line_of(text, "$$")]
    assert {c.verdict for c in claims} == {"fails"}
    assert "(\\alpha = \\gamma)" in claims[0].why


def test_signs_arguments_limits_and_other_powers_are_left_alone():
    assert relations("e^{-i(\\alpha - \\gamma)/2}") == []
    assert relations("e^{-\\lambda(t = 0)}") == []             # a function's argument
    assert relations("e^{\\sum_{k=1}^{n} a_k}") == []          # a sum's limit
    assert relations("x^{(a = b)}") == []                      # a power of another base
    assert relations("e^{i(\\le)} + e^{(a \\le b)}") == []     # no equals sign between two terms
    assert relations("\\mathrm{e}^{2(\\alpha = \\beta)}") == ["(\\alpha = \\beta)"]
