"""The notes reader on a rotation matrix named with what it depends on: ``C(\\phi, \\theta, \\psi) =``,
``R(t) =`` and a free letter (A, B, C) set equal to a matrix are read as the text's name for that
matrix, and a matrix whose name lists the three angles in the sequence's order but which is the
sequence's rotation with its first and third angles exchanged is a typo of it, as is a product of single-axis
turns that leaves out an angle the name lists."""
import kept_readings as kept
from kept_readings import verdicts_by_line as verdicts

ZXZ = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Notes\n\n"
# the z-x-z rotation R = R_z(φ) R_x(θ) R_z(ψ) (body → space), written out
R = ("\\begin{pmatrix} \\cos\\phi\\cos\\psi - \\cos\\theta\\sin\\phi\\sin\\psi & "
     "-\\cos\\phi\\sin\\psi - \\cos\\theta\\sin\\phi\\cos\\psi & \\sin\\theta\\sin\\phi \\\\ "
     "\\sin\\phi\\cos\\psi + \\cos\\theta\\cos\\phi\\sin\\psi & -\\sin\\phi\\sin\\psi + \\cos\\theta\\cos\\phi\\cos\\psi "
     "& -\\sin\\theta\\cos\\phi \\\\ \\sin\\theta\\sin\\psi & \\sin\\theta\\cos\\psi & \\cos\\theta \\end{pmatrix}")
# R with φ and ψ exchanged: R_z(ψ) R_x(θ) R_z(φ), the other order of the same sequence
SWAPPED = R.replace("\\phi", "@").replace("\\psi", "\\phi").replace("@", "\\psi")
# the same with one entry written otherwise (a sign inside the (1, 1) entry)
SWAPPED_OFF = SWAPPED.replace("\\cos\\psi\\cos\\phi - \\cos", "\\cos\\psi\\cos\\phi + \\cos", 1)


def display(head, matrix, front=ZXZ, before=""):
    return front + before + "The rotation matrix:\n\n$$" + head + " = " + matrix + "$$\n"


def test_a_name_applied_to_the_angles_or_the_time_is_read_as_the_name_of_the_matrix():
    assert SWAPPED_OFF != SWAPPED
    for head in ("C(\\phi, \\theta, \\psi)", "C", "R(t)", "R(\\phi,\\theta,\\psi)"):
        assert verdicts(display(head, R))[9] == {"holds"}, head


def test_a_free_letter_named_as_a_matrix_is_that_matrix_afterwards():
    text = display("C", R) + "\n$$C^T C = \\begin{pmatrix} 1 & 0 & 0 \\\\ 0 & 1 & 0 \\\\ 0 & 0 & 1 \\end{pmatrix}$$\n" \
        "\n$$C^T C = \\begin{pmatrix} 1 & 0 & 0 \\\\ 0 & 1 & 0 \\\\ 0 & 0 & 2 \\end{pmatrix}$$\n"
    got = verdicts(text)
    assert got[9] == {"holds"} and got[11] == {"holds"} and "holds" not in got[13]


def test_the_angles_exchanged_in_a_matrix_named_by_them_in_the_sequences_order_is_a_typo():
    for head in ("C(\\phi, \\theta, \\psi)", "R(\\phi,\\theta,\\psi)", "\\mathbf{R}(\\phi, \\theta, \\psi)"):
        assert verdicts(display(head, SWAPPED))[9] == {"typo"}, head
        assert verdicts(display(head, SWAPPED_OFF))[9] == {"typo"}, head
    claim = next(c for c in kept.check_text(display("C(\\phi, \\theta, \\psi)", SWAPPED)) if c.line == 9)
    assert "exchanged" in claim.why and claim.correction


def test_a_name_defined_before_in_a_letter_and_then_written_with_the_angles_is_held_to_the_rotation():
    before = "where $R = Q^T$ is the transfer matrix.\n\n"
    assert verdicts(display("R(\\phi, \\theta, \\psi)", SWAPPED_OFF, before=before))[11] == {"typo"}
    assert verdicts(display("R(\\phi, \\theta, \\psi)", R, before=before))[11] == {"holds"}


