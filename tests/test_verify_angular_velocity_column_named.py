"""The notes reader on a new letter set equal to the angular velocity written out as a column of the
angles' rates: in a text that states its sequence, the column that is that sequence's angular velocity
in body or in space axes holds; any other column, or a text stating no sequence, is said nothing of."""
from kept_readings import verdicts_by_line as verdicts

ZXZ = "# Notes\n\nThe z-x-z Euler angles $\\phi, \\theta, \\psi$ turn the body.\n\n"
# the z-x-z angular velocity in body axes and in space axes
BODY = ("\\begin{pmatrix} \\dot{\\phi}\\sin\\theta\\sin\\psi+\\dot{\\theta}\\cos\\psi \\\\ "
        "\\dot{\\phi}\\sin\\theta\\cos\\psi-\\dot{\\theta}\\sin\\psi \\\\ \\dot{\\psi}+\\dot{\\phi}\\cos\\theta \\end{pmatrix}")
SPACE = ("\\begin{pmatrix} \\dot{\\theta}\\cos\\phi+\\dot{\\psi}\\sin\\theta\\sin\\phi \\\\ "
         "\\dot{\\theta}\\sin\\phi-\\dot{\\psi}\\sin\\theta\\cos\\phi \\\\ \\dot{\\phi}+\\dot{\\psi}\\cos\\theta \\end{pmatrix}")


def display(front, column, name="\\Omega"):
    return front + "Its angular velocity:\n\n$$" + name + " = " + column + "$$\n"


def test_a_letter_set_to_the_stated_sequences_angular_velocity_column_holds():
    assert verdicts(display(ZXZ, BODY))[7] == {"holds"}
    assert verdicts(display(ZXZ, SPACE, "w"))[7] == {"holds"}


def test_another_column_or_a_text_without_a_stated_sequence_is_said_nothing_of():
    swapped = BODY.replace("\\sin\\theta\\sin\\psi", "\\sin\\theta\\cos\\psi", 1)
    assert swapped != BODY
    assert verdicts(display(ZXZ, swapped))[7] == {"unchecked"}
    assert "holds" not in verdicts(display("# Notes\n\n", BODY)).get(5, set())
