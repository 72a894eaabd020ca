"""The notes reader on a cross product of two written columns, as a text writes Euler's equations in
matrix form: ``\\begin{bmatrix}\\omega_1\\\\\\omega_2\\\\\\omega_3\\end{bmatrix} \\times
\\begin{bmatrix}I_1\\omega_1\\\\I_2\\omega_2\\\\I_3\\omega_3\\end{bmatrix}`` is the column of their
cross product, and the statement is read row by row; a cross product of anything but two written
columns is the vector reader's, left as before."""
import kept_readings as kept

verdicts, line_of = kept.verdicts_by_line, kept.line_of
PROSE = ("# Notes\n\nIn principal axes, with the torque components $N_1, N_2, N_3$, the equations of "
         "motion of the body in matrix form are\n\n")
COLUMN = "\\begin{{bmatrix}} {} \\\\ {} \\\\ {} \\end{{bmatrix}}"
INERTIA = "\\begin{bmatrix} I_1 & 0 & 0 \\\\ 0 & I_2 & 0 \\\\ 0 & 0 & I_3 \\end{bmatrix}"
RATES = COLUMN.format("\\dot{\\omega}_1", "\\dot{\\omega}_2", "\\dot{\\omega}_3")
OMEGA = COLUMN.format("\\omega_1", "\\omega_2", "\\omega_3")
TORQUE = COLUMN.format("N_1", "N_2", "N_3")


def _euler(momentum: str) -> str:
    return PROSE + f"$$\n{INERTIA} {RATES} + {OMEGA} \\times {momentum} = {TORQUE}\n$$\n"


def test_euler_equations_with_the_cross_product_of_two_written_columns_hold():
    text = _euler(COLUMN.format("I_1 \\omega_1", "I_2 \\omega_2", "I_3 \\omega_3"))
    assert verdicts(text)[line_of(text, "$$")] == {"holds"}


def test_euler_equations_with_two_moments_exchanged_in_the_crossed_column_are_flagged():
    text = _euler(COLUMN.format("I_1 \\omega_1", "I_3 \\omega_2", "I_2 \\omega_3"))
    assert verdicts(text)[line_of(text, "$$")] & {"fails", "typo"}


def test_a_cross_product_of_a_column_and_a_name_is_left_unread():
    text = PROSE + f"$$\n{INERTIA} {RATES} + {OMEGA} \\times \\mathbf{{H}} = {TORQUE}\n$$\n"
    assert verdicts(text)[line_of(text, "$$")] == {"unchecked"}
