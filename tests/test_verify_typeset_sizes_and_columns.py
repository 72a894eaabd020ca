"""The notes reader on how homework solutions set their formulas: a font size switch around a wide
formula, a column of components in angle brackets, a unit in brackets after a value."""
import pytest

import kept_readings as kept
from derive.lecture import angle_columns


def verdicts(text):
    return [(c.line, c.verdict) for c in kept.check_text(text)]


def _energy(half_3):
    return ("\\frac{1}{2} I_1 \\omega_1^2 + \\frac{1}{2} I_2 \\omega_2^2 + \\frac{1}{" + half_3
            + "} I_3 \\omega_3^2")


@pytest.mark.parametrize("sized", ["\\footnotesize{{{}}}", "{{\\small {}}}", "\\scriptsize {}"])
def test_a_font_size_switch_only_sets_how_big_the_formula_prints(sized):
    assert verdicts(f"# Energy\n\n$$T = {sized.format(_energy('2'))}$$\n") == [(3, "holds")]
    assert verdicts(f"# Energy\n\n$$T = {sized.format(_energy('3'))}$$\n") == [(3, "fails")]


def _column(*entries, left="\\left<", right="\\right>"):
    return left + "\\begin{array}{c} " + " \\\\ ".join(entries) + " \\end{array}" + right


_TURN = ("\\left[\\begin{array}{ccc} \\cos\\theta & -\\sin\\theta & 0\\\\ \\sin\\theta & \\cos\\theta & 0\\\\ "
         "0 & 0 & 1 \\end{array}\\right]")


@pytest.mark.parametrize("left, right", [("\\left<", "\\right>"), ("\\left\\langle", "\\right\\rangle"),
                                         ("\\langle", "\\rangle")])
def test_a_column_in_angle_brackets_is_a_column_of_components(left, right):
    turned = (_TURN + _column("x", "y", "0", left=left, right=right) + " = "
              + _column("\\cos\\theta\\, x - \\sin\\theta\\, y", "\\sin\\theta\\, x + \\cos\\theta\\, y", "0",
                        left=left, right=right))
    text = f"\\documentclass{{article}}\n\\begin{{document}}\nTurned:\n$$ {turned} $$\n\\end{{document}}\n"
    assert verdicts(text) == [(4, "holds")]


def test_angle_brackets_around_anything_but_one_matrix_are_left_as_written():
    written = "\\langle u, v\\rangle + x < y + \\left< a \\right> + \\langle\\begin{pmatrix} 1 \\end{pmatrix}\\rangle"
    assert angle_columns.squared(written) == written


@pytest.mark.parametrize("third, verdicts_read", [("I_3", {"holds"}), ("2 I_3", {"typo", "fails"})])
def test_a_long_sum_carried_to_an_indented_row_after_right_dot_is_one_statement(third, verdicts_read):
    text = ("# Energy\n\n\\begin{equation*}\n  \\begin{aligned}\n"
            "    T &= \\frac{1}{2}\\left(I_1 \\omega_1^2 + I_2 \\omega_2^2\\right. \\\\\n"
            f"      & \\ \\ \\ \\ \\left. + {third} \\omega_3^2\\right)\n  \\end{{aligned}}\n\\end{{equation*}}\n")
    [(line, verdict)] = verdicts(text)
    assert line == 3 and verdict in verdicts_read


def _energy_of_a_column(energy):
    return ("\\documentclass{article}\n\\begin{document}\nThe velocity of the centre:\n"
            "$$ v = \\left[\\begin{array}{c} s\\,\\cos\\psi\\,\\sin\\theta\\,\\dot{\\psi} \\\\ "
            "s\\,\\sin\\psi\\,\\sin\\theta\\,\\dot{\\psi} \\\\ 0 \\end{array}\\right] $$\n"
            f"Its kinetic energy:\n$$ T_\\text{{trans}} = \\frac{{1}}{{2}} M \\left( v \\cdot v \\right) = {energy} $$\n"
            "\\end{document}\n")


def test_a_dot_between_two_plain_names_set_to_columns_is_their_dot_product():
    assert verdicts(_energy_of_a_column("\\frac{1}{2} M s^2 \\sin^2\\theta\\, \\dot{\\psi}^2")) == \
        [(4, "unchecked"), (6, "holds")]
    assert verdicts(_energy_of_a_column("M s^2 \\sin^2\\theta\\, \\dot{\\psi}^2"))[1] != (6, "holds")


def _cart(energy):
    return ("# Energy\n\nA cart of 2.5 kg at 4 m/s:\n\n$$ K = \\frac{1}{2}\\,(2.5)\\,(4.0)^2 \\ \\ "
            "\\left[\\text{kg}\\left(\\frac{\\text{m}}{\\text{s}}\\right)^2\\right] = " + energy + " \\ \\ \\left[ J \\right] $$\n")


def test_coherent_units_in_brackets_after_a_value_are_no_factor():
    assert {v for _, v in verdicts(_cart("20.0"))} == {"holds"}
    assert "fails" in {v for _, v in verdicts(_cart("24.0"))}


def test_units_in_brackets_sized_by_hand_or_plain_are_no_factor_either():
    for opening, closing in (("\\bigl", "\\bigr"), ("\\Bigl", "\\Bigr"), ("", "")):
        def sized(energy):
            return _cart(energy).replace("\\left", opening).replace("\\right", closing)
        assert {v for _, v in verdicts(sized("20.0"))} == {"holds"}, opening
        assert "fails" in {v for _, v in verdicts(sized("24.0"))}, opening


def test_a_rate_in_revolutions_in_brackets_is_not_read_as_the_number_in_radians():
    text = ("# Rate\n\n$$ \\omega = 5 \\ \\ \\left[\\frac{\\text{rev}}{\\text{s}} \\right] = 10 \\pi \\ \\ "
            "\\left[\\frac{\\text{rad}}{\\text{s}} \\right] $$\n")
    assert {v for _, v in verdicts(text)} == {"unchecked"}


def test_a_chain_row_that_repeats_the_value_before_it_is_no_copied_row():
    text = ("# Energy\n\nA value written twice:\n\n\\begin{equation*}\n  \\begin{aligned}\n    E &= \\frac{1}{2} m v^2 \\\\\n"
            "      &= 0.245\\,m\\,\\pi^2 \\\\\n      &= 0.245\\,m\\,\\pi^2\n  \\end{aligned}\n\\end{equation*}\n")
    assert {v for _, v in verdicts(text)} <= {"holds", "unchecked"}
