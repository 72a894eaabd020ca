"""The kinetic energy differentiated by a vector: ∂T/∂𝛚 = 𝐋 and ∂T/∂𝐋 = 𝛚.

A rigid body's kinetic energy is T = ½ 𝛚·𝐈𝛚 = ½ 𝐋·𝐈⁻¹𝐋, so its gradient with respect to the
angular velocity is the angular momentum and its gradient with respect to the angular momentum is
the angular velocity, whatever the inertia tensor. Texts write the gradient as a derivative by the
vector, ``\\frac{dT}{d\\boldsymbol\\omega}`` or ``\\frac{\\partial T}{\\partial \\boldsymbol\\omega}``
(the normal to the energy ellipsoid in Poinsot's construction, Hamilton's 𝛚 = ∂H/∂𝐋).

Takes: the tokens of a fraction's numerator and denominator (`derive.lecture.latex_parser`,
`derive.lecture.vector_parser`) and the reading of an atom. Gives: `of_energy`, the vector quantity
that gradient is for the scalar reader (𝐋 or 𝛚); `written`, whether a fraction is written as a
derivative of one symbol by one bold symbol; `of_vector`, the gradient of a scalar value with
respect to a vector value whose components are independent symbols (the vector reader's models).

May import: :mod:`derive.lecture.vocabulary`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture.vocabulary import LVEC, OMEGA_VEC, T_, NotRead

_GRADIENT = {OMEGA_VEC: LVEC, LVEC: OMEGA_VEC}


def _differential(tok) -> str | None:
    """'d' for a plain d, '∂' for \\partial, None for any other token."""
    if tok.kind == "cmd" and tok.value == "partial":
        return "∂"
    if tok.kind == "atom" and tok.value.base == "d" and not (tok.value.sub or tok.value.bold or tok.value.sup):
        return "d"
    return None


def written(num: list, den: list) -> bool:
    """A fraction written ``dX/d𝐕`` or ``∂X/∂𝐕``: one plain symbol by one bold symbol."""
    if len(num) != 2 or len(den) != 2 or num[1].kind != "atom" or den[1].kind != "atom":
        return False
    kind = _differential(num[0])
    return kind is not None and kind == _differential(den[0]) and not num[1].value.bold and den[1].value.bold


def of_vector(top, by):
    """The gradient of the scalar ``top`` with respect to the 3-vector ``by`` whose components are
    distinct symbols; None when ``by`` is not such a vector or ``top`` is not a scalar."""
    if not isinstance(by, sp.MatrixBase) or by.shape != (3, 1) or isinstance(top, sp.MatrixBase):
        return None
    if not all(isinstance(v, sp.Symbol) for v in by) or len(set(by)) != 3 or not isinstance(top, sp.Expr):
        return None
    return sp.Matrix([sp.diff(top, v) for v in by])


def of_energy(read, num: list, den: list):
    """``dT/d𝛚`` or ``∂T/∂𝛚`` (𝐋), ``dT/d𝐋`` or ``∂T/∂𝐋`` (𝛚) of the kinetic energy T; None otherwise.

    Parameters
    ----------
    read : callable
        The reading of an atom (`derive.lecture.vocabulary.Vocabulary.resolve`).
    num, den : list of Tok
        The tokens of the fraction's numerator and denominator.
    """
    if not written(num, den):
        return None
    try:
        top, by = read(num[1].value), read(den[1].value)
    except NotRead:
        return None
    return _GRADIENT.get(by) if top is T_ else None
