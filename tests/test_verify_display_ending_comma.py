"""The notes reader on a display whose sentence goes on after it: a comma after its last statement
ends that statement and takes nothing from it (a name defined at a chain's end, statements cut at
``\\;``, a bracketed definition after the last row)."""
import kept_readings as kept
from derive.lecture.statements import statements

verdicts, line_of = kept.verdicts_by_line, kept.line_of
RADIUS = "The radius of gyration, $\\rho_z^2 = \\sum_i m_i r_i^2 / m$:\n\n"


def test_a_name_met_at_a_chains_end_before_a_comma_is_defined_by_the_member_before_it():
    text = "# Notes\n\n$$L_z = \\omega \\sum_i m_i r_i^2 = J_z \\omega,$$\n\n" + RADIUS + "$$\\rho_z = \\sqrt{\\frac{J_z}{m}}$$\n"
    assert verdicts(text)[line_of(text, "$$\\rho_z =")] == {"holds"}


def test_the_name_so_defined_before_a_comma_does_not_make_a_wrong_relation_hold():
    text = "# Notes\n\n$$L_z = \\omega \\sum_i m_i r_i^2 = J_z \\omega,$$\n\n" + RADIUS + "$$\\rho_z = \\sqrt{\\frac{m}{J_z}}$$\n"
    assert "holds" not in verdicts(text)[line_of(text, "$$\\rho_z =")]


def test_statements_cut_at_a_medium_space_stay_cut_when_a_comma_ends_the_display():
    assert statements(r"a = b c, \; d = e f,") == ["a = b c", "d = e f"]


def test_a_bracketed_definition_after_the_last_row_is_read_when_a_comma_follows_it():
    latex = "\\begin{cases} \\dot x = y \\\\ \\dot y = -\\alpha x \\end{cases}\\left(\\alpha = \\frac{k}{m}\\right)\n ,"
    assert [" ".join(s.split()) for s in statements(latex)] == ["\\dot x = y", "\\alpha = \\frac{k}{m}", "\\dot y = -\\alpha x"]


def test_a_comma_between_two_statements_still_cuts_and_one_inside_brackets_does_not():
    assert statements(r"\theta = 0, \dot\theta = 0,") == ["\\theta = 0", "\\dot\\theta = 0"]
    assert statements(r"f(a, b) = c,") == ["f(a, b) = c"]
