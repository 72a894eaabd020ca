"""Stability of equilibria from series expansions and linearisation.

Sleeping top. With p_α = p_γ the effective potential is regular at β = 0 and

    E′ = ½ I₁ β̇² + V_eff(β),   V_eff(β) = V₀ + k₂ β² + k₄ β⁴ + O(β⁶).

β = 0 is stable when k₂ > 0 (a minimum); the threshold k₂ = 0 is solved here for p_γ from the
series itself, and at the threshold the sign of k₄ settles the marginal case (the notes' "≥").

Torque-free spin. Euler's equations I ω̇ = (I ω) × ω linearised about ω = ω₀ ê_k give, in the
plane of the other two axes i, j (cyclic order i, j, k),

    δω̇_i = −Ω_i δω_j,  δω̇_j = Ω_j δω_i,   Ω_i = ω₀ (I_k − I_j)/I_i,  Ω_j = ω₀ (I_k − I_i)/I_j

(the notes' Ω₁, Ω₂ for k = 3), so δω̈ = −Ω_i Ω_j δω: oscillation at √(Ω_iΩ_j) when Ω_iΩ_j > 0,
exponential growth at rate √(−Ω_iΩ_j) when the signs differ (spin about the intermediate axis).
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import sympy as sp

from derive.symbolic.lagrangian import I1, I2, I3, Reduction, heavy_symmetric_top, p_alpha, p_gamma
from derive.symbolic.rotations import beta, beta_d

omega0 = sp.Symbol("omega_0", real=True)
delta = sp.symbols("delta1:4", real=True)


@dataclass(frozen=True)
class SleepingTop:
    """Series of V_eff about β = 0 with p_α = p_γ, and the stability threshold solved from it."""

    reduction: Reduction

    @functools.cached_property
    def potential(self):
        """V_eff(β) with p_α = p_γ."""
        return self.reduction.effective_potential.subs(p_alpha, p_gamma)

    @functools.cached_property
    def series(self):
        """V_eff to O(β⁶): V₀ + k₂ β² + k₄ β⁴."""
        return sp.series(self.potential, beta, 0, 6).removeO()

    def coefficient(self, n: int):
        return sp.factor(sp.expand(self.series).coeff(beta, n))

    @functools.cached_property
    def reduced_energy_series(self):
        """E′ ≈ ½ I₁ β̇² + V₀ + k₂ β² (the notes' second-order form)."""
        return sp.Rational(1, 2) * I1 * beta_d**2 + self.coefficient(0) + self.coefficient(2) * beta**2

    @functools.cached_property
    def condition(self):
        """k₂ ≥ 0 solved for p_γ > 0 (the set of stable spins, as a sympy relation)."""
        p = sp.Symbol("p", positive=True)
        sol = sp.solve(sp.Ge(self.coefficient(2).subs(p_gamma, p), 0), p)
        return sol.subs(p, p_gamma)

    @functools.cached_property
    def threshold(self):
        """The spin momentum at which k₂ = 0."""
        p = sp.Symbol("p", positive=True)
        (root,) = sp.solve(sp.Eq(self.coefficient(2).subs(p_gamma, p), 0), p)
        return root

    @functools.cached_property
    def quartic_at_threshold(self):
        """k₄ at the threshold: positive means the threshold spin itself is (weakly) stable."""
        return sp.factor(self.coefficient(4).subs(p_gamma, self.threshold))


@functools.lru_cache(maxsize=None)
def sleeping_top() -> SleepingTop:
    return SleepingTop(Reduction(heavy_symmetric_top()))


def euler_rhs(moments=(I1, I2, I3), w=None):
    """ω̇ = I⁻¹ ((I ω) × ω), the torque-free Euler equations in the body frame."""
    w = sp.Matrix(sp.symbols("omega1:4", real=True)) if w is None else sp.Matrix(w)
    Iw = sp.Matrix([m * wi for m, wi in zip(moments, w)])
    torque = Iw.cross(w)
    return sp.Matrix([torque[i] / moments[i] for i in range(3)])


@dataclass(frozen=True)
class SteadySpin:
    """Euler's equations linearised about steady spin ω₀ about principal axis ``axis`` (0, 1, 2)."""

    axis: int
    moments: tuple = (I1, I2, I3)

    @functools.cached_property
    def jacobian(self) -> sp.Matrix:
        w = sp.Matrix(sp.symbols("omega1:4", real=True))
        f = euler_rhs(self.moments, w)
        at = {w[i]: (omega0 if i == self.axis else 0) for i in range(3)}
        return f.jacobian(w).subs(at)

    @functools.cached_property
    def frequencies(self):
        """(Ω_i, Ω_j) with δω̇_i = −Ω_i δω_j, δω̇_j = Ω_j δω_i for the cyclic successors i, j."""
        k = self.axis
        i, j = (k + 1) % 3, (k + 2) % 3
        J = self.jacobian
        return sp.factor(-J[i, j]), sp.factor(J[j, i])

    @functools.cached_property
    def eigenvalue_squared(self):
        """λ² = −Ω_i Ω_j: negative (oscillation) is stable, positive (growth) is not."""
        Oi, Oj = self.frequencies
        return sp.factor(-Oi * Oj)
