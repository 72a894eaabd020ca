"""The exponential a text writes of a matrix (``\\exp([\\boldsymbol{\\omega}]_\\times dt)``).

Takes: the argument of a text's ``\\exp`` that may become a matrix once the text's names are put in
(a cross-product matrix, a name standing for a matrix). Gives: `MatrixExp`, the exponential
that takes the exponential of a 3 x 3 skew-symmetric matrix [v]ₓ by Rodrigues' formula,
I + sin(n)/n [v]ₓ + (1 − cos n)/n² [v]ₓ² with n² = v·v, the same matrix SymPy's general
exponential (through the Jordan form) gives, which on a skew matrix of symbolic entries costs
orders of magnitude more; any other argument is SymPy's ``exp`` unchanged.

May import: SymPy.
"""
from __future__ import annotations

import sympy as sp


def skew_exponential(m: sp.MatrixBase) -> sp.ImmutableMatrix | None:
    """exp(m) by Rodrigues' formula when ``m`` is 3 x 3 and skew-symmetric entry by entry (after
    expanding), else None.

    sin(n)/n and (1 − cos n)/n² are even in n, so either root of n² serves: where SymPy's root
    of n² is a product with absolute values among its factors (a real angle's |θ|), the factors
    are taken without them, which changes n at most in sign."""
    if m.shape != (3, 3) or any(sp.expand(m[i, j] + m[j, i]) != 0 for i in range(3) for j in range(i, 3)):
        return None
    k = sp.Matrix(m)
    n2 = k[2, 1] ** 2 + k[0, 2] ** 2 + k[1, 0] ** 2
    if n2 == 0:
        return sp.ImmutableMatrix(sp.eye(3))
    n = sp.sqrt(n2)
    n = sp.Mul(*[f.args[0] if isinstance(f, sp.Abs) else f for f in sp.Mul.make_args(n)])
    return sp.ImmutableMatrix(sp.eye(3) + sp.sin(n) / n * k + (1 - sp.cos(n)) / n2 * (k * k))


def within_quadratic_roots(m: sp.MatrixBase) -> bool:
    """Whether SymPy's exponential of ``m`` (through its Jordan form) needs no root past a square
    root: every irreducible factor of its characteristic polynomial is of degree two at most (the
    roots of a symbolic cubic take SymPy minutes and no text's claim is read through them)."""
    if not m.is_square:
        return False
    poly = m.charpoly()
    rest, factors = sp.factor_list(poly.as_expr(), poly.gen)     # what it cannot factor stays in rest
    return all(sp.degree(f, poly.gen) <= 2 for f in [rest] + [f for f, _ in factors])


class MatrixExp(sp.Function):
    """exp of an argument that may become a matrix (``exp([ω]ₓ dt)``), kept apart from SymPy's
    ``exp`` until it is one or is known to be none: a product with another exponential is not
    merged into the exponential of a sum (matrices need not commute). Once its argument is a
    matrix, a 3 x 3 skew-symmetric one's exponential is `skew_exponential` and any other is
    SymPy's where `within_quadratic_roots` (else it stays unevaluated, so unread); once it is a
    scalar, it is SymPy's ``exp``. It prints as ``exp``."""

    @classmethod
    def eval(cls, arg):
        if isinstance(arg, sp.MatrixBase):
            fast = skew_exponential(arg)
            if fast is not None:
                return fast
            return arg.exp() if within_quadratic_roots(arg) else None
        if not may_be_matrix(arg):
            return sp.exp(arg)
        return None

    def fdiff(self, argindex=1):
        return self

    def _sympystr(self, printer):
        return printer._print(sp.exp(self.args[0], evaluate=False))

    def _latex(self, printer, **kwargs):
        return printer._print(sp.exp(self.args[0], evaluate=False), **kwargs)


def may_be_matrix(arg) -> bool:
    """Whether ``arg`` may become a matrix when the text's names are put in: it holds a
    function that becomes a matrix not yet evaluated (``becomes_matrix``, the cross-product
    matrix of a column), or a factor that does not commute (a name of the
    text's standing for a matrix)."""
    return isinstance(arg, sp.Basic) and (arg.is_commutative is False or any(
        getattr(f, "becomes_matrix", False) for f in sp.preorder_traversal(arg)))
