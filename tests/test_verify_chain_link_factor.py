"""The notes reader on a row that goes on with ``=`` in names the text has not tied: the link to the
member before it is a slip where the two differ by a number, every component alike (no value of the
names makes them equal, short of making both zero); any other difference stays unjudged."""
import kept_readings as kept

HEAD = "# A corner\n\nA cube of side $b$ and mass $M$ turns at the rate $\\omega$.\n\n"
ROWS = ("$$\\begin{align*} \\mathbf{L} &= \\frac{1}{12} Mb^2\\omega \\frac{1}{\\sqrt{2}} \\begin{pmatrix} -11 \\\\ +11 \\\\ 0 "
        "\\end{pmatrix} \\\\[4pt] &= %s \\end{align*}$$\n")


def _last(text):
    return kept.check_text(HEAD + text)[-1]


def test_a_link_off_by_a_number_in_untied_names_is_a_slip_saying_the_number():
    wrong = _last(ROWS % "\\frac{11}{12}Mb^2 \\omega \\begin{pmatrix} -1 \\\\ +1 \\\\ 0 \\end{pmatrix}")
    assert wrong.verdict == "fails" and "\\sqrt{2} times the member before it" in wrong.why
    sign = _last(ROWS % "\\frac{11}{12}Mb^2 \\omega \\frac{1}{\\sqrt{2}} \\begin{pmatrix} 1 \\\\ -1 \\\\ 0 \\end{pmatrix}")
    assert sign.verdict == "fails" and "-1 times" in sign.why


def test_the_same_link_written_right_holds_and_a_difference_in_the_names_is_not_judged():
    right = _last(ROWS % "\\frac{11}{12}Mb^2 \\omega \\frac{1}{\\sqrt{2}} \\begin{pmatrix} -1 \\\\ +1 \\\\ 0 \\end{pmatrix}")
    assert right.verdict == "holds"
    # off by b, not by a number: it may rest on what the names mean, and stays unjudged
    other = _last(ROWS % "\\frac{11}{12}Mb \\omega \\frac{1}{\\sqrt{2}} \\begin{pmatrix} -1 \\\\ +1 \\\\ 0 \\end{pmatrix}")
    assert other.verdict == "unchecked"
    # components off by different numbers are not one factor: unjudged
    mixed = _last(ROWS % "\\frac{11}{12}Mb^2 \\omega \\frac{1}{\\sqrt{2}} \\begin{pmatrix} -2 \\\\ +1 \\\\ 0 \\end{pmatrix}")
    assert mixed.verdict == "unchecked"


SET_ROWS = ("$$\\begin{align*} I_{11} &= \\frac{1}{2} \\frac{M}{abc} [ab^3 c + abc^3] \\\\ &= %s \\end{align*}$$\n")
BOX = "# A box\n\nA box of sides $a$, $b$, $c$ and mass $M$.\n\n"


def test_a_row_setting_the_left_side_is_linked_to_the_row_before_it():
    wrong = kept.check_text(BOX + SET_ROWS % "\\frac{1}{12} M(b^2 + c^2)")[-1]
    assert wrong.verdict == "fails" and "\\frac{1}{6} times the member before it" in wrong.why
    right = kept.check_text(BOX + SET_ROWS % "\\frac{1}{2} M(b^2 + c^2)")
    assert all(c.verdict not in ("typo", "fails") for c in right)
