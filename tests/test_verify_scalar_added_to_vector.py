"""The notes reader on a sum that adds a number over plain letters to a cross product of vectors (a factor j
taken out of j𝐧/m with the 𝐧 left behind): it fails; the same sum dotted with a vector, or with the 𝐧 kept
in the fraction, is left alone."""
import kept_readings as kept
from derive.lecture.scalar_vector_sums import added

line_of = kept.line_of
PROSE = ("# Notes\n\nAn impulse $j\\mathbf{n}$ at the point $\\mathbf{r}$ of a body of mass $m$ and inverse "
         "inertia tensor $\\mathbf{K}$ changes the velocity of that point by\n\n")


def test_a_number_over_a_mass_added_to_a_cross_product_fails():
    text = PROSE + ("$$\n\\Delta\\mathbf{u} = j \\left[ \\frac{1}{m} + (\\mathbf{K}(\\mathbf{r} \\times \\mathbf{n})) "
                    "\\times \\mathbf{r} \\right]\n$$\n")
    claims = [c for c in kept.check_text(text) if c.line == line_of(text, "$$")]
    assert {c.verdict for c in claims} == {"fails"}


def test_the_sum_dotted_with_a_vector_or_with_the_vector_kept_is_left_alone():
    assert added("j \\left[ \\frac{1}{m} + ((\\mathbf{K}(\\mathbf{r} \\times \\mathbf{n})) \\times \\mathbf{r}) "
                 "\\cdot \\mathbf{n} \\right]") is None
    assert added("\\frac{j\\mathbf{n}}{m} + (\\mathbf{K}(\\mathbf{r} \\times j\\mathbf{n})) \\times \\mathbf{r}") is None
    assert added("\\frac{1}{2} + 2 \\times 3") is None
    assert added("\\frac{1}{m} + \\boldsymbol{\\omega} \\times \\mathbf{r}") == "\\frac{1}{m}"
