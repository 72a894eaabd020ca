"""The derived side of `derive verify`: each quantity a lecture claim names as its ``target``
(`DERIVED`, name -> function), derived independently by the core (`rotations`, `inertia`,
`lagrangian`, `stability`) and cached; `SHOWN` holds how the report writes the ones whose route
it names.
"""
from __future__ import annotations

import functools

import sympy as sp

from derive.lecture import slides as sl
from derive.symbolic import inertia, lagrangian, rotations, stability


DERIVED: dict = {}
SHOWN: dict = {}
"""(text, LaTeX) shown in the table instead of a derived value that is left unreduced."""


def _derives(name, shown=None):
    def register(f):
        DERIVED[name] = f
        if shown:
            SHOWN[name] = shown
        return f
    return register


@functools.cache
def derived(name: str):
    """The derived quantity ``name`` (computed once per process)."""
    return DERIVED[name]()


def _linear(vec) -> sp.Expr:
    """A body-component column as a linear form in the basis symbols ê₁, ê₂, ê₃."""
    return sum((vec[i] * sl.BASIS[i] for i in range(3)), sp.S.Zero)


@functools.cache
def _top():
    """The heavy symmetric top, its Routh reduction and the sleeping-top series, sharing caches."""
    st = stability.sleeping_top()
    return st.reduction.system, st.reduction, st


# Rotations (z-y-z, the notes' convention). ω̃ comes from the skew route Rᵀ Ṙ, so that the slides'
# sum route α̇ ê⁰₃ + β̇ ê′₂ + γ̇ ê₃ is checked against an independent computation.
@_derives("omega-body")
def _omega_body():
    return rotations.ZYZ.omega_body_skew()


for _i in range(3):
    DERIVED[f"omega-body-{_i + 1}"] = (lambda i: lambda: derived("omega-body")[i])(_i)


@_derives("omega-body-linear")
def _omega_body_linear():
    return _linear(derived("omega-body"))


@_derives("omega-inertial")
def _omega_inertial():
    """ω in inertial components, R ω̃ (left unreduced: only compared numerically)."""
    return rotations.ZYZ.matrix() * derived("omega-body")


@_derives("velocity", shown=("Ṙ Rᵀ r", r"\dot R R^{T}\mathbf{r}"))
def _velocity():
    """ṙ = Ṙ b = Ṙ Rᵀ r for a point fixed in the body (b = Rᵀ r its body components).

    Left unreduced: reducing the 3-angle products costs a second, the numeric test milliseconds.
    """
    rot = rotations
    R = rot.ZYZ.matrix()
    return R.applyfunc(rot.time_derivative) * R.T * sp.Matrix(sl.X)


@_derives("e2prime")
def _e2prime():
    return rotations.ZYZ.intermediate_axis()


@_derives("e2prime-linear")
def _e2prime_linear():
    return _linear(derived("e2prime"))


@_derives("e30")
def _e30():
    return rotations.ZYZ.inertial_axis()


@_derives("e30-linear")
def _e30_linear():
    return _linear(derived("e30"))


@functools.cache
def frame_vectors() -> dict:
    """ê′ₖ (the frame after the α and β turns) and ê⁰₃ as linear forms in the body basis.

    The γ turn is about ê′₃, so body components of ê′ₖ are passive(z, γ) eₖ; ê⁰₃ is Rᵀ ẑ.
    """
    rot = rotations
    primed = {sym: _linear(rot.passive("z", rot.gamma) * rot.unit(axis))
              for sym, axis in zip((sl.e1p, sl.e2p, sl.e3p), "xyz")}
    return {**primed, sl.e30: derived("e30-linear")}


# Particles: T, L and I from the velocity field v = ω × r (core `skew`) and `inertia.point_masses`.
@_derives("T-particles")
def _t_particles():
    skew = rotations.skew
    total = sp.S.Zero
    for m, r in zip(sl.m_p, sl.r_p):
        vel = skew(sl.w_vec) * r
        total += sp.Rational(1, 2) * m * (vel.T * vel)[0, 0]
    return total


@_derives("L-particles")
def _l_particles():
    skew = rotations.skew
    total = sp.zeros(3, 1)
    for m, r in zip(sl.m_p, sl.r_p):
        total += m * skew(r) * (skew(sl.w_vec) * r)
    return total


@_derives("inertia-particles")
def _inertia_particles():
    return inertia.point_masses(sl.m_p, sl.r_p)


@_derives("inertia-body-frame")
def _inertia_body_frame():
    """The tensor in the principal body frame: diag(I₁, I₂, I₃), the convention of
    `lagrangian.kinetic_energy` (a definition, so the rows using it are consistency checks)."""
    lag = lagrangian
    return sp.diag(lag.I1, lag.I2, lag.I3)


@_derives("T-body")
def _t_body():
    return sp.Rational(1, 2) * (sl.w_vec.T * derived("inertia-body-frame") * sl.w_vec)[0, 0]


@_derives("L-body")
def _l_body():
    return _linear(derived("inertia-body-frame") * sl.w_vec)


@_derives("dLdt-transport", shown=("Rᵀ d(R L̃)/dt", r"R^{T}\frac{d}{dt}\left(R\tilde{\mathbf{L}}\right)"))
def _dldt_transport():
    """Body components of the inertial d/dt of L = R L̃:  Rᵀ d(R L̃)/dt, by the chain rule
    (left unreduced, like `velocity`)."""
    rot = rotations
    R = rot.ZYZ.matrix()
    coords, rates = rot.ANGLES + sl.Lb, rot.RATES + sl.Lbd
    dL = (R * sp.Matrix(sl.Lb)).applyfunc(lambda e: rot.time_derivative(e, coords, rates))
    return R.T * dL


