"""Models: a state, parameters, a right-hand side ẏ = f(t, y; p), and the maps in and out, derived.

Each formulation (see `derive.symbolic.formulations` for the registry) is built here from the derivation
core (`rotations`, `lagrangian`, `stability`) and the effects it is given (`effects`):

* ``euler``         y = ω̃ (body axes), Euler's equations I ω̃̇ = (I ω̃) × ω̃ (torque-free).
* ``euler-angles``  y = (α, β, γ, α̇, β̇, γ̇), z-y-z angles, q̈ = 𝕄⁻¹(F + Q) from the Lagrangian;
                    singular where det 𝕄 ∝ sin²β vanishes.
* ``reduced``       y = (α, β, γ, β̇) with the conserved p_α, p_γ as parameters (symmetric body,
                    axisymmetric conservative effects): β̈ = −V_eff′(β)/I₁, α̇ and γ̇ from the
                    momenta, written so that no term cancels near β = 0 or π
                    (`half_angle_partial_fractions`).
* ``reduced-u``     y = (α, u, γ, u̇), u = cos β, with the conserved p_α, p_γ, E′ as parameters:
                    ü = f′(u)/2 from the Routh polynomial u̇² = f(u), α̇ and γ̇ as quadratures
                    in partial fractions in u; the axis cannot pass a pole (`reduced_u`).
* ``quaternion``    y = (q₀, q₁, q₂, q₃, ω̃₁, ω̃₂, ω̃₃), q̇ = ½ q ⊗ (0, ω̃), I ω̃̇ = (I ω̃) × ω̃ + τ̃:
                    no coordinate singularity. R(q) is divided by |q|², so the equations are
                    invariant under q → s q and a drifting norm does not bias the physics.
* ``euler-poisson`` y = (ω̃, n, e): the body angular velocity, the upward vertical n = Rᵀẑ and
                    the inertial x̂ as e = Rᵀx̂, all in body axes; with L = I ω̃ about the pivot,
                    L̇ = L × ω̃ + τ̃,  ṅ = n × ω̃,  ė = e × ω̃  (a vector fixed in space, seen from
                    the body). Gravity's torque is M g n × r_c. R has the rows e, n × e, n.
                    ω̃ rather than L is the state so that atol means the same as in the other
                    formulations (L = I ω̃ scales with the moments).

Besides the right-hand side every model carries

* ``init``: y (and the parameters the formulation derives, e.g. the reduced top's p_α, p_γ) from
  the scene's inputs ``INPUTS`` = (α, β, γ, ω̃₁, ω̃₂, ω̃₃, α̇, β̇, γ̇, rates_given): where the
  scene gave the rates (rates_given > 0) every model starts from them (ω̃ converted from them,
  `_omega_in`; ``build`` refuses an init map that does not read them), else from ω̃ (the rates
  derived from it where the formulation needs them);
* ``outputs``: the output file's arrays from y: α, β, γ (z-y-z; the C driver maps them to
  canonical ranges), ω̃, the axis R ê₃, energy T + V, p_α = ẑ·(R I ω̃) = L·n (= ∂L/∂α̇),
  p_γ = I₃ ω̃₃ (= ∂L/∂γ̇), n = Rᵀẑ and L = I ω̃.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field

import sympy as sp

from derive.symbolic import effect_sums as sums
from derive.symbolic import effects as fx
from derive.symbolic.formulations import POLE_CLEARANCE, REGISTRY as FORMULATIONS, SPECIAL_NAMES, model_name
from derive.symbolic.lagrangian import I1, I2, I3, EulerLagrange, Reduction, kinetic_energy, p_alpha, p_gamma
from derive.symbolic.rotations import ANGLES, RATES, ZYZ, alpha, beta, beta_d, gamma, trig_reduce, zyz_angles
from derive.symbolic.stability import euler_rhs

#: The inputs of every model's init map, in order (`formulations.INPUT_NAMES` spells them).
INPUTS = sp.symbols("in_alpha in_beta in_gamma in_omega1 in_omega2 in_omega3 "
                    "in_alpha_dot in_beta_dot in_gamma_dot in_rates_given", real=True)
_A, _B, _G, _W1, _W2, _W3, _AD, _BD, _GD, _GIVEN = INPUTS


@dataclass(frozen=True)
class Model:
    """A derived model, ready for code generation.

    ``domain`` lists expressions that must be positive for the state to be inside the model's
    domain (the generated rhs returns 1 otherwise). ``init`` gives y from ``INPUTS`` and p;
    ``init_params`` gives (index, expression) for parameters the formulation derives from the
    inputs (computed in order, each may use the ones before). ``outputs`` maps an output name to
    an expression or a tuple of three. ``checks`` are quantities of (y, p) that ``auto`` reads
    (the reduced top's Routh polynomial at the pole clearances).
    """

    name: str
    formulation: str
    description: str
    states: tuple
    params: tuple
    rhs: tuple
    outputs: dict = field(default_factory=dict)
    init: tuple = ()
    init_params: tuple = ()
    checks: dict = field(default_factory=dict)
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

    @property
    def observables(self) -> dict:
        """The outputs (named as the generated ``<name>_observables_at``)."""
        return self.outputs

    @functools.cached_property
    def jacobian(self) -> sp.Matrix:
        """∂f/∂y, row-major."""
        return sp.Matrix(self.rhs).jacobian(sp.Matrix(self.states))


_NAMES = {"alpha_d": "alpha_dot", "beta_d": "beta_dot", "gamma_d": "gamma_dot"}


def _name(s) -> str:
    return _NAMES.get(str(s), str(s))


def _moments(symmetric: bool):
    return (I1, I1, I3) if symmetric else (I1, I2, I3)


def _moment_params(symmetric: bool):
    return (I1, I3) if symmetric else (I1, I2, I3)


def _outputs(R: sp.Matrix, w: sp.Matrix, moments, effects, sym, angles) -> dict:
    """The output map from R (body → inertial), ω̃ and the z-y-z angles."""
    Iw = sp.Matrix([m * wi for m, wi in zip(moments, w)])
    V = sums.potential(effects, R, sym)
    return {
        "alpha": angles[0], "beta": angles[1], "gamma": angles[2],
        "omega": tuple(w),
        "axis": tuple(R[:, 2]),
        "energy": sp.Rational(1, 2) * (w.T * Iw)[0, 0] + V,
        "p_alpha": (R[2, :] * Iw)[0, 0],
        "p_gamma": Iw[2],
        "n": tuple(R[2, :]),
        "L": tuple(Iw),
    }


def _given(value, otherwise):
    """The scene's value where it gave rates, else the expression derived from ω̃."""
    return sp.Piecewise((value, _GIVEN > 0), (otherwise, True))


def _omega_in() -> tuple:
    """ω̃ from the inputs: the Euler rates converted where the scene gave them (rates_given > 0),
    else the given ω̃. The conversion is the derivation's own ω̃ = B(q) q̇ (`rotations.ZYZ`,
    the notes' sum, checked against Rᵀ Ṙ): ω̃₁ = −α̇ sin β cos γ + β̇ sin γ,
    ω̃₂ = α̇ sin β sin γ + β̇ cos γ, ω̃₃ = α̇ cos β + γ̇. Every formulation whose state holds ω̃
    (or momenta made from it) starts from this, so no init map drops the rates it is given."""
    at_inputs = dict(zip(ANGLES + RATES, (_A, _B, _G, _AD, _BD, _GD)))
    from_rates = ZYZ.omega_body_sum().subs(at_inputs, simultaneous=True)
    return tuple(_given(wr, w) for wr, w in zip(from_rates, (_W1, _W2, _W3)))


def _uses_given_rates(model) -> bool:
    """True when the model's init map reads every Euler rate input (each appears in y or in
    the derived parameters): the check `build` makes so that no formulation can ignore them."""
    exprs = [sp.sympify(e) for e in model.init] + [sp.sympify(e) for _, e in model.init_params]
    used = set().union(*(e.free_symbols for e in exprs)) if exprs else set()
    return {_AD, _BD, _GD} <= used


def _rates_from_omega():
    """(α̇, β̇, γ̇) from the inputs: given, or α̇ = (−ω̃₁ cos γ + ω̃₂ sin γ)/sin β,
    β̇ = ω̃₁ sin γ + ω̃₂ cos γ, γ̇ = ω̃₃ − α̇ cos β (singular at sin β = 0)."""
    ad = (-_W1 * sp.cos(_G) + _W2 * sp.sin(_G)) / sp.sin(_B)
    return (_given(_AD, ad), _given(_BD, _W1 * sp.sin(_G) + _W2 * sp.cos(_G)),
            _given(_GD, _W3 - ad * sp.cos(_B)))


def euler_free(symmetric: bool = False) -> Model:
    """Euler's equations without torque: I ω̃̇ = (I ω̃) × ω̃."""
    w = sp.Matrix(sp.symbols("omega1:4", real=True))
    moments = _moments(symmetric)
    outputs = {"energy": sp.Rational(1, 2) * sum(m * wi**2 for m, wi in zip(moments, w)),
               # |L|², named as the integral it is (an "L2" would read as the component L₂,
               # which the other models' observables call L2)
               "L_squared": sum((m * wi) ** 2 for m, wi in zip(moments, w)), "omega": tuple(w)}
    return Model("euler_free", "euler", "torque-free Euler equations in principal body axes",
                 tuple(w), _moment_params(symmetric), tuple(euler_rhs(moments, w)), outputs,
                 init=_omega_in())


def euler_angles(symmetric: bool, effects=()) -> Model:
    """The z-y-z Euler-angle Lagrangian model, L = T − ΣV, Q from the non-conservative torques."""
    effects = tuple(effects)
    sym = sums.Symbols(effects)
    moments = _moments(symmetric)
    R = ZYZ.matrix()
    w = ZYZ.omega_body_sum()
    V = sums.potential(effects, R, sym)
    system = EulerLagrange(trig_reduce(kinetic_energy(moments)) - trig_reduce(V))
    tau = sum((e.torque(w, R, sym) for e in effects if e.torque), sp.zeros(3, 1))
    # Generalised forces from torques by virtual power: Q_j = τ̃ · ∂ω̃/∂q̇_j.
    Q = (ZYZ.rate_matrix().T * tau).applyfunc(trig_reduce)
    Mm, F = system.mass_matrix, system.forcing + Q
    det = system.determinant
    acc = (Mm.adjugate() * F).applyfunc(lambda e: trig_reduce(e) / det)
    if symmetric:
        acc = acc.applyfunc(lambda e: sp.factor_terms(sp.cancel(e)))
    outputs = _outputs(R, w, moments, effects, sym, ANGLES)
    checks = {}
    if symmetric and all(e.conservative and e.axisymmetric for e in effects):
        pa, pg = outputs["p_alpha"], outputs["p_gamma"]
        checks = routh_checks(effects, sym, outputs["energy"] - pg**2 / (2 * I3), pa, pg)
    return Model(model_name("euler-angles", symmetric, [e.name for e in effects]), "euler-angles",
                 "z-y-z Euler angles (quantum-mechanics convention), Euler-Lagrange equations solved for the accelerations",
                 ANGLES + RATES, _moment_params(symmetric) + sym.params(),
                 tuple(RATES) + tuple(acc), outputs,
                 init=(_A, _B, _G) + _rates_from_omega(), checks=checks,
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


@functools.lru_cache(maxsize=None)
def _routh(effects: tuple):
    """(the effects' symbols, R, V, the Routh :class:`Reduction` of the symmetric top under
    ``effects``): one derivation per set of effects, shared by the β and the u = cos β models."""
    sym = sums.Symbols(effects)
    R = ZYZ.matrix()
    V = sums.potential(effects, R, sym)
    return sym, R, V, Reduction(EulerLagrange(trig_reduce(kinetic_energy(_moments(True))) - trig_reduce(V)))


def reduced(effects=()) -> Model:
    """The symmetric top reduced to β, with α and γ carried along (axisymmetric conservative
    effects only)."""
    effects = tuple(effects)
    if any(not (e.conservative and e.axisymmetric) for e in effects):
        raise ValueError("the reduced formulation needs conserved p_alpha, p_gamma: "
                         "axisymmetric conservative effects only")
    return _reduced(effects)


@functools.lru_cache(maxsize=None)
def _reduced(effects: tuple) -> Model:
    """:func:`reduced`, built once per set of effects (the u = cos β model reads it too)."""
    sym, R, V, red = _routh(effects)
    rates = red.rates_from_momenta
    ad = half_angle_partial_fractions(rates[RATES[0]])
    gd = p_gamma / I3 - ad * sp.cos(beta)
    Veff = half_angle_partial_fractions(red.effective_potential)
    bdd = -sp.diff(Veff, beta) / I1
    w = ZYZ.omega_body_sum().subs({RATES[0]: ad, RATES[2]: gd}, simultaneous=True)
    out = _outputs(R, w, _moments(True), effects, sym, ANGLES)
    out["energy"] = sp.Rational(1, 2) * I1 * beta_d**2 + p_gamma**2 / (2 * I3) + Veff
    out["p_alpha"], out["p_gamma"] = p_alpha, p_gamma
    params = (I1, I3) + sym.params() + (p_alpha, p_gamma)
    # p_γ = I₃ω̃₃; p_α = p_γ + (p_α − p_γ), the difference formed without cancellation:
    # ẑ·(R I ω̃) − I₃ω̃₃ = −sinβ cosγ I₁ω̃₁ + sinβ sinγ I₁ω̃₂ − 2 sin²(β/2) p_γ.
    # With the Euler rates given the same difference is I₁ α̇ sin²β − 2 sin²(β/2) p_γ (the β̇
    # terms of ω̃₁, ω̃₂ cancel exactly, so they are left out rather than cancelled in rounding).
    diff = _given(I1 * _AD * sp.sin(_B) ** 2,
                  -sp.sin(_B) * sp.cos(_G) * I1 * _W1 + sp.sin(_B) * sp.sin(_G) * I1 * _W2) \
        - 2 * sp.sin(_B / 2) ** 2 * p_gamma
    init_params = ((params.index(p_gamma), I3 * _omega_in()[2]),
                   (params.index(p_alpha), p_gamma + diff))
    E_prime = sp.Rational(1, 2) * I1 * beta_d**2 + Veff
    checks = routh_checks(effects, sym, E_prime, p_alpha, p_gamma, red.effective_potential)
    return Model(model_name("reduced", True, [e.name for e in effects]), "reduced",
                 "symmetric top reduced to beta (Routh): conserved p_alpha, p_gamma as parameters, "
                 "half-angle partial fractions so nothing cancels near beta = 0 or pi",
                 (alpha, beta, gamma, beta_d), params, (ad, beta_d, gd, bdd), out,
                 init=(_A, _B, _G, _given(_BD, _W1 * sp.sin(_G) + _W2 * sp.cos(_G))),
                 init_params=init_params, checks=checks,
                 effects=tuple(e.name for e in effects), symmetric=True)


#: The reduced-u model's coordinate u = cos β and its rate u̇ (states), and the conserved
#: E′ = E − p_γ²/(2I₃) (a parameter derived by the init map).
u, u_d = sp.symbols("u u_d", real=True)
E_prime = sp.Symbol("E_prime", real=True)


def _cos_beta_form(expr):
    """A function of β that is rational in cos β (after sin²β → 1 − cos²β, and the half-angle
    powers sin²(β/2) = (1 − u)/2, cos²(β/2) = (1 + u)/2) written in u = cos β."""
    e = expr.subs({sp.sin(beta / 2): sp.sqrt((1 - u) / 2), sp.cos(beta / 2): sp.sqrt((1 + u) / 2)})
    e = trig_reduce(e).subs(sp.sin(beta) ** 2, 1 - sp.cos(beta) ** 2).subs(sp.cos(beta), u)
    if e.has(beta):
        raise ValueError(f"{expr} is not a function of cos(beta)")
    # Each term (or guarded branch) factored: (p_α − p_γ)/(2 I₁ (1 − u)), not a nest of halves.
    return e.replace(lambda x: isinstance(x, sp.Piecewise),
                     lambda x: sp.Piecewise(*((sp.factor(v), c) for v, c in x.args)))


def reduced_u(effects=()) -> Model:
    """The symmetric top reduced to u = cos β, integrated as a second-order polynomial equation,
    with α and γ as quadratures (axisymmetric conservative effects only).

    From the Routh reduction (`lagrangian.Reduction`), E′ = ½ I₁ β̇² + V_eff(β) is conserved, and
    with u = cos β (u̇ = −sin β β̇, β̇² = u̇²/(1 − u²))

        u̇² = f(u) = (2/I₁)(1 − u²)(E′ − V_eff(u)),

    a polynomial (the cubic of the notes for gravity: V_eff's centrifugal term
    (p_α − p_γ u)²/(2 I₁ (1 − u²)) loses its denominator). Differentiating, 2 u̇ ü = f′(u) u̇, so

        ü = f′(u)/2,

    regular everywhere (Horner form in u). α̇ = (p_α − p_γ u)/(I₁ (1 − u²)) in partial fractions,
    (p_α − p_γ)/(2 I₁ (1 − u)) + (p_α + p_γ)/(2 I₁ (1 + u)) with guarded zero numerators
    (`half_angle_partial_fractions`), and γ̇ = p_γ/I₃ − u α̇. States (α, u, γ, u̇), in the order of
    the reduced model's (α, β, γ, β̇); parameters (I₁, I₃, the effects', p_α, p_γ, E′), the last
    three derived by the init map: p_γ = I₃ ω̃₃, p_α = p_γ + (p_α − p_γ) as in `reduced`, and
    E′ = T + V − p_γ²/(2I₃) = ½ I₁ (ω̃₁² + ω̃₂²) + V (the spin term cancels symbolically, so
    nothing cancels in rounding). β = acos(u) ∈ (0, π) for the outputs: the
    axis cannot pass through a pole in this form (u = ±1 is a turning point of u while the axis
    goes through; α would have to jump by π), so every run carries the pole check (mode 1).
    """
    effects = tuple(effects)
    if any(not (e.conservative and e.axisymmetric) for e in effects):
        raise ValueError("the reduced-u formulation needs conserved p_alpha, p_gamma: "
                         "axisymmetric conservative effects only")
    base = reduced(effects)  # the β model: its init map for p_α, p_γ and its Routh derivation
    sym, R, V, red = _routh(effects)
    Veff = red.effective_potential
    f = sp.cancel((1 - u**2) * (2 / I1) * (E_prime - _cos_beta_form(Veff)))
    if not f.is_polynomial(u):
        raise ValueError(f"the Routh function f(u) = {f} is not a polynomial in u")
    coeffs = sp.Poly(sp.diff(f, u) / 2, u).all_coeffs()
    udd = sp.S.Zero
    for c in coeffs:  # Horner: one multiplication by u per degree
        udd = udd * u + sp.factor(c)
    ad = _cos_beta_form(half_angle_partial_fractions(red.rates_from_momenta[RATES[0]]))
    gd = p_gamma / I3 - u * ad
    sb = sp.sqrt((1 - u) * (1 + u))  # sin β ≥ 0, no cancellation in 1 − u²
    at_u = {sp.sin(beta): sb, sp.cos(beta): u}
    bd = -u_d / sb
    Ru = R.subs(at_u)
    w = ZYZ.omega_body_sum().subs({RATES[0]: ad, RATES[1]: bd, RATES[2]: gd},
                                  simultaneous=True).subs(at_u)
    # β = acos(u): of u alone, as accurate as atan2(sb, u) or more (glibc, the u of the pole
    # clearance |u| <= √0.99 against mpmath: within 0.51 ulp vs 1.43 for the atan2 of the
    # rounded sb) and cheaper (one libm call where atan2 needs the root of 1 - u² first).
    out = _outputs(Ru, w, _moments(True), effects, sym, (alpha, sp.acos(u), gamma))
    # From the state (u, u̇), so that it shows the integration's drift: E = ½ I₁ β̇² + p_γ²/(2I₃)
    # + V_eff, V_eff in partial fractions (the centrifugal term without cancellation).
    Veff_u = _cos_beta_form(half_angle_partial_fractions(Veff))
    out["energy"] = sp.Rational(1, 2) * I1 * u_d**2 / (sb**2) + p_gamma**2 / (2 * I3) + Veff_u
    out["p_alpha"], out["p_gamma"] = p_alpha, p_gamma
    params = base.params + (E_prime,)
    # E′ = T + V − p_γ²/(2I₃) with p_γ = I₃ ω̃₃, simplified symbolically (the spin term cancels),
    # then at the inputs' ω̃ (`_omega_in`: converted from the rates where the scene gave them).
    wsym = sp.Matrix(sp.symbols("omega1:4", real=True))
    moments = _moments(True)
    T = sp.Rational(1, 2) * sum(m * wi**2 for m, wi in zip(moments, wsym))
    Ep_w = sp.expand(T - (I3 * wsym[2]) ** 2 / (2 * I3))
    if Ep_w.has(wsym[2]):
        raise ValueError("E' depends on the spin: p_gamma is not the momentum of gamma")
    Ep_in = Ep_w.subs(dict(zip(wsym, _omega_in())), simultaneous=True) \
        + sums.potential(effects, ZYZ.matrix(_A, _B, _G), sym)
    init_params = base.init_params + ((params.index(E_prime), Ep_in),)
    bd_in = base.init[3]  # β̇ at the start, given or from ω̃
    ud_in = sp.diff(sp.cos(beta), beta).subs(beta, _B) * bd_in  # u̇ = −sin β β̇
    checks = routh_checks(effects, sym, E_prime, p_alpha, p_gamma, Veff,
                          clearance=FORMULATIONS["reduced-u"].clearance)
    checks["cos_beta"] = u
    return Model(model_name("reduced-u", True, [e.name for e in effects]), "reduced-u",
                 "symmetric top reduced to u = cos(beta) (Routh): u'' = f'(u)/2 from the Routh "
                 "polynomial, conserved p_alpha, p_gamma, E' as parameters, alpha and gamma as "
                 "quadratures in partial fractions",
                 (alpha, u, gamma, u_d), params, (ad, u_d, gd, udd), out,
                 init=(_A, sp.cos(_B), _G, ud_in), init_params=init_params, checks=checks,
                 effects=tuple(e.name for e in effects), symmetric=True)


def routh_checks(effects, sym, E_prime, pa, pg, Veff=None, clearance=None) -> dict:
    """Where the β motion can go, from the Routh reduction: with u = cos β,

        u̇² = f(u) = (1 − u²)(2/I₁)(E′ − V(u)) − ((p_α − p_γ u)/I₁)²,   E′ = ½ I₁ β̇² + V_eff(β),

    and u moves between the roots of f around u₀ = cos β₀ (f(u₀) ≥ 0, f(±1) ≤ 0). So the motion
    keeps |sin β| ≥ s (s = ``clearance``, by default ``formulations.POLE_CLEARANCE``; the
    formulation's own, ``Formulation.clearance``, which the C ``pole_clear`` is rendered with)
    exactly when |u₀| < u_c and
    f(u_c) < 0 and f(−u_c) < 0, u_c = √(1 − s²): f changes sign once between u₀ and each pole.
    ``E_prime``, ``pa``, ``pg`` are the formulation's expressions of E′, p_α, p_γ (parameters
    in the reduced model, functions of the state in the Euler-angle one). Returns f_top = f(u_c),
    f_bottom = f(−u_c), cos_beta = u₀ and p_α ∓ p_γ; (p_α − p_γ u) stays a square so that
    nothing cancels when p_α ≈ p_γ.
    """
    u = sp.Symbol("u", real=True)
    V = sums.potential(effects, ZYZ.matrix(), sym)
    V_u = trig_reduce(V).subs(sp.cos(beta), u)
    if V_u.has(beta):
        raise ValueError("a Routh check needs a potential that depends on cos(beta) alone")
    if Veff is not None:
        # The derivation's V_eff must be the centrifugal term plus V (checked, not assumed).
        centrifugal = (p_alpha - p_gamma * sp.cos(beta)) ** 2 / (2 * I1 * sp.sin(beta) ** 2)
        if sp.simplify(trig_reduce(sp.together(Veff - centrifugal - V))) != 0:
            raise ValueError("V_eff is not the centrifugal term plus V")
    s = sp.Rational(1, 1) / sp.Integer(round(1 / (clearance or POLE_CLEARANCE)))
    uc = sp.sqrt(1 - s**2)

    def f(at):
        return (1 - at**2) * (2 / I1) * (E_prime - V_u.subs(u, at)) - ((pa - pg * at) / I1) ** 2

    return {"f_top": f(uc), "f_bottom": f(-uc), "cos_beta": sp.cos(beta),
            "p_alpha_minus_p_gamma": pa - pg, "p_alpha_plus_p_gamma": pa + pg}


def quaternion_of_angles(a, b, c):
    """q of R = Rz(α) Ry(β) Rz(γ), scalar first: the product of the three half-angle quaternions
    (cos(α/2), 0, 0, sin(α/2)) ⊗ (cos(β/2), 0, sin(β/2), 0) ⊗ (cos(γ/2), 0, 0, sin(γ/2))."""
    def mul(p, q):
        p0, pv, q0, qv = p[0], sp.Matrix(p[1:]), q[0], sp.Matrix(q[1:])
        return [p0 * q0 - (pv.T * qv)[0, 0]] + list(p0 * qv + q0 * pv + pv.cross(qv))

    qa = [sp.cos(a / 2), 0, 0, sp.sin(a / 2)]
    qb = [sp.cos(b / 2), 0, sp.sin(b / 2), 0]
    qc = [sp.cos(c / 2), 0, 0, sp.sin(c / 2)]
    return tuple(sp.expand(x) for x in mul(mul(qa, qb), qc))


def quaternion(symmetric: bool, effects=()) -> Model:
    """Unit quaternion + body angular velocity (Newton–Euler): singularity-free."""
    effects = tuple(effects)
    sym = sums.Symbols(effects)
    q = sp.Matrix(sp.symbols("q0:4", real=True))
    w = sp.Matrix(sp.symbols("omega1:4", real=True))
    moments = _moments(symmetric)
    q0, q1, q2, q3 = q
    n2 = q0**2 + q1**2 + q2**2 + q3**2
    Rn = sp.Matrix([
        [q0**2 + q1**2 - q2**2 - q3**2, 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
        [2 * (q1 * q2 + q0 * q3), q0**2 - q1**2 + q2**2 - q3**2, 2 * (q2 * q3 - q0 * q1)],
        [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), q0**2 - q1**2 - q2**2 + q3**2],
    ])
    R = Rn / n2
    # q̇ = ½ q ⊗ (0, ω̃): the body-frame angular velocity composes on the right.
    qv = sp.Matrix([q1, q2, q3])
    qdot = [-(qv.T * w)[0, 0] / 2] + list((q0 * w + qv.cross(w)) / 2)
    tau = sums.torque(effects, w, R, sym)
    wdot = euler_rhs(moments, w) + sp.Matrix([tau[i] / moments[i] for i in range(3)])
    # β from the quaternion directly: cos β ∝ q0² − q1² − q2² + q3², sin β ∝ 2√((q0²+q3²)(q1²+q2²)),
    # both accurate near the poles.
    a2, b2 = q0**2 + q3**2, q1**2 + q2**2
    angles = (sp.atan2(Rn[1, 2], Rn[0, 2]), sp.atan2(2 * sp.sqrt(a2 * b2), a2 - b2),
              sp.atan2(Rn[2, 1], -Rn[2, 0]))
    return Model(model_name("quaternion", symmetric, [e.name for e in effects]), "quaternion",
                 "unit quaternion (scalar first, body to inertial) + body angular velocity, Newton-Euler",
                 tuple(q) + tuple(w), _moment_params(symmetric) + sym.params(),
                 tuple(qdot) + tuple(wdot), _outputs(R, w, moments, effects, sym, angles),
                 init=quaternion_of_angles(_A, _B, _G) + _omega_in(),
                 domain=(n2,), domain_note="quaternion of zero norm",
                 effects=tuple(e.name for e in effects), symmetric=symmetric)


def euler_poisson(symmetric: bool, effects=()) -> Model:
    """Euler–Poisson: the body angular velocity ω̃, the vertical n = Rᵀẑ and e = Rᵀx̂ in body axes.

    I ω̃̇ = (I ω̃) × ω̃ + τ̃  (L̇ = L × ω̃ + τ̃ with L = I ω̃),  ṅ = n × ω̃,  ė = e × ω̃;  for gravity
    τ̃ = M g n × r_c (derived here from the effect's potential M g ẑ·(R r_c) = M g n·r_c by a
    virtual rotation).
    """
    effects = tuple(effects)
    sym = sums.Symbols(effects)
    moments = _moments(symmetric)
    w = sp.Matrix(sp.symbols("omega1:4", real=True))
    n = sp.Matrix(sp.symbols("n1:4", real=True))
    e = sp.Matrix(sp.symbols("e1:4", real=True))
    R = sp.Matrix.vstack(e.T, n.cross(e).T, n.T)
    tau = sums.torque(effects, w, R, sym)
    wdot = euler_rhs(moments, w) + sp.Matrix([tau[i] / moments[i] for i in range(3)])
    rhs = tuple(wdot) + tuple(n.cross(w)) + tuple(e.cross(w))
    R0 = ZYZ.matrix(_A, _B, _G)
    init = _omega_in() + tuple(R0[2, :]) + tuple(R0[0, :])
    return Model(model_name("euler-poisson", symmetric, [e_.name for e_ in effects]), "euler-poisson",
                 "Euler-Poisson: body angular velocity omega, the vertical n and the inertial x axis e "
                 "in body axes (L = I omega about the pivot)",
                 tuple(w) + tuple(n) + tuple(e), _moment_params(symmetric) + sym.params(), rhs,
                 _outputs(R, w, moments, effects, sym, zyz_angles(R)), init=init,
                 effects=tuple(e_.name for e_ in effects), symmetric=symmetric)


BUILDERS = {
    "euler-angles": euler_angles,
    "reduced": lambda symmetric, effects: reduced(effects),
    "reduced-u": lambda symmetric, effects: reduced_u(effects),
    "quaternion": quaternion,
    "euler-poisson": euler_poisson,
}


def build(formulation: str, symmetric: bool, effect_names=()) -> Model:
    """The model for a formulation, body symmetry and set of effects (names from `effects`)."""
    effs = fx.lookup(effect_names)
    if formulation == "euler":
        if effs:
            raise ValueError("the 'euler' formulation is torque-free")
        model = euler_free(symmetric)
    elif formulation in ("reduced", "reduced-u") and not symmetric:
        raise ValueError(f"the {formulation} formulation needs a symmetric body (I1 = I2)")
    elif formulation not in BUILDERS:
        raise ValueError(f"unknown formulation {formulation!r}")
    else:
        model = BUILDERS[formulation](symmetric, effs)
    _check_init(model)
    return model


def _check_init(model: Model) -> None:
    """Refuse a model whose init map would drop the Euler rates a scene (or a C caller) gives
    with rates_given = 1: the generated ``<name>_init`` must start from them."""
    if not _uses_given_rates(model):
        raise ValueError(f"the init map of {model.name} ignores the Euler rates given with "
                         f"rates_given = 1; build ω̃ with models._omega_in()")


#: The models committed to generated/ (the contract names euler_free and heavy_top), by name:
#: (formulation, symmetric body, effects).
CATALOGUE_KEYS = {name: key for key, name in SPECIAL_NAMES.items()}
CATALOGUE = {name: (lambda key=key: build(*key)) for name, key in CATALOGUE_KEYS.items()}
