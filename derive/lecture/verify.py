"""Check every formula of the lecture (`derive.lecture.claims.CLAIMS`) against the derivation.

For each claim the typed expression is compared with a quantity derived independently by the
core (`DERIVED`, names as in `Claim.target`): the claim's ``given`` definitions are substituted,
frame unit vectors (ê′ᵢ, ê⁰₃) are written in the body basis, each of the slide's ``cases`` is
substituted into both sides, and the difference claim − derived must vanish. The zero test is

1. symbolic, cheapest first and bounded in expression size (never an unbounded `simplify`):
   the difference is zero as built, or after `expand`; if it has no trig functions, after
   `cancel` (canonical for rational functions) or, for small ones with radicals, `simplify`;
   if it has, after `rotations.trig_reduce` (canonical for polynomials in sin/cos) — skipped
   above a few hundred nodes, where reducing 3-angle rotation products costs a second;
2. otherwise numeric at six seeded random points (deterministic: the seed is the claim id and
   target): exactly, in rationals, when the difference contains no function or radical; else
   with mpmath at 50 digits (`lambdify`), zero meaning below 10⁻⁴⁰ of the sides' size.

The numeric test decides both ways: it confirms identities the symbolic steps cannot show, and
it turns a non-zero symbolic remainder into a counterexample. ``Result.method`` names the step
that decided.

Verdicts are computed: ``holds`` when the claim as written holds; ``typo`` when it fails but the
recorded correction (a new expression, or the same one equated to another derived quantity for
a wrong label) holds; ``fails`` otherwise. Corrections are recorded only for evident slips (a
label, a duplicated or garbled line, a sign); a conceptual error gets ``fails`` and a note.
"""
from __future__ import annotations

import functools
import random
from dataclasses import dataclass

import mpmath
import sympy as sp

from derive.lecture import claims as lec
from derive.lecture import slides as sl
from derive.lecture.slides import Claim, Correction, Derived
from derive.symbolic import inertia, lagrangian, rotations, stability

VERDICTS = ("holds", "typo", "fails")
_SYMBOLIC_STEPS = ("identical", "expand", "cancel", "trig_reduce", "simplify")
_POINTS = 6
_DIGITS = 50


# ---- the derived side -------------------------------------------------------------------------
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


def _core():
    return rotations, inertia, lagrangian, stability


@functools.cache
def _top():
    """The heavy symmetric top, its Routh reduction and the sleeping-top series, sharing caches."""
    st = _core()[3].sleeping_top()
    return st.reduction.system, st.reduction, st


# Rotations (z-y-z, the notes' convention). ω̃ comes from the skew route Rᵀ Ṙ, so that the slides'
# sum route α̇ ê⁰₃ + β̇ ê′₂ + γ̇ ê₃ is checked against an independent computation.
@_derives("omega-body")
def _omega_body():
    return _core()[0].ZYZ.omega_body_skew()


for _i in range(3):
    DERIVED[f"omega-body-{_i + 1}"] = (lambda i: lambda: derived("omega-body")[i])(_i)


@_derives("omega-body-linear")
def _omega_body_linear():
    return _linear(derived("omega-body"))


@_derives("omega-inertial")
def _omega_inertial():
    """ω in inertial components, R ω̃ (left unreduced: only compared numerically)."""
    return _core()[0].ZYZ.matrix() * derived("omega-body")


@_derives("velocity", shown=("Ṙ Rᵀ r", r"\dot R R^{T}\mathbf{r}"))
def _velocity():
    """ṙ = Ṙ b = Ṙ Rᵀ r for a point fixed in the body (b = Rᵀ r its body components).

    Left unreduced: reducing the 3-angle products costs a second, the numeric test milliseconds.
    """
    rot = _core()[0]
    R = rot.ZYZ.matrix()
    return R.applyfunc(rot.time_derivative) * R.T * sp.Matrix(sl.X)


@_derives("e2prime")
def _e2prime():
    return _core()[0].ZYZ.intermediate_axis()


