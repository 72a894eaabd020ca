"""The notes reader on a vector marked twice, an arrow over a bold letter (``\\vec{\\boldsymbol{\\omega}}``,
``\\vec{\\mathbf{H}}_C``) or a bold face around an arrowed letter (``\\mathbf{\\vec{M_O}}``), as spacecraft
and engineering course notes write their vectors: the bold letter alone, which is what either mark says,
so a statement in them is read as the one in plain bold is."""
import kept_readings as kept
from derive.lecture import texmacros

verdicts, line_of = kept.verdicts_by_line, kept.line_of
PROSE = ("# Notes\n\nThe inertia tensor $\\mathbf{I}$ acts on the body's angular velocity "
         "$\\vec{\\boldsymbol{\\omega}}$. Its rotational kinetic energy is\n\n")


def test_an_arrow_over_a_bold_letter_is_the_bold_letter():
    assert texmacros.synonyms("\\vec{\\mathbf{H}}_C") == "\\mathbf{H}_C"
    assert texmacros.synonyms("\\vec{\\boldsymbol{\\omega}}^T") == "\\boldsymbol{\\omega}^T"
    assert texmacros.synonyms("\\mathbf{\\vec{M_O}}") == "\\mathbf{M_O}"
    assert texmacros.synonyms("\\vec{\\mathbf{{M_{O'}}}}") == "\\mathbf{{M_{O'}}}"
    # one mark alone, or a bold face around more than one arrowed letter, is left as written
    assert texmacros.synonyms("\\vec{F}") == "\\vec{F}"
    assert texmacros.synonyms("\\mathbf{\\vec{r}_{i/O}}") == "\\mathbf{\\vec{r}_{i/O}}"


def test_the_quadratic_form_in_a_twice_marked_angular_velocity_holds():
    text = PROSE + ("$$\nT = \\frac{1}{2} \\vec{\\boldsymbol{\\omega}}^T \\mathbf{I} "
                    "\\vec{\\boldsymbol{\\omega}}\n$$\n")
    assert verdicts(text)[line_of(text, "$$")] == {"holds"}


def test_the_quadratic_form_with_a_wrong_factor_is_flagged():
    text = PROSE + ("$$\nT = \\vec{\\boldsymbol{\\omega}}^T \\mathbf{I} "
                    "\\vec{\\boldsymbol{\\omega}}\n$$\n")
    assert verdicts(text)[line_of(text, "$$")] & {"fails", "typo"}
