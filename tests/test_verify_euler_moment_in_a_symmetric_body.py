"""The notes reader on Euler's equations written for any body, a moment's component set to each, in a
text that says its body is symmetric (I₂ = I₁ from a heading, "a symmetric top"): the equations
hold for the symmetric body too, so the text's I₂ is I₁ there as in the derivation's equations;
taken as a moment of its own, the correct equations were flagged. A slip that stays one when
I₂ = I₁ is still flagged. Where the text set the moments to values (a slab's I₁ = M(b² + c²)/12),
the equations are compared with those values in, the difference cancelled, not only expanded."""
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


def test_euler_s_equations_hold_where_the_text_set_the_moments_to_values():
    values = "$$I_1 = \\tfrac{1}{12}M(b^2 + c^2) \\qquad I_3 = \\tfrac{1}{12}M(a^2 + b^2)$$\n\n"
    text = _text(ROWS, title="A slab").replace("The moments about", values + "The moments about")
    assert [_verdicts(text, r) for r in ROWS] == [["holds"]] * 3
    slip = ROWS[0].replace("(I_3 - I_2)", "(I_2 - I_3)")
    assert _verdicts(text.replace(ROWS[0], slip), slip)[0] in ("typo", "fails")
