"""The notes reader on the text's single-axis turns applied to other angles and to basis vectors: a
turn the text defines as a function of its angle (``C_Z(\\phi) = …``) is that turn at any other angle
of its sequence (``C_Z(\\psi)``), a basis vector right of such matrices (``C_Z(\\psi) \\boldsymbol{e}_x``)
is its unit column, and a column so multiplied out and equated to another that varies with the
angles is an identity, not a condition."""
from kept_readings import verdicts_by_line as verdicts

ZXZ = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Notes\n\n"
CX = ("$$C_X(\\phi) = \\begin{pmatrix} 1 & 0 & 0 \\\\ 0 & \\cos \\phi & \\sin \\phi \\\\ 0 & -\\sin \\phi & "
      "\\cos \\phi \\end{pmatrix}$$\n\n")
CZ = ("$$C_Z(\\phi) = \\begin{pmatrix} \\cos \\phi & \\sin \\phi & 0 \\\\ -\\sin \\phi & \\cos \\phi & 0 \\\\ "
      "0 & 0 & 1 \\end{pmatrix}$$\n\n")
PRODUCT = ("\\begin{pmatrix} \\cos \\psi & \\sin \\psi\\cos\\theta & \\sin\\psi\\sin\\theta \\\\ -\\sin \\psi & "
           "\\cos \\psi\\cos\\theta & \\cos\\psi\\sin\\theta \\\\ 0 & -\\sin\\theta & \\cos\\theta \\end{pmatrix}")


def test_a_turn_defined_as_a_function_of_its_angle_is_that_turn_at_another_angle():
    right = "$$C_Z(\\psi) C_X(\\theta) = " + PRODUCT + "$$\n\n"
    wrong = "$$C_Z(\\psi) C_X(\\theta) = " + PRODUCT.replace("-\\sin \\psi & ", "\\sin \\psi & ") + "$$\n"
    got = verdicts(ZXZ + CX + CZ + right + wrong)
    assert got[7] == {"holds"} and got[9] == {"holds"}
    assert got[11] == {"holds"} and got[13] & {"typo", "fails"}


def test_a_turn_defined_without_its_argument_is_read_at_its_own_angle_only():
    bare = CZ.replace("C_Z(\\phi) =", "C_Z =")
    got = verdicts(ZXZ + CX + bare + "$$C_Z(\\psi) C_X(\\theta) = " + PRODUCT + "$$\n")
    assert got[11] == {"unchecked"}
    own = CZ.replace("C_Z(\\phi) =", "C_Z =").replace("\\phi", "\\psi")
    got = verdicts(ZXZ + CX + own + "$$C_Z(\\psi) C_X(\\theta) = " + PRODUCT + "$$\n")
    assert got[11] == {"holds"}


def test_a_basis_vector_right_of_the_texts_matrices_is_its_unit_column():
    right = "$$C_Z(\\psi) C_X(\\theta) \\boldsymbol{e}_x = \\begin{pmatrix} \\cos\\psi \\\\ -\\sin\\psi \\\\ 0 \\end{pmatrix}$$\n\n"
    column = "$$C_Z(\\psi) C_X(\\theta) \\boldsymbol{e}_z = \\begin{pmatrix} \\sin\\psi\\sin\\theta \\\\ \\cos\\psi\\sin\\theta " \
        "\\\\ \\cos\\theta \\end{pmatrix}$$\n\n"
    slipped = column.replace("\\cos\\psi\\sin\\theta", "\\cos\\phi\\sin\\theta")
    got = verdicts(ZXZ + CX + CZ + right + column + slipped)
    assert got[11] == {"holds"} and got[13] == {"holds"}
    assert got[15] & {"typo", "fails"}


def test_a_multiplied_out_column_equated_to_a_constant_one_stays_a_condition():
    # true only where θ = 0: an orientation the text may be choosing, not a slip
    text = ZXZ + CX + CZ + "$$C_X(\\theta) \\boldsymbol{e}_z = \\begin{pmatrix} 0 \\\\ 0 \\\\ 1 \\end{pmatrix}$$\n"
    assert verdicts(text)[11] == {"unchecked"}


# the sequence named with its angles, R_ijk(φ, θ, ψ), in inline math set as a paragraph of its own; the
# text declares no convention, its product gives it
PLAIN = "# Notes\n\nThe frame turns about one axis at a time.\n\nIts sequence:\n\n"
SEQUENCE = "$R_{123}(\\phi, \\theta, \\psi) = R_3(\\psi) R_2(\\theta) R_1(\\phi)$\n\n"
R1_AT_THETA = ("$$R_1(\\theta) = \\begin{pmatrix} 1 & 0 & 0 \\\\ 0 & \\cos \\theta & \\sin \\theta \\\\ 0 & "
               "-\\sin \\theta & \\cos \\theta \\end{pmatrix}$$\n\n")
R1R3 = ("\\begin{pmatrix} \\cos \\phi & \\sin \\phi & 0 \\\\ -\\cos\\theta\\sin \\phi & \\cos\\theta\\cos \\phi & "
        "\\sin\\theta \\\\ \\sin\\theta\\sin\\phi & -\\sin\\theta\\cos\\phi & \\cos\\theta \\end{pmatrix}")


def test_a_turn_written_with_its_argument_in_the_sequence_is_that_turn_at_another_angle():
    # R_1 and R_3 enter the text at φ and ψ in the sequence's product; at θ and φ they are the same turns
    right = "$$R_1(\\theta) R_3(\\phi) = " + R1R3 + "$$\n\n"
    wrong = "$$R_1(\\theta) R_3(\\phi) = " + R1R3.replace("-\\sin\\theta\\cos\\phi", "\\sin\\theta\\cos\\phi") + "$$\n"
    got = verdicts(PLAIN + SEQUENCE + R1_AT_THETA + right + wrong)
    assert got[7] == {"holds"} and got[9] == {"holds"}
    assert got[11] == {"holds"} and got[13] & {"typo", "fails"}
    slipped = R1_AT_THETA.replace("0 & -\\sin \\theta", "0 & \\sin \\theta")
    assert verdicts(PLAIN + SEQUENCE + slipped)[9] & {"typo", "fails"}
