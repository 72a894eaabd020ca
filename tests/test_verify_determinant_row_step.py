"""The notes reader on a determinant set to zero that the text rewrites by one row operation (the
secular equation of an inertia tensor, then "taking row 1 from row 2"): the rewritten determinant
holds when it equals the first up to a number, fails when its changed row is not the old row plus
a multiple of another, and a determinant that differs in two rows is a new equation, not judged."""
import kept_readings as kept

HEAD = "# Principal moments\n\nThe moments about the corner are the roots in $I$ of\n\n"
SECULAR = ("$$\n\\begin{vmatrix} (2 A - I) & -B & -B \\\\ -B & (2 A - I) & -B \\\\ -B & -B & (2 A - I) "
           "\\end{vmatrix} = 0\n$$\n\nTaking row 1 from row 2,\n\n")


def _rewritten(text):
    return [c for c in kept.check_text(text) if c.line == kept.line_of(text, "Taking row") + 2]


def test_a_row_less_another_row_holds():
    text = HEAD + SECULAR + ("$$\n\\begin{vmatrix} (2 A - I) & -B & -B \\\\ (I - 2 A - B) & (2 A - I + B) & 0 \\\\ "
                             "-B & -B & (2 A - I) \\end{vmatrix} = 0\n$$\n")
    assert [c.verdict for c in _rewritten(text)] == ["holds"]


def test_a_row_that_drops_the_unknown_fails():
    text = HEAD + SECULAR + ("$$\n\\begin{vmatrix} (2 A - I) & -B & -B \\\\ (- 2 A - B) & (2 A - I + B) & 0 \\\\ "
                             "-B & -B & (2 A - I) \\end{vmatrix} = 0\n$$\n")
    got = _rewritten(text)
    assert [c.verdict for c in got] == ["fails"] and got[0].kind == "determinant" and "row 2" in got[0].why


def test_two_rows_changed_is_a_new_equation_not_judged():
    text = HEAD + SECULAR + ("$$\n\\begin{vmatrix} (2 A - I) & -B & -B \\\\ (- 2 A - B) & (2 A - I + B) & 0 \\\\ "
                             "-B & 0 & (2 A - I) \\end{vmatrix} = 0\n$$\n")
    assert not {c.verdict for c in _rewritten(text)} & {"holds", "fails", "typo"}
