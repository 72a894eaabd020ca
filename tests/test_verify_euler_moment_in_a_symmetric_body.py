"""The notes reader on Euler's equations written for any body, a moment's component set to each, in a
text that says its body is symmetric (I₂ = I₁ from a heading, "a symmetric top"): the equations
hold for the symmetric body too, so the text's I₂ is I₁ there as in the derivation's equations;
taken as a moment of its own, the correct equations were flagged. A slip that stays one when
I₂ = I₁ is still flagged."""
from kept_readings import by_line, line_of

ROWS = (r"N_1 = I_1 \dot{\omega}_1 + (I_3 - I_2)\omega_2 \omega_3",
        r"N_2 = I_2 \dot{\omega}_2 + (I_1 - I_3)\omega_1 \omega_3",
        r"N_3 = I_3 \dot{\omega}_3 + (I_2 - I_1)\omega_1 \omega_2")


def _text(rows, title="Rotation of a symmetric top"):
    return f"# {title}\n\nThe moments about the centre of mass in body axes are\n\n" + "".join(
        "$$" + r + "$$\n\n" for r in rows)


def _verdicts(text, row):
    return [c.verdict for c in by_line(text)[line_of(text, "$$" + row)]]


def test_euler_s_equations_for_any_body_hold_in_a_text_whose_body_is_symmetric():
    text = _text(ROWS)
    assert [_verdicts(text, r) for r in ROWS] == [["holds"]] * 3


def test_a_slip_that_stays_one_for_the_symmetric_body_is_flagged():
    slip = ROWS[2].replace("(I_2 - I_1)", "(I_3 - I_1)")
    assert _verdicts(_text((*ROWS[:2], slip)), slip) == ["fails"]


def test_with_no_word_of_symmetry_the_equations_hold_and_a_slip_is_flagged():
    slip = ROWS[2].replace("(I_2 - I_1)", "(I_3 - I_1)")
    text = _text((*ROWS[:2], slip), title="Rotation of a rigid body")
    assert [_verdicts(text, r) for r in (*ROWS[:2], slip)] == [["holds"], ["holds"], ["fails"]]
