"""An equation of motion written as matrices: columns of the body components, read row by row.

Takes: the two members of an equation (``\\begin{bmatrix} I_1 & 0 \\\\ 0 & I_2 \\end{bmatrix}
\\begin{bmatrix} \\dot{\\omega}_1 \\\\ \\dot{\\omega}_2 \\end{bmatrix} = M \\begin{bmatrix} \\omega_1 \\\\
\\omega_2 \\end{bmatrix}``, a linearised system in matrix form) and the checker's test of one scalar
equation of motion. Gives: `rows_verdict`, the verdict on the whole equation — it holds when each of
its rows does (each a multiple of one of Euler's equations under the section's settings), it fails
naming the first row that does not — or None when the members are not two columns of one shape.

May import: SymPy.
"""
from __future__ import annotations

import sympy as sp


def rows_verdict(members, eom_check):
    """``("holds" | "fails", why)`` for two column matrices read row by row with ``eom_check`` (the
    checker's ``_eom_check``: ``(ok, why, residual)`` for ``lhs − rhs`` of one row); None otherwise.

    Parameters
    ----------
    members : list
        The equation's two sides, as parsed.
    eom_check : callable
        The scalar test of one row's residual.
    """
    if len(members) != 2 or not all(isinstance(m, sp.MatrixBase) for m in members):
        return None
    a, b = members
    if a.shape != b.shape or a.shape[1] != 1 or a.shape[0] < 2:
        return None
    rows = [sp.expand(r) for r in a - b]
    if any(r == 0 for r in rows):
        return None                       # a row 0 = 0 says nothing; the reader leaves such a form
    whys = []
    for k, row in enumerate(rows, 1):
        ok, why, _ = eom_check(row)
        if not ok:
            return "fails", f"row {k}: {why}"
        whys.append(f"row {k}: {why}")
    return "holds", "read row by row: " + "; ".join(whys)
