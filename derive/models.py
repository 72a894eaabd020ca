"""Models: a state, parameters, a right-hand side ẏ = f(t, y; p) and observables, derived.

Four formulations of the rigid body with a fixed point, each built from the derivation core
(`rotations`, `lagrangian`, `stability`) and the effects it is given (`effects`):

* ``euler``        y = ω̃ (body axes), Euler's equations I ω̃̇ = (I ω̃) × ω̃ + τ̃.
* ``euler-angles`` y = (α, β, γ, α̇, β̇, γ̇), z-y-z angles, q̈ = 𝕄⁻¹(F + Q) from the Lagrangian;
                   singular where det 𝕄 ∝ sin²β vanishes.
* ``reduced``      y = (α, β, γ, β̇) with the conserved p_α, p_γ as parameters (symmetric body,
                   conservative effects only): β̈ = −V_eff′(β)/I₁, α̇ and γ̇ from the momenta,
                   written so that no term cancels near β = 0 or π (`half_angle_partial_fractions`).
* ``quaternion``   y = (q₀, q₁, q₂, q₃, ω̃₁, ω̃₂, ω̃₃), q̇ = ½ q ⊗ (0, ω̃), I ω̃̇ = (I ω̃) × ω̃ + τ̃:
                   no coordinate singularity. R(q) is divided by |q|², so the equations are
                   invariant under q → s q and a drifting norm does not bias the physics.

Observables shared by all: ``energy`` T + V; ``p_alpha`` = ẑ·(R I ω̃), the vertical component of
angular momentum about the pivot (= ∂L/∂α̇); ``p_gamma`` = I₃ ω̃₃ (= ∂L/∂γ̇); ``axis`` = R ê₃;
``omega`` = ω̃.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field

import sympy as sp

from . import effects as fx
from .lagrangian import I1, I2, I3, EulerLagrange, Reduction, kinetic_energy, p_alpha, p_gamma
from .rotations import ANGLES, RATES, ZYZ, alpha, beta, beta_d, gamma, trig_reduce
from .stability import euler_rhs


@dataclass(frozen=True)
class Model:
    """A derived model, ready for code generation.

    ``domain`` lists expressions that must be non-zero-and-positive for the state to be inside
    the model's domain (the generated rhs returns 1 otherwise).
    """

    name: str
    formulation: str
    description: str
    states: tuple
    params: tuple
    rhs: tuple
    observables: dict = field(default_factory=dict)
    domain: tuple = ()
    domain_note: str = ""
    effects: tuple = ()
    symmetric: bool = False

    @property
    def state_names(self) -> tuple[str, ...]:
        return tuple(_name(s) for s in self.states)

    @property
    def param_names(self) -> tuple[str, ...]:
        return tuple(_name(s) for s in self.params)

    @functools.cached_property
    def jacobian(self) -> sp.Matrix:
        """∂f/∂y, row-major."""
        return sp.Matrix(self.rhs).jacobian(sp.Matrix(self.states))


_NAMES = {"alpha_d": "alpha_dot", "beta_d": "beta_dot", "gamma_d": "gamma_dot", "c": "c"}


def _name(s) -> str:
    return _NAMES.get(str(s), str(s))


def _moments(symmetric: bool):
    return (I1, I1, I3) if symmetric else (I1, I2, I3)


def _moment_params(symmetric: bool):
    return (I1, I3) if symmetric else (I1, I2, I3)


def _effect_params(effects):
    return tuple(p for e in effects for p in e.params)


def _observables(R: sp.Matrix, w: sp.Matrix, moments, effects) -> dict:
    Iw = sp.Matrix([m * wi for m, wi in zip(moments, w)])
    V = sum((e.potential(R) for e in effects if e.potential), sp.S.Zero)
    return {
        "energy": sp.Rational(1, 2) * (w.T * Iw)[0, 0] + V,
        "p_alpha": (R[2, :] * Iw)[0, 0],
        "p_gamma": Iw[2],
        "axis": tuple(R[:, 2]),
        "omega": tuple(w),
    }


def _torque(effects, omega, R) -> sp.Matrix:
    tau = sp.zeros(3, 1)
    for e in effects:
        if e.torque:
            tau += e.torque(omega, R)
        if e.potential:
            tau += fx.torque_from_potential(e.potential, R)
    return tau


def euler_free(symmetric: bool = False) -> Model:
    """Euler's equations without torque: I ω̃̇ = (I ω̃) × ω̃."""
    w = sp.Matrix(sp.symbols("omega1:4", real=True))
    moments = _moments(symmetric)
    obs = {"energy": sp.Rational(1, 2) * sum(m * wi**2 for m, wi in zip(moments, w)),
           "L2": sum((m * wi) ** 2 for m, wi in zip(moments, w)), "omega": tuple(w)}
    return Model("euler_free", "euler", "torque-free Euler equations in principal body axes",
                 tuple(w), _moment_params(symmetric), tuple(euler_rhs(moments, w)), obs)


