"""A known vector set equal to a column of letters the text has not defined
(``\\boldsymbol{\\omega} = \\begin{bmatrix} p \\\\ q \\\\ r \\end{bmatrix}``, the body rates of the aerospace
texts) names its components: p, q, r are ω̃₁, ω̃₂, ω̃₃ from there on, so the rates of a 3-2-1
sequence written in them are judged, and a slip in them is flagged."""
import kept_readings as kept

HEAD = "---\nconvention: z-y-x\n---\n# Body rates\n\nThe roll, pitch and yaw rates about the body axes:\n\n"
NAMED = "$$\n\\boldsymbol{\\omega} = \\begin{bmatrix} p \\\\ q \\\\ r \\end{bmatrix}\n$$\n\n"
RATES = ("$$\n\\begin{bmatrix} p \\\\ q \\\\ r \\end{bmatrix} = \\begin{bmatrix} \\dot\\phi - \\dot\\psi\\sin\\theta \\\\ "
         "\\dot\\theta\\cos\\phi + \\dot\\psi\\sin\\phi\\cos\\theta \\\\ -\\dot\\theta\\sin\\phi + \\dot\\psi\\cos\\phi%s\\cos\\theta "
         "\\end{bmatrix}\n$$\n")


def _verdicts(text: str) -> dict:
    return {c.line: c.verdict for c in kept.check_text(text)}


def test_the_column_names_the_components_and_the_rates_in_them_hold():
    out = _verdicts(HEAD + NAMED + RATES % "")
    assert out == {8: "unchecked", 12: "holds"}


def test_a_slip_in_the_rates_written_in_the_named_components_is_flagged():
    assert _verdicts(HEAD + NAMED + RATES % "\\sin\\phi")[12] in ("typo", "fails")


def test_without_the_naming_column_the_letters_stay_unchecked():
    assert _verdicts(HEAD + RATES % "") == {8: "unchecked"}