@_derives("e2prime-linear")
def _e2prime_linear():
    return _linear(derived("e2prime"))


@_derives("e30")
def _e30():
    return _core()[0].ZYZ.inertial_axis()


@_derives("e30-linear")
def _e30_linear():
    return _linear(derived("e30"))


@functools.cache
def _frames() -> dict:
    """ê′ₖ (the frame after the α and β turns) and ê⁰₃ as linear forms in the body basis.

    The γ turn is about ê′₃, so body components of ê′ₖ are passive(z, γ) eₖ; ê⁰₃ is Rᵀ ẑ.
    """
    rot = _core()[0]
    primed = {sym: _linear(rot.passive("z", rot.gamma) * rot.unit(axis))
              for sym, axis in zip((sl.e1p, sl.e2p, sl.e3p), "xyz")}
    return {**primed, sl.e30: derived("e30-linear")}


# Particles: T, L and I from the velocity field v = ω × r (core `skew`) and `inertia.point_masses`.
@_derives("T-particles")
def _t_particles():
    skew = _core()[0].skew
    total = sp.S.Zero
    for m, r in zip(sl.m_p, sl.r_p):
        vel = skew(sl.w_vec) * r
        total += sp.Rational(1, 2) * m * (vel.T * vel)[0, 0]
    return total


@_derives("L-particles")
def _l_particles():
    skew = _core()[0].skew
    total = sp.zeros(3, 1)
    for m, r in zip(sl.m_p, sl.r_p):
        total += m * skew(r) * (skew(sl.w_vec) * r)
    return total


@_derives("inertia-particles")
def _inertia_particles():
    return _core()[1].point_masses(sl.m_p, sl.r_p)


@_derives("inertia-body-frame")
def _inertia_body_frame():
    """The tensor in the principal body frame: diag(I₁, I₂, I₃), the convention of
    `lagrangian.kinetic_energy` (a definition, so the rows using it are consistency checks)."""
    lag = _core()[2]
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
    rot = _core()[0]
    R = rot.ZYZ.matrix()
    coords, rates = rot.ANGLES + sl.Lb, rot.RATES + sl.Lbd
    dL = (R * sp.Matrix(sl.Lb)).applyfunc(lambda e: rot.time_derivative(e, coords, rates))
    return R.T * dL


# Euler's equations: I ω̇ − (Iω)×ω, with (Iω)×ω = I · euler_rhs.
def _euler_residual(moments=None):
    lag, stab = _core()[2], _core()[3]
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
    lag, stab = _core()[2], _core()[3]
    return stab.euler_rhs((lag.I1, lag.I1, lag.I3), sl.w_vec)[:2, :]


for _i in range(2):
    DERIVED[f"euler-rhs-symmetric-{_i + 1}"] = (lambda i: lambda: derived("euler-rhs-symmetric")[i])(_i)


def _spin(moments=None):
    lag, stab = _core()[2], _core()[3]
    return stab.SteadySpin(2, moments or (lag.I1, lag.I2, lag.I3))


@_derives("symmetric-frequencies")
def _symmetric_frequencies():
    lag, stab = _core()[2], _core()[3]
    return sp.Matrix(_spin((lag.I1, lag.I1, lag.I3)).frequencies).subs(stab.omega0, sl.w3)


@_derives("asym-Omega1")
def _asym_omega1():
    return _spin().frequencies[0].subs(_core()[3].omega0, sl.w3)


@_derives("asym-Omega2")
def _asym_omega2():
    return _spin().frequencies[1].subs(_core()[3].omega0, sl.w3)


@_derives("asym-omega3-dot")
def _asym_omega3_dot():
    """ω̇₃ to first order in the perturbation (δω₁, δω₂, δω₃) of spin about axis 3."""
    stab = _core()[3]
    return (_spin().jacobian * sp.Matrix(stab.delta))[2]


@_derives("asym-linear")
def _asym_linear():
    """(ω̇₁, ω̇₂) linearised about ω₃ ê₃, the small components being ω₁, ω₂ themselves."""
    stab = _core()[3]
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
    return _core()[2].kinetic_energy()


