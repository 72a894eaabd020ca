"""The notes reader on a chain that names a matrix, ``\\boldsymbol{r} = (\\boldsymbol{e}_X \\; \\boldsymbol{e}_Y
\\; \\boldsymbol{e}_Z) (X, Y, Z)^T = X \\boldsymbol{e}_X + …``: the name is recorded as the first member and
the chain's other links are checked against it, as for a symbol."""
from kept_readings import verdicts_by_line as verdicts

ZXZ = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Notes\n\n"
ROW = "\\begin{pmatrix} \\boldsymbol{e}_X & \\boldsymbol{e}_Y & \\boldsymbol{e}_Z \\end{pmatrix} " \
    "\\begin{pmatrix} X \\\\ Y \\\\ Z \\end{pmatrix}"


def test_a_basis_written_as_a_row_times_a_column_is_the_sum_its_chain_writes():
    right = "$$\\boldsymbol{r} = " + ROW + " = X \\boldsymbol{e}_X + Y \\boldsymbol{e}_Y + Z \\boldsymbol{e}_Z$$\n\n"
    exchanged = right.replace("\\boldsymbol{r} =", "\\boldsymbol{s} =").replace("Y \\boldsymbol{e}_Y", "Y \\boldsymbol{e}_Z")
    got = verdicts(ZXZ + right + exchanged)
    assert "holds" in got[7] and "holds" not in got[9]
