"""The orientation a text chooses: the fixed (inertial) first axis along the angular momentum.

A text on the free body often turns its fixed axes so that 𝐋 lies along the first one (Z in
z-x-z): then the body components of 𝐋 are |𝐋| times those of that axis, Iᵢω̃ᵢ = |𝐋| (Rᵀ ẑ)ᵢ
(I₁ω₁ = L sin θ sin ψ, I₂ω₂ = L sin θ cos ψ, I₃ω₃ = L cos θ in z-x-z), and the second and
third angles are functions of ω̃: cos θ = I₃ω̃₃/|𝐋|, sin θ = √(1 − cos²θ) (0 ≤ θ ≤ π), and sin ψ,
cos ψ from the other two components. The rates follow from ω̃ = M(angles) q̇ (M invertible where
sin θ ≠ 0). `AlongMomentum.apply` writes an expression in ω̃ alone that way, so a relation the
text derives for its chosen orientation (φ̇ = L (I₁ω₁² + I₂ω₂²)/(L² − I₃²ω₃²), tan θ = …) can
be checked. Only for the proper Euler sequences (first and third axes equal).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.sparse_forms`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import functools

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.sparse_forms import free_symbols
from derive.symbolic import rotations as rot
from derive.symbolic.lagrangian import I1, I2, I3


class AlongMomentum:
    """The substitutions of the orientation with 𝐋 along the fixed first axis, for one convention."""

    def __init__(self, conv, omega: sp.Matrix):
        self.ok = conv.axes[0] == conv.axes[2]
        if not self.ok:
            return
        theta, psi = rot.ANGLES[1], rot.ANGLES[2]
        n = conv.inertial_axis()
        k3 = "xyz".index(conv.axes[2])
        Iw = [I1 * lx.W[0], I2 * lx.W[1], I3 * lx.W[2]]
        L = sp.sqrt(sum(x**2 for x in Iw))
        u = [x / L for x in Iw]
        if sp.simplify(n[k3] - sp.cos(theta)) != 0:
            self.ok = False
            return
        sin_t = sp.sqrt(1 - u[k3] ** 2)
        S, C = sp.symbols("S C")
        i, j = [k for k in range(3) if k != k3]
        eqs = [sp.expand(sp.cancel(n[k] / sp.sin(theta))).xreplace({sp.sin(psi): S, sp.cos(psi): C}) - u[k] / sin_t
               for k in (i, j)]
        found = sp.solve(eqs, [S, C], dict=True)
        if len(found) != 1:
            self.ok = False
            return
        self.trig = {sp.cos(theta): u[k3], sp.sin(theta): sin_t, sp.sin(psi): found[0][S], sp.cos(psi): found[0][C]}
        self._omega = omega

    @functools.cached_property
    def rates(self) -> dict:
        """q̇ in ω̃ (ω̃ = M(angles) q̇ solved): derived on the first relation with rates, since most
        relations a text states for its orientation have none."""
        M = self._omega.jacobian(sp.Matrix(rot.RATES))
        rates = M.LUsolve(sp.Matrix(lx.W))
        return {r: sp.simplify(v) for r, v in zip(rot.RATES, rates)}

    @classmethod
    def of(cls, trig: dict | None, omega: sp.Matrix) -> AlongMomentum:
        """The orientation from its angles' substitutions ``trig`` (None where it does not apply),
        as computed for the convention before; its rates are derived from ``omega`` when asked."""
        self = cls.__new__(cls)
        self.ok = trig is not None
        if self.ok:
            self.trig, self._omega = trig, omega
        return self

    def apply(self, v):
        """v with the rates and the second and third angles written in ω̃ (the first angle stays)."""
        v = sp.sympify(v)
        if free_symbols(v) & set(rot.RATES):
            v = v.xreplace(self.rates)
        if v.has(sp.tan, sp.cot):
            v = v.replace(sp.tan, lambda a: sp.sin(a) / sp.cos(a)).replace(sp.cot, lambda a: sp.cos(a) / sp.sin(a))
        return v.xreplace(self.trig)

    def angles_left(self, v) -> bool:
        """Does v still hold the second or third angle outside sin and cos (θ alone, sin 2θ)?"""
        return bool(free_symbols(sp.sympify(v)) & {rot.ANGLES[1], rot.ANGLES[2]})
