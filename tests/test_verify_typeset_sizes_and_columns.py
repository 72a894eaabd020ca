"""The notes reader on how homework solutions set their formulas: a font size switch around a wide
formula, a column of components in angle brackets, a unit in brackets after a value."""
import pytest

import kept_readings as kept


def verdicts(text):
    return [(c.line, c.verdict) for c in kept.check_text(text)]


def _energy(half_3):
    return ("\\frac{1}{2} I_1 \\omega_1^2 + \\frac{1}{2} I_2 \\omega_2^2 + \\frac{1}{" + half_3
            + "} I_3 \\omega_3^2")


@pytest.mark.parametrize("sized", ["\\footnotesize{{{}}}", "{{\\small {}}}", "\\scriptsize {}"])
def test_a_font_size_switch_only_sets_how_big_the_formula_prints(sized):
    assert verdicts(f"# Energy\n\n$$T = {sized.format(_energy('2'))}$$\n") == [(3, "holds")]
    assert verdicts(f"# Energy\n\n$$T = {sized.format(_energy('3'))}$$\n") == [(3, "fails")]