def euler_angles(symmetric: bool, effects=()) -> Model:
    """The z-y-z Euler-angle Lagrangian model, L = T − ΣV, Q from the non-conservative torques."""
    effects = tuple(effects)
    moments = _moments(symmetric)
    R = ZYZ.matrix()
    w = ZYZ.omega_body_sum()
    V = sum((e.potential(R) for e in effects if e.potential), sp.S.Zero)
    system = EulerLagrange(trig_reduce(kinetic_energy(moments)) - trig_reduce(V))
    tau = sum((e.torque(w, R) for e in effects if e.torque), sp.zeros(3, 1))
    # Generalised forces from torques by virtual power: Q_j = τ̃ · ∂ω̃/∂q̇_j.
    Q = (ZYZ.rate_matrix().T * tau).applyfunc(trig_reduce)
    Mm, F = system.mass_matrix, system.forcing + Q
    det = system.determinant
    acc = (Mm.adjugate() * F).applyfunc(lambda e: trig_reduce(e) / det)
    if symmetric:
        acc = acc.applyfunc(lambda e: sp.factor_terms(sp.cancel(e)))
    name = "heavy_top" if symmetric and [e.name for e in effects] == ["gravity"] else \
        _variant("euler_angles", symmetric, effects)
    return Model(name, "euler-angles",
                 "z-y-z Euler angles (quantum-mechanics convention), Euler-Lagrange equations solved for the accelerations",
                 ANGLES + RATES, _moment_params(symmetric) + _effect_params(effects),
                 tuple(RATES) + tuple(acc), _observables(R, w, moments, effects),
                 # det 𝕄 ∝ sin²β: below machine epsilon the solve for q̈ has no correct digits.
                 domain=(sp.sin(beta) ** 2 - sp.Symbol("DBL_EPSILON"),),
                 domain_note="coordinate singularity of the Euler-angle formulation: sin(beta)^2 below "
                             "machine epsilon, where the mass matrix is singular; use formulation = "
                             "\"quaternion\" or \"auto\"",
                 effects=tuple(e.name for e in effects), symmetric=symmetric)


def half_angle_partial_fractions(expr, x=beta, guard=True):
    """Rewrite a rational function of cos x (sin²x = 1 − cos²x) so that nothing cancels near
    x = 0 or x = π.

    Partial fractions in c = cos x separate the poles at c = 1 and c = −1, and

        1 − cos x = 2 sin²(x/2),     1 + cos x = 2 cos²(x/2)

    turn each pole into a half-angle power that is accurate near its zero. For the top,
    (p_α − p_γ cos β)/sin²β = ½ (p_α − p_γ)/(1 − cos β) + ½ (p_α + p_γ)/(1 + cos β): the
    difference p_α − p_γ is formed from the parameters first instead of the nearly equal
    p_α and p_γ cos β. A numerator coefficient that vanishes for some parameters (p_α = p_γ) is
    guarded so the removable 0·∞ at the pole never evaluates to NaN.
    """
    c = sp.Dummy("c")
    e = sp.together(expr.subs(sp.sin(x) ** 2, 1 - sp.cos(x) ** 2))
    e = sp.together(e.subs(sp.sin(x), sp.sqrt(1 - c**2)).subs(sp.cos(x), c))
    if e.has(sp.sqrt(1 - c**2)):
        raise ValueError("expression is not a rational function of cos x after sin² → 1 − cos²")
    terms = sp.Add.make_args(sp.apart(sp.factor(e), c))
    out = sp.S.Zero
    for term in terms:
        num, den = sp.fraction(sp.factor(term))
        den_poly = sp.Poly(den, c)
        coeff = sp.factor(num)
        pole = None
        for r in (1, -1):
            if den_poly.eval(r) == 0:
                pole = r
        if pole is None:
            out += term.subs(c, sp.cos(x))
            continue
        # den = k (c ∓ 1)^n  → substitute the half-angle form of (1 ∓ c).
        n = sp.degree(den_poly)
        k = sp.LC(den_poly)
        if den_poly != sp.Poly(k * (c - pole) ** n, c):
            raise ValueError(f"partial fraction {term} has a pole other than cos x = ±1")
        half = 2 * sp.sin(x / 2) ** 2 if pole == 1 else 2 * sp.cos(x / 2) ** 2
        sign = -1 if pole == 1 else 1  # c − 1 = −(1 − c), c + 1 = (1 + c)
        new = coeff / (k * (sign * half) ** n)
        if guard and coeff.free_symbols - {c}:
            new = sp.Piecewise((0, sp.Eq(coeff, 0)), (new, True))
        out += new
    return out


