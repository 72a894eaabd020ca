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


#: The extensions' lengths: rolling resistance δ and the spin friction's radius r_s (m).
DELTA, R_SPIN = sp.symbols("delta r_spin", nonnegative=True)
#: The rolling direction ω_t/|ω_t| (0 at ω_t = 0) and the spin's sign σ = r_s ω_n/√((r_s ω_n)² + ε²)
#: (sgn ω_n under exact Coulomb, ε = 0), which the C code supplies as it supplies d.
ROLL_DIR = sp.Matrix(sp.symbols("e1 e2 e3", real=True))
SPIN_SIGN = sp.Symbol("sigma", real=True)

#: Extension key → its moment per unit normal force, τ/N, in body components, given n.
MOMENTS: dict[str, Callable] = {
    "rolling_resistance": lambda n: -DELTA * ROLL_DIR,
    "spin_friction": lambda n: -MU * R_SPIN * SPIN_SIGN * n,
}


def moment_per_normal(n) -> sp.Matrix:
    """m = τ/N, the sum of the extensions' moments per unit normal force (body components)."""
    return sum((m(n) for m in MOMENTS.values()), sp.zeros(3, 1))
