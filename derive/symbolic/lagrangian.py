"""Lagrangian mechanics of a rigid body with a fixed point, in Euler angles.

    T = ½ ω̃ᵀ I ω̃ = ½ (I₁ ω̃₁² + I₂ ω̃₂² + I₃ ω̃₃²)        (principal body axes)
    V = M g z_cm,   z_cm = l (R ê₃)·ẑ = l cos β            (uniform g along −z, centre of mass on
                                                           body axis 3 at distance l from the pivot)
    L = T − V

Coordinates q = (α, β, γ) and rates q̇ are independent symbols; the Euler–Lagrange equations

    d/dt ∂L/∂q̇ − ∂L/∂q = Q

are written as  𝕄(q) q̈ = F(q, q̇) + Q  with the mass matrix 𝕄 = ∂²L/∂q̇∂q̇ and
F = ∂L/∂q − (∂²L/∂q̇∂q) q̇, then solved for q̈. A coordinate that L does not contain is cyclic
and its momentum p = ∂L/∂q̇ is conserved (without generalised forces). The energy function is
h = q̇·∂L/∂q̇ − L. Eliminating the rates of the cyclic coordinates α, γ in favour of p_α, p_γ
reduces the symmetric top to one degree of freedom in β (Routh's procedure).
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import sympy as sp

from derive.symbolic.rotations import ANGLES, RATES, ZYZ, Convention, alpha_d, beta, beta_d, gamma_d, trig_reduce

I1, I2, I3 = sp.symbols("I1 I2 I3", positive=True)
Mass, g, l = sp.symbols("M g l", positive=True)
p_alpha, p_gamma = sp.symbols("p_alpha p_gamma", real=True)
E = sp.Symbol("E", real=True)
ACCELS = sp.symbols("alpha_dd beta_dd gamma_dd", real=True)


def kinetic_energy(moments=(I1, I2, I3), convention: Convention = ZYZ):
    """T(q, q̇) = ½ Σ I_i ω̃_i², ω̃ from the convention's Euler angles."""
    w = convention.omega_body_sum()
    return sp.Rational(1, 2) * sum((Ii * wi**2 for Ii, wi in zip(moments, w)), sp.S.Zero)


def kinetic_energy_symmetric(convention: Convention = ZYZ):
    """T for I₁ = I₂, in the canonical trig form (`trig_reduce`)."""
    return trig_reduce(kinetic_energy((I1, I1, I3), convention))


def gravity_potential(M=Mass, g_=g, l_=l, convention: Convention = ZYZ):
    """V = M g l (R ê₃)·ẑ: the height of a centre of mass on body axis 3, times M g."""
    R = convention.matrix()
    return trig_reduce(M * g_ * l_ * R[2, 2])


@dataclass(frozen=True)
class EulerLagrange:
    """The equations 𝕄(q) q̈ = F(q, q̇) of a Lagrangian, and their solution for q̈."""

    lagrangian: sp.Expr
    coords: tuple = ANGLES
    rates: tuple = RATES

    @functools.cached_property
    def mass_matrix(self) -> sp.Matrix:
        """𝕄_ij = ∂²L/∂q̇_i∂q̇_j."""
        return sp.hessian(self.lagrangian, self.rates).applyfunc(trig_reduce)

    @functools.cached_property
    def forcing(self) -> sp.Matrix:
        """F_i = ∂L/∂q_i − Σ_j ∂²L/∂q̇_i∂q_j q̇_j."""
        L = self.lagrangian
        F = []
        for qd_i in self.rates:
            dL = sp.diff(L, qd_i)
            F.append(-sum((sp.diff(dL, q) * qd for q, qd in zip(self.coords, self.rates)), sp.S.Zero))
        F = sp.Matrix(F) + sp.Matrix([sp.diff(L, q) for q in self.coords])
        return F.applyfunc(trig_reduce)

    @functools.cached_property
    def accelerations(self) -> sp.Matrix:
        """q̈ = 𝕄⁻¹ F, by the adjugate: q̈ = adj(𝕄) F / det 𝕄 (exact, no pivoting on symbols)."""
        Mm = self.mass_matrix
        det = sp.factor(trig_reduce(Mm.det()))
        num = (Mm.adjugate() * self.forcing).applyfunc(trig_reduce)
        return num.applyfunc(lambda e: sp.factor_terms(e) / det)

    @functools.cached_property
    def determinant(self):
        return sp.factor(trig_reduce(self.mass_matrix.det()))

    @functools.cached_property
    def cyclic(self) -> tuple:
        """Coordinates absent from L (so their momenta are conserved)."""
        return tuple(q for q in self.coords if not self.lagrangian.has(q))

    def momentum(self, q):
        """p_q = ∂L/∂q̇."""
        return trig_reduce(sp.diff(self.lagrangian, self.rates[self.coords.index(q)]))

    @functools.cached_property
    def energy(self):
        """h = Σ q̇ ∂L/∂q̇ − L (equals T + V for L quadratic in q̇)."""
        L = self.lagrangian
        return trig_reduce(sum((qd * sp.diff(L, qd) for qd in self.rates), sp.S.Zero) - L)


