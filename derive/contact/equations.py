"""Newton–Euler for a body on the plane z = 0, with the contact force solved from the constraints.

Unknowns and conventions (body components throughout; the vertical n = Rᵀẑ, see geometry):
ω the angular velocity, v the centre of mass's velocity (v_b = Rᵀ v), f the contact force,
I = diag(I₁, I₂, I₃) about the centre of mass, a(n) the contact point from the centre of mass.

    I ω̇ = (I ω) × ω + a × f                       (Euler, moments about the centre of mass)
    M (v̇_b + ω × v_b) = f − M g n                  (Newton, in rotating components)
    ṅ = n × ω                                      (a fixed vector seen from the body)

The contact point's material velocity is u = v_b + ω × a, its slip u_t = u − (u·n) n.

Sliding: the gap φ = z + a(n)·n stays zero, so φ̈ = 0, with ż = n·v_b and
φ̇ = n·v_b + ∇(a·n)·ṅ. With f = N n + F_t(N, u_t) from the law, φ̈ is linear in N:
φ̈ = c₁ N + c₀, and N = −c₀/c₁ (c₁ > 0: the contact's effective inverse mass along n).

Rolling: u = 0 is held, so u̇ + ω × u = 0 (the inertial rate of u, in body components) with
u̇ = v̇_b + ω̇ × a + ω × (∂a/∂n) ṅ. This is linear in f: u̇ = A f + b, and
f = −A⁻¹ (b + ω × u); A = 1/M − [a]ₓ I⁻¹ [a]ₓ is the contact's inverse mass matrix.

Flight: f = 0.

A law's extensions (rolling resistance, spin friction) add a moment τ = N m about the centre of
mass, m = τ/N the moment per unit normal force (:func:`derive.contact.friction.moment_per_normal`),
to Euler's equations: I ω̇ = (I ω) × ω + a × f + τ. Sliding, φ̈ = 0 stays linear in N with τ in
it, φ̈ = (c₁ + k·m) N + c₀; rolling, τ = (f·n) m adds ((I⁻¹ m) × a) nᵀ to A.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import sympy as sp

from derive.contact.geometry import N_VEC, SHAPES, Shape
from derive.contact.friction import NORMAL, force
from derive.contact.laws import Law

I1, I2, I3 = sp.symbols("I1 I2 I3", positive=True)
MASS, GRAV = sp.symbols("M g", positive=True)
OMEGA = sp.Matrix(sp.symbols("w1 w2 w3", real=True))
VEL = sp.Matrix(sp.symbols("vb1 vb2 vb3", real=True))
FORCE = sp.Matrix(sp.symbols("f1 f2 f3", real=True))
#: The contact moment per unit normal force, m = τ/N (body components), as the C code supplies it.
MOMENT = sp.Matrix(sp.symbols("m1 m2 m3", real=True))
SLIP = sp.Matrix(sp.symbols("ut1 ut2 ut3", real=True))
INERTIA = sp.diag(I1, I2, I3)


def cross(a, b) -> sp.Matrix:
    return sp.Matrix([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def dot(a, b):
    return (a.T * b)[0]


def omega_dot(a: sp.Matrix, f: sp.Matrix = FORCE, w: sp.Matrix = OMEGA, tau: sp.Matrix | None = None) -> sp.Matrix:
    """ω̇ = I⁻¹ ((I ω) × ω + a × f + τ): Euler's equations about the centre of mass, τ the
    contact's moment (none when not given)."""
    moment = cross(a, f) if tau is None else cross(a, f) + tau
    return INERTIA.inv() * (cross(INERTIA * w, w) + moment)


def velocity_dot(f: sp.Matrix = FORCE, n: sp.Matrix = N_VEC, w=OMEGA, v=VEL) -> sp.Matrix:
    """v̇_b = f/M − g n − ω × v_b: Newton's law in body components."""
    return f / MASS - GRAV * n - cross(w, v)


