"""The notes reader on digits Python counts and LaTeX does not write as numbers: a circled ①, ②, ③
marking the parts of a sum (or a superscript ²) is a mark the scanner does not read, not a number whose
pattern fails, so the display holding it stays unread and the rest of the text is read."""
import kept_readings as kept
from derive.lecture import vocabulary
from derive.lecture.coordinate_functions import tokens
from derive.lecture.operator_notation import NotHandled
from derive.lecture.vocabulary import NotRead

verdicts, line_of = kept.verdicts_by_line, kept.line_of


def test_a_text_with_a_circled_digit_marking_a_part_is_read_past_it():
    text = ("# Notes\n\nThe first part of the energy:\n\n$$\n①=\\frac{1}{2}\\mu|\\vec{V}|^2\n$$\n\n"
            "With the density $\\rho(\\mathbf{r})$ of the body:\n\n$$\n\\mathbf{L} = \\int \\rho(\\mathbf{r})\\, "
            "\\mathbf{r} \\times (\\boldsymbol\\omega \\times \\mathbf{r})\\, \\mathrm{d}^3 r = \\int \\rho(\\mathbf{r}) "
            "\\left(\\boldsymbol\\omega r^2 - \\mathbf{r}(\\mathbf{r}\\cdot\\boldsymbol\\omega)\\right) \\mathrm{d}^3 r\n$$\n")
    got = verdicts(text)
    assert got[line_of(text, "$$\n\\mathbf{L}")] == {"holds"}
    assert "holds" not in got.get(line_of(text, "$$\n①"), set())


def test_the_scanner_refuses_a_circled_digit_as_a_mark_it_cannot_read():
    for latex in ("① = a", "x^² = a"):
        try:
            vocabulary.scan(latex)
        except NotRead:
            continue
        raise AssertionError(latex)


def test_the_coordinate_scanner_takes_only_ascii_digits_for_numbers():
    try:
        tokens("② + 2")
    except (NotHandled, NotRead):
        return
    raise AssertionError("a circled digit scanned as a number")