def reduced(effects=()) -> Model:
    """The symmetric top reduced to β, with α and γ carried along (conservative effects only)."""
    effects = tuple(effects)
    if any(not e.conservative for e in effects):
        raise ValueError("the reduced formulation needs conserved p_alpha, p_gamma: no damping")
    R = ZYZ.matrix()
    V = sum((e.potential(R) for e in effects if e.potential), sp.S.Zero)
    system = EulerLagrange(trig_reduce(kinetic_energy(_moments(True))) - trig_reduce(V))
    red = Reduction(system)
    rates = red.rates_from_momenta
    ad = half_angle_partial_fractions(rates[RATES[0]])
    gd = p_gamma / I3 - ad * sp.cos(beta)
    Veff = half_angle_partial_fractions(red.effective_potential)
    bdd = -sp.diff(Veff, beta) / I1
    w = ZYZ.omega_body_sum().subs({RATES[0]: ad, RATES[2]: gd}, simultaneous=True)
    obs = _observables(R, w, _moments(True), effects)
    obs["energy"] = sp.Rational(1, 2) * I1 * beta_d**2 + p_gamma**2 / (2 * I3) + Veff
    obs["p_alpha"], obs["p_gamma"] = p_alpha, p_gamma
    obs["alpha_dot"], obs["gamma_dot"] = ad, gd
    name = "heavy_top_reduced" if [e.name for e in effects] == ["gravity"] else _variant("reduced", True, effects)
    return Model(name, "reduced",
                 "symmetric top reduced to beta (Routh): conserved p_alpha, p_gamma as parameters, "
                 "half-angle partial fractions so nothing cancels near beta = 0 or pi",
                 (alpha, beta, gamma, beta_d), (I1, I3) + _effect_params(effects) + (p_alpha, p_gamma),
                 (ad, beta_d, gd, bdd), obs, effects=tuple(e.name for e in effects), symmetric=True)


def quaternion(symmetric: bool, effects=()) -> Model:
    """Unit quaternion + body angular velocity (Newton–Euler): singularity-free."""
    effects = tuple(effects)
    q = sp.Matrix(sp.symbols("q0:4", real=True))
    w = sp.Matrix(sp.symbols("omega1:4", real=True))
    moments = _moments(symmetric)
    q0, q1, q2, q3 = q
    n2 = q0**2 + q1**2 + q2**2 + q3**2
    R = sp.Matrix([
        [q0**2 + q1**2 - q2**2 - q3**2, 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
        [2 * (q1 * q2 + q0 * q3), q0**2 - q1**2 + q2**2 - q3**2, 2 * (q2 * q3 - q0 * q1)],
        [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), q0**2 - q1**2 - q2**2 + q3**2],
    ]) / n2
    # q̇ = ½ q ⊗ (0, ω̃): the body-frame angular velocity composes on the right.
    qv = sp.Matrix([q1, q2, q3])
    qdot = [-(qv.T * w)[0, 0] / 2] + list((q0 * w + qv.cross(w)) / 2)
    tau = _torque(effects, w, R)
    wdot = euler_rhs(moments, w) + sp.Matrix([tau[i] / moments[i] for i in range(3)])
    name = _variant("quaternion", symmetric, effects)
    if not symmetric and [e.name for e in effects] == ["gravity_general", "damping"]:
        name = "rigid_body"
    return Model(name, "quaternion",
                 "unit quaternion (scalar first, body to inertial) + body angular velocity, Newton-Euler",
                 tuple(q) + tuple(w), _moment_params(symmetric) + _effect_params(effects),
                 tuple(qdot) + tuple(wdot), _observables(R, w, moments, effects),
                 domain=(n2,), domain_note="quaternion of zero norm",
                 effects=tuple(e.name for e in effects), symmetric=symmetric)


def _variant(formulation: str, symmetric: bool, effects) -> str:
    parts = [formulation.replace("-", "_"), "sym" if symmetric else "asym"] + [e.name for e in effects]
    return "_".join(parts)


def build(formulation: str, symmetric: bool, effect_names=()) -> Model:
    """The model for a formulation, body symmetry and set of effects (names from `effects`)."""
    effs = fx.lookup(effect_names)
    if formulation == "euler":
        if effs:
            raise ValueError("the 'euler' formulation is torque-free")
        return euler_free(symmetric)
    if formulation == "euler-angles":
        return euler_angles(symmetric, effs)
    if formulation == "reduced":
        if not symmetric:
            raise ValueError("the reduced formulation needs a symmetric body (I1 = I2)")
        return reduced(effs)
    if formulation == "quaternion":
        return quaternion(symmetric, effs)
    raise ValueError(f"unknown formulation {formulation!r}")


#: The models committed to generated/ (the contract names euler_free and heavy_top).
CATALOGUE = {
    "euler_free": lambda: euler_free(False),
    "heavy_top": lambda: euler_angles(True, fx.lookup(["gravity"])),
    "heavy_top_reduced": lambda: reduced(fx.lookup(["gravity"])),
    "rigid_body": lambda: quaternion(False, fx.lookup(["gravity_general", "damping"])),
}
