"""The notes reader on a vector's length between bars written right after a scalar factor, ``m|\\vec{v}|^2``:
the bar opens a factor of the product (the squared length 𝐯 · 𝐯), as ``m (\\vec v \\cdot \\vec v)`` would;
inside the bars a bar closes the group, and a bar before a subscript (an evaluation) starts nothing."""
import kept_readings as kept

verdicts, line_of = kept.verdicts_by_line, kept.line_of
HEAD = "# Notes\n\nA particle of mass $m$; for any two vectors:\n\n"


def test_a_squared_length_after_a_mass_is_read_as_the_dot_product():
    text = HEAD + ("$$\n\\frac{1}{2}m|\\vec{a}+\\vec{b}|^2=\\frac{1}{2}m|\\vec{a}|^2+\\frac{1}{2}m|\\vec{b}|^2"
                   "+m\\vec{a}\\cdot\\vec{b}\n$$\n")
    assert verdicts(text)[line_of(text, "$$")] == {"holds"}


def test_a_slip_in_such_an_expansion_is_flagged():
    text = HEAD + ("$$\n\\frac{1}{2}m|\\vec{a}+\\vec{b}|^2=\\frac{1}{2}m|\\vec{a}|^2+\\frac{1}{2}m|\\vec{b}|^2"
                   "+2m\\vec{a}\\cdot\\vec{b}\n$$\n")
    assert "holds" not in verdicts(text)[line_of(text, "$$")]