@_derives("kinetic-energy-symmetric")
def _kinetic_energy_symmetric():
    return _core()[2].kinetic_energy_symmetric()


@_derives("heavy-top-lagrangian")
def _heavy_top_lagrangian():
    return _top()[0].lagrangian


@_derives("cyclic")
def _cyclic():
    return sp.Matrix(_top()[0].cyclic)


@_derives("p-alpha")
def _p_alpha():
    return _top()[0].momentum(_core()[0].alpha)


@_derives("p-gamma")
def _p_gamma():
    return _top()[0].momentum(_core()[0].gamma)


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
    rot = _core()[0]
    return rot.ZYZ.matrix(*(sl.ASSIGNMENT_ANGLES[q] for q in rot.ANGLES)).T


@_derives("assignment-20-gram")
def _assignment_gram():
    P = derived("assignment-20-matrix")
    return (P.T * P, P.det())


@_derives("assignment-20-V")
def _assignment_v():
    return derived("assignment-20-matrix") * sp.Matrix([sl.Vx, sl.Vy, sl.Vz])


# ---- the comparison ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Result:
    """The verdict on one claim: ``derived`` is the derived value it was compared with,
    ``corrected`` the recorded `Correction` (None without one)."""

    id: str
    where: str
    verdict: str
    method: str
    derived: object
    corrected: Correction | None
    note: str


@dataclass(frozen=True)
class _Outcome:
    ok: bool
    method: str


def _column(obj) -> sp.Matrix:
    """Any claim value as a flat column: matrices and tuples entrywise; a relation a ≥ b as
    (a − b, strict?) so that two relations compare by their normal forms."""
    if isinstance(obj, tuple):
        return sp.Matrix.vstack(*(_column(x) for x in obj))
    if isinstance(obj, sp.MatrixBase):
        return sp.Matrix(obj).reshape(len(obj), 1)
    if isinstance(obj, sp.core.relational.Relational):
        if isinstance(obj, (sp.GreaterThan, sp.StrictGreaterThan)):
            diff = obj.lhs - obj.rhs
        elif isinstance(obj, (sp.LessThan, sp.StrictLessThan)):
            diff = obj.rhs - obj.lhs
        else:
            raise TypeError(f"unsupported relation {obj}")
        strict = isinstance(obj, (sp.StrictGreaterThan, sp.StrictLessThan))
        return sp.Matrix([diff, int(strict)])
    return sp.Matrix([sp.sympify(obj)])


def _resolve(value):
    if isinstance(value, Derived):
        d = derived(value.name)
        return d if value.index is None else d[value.index]
    return value


def _substitute(obj, mapping: dict):
    """Replace symbols (exactly, by `xreplace`: the keys are symbols, the values expressions)."""
    if not mapping:
        return obj
    if isinstance(obj, tuple):
        return tuple(_substitute(x, mapping) for x in obj)
    return obj.xreplace(mapping)


def _prepared(claim: Claim, expr):
    """The claim as meant: slide definitions (``given``) in, frame vectors in the body basis."""
    expr = _substitute(expr, {k: _resolve(v) for k, v in claim.given.items()})
    frames = set(sl.FRAME_SYMBOLS)
    has_frames = any(getattr(x, "free_symbols", set()) & frames for x in (expr if isinstance(expr, tuple) else (expr,)))
    return _substitute(expr, _frames()) if has_frames else expr


def _sides(claim: Claim, expr, target: str):
    """(claim side, derived side) of the comparison, per the claim's mode."""
    value = derived(target)
    if claim.mode == "equal":
        return _column(expr), _column(value)
    if claim.mode == "solves":
        states = dict(zip(claim.states, expr))
        return sp.Matrix(expr).diff(claim.time), _column(value).xreplace(states)
    if claim.mode == "sign":
        return _column(expr), _column(value).applyfunc(sp.sign)
    if claim.mode == "beta-lagrangian":
        rot = _core()[0]
        b, bd = rot.beta, rot.beta_d
        # Euler–Lagrange for one degree of freedom: β̈ = (∂L/∂β − β̇ ∂²L/∂β̇∂β) / ∂²L/∂β̇².
        accel = (sp.diff(expr, b) - bd * sp.diff(expr, bd, b)) / sp.diff(expr, bd, 2)
        return _column(accel), _column(value)
    raise ValueError(f"{claim.id}: unknown mode {claim.mode!r}")


