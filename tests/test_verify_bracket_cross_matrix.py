"""A text that defines its bracket for the cross-product matrix (b × y ≡ [b] y) has its later brackets
acting on a vector read as that matrix, plain letters it writes bold elsewhere as those vectors; a
wrong matrix is flagged, and a text that defines no such bracket keeps its brackets as grouping."""
import kept_readings as kept

from derive.lecture import bracket_cross

DEFINED = ("The particles sit at $\\mathbf{r}_i$; $\\mathbf{S}$ is a point and $\\mathbf{y}$ any vector. The cross "
           "product is a matrix product:\n\n"
           "$$\\mathbf{b} \\times \\mathbf{y} \\equiv \\left[\\mathbf{b}\\right] \\mathbf{y}$$\n\n")


def verdicts(text: str) -> list:
    return [c.verdict for c in kept.check_text(text)]


def test_the_defining_display_and_a_bracket_of_a_difference_acting_on_a_vector_hold():
    text = DEFINED + "so that\n\n$$[r_i -S]\\mathbf{y} = (\\mathbf{r}_i - \\mathbf{S})\\times \\mathbf{y}$$\n"
    assert verdicts(text) == ["holds", "holds"]


def test_the_written_matrix_of_the_bracket_holds_and_a_sign_slip_in_it_is_flagged():
    right = "0 & -b_z & b_y \\\\ b_z & 0 & -b_x \\\\ -b_y & b_x & 0"
    wrong = "0 & b_z & b_y \\\\ b_z & 0 & -b_x \\\\ -b_y & b_x & 0"
    matrix = "with\n\n$$\\left[\\mathbf{{b}}\\right] {rel} \\begin{{bmatrix}} {entries} \\end{{bmatrix}}$$\n"
    assert verdicts(DEFINED + matrix.format(rel="\\equiv", entries=right))[-1] == "holds"
    assert verdicts(DEFINED + matrix.format(rel="=", entries=wrong))[-1] in ("typo", "fails")
    # the text's own definition (≡) of a matrix that is not the cross product's: never passed, not flagged
    assert verdicts(DEFINED + matrix.format(rel="\\equiv", entries=wrong))[-1] == "unchecked"


def test_a_bracket_of_a_name_the_text_never_writes_bold_is_left_as_it_is():
    text = DEFINED + "$$[I_S] \\mathbf{y} = \\mathbf{y}$$\n"
    assert "[I_S] \\mathbf{y}" in bracket_cross.marked(text)


def test_a_text_that_defines_no_bracket_keeps_its_brackets():
    text = "$$[a - b]\\mathbf{y} = \\mathbf{y}$$\n"
    assert bracket_cross.marked(text) == text
