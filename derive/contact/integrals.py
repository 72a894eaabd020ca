"""The integrals of a body on the plane, as expressions in the body-frame state, and which hold.

With n the vertical, ω the angular velocity and v_b the centre of mass's velocity (body
components), a(n) the contact point from the centre of mass and z the centre of mass's height:

* energy      E = ½ M |v|² + ½ ωᵀ I ω + M g z          (conserved frictionless and rolling;
                                                        Ė = F_t·u_t ≤ 0 while sliding)
* p_alpha     p_α = (I ω)·n = L·ẑ                       (frictionless: the contact force is
                                                        vertical, so its moment about the
                                                        centre of mass is horizontal)
* p_gamma     p_γ = I₃ ω₃                               (frictionless, axisymmetric: a × n has
                                                        no ê₃ part for every shape here)
* jellett     J = L·a = (I ω)·a                         (axisymmetric with a spherical contact
                                                        a = s ê₃ − r n, under any contact force:
                                                        dJ/dt = (a × f)·a + L·ȧ = s L·(ω × ê₃) = 0
                                                        when I₁ = I₂)
* routh       ω₃ √(I₁ I₃ + M aᵀ I a)                   (rolling, axisymmetric, spherical contact)

The horizontal momentum M v_x, M v_y is conserved on the frictionless plane too.
"""
from __future__ import annotations

import sympy as sp

from derive.contact.equations import I1, I2, I3, INERTIA, MASS, GRAV, OMEGA, VEL, Contact, dot
from derive.contact.geometry import N_VEC
from derive.contact.laws import Law
from derive.contact.scene import integrals_held

HEIGHT = sp.Symbol("z", real=True)


def energy() -> sp.Expr:
    """E = ½ M |v_b|² + ½ ωᵀ I ω + M g z."""
    return MASS * dot(VEL, VEL) / 2 + dot(OMEGA, INERTIA * OMEGA) / 2 + MASS * GRAV * HEIGHT


def expressions(c: Contact) -> dict[str, sp.Expr]:
    """Every monitored integral's expression (whether it holds is :func:`holds`)."""
    a = c.a
    return {
        "energy": energy(),
        "p_alpha": dot(INERTIA * OMEGA, N_VEC),
        "p_gamma": I3 * OMEGA[2],
        "jellett": dot(INERTIA * OMEGA, a),
        "routh": OMEGA[2] * sp.sqrt(I1 * I3 + MASS * dot(a, INERTIA * a)),
    }


def holds(c: Contact, law: Law, symmetric: bool) -> tuple[str, ...]:
    """The integrals the case has (:func:`derive.contact.scene.integrals_held`)."""
    return integrals_held(c.shape.name, law.name, symmetric)


#: Moments of an axisymmetric body (I₂ = I₁) for the checks of the integrals.
SYMMETRIC = {I2: I1}