def test_the_exchanged_angles_are_said_nothing_of_where_the_text_does_not_tie_the_order():
    # the name lists the angles in another order, or none, or the text names no angles of its own
    for head in ("C(\\psi, \\theta, \\phi)", "C", "R(t)"):
        assert verdicts(display(head, SWAPPED))[9] == {"unchecked"}, head
    unnamed = "---\nconvention: z-x-z\n---\n# Notes\n\n"
    assert verdicts(display("C(\\phi, \\theta, \\psi)", SWAPPED, front=unnamed))[8] == {"unchecked"}


def test_the_products_after_an_exchanged_matrix_use_the_rotation_it_meant():
    after = ("\n$$C \\boldsymbol{e}_z = \\begin{pmatrix} \\sin\\theta\\sin\\phi \\\\ -\\sin\\theta\\cos\\phi \\\\ "
             "\\cos\\theta \\end{pmatrix}$$\n")
    got = verdicts(display("C(\\phi, \\theta, \\psi)", SWAPPED) + after)
    assert got[9] == {"typo"} and got[11] == {"holds"}



def test_a_name_defined_before_as_the_free_letter_transposed_follows_it_to_the_matrix():
    before = "where $R = C^T$ is the transfer matrix.\n\n"
    column = "\n$$R \\boldsymbol{e}_z = \\begin{pmatrix} \\sin\\theta\\sin\\phi \\\\ -\\sin\\theta\\cos\\phi \\\\ " \
        "\\cos\\theta \\end{pmatrix}$$\n"
    got = verdicts(display("C", "\\left(" + R + "\\right)^T", before=before) + column)
    assert got[11] == {"holds"} and got[13] == {"holds"}


def test_a_product_of_single_axis_turns_that_leaves_out_an_angle_its_name_lists_is_a_typo():
    for product in ("R_z(\\psi) R_y(\\theta) R_x(\\psi)", "R_z(\\phi) R_x(\\theta) R_z(\\phi)"):
        assert verdicts(display("R_{BE}(\\phi, \\theta, \\psi)", product))[9] == {"typo"}, product
    for product in ("R_z(\\phi) R_x(\\theta) R_z(\\psi)", "R_z(\\psi) R_x(\\theta) R_z(\\phi)"):
        assert "typo" not in verdicts(display("R(\\phi, \\theta, \\psi)", product)).get(9, set()), product
    assert "typo" not in verdicts(display("R(\\phi, \\theta)", "R_z(\\phi) R_x(\\theta) R_z(\\phi)")).get(9, set())


# R with its (1, 3) entry written sin ψ sin φ for sin θ sin φ: that column is then no unit vector
ONE_OFF = R.replace("\\sin\\theta\\sin\\phi \\\\", "\\sin\\psi\\sin\\phi \\\\", 1)


def test_the_stated_sequences_rotation_with_one_entry_written_otherwise_is_a_typo_and_its_products_use_the_rotation():
    assert ONE_OFF != R
    after = ("\n$$A \\boldsymbol{e}_z = \\begin{pmatrix} \\sin\\theta\\sin\\phi \\\\ -\\sin\\theta\\cos\\phi \\\\ "
             "\\cos\\theta \\end{pmatrix}$$\n")
    got = verdicts(display("A", ONE_OFF) + after)
    assert got[9] == {"typo"} and got[11] == {"holds"}
    claim = next(c for c in kept.check_text(display("A", ONE_OFF)) if c.line == 9)
    assert "row 1, column 3" in claim.why and claim.correction


def test_a_matrix_one_entry_off_a_rotation_is_said_nothing_of_where_no_sequence_is_stated_or_two_entries_are_off():
    unstated = "# Notes\n\n"
    assert "typo" not in verdicts(display("A", ONE_OFF, front=unstated)).get(3, set())
    two_off = ONE_OFF.replace("& \\cos\\theta \\end", "& \\cos\\psi \\end", 1)
    assert two_off != ONE_OFF
    assert "typo" not in verdicts(display("A", two_off)).get(9, set())
