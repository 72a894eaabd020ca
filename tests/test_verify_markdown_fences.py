"""Markdown's fenced blocks as they render (`derive.lecture.fences`): a ``math`` block is a display,
code is blanked, and a MyST directive fenced with four backticks is its body, displays and all."""
from derive.lecture.fences import rendered_fences
from derive.lecture import notes_check as nc

EXAMPLE = """# Rolling

````{prf:example}
:label: ex-ball
A ball rolls.

```{math}
:label: eq-a
a = \\frac{5}{7} g \\sin\\theta
```
````

```python
x = 1
```
"""


def test_a_directive_fenced_with_four_backticks_keeps_its_displays():
    out = rendered_fences(EXAMPLE).split("\n")
    assert out[2].strip() == "" and out[3].strip() == ""        # the fence and its option (lines 3, 4)
    assert out[4] == "A ball rolls."
    assert out[6] == "$$" and out[7].strip() == "" and out[8].startswith("a = ") and out[9] == "$$"
    assert out[10].strip() == ""                                 # the directive's closing fence


def test_code_is_blanked_and_every_line_kept_in_its_place():
    out = rendered_fences(EXAMPLE)
    assert "x = 1" not in out and out.count("\n") == EXAMPLE.count("\n")


def test_a_fence_never_closed_is_read_as_the_text_it_is():
    assert rendered_fences("```\nx = 1") == "```\nx = 1"


def test_the_reader_judges_a_display_inside_a_myst_example():
    text = EXAMPLE.replace("a = \\frac{5}{7} g \\sin\\theta", "\\sin^2\\theta + \\cos^2\\theta = 1")
    assert [c.verdict for c in nc.check_text(text) if c.line == 7] == ["holds"]
