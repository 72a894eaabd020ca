"""Dot products of the body's own vectors as the formula reader meets them: 𝛚·𝛚, 𝐋·𝐋, 𝛚·𝐋,
and the same with scalar factors, ``\\boldsymbol{\\omega} \\cdot \\frac{\\mathbf{L}}{L}`` (a unit
vector along 𝐋 written as 𝐋 over its length).

Takes: the values `derive.lecture.latex_parser` has read on either side of a ``\\cdot``.
Gives: `dot`, their dot product in body components (𝛚 = ω̃, 𝐋 = (Iᵢ ω̃ᵢ)), or None when a side
is not one of those vectors times scalars.

May import: :mod:`derive.lecture.vocabulary`, :mod:`derive.symbolic.lagrangian`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture.vocabulary import LVEC, OMEGA_VEC, Quantity, W
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


def dot(a, b):
    """a · b in body components when each side is 𝛚 or 𝐋 times scalars; None for anything else."""
    sa, sb = _scaled(a), _scaled(b)
    if sa is None or sb is None:
        return None
    return sa[0] * sb[0] * sum((x * y for x, y in zip(_COMPONENTS[sa[1]], _COMPONENTS[sb[1]])), sp.S.Zero)
