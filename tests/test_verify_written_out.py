"""The notes reader on a display with no relation that writes out the name the display before it
defined: checked as ``name = expression``, and never judged wrong."""
from kept_readings import by_line

ZXZ = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Notes\n\n"
TEXT = ZXZ + ("$$\nK = \\begin{bmatrix} \\cos\\theta & 0 \\\\ 0 & 1 \\end{bmatrix} "
              "\\begin{bmatrix} a \\\\ b \\end{bmatrix}\n$$\n\nWritten out:\n\n$$\nOUT\n$$\n")


def verdicts(out):
    return [c.verdict for c in by_line(TEXT.replace("OUT", out))[13]]


def test_a_bare_display_that_writes_out_the_name_defined_before_it_holds():
    assert verdicts("\\begin{bmatrix} a\\cos\\theta \\\\ b \\end{bmatrix}") == ["holds"]


def test_a_bare_display_that_does_not_agree_with_the_name_before_it_is_never_judged():
    assert verdicts("\\begin{bmatrix} a\\sin\\theta \\\\ b \\end{bmatrix}") == ["unchecked"]
    assert verdicts("a + b") == ["unchecked"]           # another shape: not the name written out
