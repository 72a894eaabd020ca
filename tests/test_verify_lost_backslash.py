"""The notes reader on a symbol's command typed without its backslash: ``\\sin theta`` in a display that
writes ``\\cos\\theta`` sets the letters t h e t a as a product, a typo corrected by the backslash; a display
that never writes the command, a word in ``\\text{…}`` and a word that is a whole subscript are left alone."""
import kept_readings as kept
from derive.lecture.lost_backslash import lost, restored

verdicts, line_of = kept.verdicts_by_line, kept.line_of
PROSE = "# Notes\n\nA vector turned by the angle $\\theta$ about a unit vector, written out:\n\n"


def test_a_greek_letter_without_its_backslash_beside_the_command_is_a_typo():
    text = PROSE + "$$\nx' = \\cos\\theta\\, x + \\sin\ntheta\\, y\n$$\n"
    claims = [c for c in kept.check_text(text) if c.line == line_of(text, "$$")]
    assert {c.verdict for c in claims} == {"typo"}
    assert "\\sin\n\\theta" in claims[0].correction


def test_infinity_without_its_backslash_in_a_limit_beside_the_command_is_a_typo():
    text = PROSE + ("$$\n\\lim_{N\\to\\infty} \\left(1 + \\frac{x}{N}\\right)^N = \\lim_{N \\to infty} "
                    "e^{N \\ln (1 + x/N)}\n$$\n")
    assert "typo" in verdicts(text)[line_of(text, "$$")]


def test_the_letters_are_left_alone_where_the_display_never_writes_the_command():
    assert lost("y = theta x", "y = theta x") == []
    assert lost("y = \\text{theta} + I_{theta} + x_theta", "\\theta") == []
    assert lost("y = \\operatorname*{theta} + \\mathrm{theta}", "\\theta") == []
    assert lost("y = \\sin\\theta + thetas", "\\theta") == []
    assert lost("y = 2 theta", "\\theta") == ["theta"]


def test_the_correction_puts_the_backslash_back_only_on_the_bare_word():
    assert restored("\\sin theta + \\text{theta} + \\theta", ["theta"]) == "\\sin \\theta + \\text{theta} + \\theta"