@dataclass(frozen=True)
class Contact:
    """The derived equations of one shape (symbols: n, ω, v_b, u_t, the law's, the parameters)."""

    shape: Shape

    @functools.cached_property
    def a(self) -> sp.Matrix:
        return self.shape.contact(N_VEC)

    @functools.cached_property
    def n_dot(self) -> sp.Matrix:
        return cross(N_VEC, OMEGA)

    @functools.cached_property
    def gap_rate(self) -> sp.Expr:
        """φ̇ − n·v_b for the gap φ = z + a(n)·n: ∇(a·n)·ṅ, a function of n and ω."""
        h = dot(self.a, N_VEC)
        grad = sp.Matrix([sp.diff(h, x) for x in N_VEC])
        return dot(grad, self.n_dot)

    def gap_acceleration(self, f: sp.Matrix, tau: sp.Matrix | None = None) -> sp.Expr:
        """φ̈ for the gap φ = z + a(n)·n, the accelerations eliminated for the force f (and the
        moment τ)."""
        rate = self.gap_rate
        wd, vd = omega_dot(self.a, f, tau=tau), velocity_dot(f)
        return (dot(self.n_dot, VEL) + dot(N_VEC, vd)
                + sum(sp.diff(rate, x) * xd for x, xd in zip(N_VEC, self.n_dot))
                + sum(sp.diff(rate, x) * xd for x, xd in zip(OMEGA, wd)))

    @functools.lru_cache(maxsize=None)  # a kernel's sliding force and its moment both read them
    def gap_coefficients(self, law: Law) -> tuple[sp.Expr, sp.Expr, sp.Matrix]:
        """(c₁, c₀, f) with φ̈ = c₁ N + c₀ while sliding under ``law``, f = N n + F_t(N, u_t)."""
        f = NORMAL * N_VEC + force(law, NORMAL, SLIP)
        acc = sp.expand(self.gap_acceleration(f))
        c1, c0 = acc.coeff(NORMAL, 1), acc.coeff(NORMAL, 0)
        # expanded, φ̈ is linear in N when each of its terms is N times a factor free of N, or free of N
        if any(t.as_independent(NORMAL, as_Add=False)[1] not in (1, NORMAL) for t in sp.Add.make_args(acc)):
            raise ValueError(f"the gap's acceleration is not linear in N under {law.name}")
        return c1, c0, f

    def sliding(self, law: Law) -> tuple[sp.Expr, sp.Matrix]:
        """(N, f) while sliding under ``law``: N = −c₀/c₁ solved from φ̈ = 0, f = N n + F_t."""
        c1, c0, f = self.gap_coefficients(law)
        return -c0 / c1, f

    @functools.cached_property
    def moment_coefficient(self) -> sp.Expr:
        """k·m, what the moment τ = N m adds to c₁ (linear in m) under any law: sliding with the
        extensions, N = −c₀/(c₁ + k·m). τ enters φ̈ only through ω̇ (by I⁻¹ τ), so k·m =
        ∂φ̇/∂ω · I⁻¹ m, expanded as c₁ is (the terms φ̈ with τ has and φ̈ without τ lacks)."""
        per_normal = INERTIA.inv() * MOMENT
        return sp.expand(sum(sp.diff(self.gap_rate, w) * x for w, x in zip(OMEGA, per_normal)))

    @functools.cached_property
    def rolling(self) -> tuple[sp.Matrix, sp.Matrix]:
        """(A, b) with u̇ = A f + b while the contact point does not slip."""
        Ja = self.a.jacobian(N_VEC)
        ud = velocity_dot() + cross(omega_dot(self.a), self.a) + cross(OMEGA, Ja * self.n_dot)
        A = ud.jacobian(FORCE)
        b = ud.subs({x: 0 for x in FORCE})
        return A, b

    @functools.cached_property
    def rolling_moment(self) -> sp.Matrix:
        """What the moment τ = (f·n) m adds to A: u̇ gains (I⁻¹ τ) × a, linear in f."""
        return cross(INERTIA.inv() * MOMENT * dot(FORCE, N_VEC), self.a).jacobian(FORCE)


@functools.lru_cache(maxsize=None)
def contact(shape: str) -> Contact:
    """The derivation for a registered shape (cached: one per process)."""
    return Contact(SHAPES[shape])
