"""Dot products of the body's own vectors as the formula reader meets them: 𝛚·𝛚, 𝐋·𝐋, 𝛚·𝐋,
and the same with scalar factors, ``\\boldsymbol{\\omega} \\cdot \\frac{\\mathbf{L}}{L}`` (a unit
vector along 𝐋 written as 𝐋 over its length); and a body axis ê₁, ê₂, ê₃ (or a vector written in
them) dotted with any of these, ``\\hat{\\mathbf{e}}_3 \\cdot \\mathbf{L} = I_3 \\omega_3``.

Takes: the values `derive.lecture.latex_parser` has read on either side of a ``\\cdot``.
Gives: `dot`, their dot product in body components (𝛚 = ω̃, 𝐋 = (Iᵢ ω̃ᵢ)), or None when a side
is not one of those vectors times scalars nor a form in ê₁ ê₂ ê₃; `row_on_column`, the same of
a row on a column, ``\\mathbf{H}^T \\mathbf{H}``.

May import: :mod:`derive.lecture.vocabulary`, :mod:`derive.symbolic.lagrangian`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture.vocabulary import BASIS, LVEC, OMEGA_VEC, Quantity, Transposed, W
from derive.symbolic.lagrangian import I1, I2, I3

_COMPONENTS = {OMEGA_VEC: W, LVEC: [m * w for m, w in zip((I1, I2, I3), W)]}


def _scaled(x):
    """(scalar factor, vector) of one of the body's vectors times scalars; None otherwise."""
    if isinstance(x, Quantity):
        return (sp.S.One, x) if x in _COMPONENTS else None
    if not isinstance(x, sp.Mul):
        return None
    vectors = [f for f in x.args if f in _COMPONENTS]
    rest = [f for f in x.args if f not in _COMPONENTS]
    if len(vectors) != 1 or any(set(_COMPONENTS) & getattr(f, "free_symbols", set()) for f in rest) or \
            any(isinstance(f, sp.MatrixBase) or getattr(f, "is_commutative", True) is False for f in rest):
        return None
    return sp.Mul(*rest), vectors[0]


def _in_basis(x):
    """The body components of a linear form in ê₁ ê₂ ê₃ whose coefficients hold no unit vector,
    no matrix and none of the body's vectors; None otherwise."""
    if not isinstance(x, sp.Expr) or isinstance(x, sp.MatrixBase) or not (x.free_symbols & set(BASIS)):
        return None
    ex = sp.expand(x)
    coeffs = [ex.coeff(e) for e in BASIS]
    if sp.expand(ex - sum(c * e for c, e in zip(coeffs, BASIS))) != 0:
        return None
    if any(c.free_symbols & (set(BASIS) | set(_COMPONENTS)) or c.is_commutative is False for c in coeffs):
        return None
    return coeffs


def _components(x):
    """A side of a dot product in body components: 𝛚 or 𝐋 times scalars, or a form in ê₁ ê₂ ê₃."""
    scaled = _scaled(x)
    if scaled is not None:
        return [scaled[0] * c for c in _COMPONENTS[scaled[1]]]
    return _in_basis(x)


def dot(a, b):
    """a · b in body components when each side is 𝛚 or 𝐋 times scalars, or a vector written in the
    body axes ê₁ ê₂ ê₃ (not both: a dot of two written forms is the reader's own arithmetic); None
    for anything else."""
    sa, sb = _scaled(a), _scaled(b)
    if sa is not None and sb is not None:
        return sa[0] * sb[0] * sum((x * y for x, y in zip(_COMPONENTS[sa[1]], _COMPONENTS[sb[1]])), sp.S.Zero)
    if sa is None and sb is None:
        return None
    ca, cb = _components(a), _components(b)
    if ca is None or cb is None:
        return None
    return sum((x * y for x, y in zip(ca, cb)), sp.S.Zero)


def row_on_column(a, b):
    """𝐚ᵀ𝐛, a row on a column (``\\mathbf{H}^T \\mathbf{H}``): the matrix product is the number a · b
    (`dot`); None when a is not transposed or `dot` cannot read it."""
    return dot(a.args[0], b) if isinstance(a, Transposed) else None
