"""The body's orientation and where it touches the table, derived from the shape.

Frames as in :mod:`derive.symbolic.rotations`: R(α, β, γ) (z-y-z) maps body components to
inertial ones. The upward vertical in body components is n = Rᵀ ẑ (the third row of R),

    n = (−sin β cos γ, sin β sin γ, cos β).

A shape is a convex surface fixed in the body, described in body axes relative to the centre of
mass; it touches the plane at its lowest point, the point a of the surface that minimises x·n.
The centre of mass then sits at height z = −a·n (the height constraint z_com = −a·ẑ in
inertial components), and a(n) is the vector from the centre of mass to the contact point:

* point at s ê₃ (a pointed tip):          a = s ê₃
* sphere of radius r centred at s ê₃:     a = s ê₃ − r n
* disc of radius r centred at s ê₃, in the plane ⊥ ê₃ (its rim):
                                           a = s ê₃ − r n⊥/|n⊥|,  n⊥ = n − n₃ ê₃

(the lowest rim point lies opposite the horizontal part of the vertical). A shape is spherical
(a sphere or a point, r = 0) when its contact point moves as a = s ê₃ − r n: then Jellett's
integral holds for any contact force.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import sympy as sp

from derive.symbolic.rotations import ANGLES, ZYZ

#: The vertical in body components, as symbols (n₁, n₂, n₃), |n| = 1.
N_VEC = sp.Matrix(sp.symbols("n1 n2 n3", real=True))
#: The sphere's or disc's radius r and the offset s of its centre along body axis 3.
RADIUS, OFFSET = sp.symbols("r s", real=True)
E3 = sp.Matrix([0, 0, 1])


@dataclass(frozen=True)
class Shape:
    """One way the body touches the plane: a(n) from the centre of mass to the contact point."""

    name: str
    point: Callable[[sp.Matrix], sp.Matrix]
    spherical: bool
    description: str

    def contact(self, n: sp.Matrix = N_VEC) -> sp.Matrix:
        """a(n), body components: the lowest point of the surface for the vertical n."""
        return self.point(n)


def _disc(n):
    perp = sp.sqrt(n[0] ** 2 + n[1] ** 2)
    return OFFSET * E3 - RADIUS * sp.Matrix([n[0] / perp, n[1] / perp, 0])


#: The shapes a scene may name (``[contact] shape``).
SHAPES: dict[str, Shape] = {s.name: s for s in (
    Shape("point", lambda n: OFFSET * E3, True, "a pointed tip at s ê₃"),
    Shape("sphere", lambda n: OFFSET * E3 - RADIUS * n, True, "a ball of radius r centred at s ê₃"),
    Shape("disc", _disc, False, "a thin disc's rim, radius r, centred at s ê₃"),
)}


def vertical_in_body(angles=ANGLES) -> sp.Matrix:
    """n = Rᵀ ẑ from the z-y-z rotation: the third row of R(α, β, γ)."""
    return ZYZ.matrix(*angles)[2, :].T


def contact_inertial(shape: Shape, angles=ANGLES) -> sp.Matrix:
    """a⁰ = R a(n): the contact point relative to the centre of mass, inertial components."""
    R = ZYZ.matrix(*angles)
    return (R * shape.contact(vertical_in_body(angles))).applyfunc(sp.simplify)


def height_in_angles(shape: Shape, angles=ANGLES):
    """z_com(α, β, γ) = −a⁰·ẑ (independent of α for every shape, of γ for axisymmetric ones)."""
    # a⁰'s third component alone, simplified as contact_inertial simplifies each one
    a0_z = (ZYZ.matrix(*angles)[2, :] * shape.contact(vertical_in_body(angles)))[0]
    return sp.simplify(-sp.simplify(a0_z))
