"""A moment's body component named by the text and set equal to Euler's left side.

Takes: the value a statement gives a new name of the text's (``M_{cm_1} = I_1\\dot{\\omega_1} +
\\omega_2\\omega_3(I_3-I_2)``) and the derivation's Euler residuals. Gives: `row`, which body
component that value is Euler's left side of and how far from it (zero when it holds), or None
when it is no such value, in the section's case (a symmetric body's I₂ = I₁ on the text's side too). A name set equal to Iᵢω̃̇ᵢ plus terms in the rates is the moment's
component i about the centre of mass: Euler's equation Iᵢω̃̇ᵢ − ((Iω̃)×ω̃)ᵢ = Mᵢ, the text's
name on the moment's side.

May import: :mod:`derive.lecture.latex`, :mod:`derive.symbolic.lagrangian`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import latex as lx
from derive.symbolic.lagrangian import I1, I2, I3


def row(value, euler: list, subs: dict | None = None) -> tuple[int, sp.Expr] | None:
    """(i, value − Euler's residual i) when ``value`` is Iᵢω̃̇ᵢ plus terms in the principal moments
    and the rates ω̃ (at least one), else None; the difference taken in the section's case ``subs``
    (the residuals' own), so that a body the text made symmetric (I₂ = I₁) is so on both sides."""
    value = sp.expand(sp.sympify(value)) if not isinstance(value, sp.MatrixBase) else None
    if value is None or not value.free_symbols & set(lx.WD):
        return None
    if not value.free_symbols <= {I1, I2, I3, *lx.W, *lx.WD}:
        return None
    rates = [k for k in range(3) if value.has(lx.WD[k])]
    if len(rates) != 1 or not value.free_symbols & set(lx.W):
        return None                    # Iᵢω̃̇ᵢ alone: a planar or assumed case, not the full row
    i = rates[0]
    if sp.expand(sp.diff(value, lx.WD[i])) != (I1, I2, I3)[i]:
        return None
    # the residuals divide by the moments the case may have set to values: cancelled, not only expanded
    return i, sp.expand(sp.cancel((value - euler[i]).xreplace(subs or {})))