def _trig_angles(expr) -> tuple:
    return tuple(sorted({f.args[0] for f in expr.atoms(sp.sin, sp.cos, sp.tan)}, key=sp.default_sort_key))


# Size bounds (in expression-tree nodes) of the symbolic steps; larger remainders go to the
# numeric test, which costs milliseconds where a 3-angle `trig_reduce` costs a second.
_EXPAND_MAX_NODES = 400
_TRIG_REDUCE_MAX_NODES = 250
_SIMPLIFY_MAX_NODES = 80        # `simplify` only on small trig-free remainders: unbounded otherwise


def _size(e) -> int:
    return sum(1 for _ in sp.preorder_traversal(e))


def _symbolic_zero(d) -> str | None:
    """The first symbolic step showing d = 0, or None (not shown: the numeric test decides)."""
    if d == 0:
        return "identical"
    if _size(d) > _EXPAND_MAX_NODES:
        return None
    d = sp.expand(d)
    if d == 0:
        return "expand"
    if not d.has(sp.sin, sp.cos, sp.tan):
        if sp.cancel(sp.together(d)) == 0:        # canonical for rational functions
            return "cancel"
        if not _radicals(d) or _size(d) > _SIMPLIFY_MAX_NODES:
            return None
        return "simplify" if sp.simplify(d) == 0 else None
    if _size(d) > _TRIG_REDUCE_MAX_NODES:
        return None
    reduced = _core()[0].trig_reduce(d, _trig_angles(d))
    if reduced == 0:
        return "trig_reduce"
    return None


def _radicals(e) -> bool:
    """Whether e has non-integer powers or functions, where `cancel` is not a canonical form."""
    return bool(e.atoms(sp.Function)) or any(not p.exp.is_Integer for p in e.atoms(sp.Pow))


def _sample(symbols, rng: random.Random) -> list:
    """Rationals away from 0: positive symbols in [1/2, 3], others ±[1/5, 2]."""
    point = []
    for x in symbols:
        if x.is_positive:
            point.append(sp.Rational(rng.randint(50, 300), 100))
        else:
            point.append(sp.Rational(rng.choice((-1, 1)) * rng.randint(20, 200), 100))
    return point


def _numeric_zero(lhs: sp.Matrix, rhs: sp.Matrix, seed: str) -> _Outcome:
    """claim − derived at `_POINTS` seeded random points: exact when the difference is rational
    there, else by mpmath at `_DIGITS` digits (relative to the size of the two sides)."""
    symbols = sorted(lhs.free_symbols | rhs.free_symbols, key=lambda x: x.name)
    transcendental = any(e.has(sp.Function) or any(not p.exp.is_Integer for p in e.atoms(sp.Pow))
                         for e in (*lhs, *rhs))
    rng = random.Random(seed)
    if transcendental:
        f = sp.lambdify(symbols, [*lhs, *rhs], modules="mpmath", cse=True)
    n, used = len(lhs), 0
    for _ in range(3 * _POINTS):
        if used == _POINTS:
            break
        point = _sample(symbols, rng)
        if not transcendental:
            vals = [e.xreplace(dict(zip(symbols, point))) for e in (*lhs, *rhs)]
            if any(not v.is_Rational for v in vals):
                continue                               # a pole of the formula: draw again
            used += 1
            bad = [a - b for a, b in zip(vals[:n], vals[n:]) if a != b]
            if bad:
                return _Outcome(False, f"exact rational: claim − derived = {bad[0]} at a sample point")
            continue
        with mpmath.workdps(_DIGITS):
            try:
                vals = [mpmath.mpmathify(v) for v in f(*(mpmath.mpf(p.p) / p.q for p in point))]
            except (ZeroDivisionError, ValueError):
                continue
            if not all(mpmath.isfinite(v) for v in vals):
                continue
            used += 1
            for a, b in zip(vals[:n], vals[n:]):
                size = max(1, abs(a), abs(b))
                if abs(a - b) > size * mpmath.mpf(10) ** (10 - _DIGITS):
                    return _Outcome(False, f"mpmath {_DIGITS} digits: |claim − derived| = "
                                           f"{mpmath.nstr(abs(a - b), 3)} at a sample point")
    how = f"mpmath {_DIGITS} digits" if transcendental else "exact rational"
    return _Outcome(used > 0, f"{how} at {used} points")


