"""A tensor the text has written out, written again diagonal: the same tensor in its principal axes.

Takes: the 3×3 matrix a text bound to a name (``\\mathbf{I}^{corner} = \\frac{1}{12} M b^2 (…)``) and
the diagonal matrix it later sets that name to (the principal moments, after solving the secular
determinant). Gives `diagonalised`: why the later matrix holds when the two have the same
characteristic polynomial, det(λ𝟙 − A) = det(λ𝟙 − D) (a symmetric tensor and its diagonal form
in the axes of its eigenvectors, D = QᵀAQ, share it), else None (the caller compares the two as
before).

May import: :mod:`derive.lecture.zero_test`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture.zero_test import nonzero_somewhere

_LAMBDA = sp.Dummy("lambda")


def diagonalised(old, new) -> str | None:
    """Why ``new`` (diagonal) is ``old`` (3×3, not diagonal) in its principal axes, or None."""
    if not (isinstance(old, sp.MatrixBase) and isinstance(new, sp.MatrixBase)) or old.shape != (3, 3) \
            or new.shape != (3, 3):
        return None
    old, new = sp.Matrix(old), sp.Matrix(new)
    if old.is_diagonal() or not new.is_diagonal() or old != old.T:
        return None
    d = sp.expand(old.charpoly(_LAMBDA).as_expr() - new.charpoly(_LAMBDA).as_expr())
    if nonzero_somewhere(d) or sp.simplify(d) != 0:
        return None
    return "the text's matrix in its principal axes: the same characteristic polynomial, so the same principal moments"
