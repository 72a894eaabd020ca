"""Which integrals a scene's effects leave, decided by symbolic invariance (``derive analyze``
for a body with terms written by the user, and the plots' list of conserved quantities)."""
from __future__ import annotations

import sympy as sp

from derive.symbolic import effects as fx
from derive.symbolic.effect_sums import Symbols
from derive.symbolic.rotations import ANGLES, ZYZ, trig_reduce


def symmetries(effect_names, symmetric: bool, labels=None) -> dict:
    """Which integrals the effects leave: invariance checked symbolically, not by name.

    Parameters
    ----------
    effect_names : sequence of str
        Registry effects (built-in or the user's terms, registered).
    symmetric : bool
        I1 == I2.
    labels : mapping of str to str, optional
        How to name an effect in the reasons (a term's "potential 'magnet'").

    Returns
    -------
    dict
        ``{"energy": bool, "p_alpha": bool, "p_gamma": bool, "why": {integral: str}}``:

        * p_α = ẑ·L = L·n is conserved when every V is invariant under rotations about the
          inertial vertical, V(Rz(ε) R) = V(R), and every torque has no vertical component,
          ẑ·(R τ̃) ≡ 0. In z-y-z angles Rz(ε) R is R at α + ε, so the invariance is ∂V/∂α ≡ 0,
          simplified symbolically (an identity on the chart, so everywhere by continuity);
        * p_γ = I₃ω̃₃ for a symmetric body when every V is invariant about body axis 3,
          V(R Rz(ε)) = V(R), i.e. ∂V/∂γ ≡ 0, and every torque has τ̃₃ ≡ 0;
        * the energy T + ΣV when no effect has a torque (a torque does work; time enters only
          through torques).

        ``why`` says, for each integral not conserved, the first effect that breaks it.
    """
    labels = labels or {}
    # In z-y-z angles Rz(ε) R is R at α + ε and R Rz(ε) is R at γ + ε: the invariances are
    # ∂V/∂α ≡ 0 and ∂V/∂γ ≡ 0 (identities on the chart, so everywhere by continuity).
    R = ZYZ.matrix()
    w = sp.Matrix(sp.symbols("omega1:4", real=True))
    why = {}
    for effect in fx.lookup(effect_names):
        label = labels.get(effect.name, f"effect {effect.name!r}")
        sym = Symbols((effect,))
        if effect.potential is not None:
            V = effect.potential(R, sym)
            if not _zero(sp.diff(V, ANGLES[0])):
                why.setdefault("p_alpha", f"{label} is not invariant about the vertical")
            if not _zero(sp.diff(V, ANGLES[2])):
                why.setdefault("p_gamma", f"{label} is not invariant about body axis 3")
        if effect.torque is not None:
            why.setdefault("energy", f"{label} does work")
            tau = effect.torque(w, R, sym)
            if not _zero((R[2, :] * tau)[0, 0]):
                why.setdefault("p_alpha", f"{label} has a vertical component")
            if not _zero(tau[2]):
                why.setdefault("p_gamma", f"{label} has a component along body axis 3")
    if not symmetric:
        why.setdefault("p_gamma", "the body is not symmetric (I1 != I2)")
    return {"energy": "energy" not in why, "p_alpha": "p_alpha" not in why,
            "p_gamma": "p_gamma" not in why, "why": why}


def _zero(expr) -> bool:
    if expr == 0:
        return True
    e = sp.simplify(trig_reduce(sp.expand(expr)))
    return e == 0
