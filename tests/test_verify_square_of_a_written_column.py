"""The notes reader on the square of a bold letter the text wrote as a column: r² is r·r, as a vector's square is
written (a power of a column was a power of a non-square matrix, which left the display unjudged)."""
import kept_readings as kept

PROSE = ("# Notes\n\nA particle at $\\mathbf{r}$, whose coordinates are\n\n"
         "$$\n\\mathbf{r} = \\begin{pmatrix} x \\\\ y \\\\ z \\end{pmatrix}\n$$\n\nhas the squared distance\n\n")


def test_the_square_of_a_written_column_is_its_dot_product_with_itself():
    text = PROSE + "$$\nd = \\mathbf{r}^2 = x^2 + y^2 + z^2\n$$\n"
    claims = [c for c in kept.check_text(text) if c.latex.startswith("d =")]
    assert {c.verdict for c in claims} == {"holds"}
