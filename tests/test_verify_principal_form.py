"""A tensor written out, then written again diagonal under the same name: the same tensor in its
principal axes when the characteristic polynomials agree (`derive.lecture.principal_form`)."""
import sympy as sp

import kept_readings as kept
from derive.lecture.principal_form import diagonalised

CUBE = r"""# The cube about its corner

All nine components together give

$$
\mathbf{I}^{corner} = \frac{1}{12} Mb^2 \begin{pmatrix} 8 & -3 & -3 \\ -3 & 8 & -3 \\ -3 & -3 & 8 \end{pmatrix}
$$

and the secular determinant's roots are the principal moments,

$$
\mathbf{I}^{corner} = \begin{pmatrix} \frac{1}{6}Mb^2 & 0 & 0 \\ 0 & \frac{11}{12}Mb^2 & 0 \\ 0 & 0 & \frac{11}{12}Mb^2 \end{pmatrix}
$$
"""


def _verdicts(text, start):
    line = max(k for k, row in enumerate(text.split("\n"), 1) if row.startswith(start)) - 1   # its $$
    return [c.verdict for c in kept.by_line(text).get(line, [])]


def test_the_diagonal_form_with_the_tensors_eigenvalues_holds():
    assert _verdicts(CUBE, "\\mathbf{I}^{corner} = \\begin") == ["holds"]


def test_a_diagonal_form_with_a_wrong_principal_moment_does_not_hold():
    text = CUBE.replace("\\frac{1}{6}Mb^2 & 0 & 0", "\\frac{1}{3}Mb^2 & 0 & 0")
    assert "holds" not in _verdicts(text, "\\mathbf{I}^{corner} = \\begin")


def test_only_a_symmetric_tensor_written_again_diagonal_is_compared_by_its_eigenvalues():
    a, b = sp.symbols("a b", positive=True)
    tensor = sp.Matrix([[2 * a, -a, 0], [-a, 2 * a, 0], [0, 0, b]])
    assert diagonalised(tensor, sp.diag(a, 3 * a, b)) is not None
    assert diagonalised(tensor, sp.diag(a, 2 * a, b)) is None
    assert diagonalised(sp.diag(a, 3 * a, b), tensor) is None               # the diagonal one first: no
    assert diagonalised(sp.Matrix([[2 * a, -a, 0], [0, 2 * a, 0], [0, 0, b]]), sp.diag(2 * a, 2 * a, b)) is None