def _compare(claim: Claim, expr, target: str) -> _Outcome:
    """Does ``expr`` (the claim, or its correction) equal ``target`` in every case?"""
    lhs0, rhs0 = _sides(claim, _prepared(claim, expr), target)
    if lhs0.shape != rhs0.shape:
        return _Outcome(False, f"shape {lhs0.shape} ≠ derived {rhs0.shape}")
    methods = []
    for k, case in enumerate(claim.cases):
        lhs, rhs = lhs0.xreplace(case), rhs0.xreplace(case)
        steps = [_symbolic_zero(d) for d in lhs - rhs]
        if all(steps):
            methods.append(max(steps, key=_SYMBOLIC_STEPS.index))
            continue
        numeric = _numeric_zero(lhs, rhs, f"{claim.id}/{target}/{k}")
        if not numeric.ok:
            where = f" (case {k + 1} of {len(claim.cases)})" if len(claim.cases) > 1 else ""
            return _Outcome(False, numeric.method + where)
        methods.append(numeric.method)
    method = methods[0] if len(set(methods)) == 1 else ", ".join(methods)
    if len(claim.cases) > 1:
        method += f" ({len(claim.cases)} cases)"
    return _Outcome(True, method)


def where(claim: Claim) -> str:
    return f"{claim.section} — “{claim.quote}”"


def check(claim: Claim) -> Result:
    """Compare the claim as written; if it fails, its recorded correction (see module docstring)."""
    written = _compare(claim, claim.expr, claim.target)
    corr = claim.correction
    if written.ok:
        verdict, method = "holds", written.method
    elif corr is None:
        verdict, method = "fails", f"as written: {written.method}"
    else:
        fixed = _compare(claim, claim.expr if corr.expr is None else corr.expr, corr.target or claim.target)
        verdict = "typo" if fixed.ok else "fails"
        method = f"as written: {written.method}; corrected: {fixed.method}"
    target = corr.target if (verdict == "typo" and corr.target) else claim.target
    return Result(claim.id, where(claim), verdict, method, derived(target), corr, claim.note)


@functools.cache
def _run() -> tuple[Result, ...]:
    return tuple(check(c) for c in lec.CLAIMS)


def run() -> list[Result]:
    """Every claim checked, in the order of the slides (computed once per process)."""
    return list(_run())


def mismatches(results=None) -> list[tuple[str, str, str]]:
    """(id, expected, got) for every claim whose verdict differs from `lecture.EXPECTED`."""
    results = run() if results is None else results
    got = {r.id: r.verdict for r in results}
    ids = list(dict.fromkeys([*got, *lec.EXPECTED]))
    return [(i, lec.EXPECTED.get(i, "—"), got.get(i, "—")) for i in ids if lec.EXPECTED.get(i) != got.get(i)]


# ---- the table --------------------------------------------------------------------------------
def _compact(obj) -> str:
    if isinstance(obj, tuple):
        return "(" + ", ".join(_compact(x) for x in obj) + ")"
    if isinstance(obj, sp.MatrixBase):
        if obj.cols == 1:
            return "(" + ", ".join(sp.sstr(x) for x in obj) + ")"
        return "[" + "; ".join(", ".join(sp.sstr(x) for x in obj.row(i)) for i in range(obj.rows)) + "]"
    return sp.sstr(obj)


