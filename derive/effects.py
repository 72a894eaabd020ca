"""Effects: what acts on the body besides its own inertia. A registry, one entry per effect.

An effect contributes parameters and either a potential energy V(R) (conservative) or a body
torque τ̃(ω̃, R) (everything else). Every formulation derives its equations from these two
things, so adding an effect adds one entry here and touches no formulation:

* Lagrangian (Euler angles): V enters L = T − V; a torque enters as the generalised force
  Q_j = τ̃ · ∂ω̃/∂q̇_j (virtual power).
* Newton–Euler (quaternion): τ̃ is used directly; a potential yields its torque by a virtual
  rotation δθ about the body axes, R → R (1 + [δθ]ₓ):  τ̃_k = −∂V/∂δθ_k |₀.

R maps body to inertial components (v⁰ = R ṽ); ẑ is the inertial vertical; ω̃ is in body axes.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import sympy as sp

from .rotations import skew

M, g, l = sp.symbols("M g l", positive=True)
cx, cy, cz = sp.symbols("cx cy cz", real=True)
c_damp = sp.Symbol("c", nonnegative=True)


@dataclass(frozen=True)
class Effect:
    """One effect: its parameters (names in order), potential V(R, p) and torque τ̃(ω̃, R, p)."""

    name: str
    description: str
    params: tuple
    potential: Callable | None = None
    torque: Callable | None = None
    conservative: bool = True


def _gravity_potential(com):
    def V(R):
        # Height of the centre of mass: ẑ · (R r_c), times M g (g along −ẑ).
        return M * g * (R[2, :] * sp.Matrix(com))[0, 0]

    return V


def _viscous(omega, R):
    return -c_damp * sp.Matrix(omega)


REGISTRY: dict[str, Effect] = {
    e.name: e
    for e in (
        Effect(
            "gravity",
            "uniform gravity g along −z, centre of mass on body axis 3 at distance l from the pivot",
            params=(M, g, l),
            potential=_gravity_potential((0, 0, l)),
        ),
        Effect(
            "gravity_general",
            "uniform gravity g along −z, centre of mass at (cx, cy, cz) in body axes",
            params=(M, g, cx, cy, cz),
            potential=_gravity_potential((cx, cy, cz)),
        ),
        Effect(
            "damping",
            "viscous torque −c ω about the pivot",
            params=(c_damp,),
            torque=_viscous,
            conservative=False,
        ),
    )
}


def lookup(names) -> tuple[Effect, ...]:
    """The effects named, in registry order (so a model's parameter layout does not depend on
    the order a scene lists them in)."""
    unknown = [n for n in names if n not in REGISTRY]
    if unknown:
        raise KeyError(f"unknown effect {unknown[0]!r} (known: {', '.join(REGISTRY)})")
    return tuple(e for n, e in REGISTRY.items() if n in set(names))


def torque_from_potential(V: Callable, R: sp.Matrix) -> sp.Matrix:
    """τ̃_k = −d/dε V(R (1 + ε [ê_k]ₓ)) at ε = 0: the torque of a potential, in body axes."""
    eps = sp.Symbol("epsilon")
    tau = []
    for k in range(3):
        e = sp.zeros(3, 1)
        e[k] = 1
        tau.append(-sp.diff(V(R * (sp.eye(3) + eps * skew(e))), eps).subs(eps, 0))
    return sp.Matrix(tau)
