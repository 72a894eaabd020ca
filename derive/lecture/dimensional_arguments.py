"""A function of a quantity with a dimension: the text's letter is not the derivation's.

Takes: a display as `derive.lecture.latex.parse` reads it. Gives: `dimensional_argument`, why
the display is left unchecked, or None.
May import: SymPy, :mod:`derive.lecture.vocabulary`, :mod:`derive.symbolic`.

A sine, cosine, exponential or logarithm takes a pure number. Where a display applies one to a
letter the reader takes for a quantity with a dimension — an energy E, a kinetic energy T, a
Lagrangian L, a mass M, a length l, the acceleration g, a principal moment I₁, a conserved
momentum — times a number (``\\sin E``, ``\\cos(M/2)``, ``e^{T}``), the text uses the letter for a
quantity of its own (Kepler's equation ``M = E - e \\sin E`` in the mean and eccentric anomalies),
and a verdict in the derivation's names would judge something the text never said.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import vocabulary as vc
from derive.symbolic.lagrangian import I1, I2, I3, Mass, g, l, p_alpha, p_gamma

DIMENSIONAL = {vc.T_: "a kinetic energy", vc.LAGRANGIAN: "a Lagrangian", vc.ENERGY: "an energy", vc.EPRIME: "an energy",
               vc.VEFF: "a potential", vc.LMAG: "an angular momentum", Mass: "a mass", l: "a length",
               g: "an acceleration", I1: "a moment of inertia", I2: "a moment of inertia", I3: "a moment of inertia",
               p_alpha: "an angular momentum", p_gamma: "an angular momentum"}
"""The derivation's names with a dimension, and what each is."""

_PURE = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc, sp.exp, sp.log, sp.sinh, sp.cosh, sp.tanh,
         sp.asin, sp.acos, sp.atan)
"""The functions whose argument is a pure number."""


def dimensional_argument(members) -> str | None:
    """Why a display that applies a function to a quantity with a dimension is not judged, or None.

    Parameters
    ----------
    members : sequence
        The parsed members (each with a SymPy ``value``: an expression or a matrix).

    Returns
    -------
    str or None
        ``"… of E, an energy: …"`` when some member holds f(c·q) with f in sin, cos, tan, exp,
        log, … (and their hyperbolic and inverse kin), c a number and q one of `DIMENSIONAL`.
    """
    for member in members:
        value = member.value
        if not isinstance(value, (sp.Basic, sp.MatrixBase)):
            continue
        for call in value.atoms(*_PURE):
            rest = call.args[0].as_coeff_Mul()[1] if call.args else None
            if rest in DIMENSIONAL:
                return (f"{call.func.__name__} of {vc.QUANTITY_LATEX.get(rest, rest)}, {DIMENSIONAL[rest]}, "
                        "takes a pure number: the text's letter is a quantity of its own, not the derivation's")
    return None