@functools.cache
def _symbol_names() -> dict:
    """LaTeX names of the plain symbols that stand for dotted or tilded quantities."""
    rot = _core()[0]
    names = {qd: rf"\dot{{{sp.latex(q)}}}" for q, qd in zip(rot.ANGLES, rot.RATES)}
    for i in range(3):
        names[sl.w_vec[i]] = rf"\tilde{{\omega}}_{{{i + 1}}}"
        names[(sl.wd1, sl.wd2, sl.wd3)[i]] = rf"\dot{{\tilde{{\omega}}}}_{{{i + 1}}}"
        names[sl.Lb[i]] = rf"\tilde{{L}}_{{{i + 1}}}"
        names[sl.Lbd[i]] = rf"\dot{{\tilde{{L}}}}_{{{i + 1}}}"
        names[sl.BASIS[i]] = rf"\hat{{\mathbf{{e}}}}_{{{i + 1}}}"
    return names


def latex(obj) -> str:
    """LaTeX of a derived value (tuples joined by commas), rates printed as dotted angles."""
    if isinstance(obj, tuple):
        return r",\ ".join(latex(x) for x in obj)
    return sp.latex(obj, symbol_names=_symbol_names())


def _shown(r: Result, fmt: str) -> str:
    """The derived value as shown: its `SHOWN` form if it is left unreduced."""
    target = r.corrected.target if (r.verdict == "typo" and r.corrected.target) else _claim(r.id).target
    if target in SHOWN:
        return SHOWN[target][fmt == "markdown"]
    return latex(r.derived) if fmt == "markdown" else _compact(r.derived)


def _corrected(r: Result, fmt: str) -> str:
    corr = r.corrected
    if fmt == "markdown":
        return f"${corr.latex}$"
    fixed = _compact(corr.expr) if corr.expr is not None else "same expression"
    return fixed + (f", equal to {corr.target}" if corr.target else "")


@functools.cache
def _claims_by_id() -> dict:
    return {c.id: c for c in lec.CLAIMS}


def _claim(ident: str) -> Claim:
    return _claims_by_id()[ident]


def _cell(text: str) -> str:
    return text.replace("|", r"\|").replace("\n", " ")


def table(fmt: str = "text") -> str:
    """The verification table: id, where, verdict (typo with the corrected form), method,
    derived expression, note.

    ``fmt="markdown"``: one table row per claim, LaTeX in the cells. ``fmt="text"``: one line
    per claim (id, verdict, method) followed by indented where / corrected / derived / note
    lines, and a count of the verdicts.
    """
    results = run()
    if fmt == "markdown":
        head = ("id", "where", "verdict", "method", "derived", "note")
        lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
        for r in results:
            verdict = f"typo → {_corrected(r, fmt)}" if r.verdict == "typo" else f"**{r.verdict}**"
            claim = _claim(r.id)
            cells = (f"`{r.id}`", f"{claim.section} — `{claim.quote}`", verdict, r.method, f"${_shown(r, fmt)}$", r.note)
            lines.append("| " + " | ".join(_cell(x) for x in cells) + " |")
        return "\n".join(lines) + "\n"
    if fmt != "text":
        raise ValueError(f"unknown format {fmt!r} (text or markdown)")
    width = max(len(r.id) for r in results)
    out = []
    for r in results:
        out.append(f"{r.id:<{width}}  {r.verdict:<5}  {r.method}")
        pad = " " * (width + 2)
        out.append(f"{pad}where:     {r.where}")
        if r.verdict == "typo":
            out.append(f"{pad}corrected: {_corrected(r, fmt)}")
        out.append(f"{pad}derived:   {_shown(r, fmt)}")
        if r.note:
            out.append(f"{pad}note:      {r.note}")
    counts = ", ".join(f"{sum(r.verdict == v for r in results)} {v}" for v in VERDICTS)
    out.append(f"{len(results)} claims: {counts}")
    return "\n".join(out) + "\n"
