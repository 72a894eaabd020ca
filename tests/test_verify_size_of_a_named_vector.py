"""The notes reader on a display that names a vector and beside it sets the plain letter
(``\\vec{M} = \\vec{r}\\times\\vec{F}_{g}; \\qquad M = m g r \\sin\\gamma``): the plain letter is that
vector's size, a quantity of the text's, never the letter the reader takes M for without it (the mass)."""
import kept_readings as kept
from derive.lecture.vector_size import vector_size

verdicts, line_of = kept.verdicts_by_line, kept.line_of
TORQUE = ("# A weight on a spinning top\n\nA weight at $\\vec{r}$ on the axis exerts the torque\n\n"
          "$$\n\\vec{M} = \\vec{r}\\times\\vec{F}_{g}; \\qquad M=m\\,g\\,r\\sin\\gamma\n$$\n\n"
          "and the axis turns about the vertical at the rate\n\n")


def test_a_relation_in_the_size_of_a_named_torque_is_not_judged_with_the_mass():
    text = TORQUE + "$$\n\\frac{\\mathrm{d}\\varphi}{\\mathrm{d}t} = \\frac{M}{L\\sin\\gamma}\n$$\n"
    found = verdicts(text)[line_of(text, "$$\n\\frac{\\mathrm{d}\\varphi}")]
    assert not found & {"typo", "fails"}


def test_the_plain_letter_beside_its_named_vector_is_recorded_as_a_definition():
    text = TORQUE + "$$\n\\Omega = \\frac{M}{L}\n$$\n"
    assert verdicts(text)[line_of(text, "$$\n\\vec{M} =")] == {"unchecked"}


def test_only_a_plain_letter_whose_vector_the_display_names_is_its_size():
    assert vector_size("M=m\\,g\\,r\\sin\\gamma", ["\\vec{M} = \\vec{r}\\times\\vec{F}_{g};", "M=m\\,g\\,r\\sin\\gamma"]) \
        == ("M", "m\\,g\\,r\\sin\\gamma")
    assert vector_size("M = m g r", ["\\vec{F} = m\\vec{g}", "M = m g r"]) is None     # another vector named
    assert vector_size("M_z = m g r", ["\\vec{M} = \\vec{r} \\times \\vec{F}", "M_z = m g r"]) is None
    assert vector_size("M = a = b", ["\\mathbf{M} = c", "M = a = b"]) is None          # a chain, not a size
