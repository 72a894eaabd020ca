"""Inertia tensors: point masses, standard solids, principal moments and axes.

    I_ij = Σ_p m_p (δ_ij r_p² − r_pi r_pj)          (point masses, the notes' definition)
    I_ij = ∫ ρ (δ_ij r² − r_i r_j) dV                (a solid of uniform density ρ = M / V)

Solids are integrated here, not looked up: each is a region in its natural coordinates with
the Jacobian of the volume element, integrated variable by variable with the exact rules for
powers and for whole periods of sines and cosines (`integrate_terms`; `sympy.integrate` for any
other term). Axis 3 is the
symmetry axis. "About the centre of mass" and "about a pivot on the symmetry axis at distance d
from the centre of mass" are related by the parallel-axis theorem, I_pivot = I_cm + M (d² 1 − d dᵀ),
which `shift` applies (and tests check against direct integration about the pivot).
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
import sympy as sp

M, R, H, a, b, c, d = sp.symbols("M R H a b c d", positive=True)
_x, _y, _z = sp.symbols("x y z", real=True)
_r, _phi, _theta, _rho = sp.symbols("r phi theta rho", nonnegative=True)


def point_masses(masses, positions) -> sp.Matrix:
    """I_ij = Σ m (δ_ij r² − r_i r_j) for point masses (exact if the inputs are symbolic)."""
    I = sp.zeros(3, 3)
    for m, r in zip(masses, positions):
        r = sp.Matrix(r)
        I += m * ((r.T * r)[0, 0] * sp.eye(3) - r * r.T)
    return I


def point_masses_numeric(masses, positions) -> np.ndarray:
    """The same sum in floating point, for many points: I = Σ m (|r|² 1 − r rᵀ)."""
    m = np.asarray(masses, dtype=float)
    r = np.asarray(positions, dtype=float)
    r2 = np.einsum("pi,pi->p", r, r)
    return np.einsum("p,ij->ij", m * r2, np.eye(3)) - np.einsum("p,pi,pj->ij", m, r, r)


def shift(I_cm: sp.Matrix, mass, d_vec) -> sp.Matrix:
    """Parallel-axis theorem: the tensor about a point displaced by ``d_vec`` from the centre of mass."""
    dv = sp.Matrix(d_vec)
    return I_cm + mass * ((dv.T * dv)[0, 0] * sp.eye(3) - dv * dv.T)


@dataclass(frozen=True)
class Solid:
    """A uniform solid: its region in natural coordinates and where its centre of mass sits.

    ``position`` gives (x, y, z) in terms of the coordinates, ``jacobian`` the volume element
    factor, ``limits`` the integration limits (innermost first), ``com`` the centre of mass on
    axis 3 in the integration frame (for the cone that frame has its origin at the apex).
    """

    name: str
    position: tuple
    jacobian: object
    limits: tuple
    parameters: tuple

    def _integrate(self, f):
        """∫ f J over the region, variable by variable (innermost first) with :func:`integrate_terms`."""
        f = f * self.jacobian
        for v, lo, hi in self.limits:
            f = integrate_terms(f, v, lo, hi)
        return f

    @functools.cached_property
    def volume(self):
        return sp.simplify(self._integrate(sp.S.One))

    @functools.cached_property
    def centre_of_mass(self) -> sp.Matrix:
        return sp.Matrix([sp.simplify(self._integrate(xi) / self.volume) for xi in self.position])

    @functools.cached_property
    def tensor_about_origin(self) -> sp.Matrix:
        """∫ ρ (δ_ij r² − r_i r_j) dV about the integration origin, ρ = M / V."""
        r = sp.Matrix(self.position)
        r2 = (r.T * r)[0, 0]
        I = sp.zeros(3, 3)
        for i in range(3):
            for j in range(i, 3):
                f = (r2 if i == j else 0) - r[i] * r[j]
                I[i, j] = I[j, i] = sp.simplify(M * self._integrate(sp.expand(f)) / self.volume)
        return I

    @functools.cached_property
    def about_centre_of_mass(self) -> sp.Matrix:
        """Parallel-axis theorem backwards from the integration origin to the centre of mass."""
        I0 = self.tensor_about_origin
        com = self.centre_of_mass
        return (I0 - M * ((com.T * com)[0, 0] * sp.eye(3) - com * com.T)).applyfunc(sp.simplify)

    def about_pivot(self, distance=d) -> sp.Matrix:
        """About a pivot on the symmetry axis at ``distance`` from the centre of mass."""
        return shift(self.about_centre_of_mass, M, (0, 0, distance)).applyfunc(sp.simplify)


def _power_integral(k, lo, hi):
    """∫ v^k dv from lo to hi = (hi^(k+1) − lo^(k+1)) / (k + 1), k ≥ 0."""
    return (hi ** (k + 1) - lo ** (k + 1)) / (k + 1)


def _trig_integral(m, n, lo, hi):
    """∫ cos^m v sin^n v dv (m, n ≥ 0) over a whole period [0, 2π] or over [0, π], by the Wallis
    and Beta-function rules (None for other limits):

        ∫₀^2π cos^m sin^n = 2π (m−1)!! (n−1)!! / (m+n)!!   (m, n even; else 0)
        ∫₀^π  cos^m sin^n = Γ((m+1)/2) Γ((n+1)/2) / Γ((m+n)/2 + 1)   (m even; else 0)
    """
    if lo != 0 or hi not in (sp.pi, 2 * sp.pi):
        return None
    if m % 2 or (hi == 2 * sp.pi and n % 2):
        return sp.S.Zero
    if hi == 2 * sp.pi:
        return 2 * sp.pi * sp.factorial2(m - 1) * sp.factorial2(n - 1) / sp.factorial2(m + n)
    return sp.gamma(sp.Rational(m + 1, 2)) * sp.gamma(sp.Rational(n + 1, 2)) / sp.gamma(sp.Rational(m + n, 2) + 1)


def _whole_harmonic(g, v) -> bool:
    """Whether g is sin(k v + c) or cos(k v + c), k a nonzero integer (its integral over a whole
    period [0, 2π] is 0)."""
    if not isinstance(g, (sp.sin, sp.cos)):
        return False
    k = sp.diff(g.args[0], v)
    return k.is_Integer and k != 0 and sp.diff(g.args[0], v, 2) == 0


def integrate_terms(f, v, lo, hi):
    """∫ f dv from ``lo`` to ``hi``, term by term of the expanded integrand: a term's factor in v
    that is v^k (k ≥ 0) or cos^m v sin^n v over [0, 2π] or [0, π] by the exact rules
    (:func:`_power_integral`, :func:`_trig_integral`), any other by ``sympy.integrate``."""
    total = sp.S.Zero
    for term in sp.Add.make_args(sp.expand(f)):
        if term == 0:
            continue
        outer, inner = term.as_independent(v, as_Add=False)
        powers = inner.as_powers_dict()
        exps = {base: e for base, e in powers.items() if base != 1}
        ok = all(e.is_Integer and e >= 0 for e in exps.values())
        value = None
        if ok and set(exps) <= {v}:
            value = _power_integral(int(exps.get(v, 0)), lo, hi)
        elif ok and set(exps) <= {sp.cos(v), sp.sin(v)}:
            value = _trig_integral(int(exps.get(sp.cos(v), 0)), int(exps.get(sp.sin(v), 0)), lo, hi)
        elif _whole_harmonic(inner, v) and lo == 0 and hi == 2 * sp.pi:
            value = sp.S.Zero
        total += outer * (value if value is not None else sp.integrate(inner, (v, lo, hi)))
    return total


def _cyl(radius, height_from, height_to):
    return dict(position=(_r * sp.cos(_phi), _r * sp.sin(_phi), _z), jacobian=_r,
                limits=((_r, 0, radius), (_phi, 0, 2 * sp.pi), (_z, height_from, height_to)))


SOLIDS = {
    # Solid cylinder of radius R and height H, centred on the origin.
    "cylinder": Solid("cylinder", parameters=(M, R, H), **_cyl(R, -H / 2, H / 2)),
    # Solid sphere of radius R: spherical coordinates, volume element r² sin θ.
    "sphere": Solid(
        "sphere", parameters=(M, R),
        position=(_r * sp.sin(_theta) * sp.cos(_phi), _r * sp.sin(_theta) * sp.sin(_phi), _r * sp.cos(_theta)),
        jacobian=_r**2 * sp.sin(_theta),
        # φ innermost: the trigonometric integrals in φ vanish first, so the later ones are simpler.
        limits=((_phi, 0, 2 * sp.pi), (_r, 0, R), (_theta, 0, sp.pi)),
    ),
    # Solid cone, apex at the origin, axis +z, height H, base radius R: radius r ≤ R z / H.
    "cone": Solid(
        "cone", parameters=(M, R, H),
        position=(_r * sp.cos(_phi), _r * sp.sin(_phi), _z), jacobian=_r,
        limits=((_r, 0, R * _z / H), (_phi, 0, 2 * sp.pi), (_z, 0, H)),
    ),
    # Rectangular box with edges a, b, c along axes 1, 2, 3, centred on the origin.
    "box": Solid(
        "box", parameters=(M, a, b, c), position=(_x, _y, _z), jacobian=sp.S.One,
        limits=((_x, -a / 2, a / 2), (_y, -b / 2, b / 2), (_z, -c / 2, c / 2)),
    ),
}


def thin_disk() -> sp.Matrix:
    """A thin disk of radius R: the cylinder's tensor in the limit H → 0."""
    return SOLIDS["cylinder"].about_centre_of_mass.applyfunc(lambda e: sp.limit(e, H, 0))


def principal_axes(I) -> tuple[np.ndarray, np.ndarray]:
    """Principal moments (ascending) and axes (columns, right-handed) of a numeric tensor."""
    I = np.asarray(I, dtype=float)
    if not np.allclose(I, I.T, rtol=1e-12, atol=1e-15 * np.abs(I).max()):
        raise ValueError("inertia tensor is not symmetric")
    moments, axes = np.linalg.eigh(I)
    if np.linalg.det(axes) < 0:
        axes[:, 2] = -axes[:, 2]
    return moments, axes
