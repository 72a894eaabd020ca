"""The effects of a set summed as SymPy expressions, for the derivations.

``Symbols`` gives each effect parameter one SymPy symbol (shared with the derivation core's M,
g, l); ``potential`` is ΣV of the conservative effects; ``torque`` is Σ τ̃, each potential's
torque found by a virtual rotation,

    τ̃_k = −d/dε V(R (1 + ε [ê_k]ₓ)) at ε = 0        (body axes).

The registry itself (:mod:`derive.symbolic.effects`) stays free of SymPy: the warm simulate
path reads it; this module is for the code that derives.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import sympy as sp

from derive.symbolic import lagrangian
from derive.symbolic.rotations import skew


@dataclass
class Symbols:
    """``sym(name)`` for the parameters of a set of effects: one SymPy symbol per name, with the
    declared assumptions (shared with the derivation core's M, g, l)."""

    effects: tuple
    _cache: dict = field(default_factory=dict)

    def __call__(self, name: str):
        if name not in self._cache:
            known = {"M": lagrangian.Mass, "g": lagrangian.g, "l": lagrangian.l}
            if name in known:
                self._cache[name] = known[name]
            else:
                assumptions = next((dict(p.assumptions) for e in self.effects for p in e.params
                                    if p.name == name), {"real": True})
                self._cache[name] = sp.Symbol(name, **assumptions)
        return self._cache[name]

    def params(self) -> tuple:
        return tuple(self(p.name) for e in self.effects for p in e.params)


def potential(effects, R, sym):
    """ΣV of the conservative effects."""
    return sum((e.potential(R, sym) for e in effects if e.potential), sp.S.Zero)


def torque_from_potential(V: Callable, R, sym):
    """τ̃_k = −d/dε V(R (1 + ε [ê_k]ₓ), sym) at ε = 0: the torque of a potential, in body axes."""
    eps = sp.Symbol("epsilon")
    tau = []
    for k in range(3):
        e = sp.zeros(3, 1)
        e[k] = 1
        tau.append(-sp.diff(V(R * (sp.eye(3) + eps * skew(e)), sym), eps).subs(eps, 0))
    return sp.Matrix(tau)


def torque(effects, omega, R, sym):
    """Σ τ̃ of every effect: the torques, and the potentials' torques by virtual rotation."""
    tau = sp.zeros(3, 1)
    for e in effects:
        if e.torque:
            tau += e.torque(omega, R, sym)
        if e.potential:
            tau += torque_from_potential(e.potential, R, sym)
    return tau
