"""A bold or arrowed vector with ``^\\times`` (``\\boldsymbol{u}^\\times``, Hughes' notation) is the skew
matrix of its cross product: ``\\boldsymbol{u}^\\times \\boldsymbol{v} = \\boldsymbol{u} \\times \\boldsymbol{v}``
holds, the product in the wrong order is flagged, and a plain letter with ``^\\times`` is left as written."""
import kept_readings as kept

from derive.lecture import source

PROSE = ("Here $\\boldsymbol{u}$ and $\\boldsymbol{v}$ are any two columns, and the skew matrix acts as the "
         "cross product:\n\n")


def verdicts(display: str) -> list:
    return [c.verdict for c in kept.check_text(PROSE + "$$" + display + "$$\n")]


def test_a_bold_vector_with_a_superscript_times_is_its_cross_product_matrix():
    assert verdicts(r"\boldsymbol{u}^\times \boldsymbol{v} = \boldsymbol{u} \times \boldsymbol{v}") == ["holds"]
    assert verdicts(r"\boldsymbol{u}^{\times} \boldsymbol{v} = -\boldsymbol{v} \times \boldsymbol{u}") == ["holds"]


def test_the_cross_product_matrix_in_the_wrong_order_is_flagged():
    slip = r"\boldsymbol{u}^\times \boldsymbol{v} = \boldsymbol{v} \times \boldsymbol{u}"
    assert verdicts(slip)[0] in ("typo", "fails")


def test_a_subscripted_vector_and_an_arrow_are_read_and_a_plain_letter_is_not():
    assert source.normalize(r"\boldsymbol{r}_n^\times x") == r"\crossmatrix\left(\boldsymbol{r}_n\right) x"
    assert source.normalize(r"\vec{r}^{\times}") == r"\crossmatrix\left(\vec{r}\right)"
    assert source.normalize(r"a^\times") == r"a^\times"
