"""Formulas as an encyclopaedia renders them (derive/lecture/source.py, statements.py): its TeX puts
braces round every symbol, ``{\\dot {\\omega }}_{1}``, ``{\\boldsymbol {I}}_{0}^{-1}``, and round every
display environment, ``{\\begin{aligned} … \\end{aligned}}``; those braces only group."""
import kept_readings as kept

from derive.lecture import source

EULER = ("## Euler\n\nThe body-frame components $\\omega_1, \\omega_2, \\omega_3$ of the angular velocity along "
         "principal axes, with $M_1, M_2, M_3$ the components of the torque.\n\n")
ROWS = ("{\\begin{aligned}I_{1}\\,{\\dot {\\omega }}_{1}+(I_{3}-I_{2})\\,\\omega _{2}\\,\\omega _{3}&=M_{1}\\\\"
        "I_{2}\\,{\\dot {\\omega }}_{2}+(I_{1}-I_{3})\\,\\omega _{3}\\,\\omega _{1}&=M_{2}\\\\"
        "I_{3}\\,{\\dot {\\omega }}_{3}+(I_{2}-I_{1})\\,\\omega _{1}\\,\\omega _{2}&=M_{3}\\end{aligned}}")


def verdicts(text: str) -> list:
    return [c.verdict for c in kept.check_text(text)]


def test_eulers_equations_in_a_braced_aligned_block_with_braced_dotted_symbols_hold_row_by_row():
    assert verdicts(EULER + "$$" + ROWS + "$$\n") == ["holds", "holds", "holds"]


def test_a_wrong_sign_in_such_a_block_is_flagged_in_its_row_only():
    wrong = ROWS.replace("(I_{1}-I_{3})", "(I_{3}-I_{1})")
    assert verdicts(EULER + "$$" + wrong + "$$\n") == ["holds", "typo", "holds"]


def test_a_braced_symbol_under_an_accent_or_a_bold_face_before_its_index_is_that_symbol():
    assert source.normalize("{\\dot {\\omega }}_{1}") == "\\dot{\\omega }_{1}"
    assert source.normalize("{\\boldsymbol {R}}{\\boldsymbol {I}}_{0}^{-1}").endswith("\\boldsymbol {I}_{0}^{-1}")
    assert source.normalize("a_{s}{\\boldsymbol {\\omega }}_{s}") == "a_{s}\\boldsymbol {\\omega }_{s}"


def test_a_braced_argument_before_an_index_keeps_its_braces():
    assert source.normalize("\\frac{1}{x}^2") == "\\frac{1}{x}^2"
    assert source.normalize("\\sqrt{x}{y}_1") == "\\sqrt{x}{y}_1"
