"""The notes reader on the letter o typed for the digit 0 in a matrix of numbers: a typo corrected by the
digit; a matrix with a letter or an expression among its entries (a position o beside a block R) is left alone."""
import kept_readings as kept
from derive.lecture.letter_digits import corrected, mistyped

line_of = kept.line_of
PROSE = "# Notes\n\nThe spin-one matrices in the basis of the states of J_z:\n\n"


def test_the_letter_o_among_the_numbers_of_a_matrix_is_a_typo():
    text = PROSE + ("$$\nS = \\frac{1}{\\sqrt{2}} \\begin{pmatrix} 0 & -i & 0 \\\\ i & 0 & -i \\\\ 0 & i & o "
                    "\\end{pmatrix}\n$$\n")
    claims = [c for c in kept.check_text(text) if c.line == line_of(text, "$$")]
    assert {c.verdict for c in claims} == {"typo"}
    assert "0 & i & 0" in claims[0].correction


def test_a_matrix_with_a_letter_of_its_own_among_its_entries_is_left_alone():
    assert mistyped("\\begin{bmatrix} R & o \\\\ 0 & 1 \\end{bmatrix}") == []
    assert mistyped("\\begin{bmatrix} 1 & o \\\\ 2 & 1 \\end{bmatrix}") == []     # no zero written
    assert mistyped("\\begin{bmatrix} 1 & 0 \\\\ 0 & 1 \\end{bmatrix}") == []


def test_the_correction_writes_the_digit_only_where_the_letter_stands_alone():
    piece = "\\begin{pmatrix} 0 & 1 \\\\ o & 0 \\end{pmatrix}"
    assert corrected(piece, mistyped(piece)) == "\\begin{pmatrix} 0 & 1 \\\\ 0 & 0 \\end{pmatrix}"


def test_a_small_space_between_an_entrys_factors_keeps_it_a_number():
    # 2\,i and -\,i are numbers as 2i and -i are: the letter o among them is still the digit mistyped
    assert mistyped("\\begin{pmatrix} 0 & -\\,i \\\\ 2\\,i & o \\end{pmatrix}") != []
    assert mistyped("\\begin{pmatrix} 0 & -\\,i \\\\ 2\\,x & o \\end{pmatrix}") == []
