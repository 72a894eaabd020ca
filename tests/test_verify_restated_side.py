"""The notes reader on a display that states no relation after prose saying the side just written is
the same as it (``this right-hand side is the same as``, ``which equals``): the display goes on with
``= …`` from the statement before, and is never taken as more terms of that statement's last side."""
import kept_readings as kept

verdicts, line_of = kept.verdicts_by_line, kept.line_of

TOP = ("# The heavy top\n\nA heavy symmetric top in z-x-z Euler angles has the Lagrangian\n\n"
       "$$ \\mathcal L=\\frac{I_1}{2}\\left(\\dot \\theta ^2 + \\dot \\phi ^2 \\sin^2 \\theta\\right) + "
       "\\frac{I_3} 2 \\left(\\dot \\psi+ \\dot \\phi \\cos \\theta \\right)^2 - mgl \\cos \\theta $$\n\n"
       "Lagrange's equation for the nutation angle gives\n\n"
       "$$I_1 \\ddot \\theta = I_1 \\dot\\phi^2 \\sin\\theta\\cos\\theta - I_3(\\dot\\psi + \\dot\\phi\\cos\\theta)"
       "\\dot\\phi\\sin\\theta - \\frac{\\partial }{\\partial \\theta} (mgl \\cos \\theta)$$\n\n")
RIGHT = ("- \\frac{\\partial }{\\partial \\theta} \\left \\{ mgl \\cos \\theta \\right \\} + I_1 \\dot\\phi^2 "
         "\\sin\\theta\\cos\\theta - I_3(\\dot\\psi + \\dot\\phi\\cos\\theta)\\dot\\phi\\sin\\theta")
WRONG = ("- \\frac{\\partial }{\\partial \\theta} \\left \\{ mgl \\cos \\theta \\right \\} - I_1 \\dot\\phi^2 "
         "\\sin\\theta\\cos\\theta - I_3(\\dot\\psi + \\dot\\phi\\cos\\theta)\\dot\\phi\\sin\\theta")


def test_a_display_the_prose_calls_the_same_as_the_right_side_is_read_as_equal_to_it():
    text = TOP + "and this right-hand side is the same as\n\n$$" + RIGHT + "$$\n"
    found = verdicts(text)
    assert found[line_of(text, "$$- \\frac")] == {"holds"}
    assert found[line_of(text, "$$I_1 \\ddot")] == {"holds"}       # its equation is read whole, as written


def test_a_wrong_value_of_the_right_side_does_not_hold_and_leaves_the_equation_before_it_alone():
    text = TOP + "which equals\n\n$$" + WRONG + "$$\n"
    found = verdicts(text)
    assert "holds" not in found[line_of(text, "$$- \\frac")]
    assert found[line_of(text, "$$I_1 \\ddot")] == {"holds"}


def test_a_display_after_prose_with_a_subject_of_its_own_is_not_the_side_before_it():
    text = TOP + "The potential energy of the top, which is conserved, is equal to\n\n$$" + RIGHT + "$$\n"
    assert "holds" not in verdicts(text).get(line_of(text, "$$- \\frac"), set())