# Euler's equations: I ω̇ − (Iω)×ω, with (Iω)×ω = I · euler_rhs.
def _euler_residual(moments=None):
    lag, stab = lagrangian, stability
    moments = moments or (lag.I1, lag.I2, lag.I3)
    rhs = stab.euler_rhs(moments, sl.w_vec)
    wd = (sl.wd1, sl.wd2, sl.wd3)
    return sp.Matrix([sp.expand(moments[i] * (wd[i] - rhs[i])) for i in range(3)])


@_derives("dLdt-body")
def _dldt_body():
    return _linear(_euler_residual())


for _i in range(3):
    DERIVED[f"euler-residual-{_i + 1}"] = (lambda i: lambda: _euler_residual()[i])(_i)


@_derives("euler-rhs-symmetric")
def _euler_rhs_symmetric():
    lag, stab = lagrangian, stability
    return stab.euler_rhs((lag.I1, lag.I1, lag.I3), sl.w_vec)[:2, :]


for _i in range(2):
    DERIVED[f"euler-rhs-symmetric-{_i + 1}"] = (lambda i: lambda: derived("euler-rhs-symmetric")[i])(_i)


def _spin(moments=None):
    lag, stab = lagrangian, stability
    return stab.SteadySpin(2, moments or (lag.I1, lag.I2, lag.I3))


@_derives("symmetric-frequencies")
def _symmetric_frequencies():
    lag, stab = lagrangian, stability
    return sp.Matrix(_spin((lag.I1, lag.I1, lag.I3)).frequencies).subs(stab.omega0, sl.w3)


@_derives("asym-Omega1")
def _asym_omega1():
    return _spin().frequencies[0].subs(stability.omega0, sl.w3)


@_derives("asym-Omega2")
def _asym_omega2():
    return _spin().frequencies[1].subs(stability.omega0, sl.w3)


@_derives("asym-omega3-dot")
def _asym_omega3_dot():
    """ω̇₃ to first order in the perturbation (δω₁, δω₂, δω₃) of spin about axis 3."""
    stab = stability
    return (_spin().jacobian * sp.Matrix(stab.delta))[2]


@_derives("asym-linear")
def _asym_linear():
    """(ω̇₁, ω̇₂) linearised about ω₃ ê₃, the small components being ω₁, ω₂ themselves."""
    stab = stability
    lin = _spin().jacobian * sp.Matrix([sl.w1, sl.w2, stab.delta[2]])
    return lin[:2, :].subs(stab.omega0, sl.w3)


@functools.cache
def _plane_matrix() -> sp.Matrix:
    """The Jacobian in the (1, 2) plane written with the core's frequencies as symbols Ω₁, Ω₂:
    `SteadySpin.frequencies` defines Ω₁ = −J₁₂, Ω₂ = J₂₁; the diagonal is taken from J."""
    J = _spin().jacobian
    Oi, Oj = _spin().frequencies
    assert sp.expand(J[0, 1] + Oi) == 0 and sp.expand(J[1, 0] - Oj) == 0
    return sp.Matrix([[J[0, 0], -sl.Omega1], [sl.Omega2, J[1, 1]]])


@_derives("asym-linear-system")
def _asym_linear_system():
    return _plane_matrix() * sp.Matrix([sl.w1, sl.w2])


@_derives("asym-lambda-squared")
def _asym_lambda_squared():
    """λ² for the eigenvalues ±λ of the plane matrix (> 0: real growth, < 0: oscillation)."""
    lam = next(iter(_plane_matrix().eigenvals()))
    return sp.expand(lam**2)


# Lagrangian mechanics of the heavy symmetric top.
@_derives("kinetic-energy")
def _kinetic_energy():
    return lagrangian.kinetic_energy()


@_derives("kinetic-energy-symmetric")
def _kinetic_energy_symmetric():
    return lagrangian.kinetic_energy_symmetric()


@_derives("heavy-top-lagrangian")
def _heavy_top_lagrangian():
    return _top()[0].lagrangian


@_derives("cyclic")
def _cyclic():
    return sp.Matrix(_top()[0].cyclic)


@_derives("p-alpha")
def _p_alpha():
    return _top()[0].momentum(rotations.alpha)


@_derives("p-gamma")
def _p_gamma():
    return _top()[0].momentum(rotations.gamma)


DERIVED.update({
    "energy-reduced": lambda: _top()[1].energy,
    "V-eff": lambda: _top()[1].effective_potential,
    "E-prime": lambda: _top()[1].reduced_energy,
    "L-substituted": lambda: _top()[1].lagrangian_substituted,
    "beta-acceleration": lambda: _top()[1].beta_acceleration,
    "E-prime-series": lambda: _top()[2].reduced_energy_series,
    "stability-condition": lambda: _top()[2].condition,
    "threshold-quartic": lambda: _top()[2].quartic_at_threshold,
})


# Assignment #20: the passive transformation V′ = Rᵀ V at α = β = 90°, γ = 0.
@_derives("assignment-20-matrix")
def _assignment_matrix():
    rot = rotations
    return rot.ZYZ.matrix(*(sl.ASSIGNMENT_ANGLES[q] for q in rot.ANGLES)).T


@_derives("assignment-20-gram")
def _assignment_gram():
    P = derived("assignment-20-matrix")
    return (P.T * P, P.det())


@_derives("assignment-20-V")
def _assignment_v():
    return derived("assignment-20-matrix") * sp.Matrix([sl.Vx, sl.Vy, sl.Vz])
