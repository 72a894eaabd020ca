"""The contact laws' sliding force F_t(N, u_t) and its power F_t·u_t, in SymPy, by law name.

The formulas are :mod:`derive.contact.laws`'s (which keeps the registry of names and phases):
F_t = 0 (``none``), −μ N d with d the slip direction the C code supplies (``coulomb``),
−μ N u_t/√(|u_t|² + ε²) (``coulomb_regularized``), −μ u_t (``viscous``); ``rolling`` has no
sliding force. Only a derivation reads this module.
"""
from __future__ import annotations

from typing import Callable

import sympy as sp

MU, EPS = sp.symbols("mu epsilon", nonnegative=True)
NORMAL = sp.Symbol("N", real=True)
#: The slip direction the C code supplies for exact Coulomb (u_t/|u_t|, or the predicted one).
SLIP_DIR = sp.Matrix(sp.symbols("d1 d2 d3", real=True))


def _norm(v):
    return sp.sqrt((v.T * v)[0])


#: Law name → (F_t(N, u_t) or None, F_t·u_t as a function of N and u_t).
FORCES: dict[str, tuple[Callable | None, Callable]] = {
    "none": (lambda N, ut: sp.zeros(3, 1), lambda N, ut: sp.S.Zero),
    "coulomb": (lambda N, ut: -MU * N * SLIP_DIR, lambda N, ut: -MU * N * _norm(ut)),
    "coulomb_regularized": (lambda N, ut: -MU * N * ut / sp.sqrt((ut.T * ut)[0] + EPS**2),
                            lambda N, ut: -MU * N * (ut.T * ut)[0] / sp.sqrt((ut.T * ut)[0] + EPS**2)),
    "viscous": (lambda N, ut: -MU * ut, lambda N, ut: -MU * (ut.T * ut)[0]),
    "rolling": (None, lambda N, ut: sp.S.Zero),
}


def force(law, N, ut) -> sp.Matrix:
    """F_t(N, u_t) while sliding under ``law`` (a :class:`~derive.contact.laws.Law`)."""
    return FORCES[law.name][0](N, ut)


def power(law, N, ut) -> sp.Expr:
    """F_t·u_t, the contact force's power while sliding under ``law``."""
    return FORCES[law.name][1](N, ut)