def heavy_symmetric_top(convention: Convention = ZYZ) -> EulerLagrange:
    """L = T(I₁ = I₂) − M g l cos β: the notes' heavy symmetric top."""
    return EulerLagrange(kinetic_energy_symmetric(convention) - gravity_potential(convention=convention))


@dataclass(frozen=True)
class Reduction:
    """Routh reduction of the symmetric top to the β degree of freedom.

    The cyclic momenta p_α(β, α̇, γ̇) and p_γ(β, α̇, γ̇) are solved for α̇, γ̇ and substituted:

        E  = ½ I₁ β̇² + p_γ²/(2I₃) + V_eff(β)
        E′ = E − p_γ²/(2I₃) = ½ I₁ β̇² + V_eff(β)
        Routhian  R(β, β̇) = α̇ p_α + γ̇ p_γ − L;  the β motion follows from L_β = −R, i.e.
        L_β = ½ I₁ β̇² − V_eff(β) − p_γ²/(2I₃).

    Plugging the rates into L itself gives L|_{p} = ½ I₁ β̇² + (centrifugal) + p_γ²/(2I₃) −
    M g l cos β, with the *wrong sign* of the centrifugal term for use as a Lagrangian in β.
    """

    system: EulerLagrange

    @functools.cached_property
    def rates_from_momenta(self) -> dict:
        """{α̇: …, γ̇: …} in terms of p_α, p_γ and β.

        The momenta are linear in the rates, p = A (α̇, γ̇)ᵀ + r with A = ∂(p_α, p_γ)/∂(α̇, γ̇)
        and r the rest (β̇ terms of a Tait–Bryan sequence), so Cramer's rule solves them:
        α̇ = (b₁ A₂₂ − A₁₂ b₂)/det A, γ̇ = (A₁₁ b₂ − A₂₁ b₁)/det A with b = (p_α, p_γ) − r.
        """
        rates = sp.Matrix([alpha_d, gamma_d])
        p = sp.Matrix([self.system.momentum(ANGLES[0]), self.system.momentum(ANGLES[2])])
        A = p.jacobian(rates)
        b = sp.Matrix([p_alpha, p_gamma]) - sp.expand(p - A * rates)
        det = A.det()
        sol = {alpha_d: (b[0] * A[1, 1] - A[0, 1] * b[1]) / det, gamma_d: (A[0, 0] * b[1] - A[1, 0] * b[0]) / det}
        return {k: sp.factor(trig_reduce(sp.together(v))) for k, v in sol.items()}

    def _substituted(self, expr):
        return sp.factor(sp.together(trig_reduce(expr.subs(self.rates_from_momenta))))

    @functools.cached_property
    def energy(self):
        """E(β, β̇; p_α, p_γ)."""
        return self._substituted(self.system.energy)

    @functools.cached_property
    def spin_energy(self):
        """p_γ²/(2I₃): the part of E that is constant because p_γ is."""
        return p_gamma**2 / (2 * I3)

    @functools.cached_property
    def effective_potential(self):
        """V_eff(β) = E − ½ I₁ β̇² − p_γ²/(2I₃)."""
        rest = self.energy - sp.Rational(1, 2) * I1 * beta_d**2 - self.spin_energy
        return sp.factor(sp.together(trig_reduce(sp.expand(rest))))

    @functools.cached_property
    def reduced_energy(self):
        """E′ = ½ I₁ β̇² + V_eff(β)."""
        return sp.Rational(1, 2) * I1 * beta_d**2 + self.effective_potential

    @functools.cached_property
    def lagrangian_substituted(self):
        """L with α̇, γ̇ replaced by their momentum expressions (an identity, not a Lagrangian in β)."""
        return self._substituted(self.system.lagrangian)

    @functools.cached_property
    def routh_lagrangian(self):
        """L_β = L − α̇ p_α − γ̇ p_γ (minus the Routhian): the correct Lagrangian for the β motion."""
        L = self.system.lagrangian
        return self._substituted(L - alpha_d * self.system.momentum(ANGLES[0]) - gamma_d * self.system.momentum(ANGLES[2]))

    @functools.cached_property
    def beta_acceleration(self):
        """β̈ = −V_eff′(β)/I₁ (from L_β; p_γ²/(2I₃) is a constant)."""
        return sp.factor(sp.together(-sp.diff(self.effective_potential, beta) / I1))
