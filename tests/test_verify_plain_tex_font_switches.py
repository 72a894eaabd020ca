"""The notes reader on plain TeX's font switches, as older texts and reference books set their
vectors: ``{\\bf a}`` is the bold a (``\\mathbf{a}``), ``{\\rm space}`` an upright label."""
from derive.lecture import texmacros
from kept_readings import verdicts_by_line as verdicts

TRIPLE = ("# Vectors\n\nThe triple product:\n\n$$\n{\\bf a}\\cdot({\\bf b}\\times{\\bf c}) = "
          "{\\bf b}\\cdot({\\bf c}\\times{\\bf a})\n$$\n\nand\n\n$$\n{\\bf a}\\cdot({\\bf b}\\times{\\bf c}) = "
          "{\\bf b}\\cdot({\\bf a}\\times{\\bf c})\n$$\n")


def test_a_group_opening_with_a_font_switch_is_the_command_for_the_rest_of_the_group():
    assert texmacros.font_switches("(d{\\bf G})_{\\rm space}") == "(d{\\mathbf{G}})_{\\mathrm{space}}"
    assert texmacros.font_switches("\\{ {\\bf a} \\}") == "\\{ {\\mathbf{a}} \\}"


def test_vectors_set_bold_by_a_switch_are_read_as_vectors():
    got = verdicts(TRIPLE)
    assert got[5] == {"holds"} and got[11] == {"typo"}
