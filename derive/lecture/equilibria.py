"""The relative equilibria of `derive analyze` and their stability, evaluated at a scene's
numbers: sleeping and hanging tops, steady precession, permanent rotations of a free body and
rest equilibria (the module docstring of :mod:`derive.lecture.analysis` gives the conditions).
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from derive.lecture.closed_forms import _ep_jacobian, _latex, _routh
from derive.symbolic import integrable
from derive.symbolic.lagrangian import I1, I2, I3, Mass, g, l, p_gamma
from derive.symbolic.rotations import ZYZ
from derive.symbolic.stability import SteadySpin, omega0


#: A real part above this fraction of the spectrum's scale counts as growth (round-off in the
#: eigenvalues of a Hamiltonian linearisation is far below it).
EIGEN_TOLERANCE = 1e-7

#: The SI unit of every number the analysis reports (``Equilibrium.values`` and the fields of a
#: steady precession's records), ASCII as in the JSON's ``units``; the Markdown shows them with
#: superscripts (``integrable.pretty_unit``). Eigenvalues λ of the linearisation ẏ = J y are
#: rates (s⁻¹); λ² is in s⁻².
UNITS = {
    "p_gamma": "kg m^2 s^-1", "p_alpha": "kg m^2 s^-1", "threshold": "kg m^2 s^-1",
    "k2": "J rad^-2", "V_eff_second_derivative": "J rad^-2",
    "discriminant": "kg^2 m^4 s^-2",
    "omega0": "rad s^-1", "alpha_dot": "rad s^-1", "alpha_dot_roots": "rad s^-1",
    "alpha_dot_scene": "rad s^-1", "nutation_frequency": "rad s^-1",
    "lambda_squared": "s^-2", "eigenvalues": "s^-1",
    "beta0": "rad", "r_c": "m",
}


@dataclass
class Equilibrium:
    """One relative equilibrium: the JSON contract's ``kind``, ``axis``, ``condition``,
    ``stable``, plus the condition in LaTeX, the scene's ``values`` and the ``eigenvalues``."""

    kind: str
    axis: int | None
    condition: str
    stable: bool | None
    latex: str = ""
    description: str = ""
    method: str = ""
    values: dict = field(default_factory=dict)
    eigenvalues: list = field(default_factory=list)

    def to_json(self) -> dict:
        values = {k: ([r.to_json() for r in v] if k == "roots" else v) for k, v in self.values.items()}
        return {"kind": self.kind, "axis": self.axis, "condition": self.condition,
                "stable": self.stable, "description": self.description, "method": self.method,
                "values": values, "units": self.units,
                "eigenvalues": [[float(z.real), float(z.imag)] for z in self.eigenvalues]}

    @property
    def units(self) -> dict:
        """{name: SI unit} of every number in ``values`` (and in its ``roots`` records) and of
        the eigenvalues."""
        names = list(self.values)
        for r in self.values.get("roots", []):
            names += list(r.to_json())
        return {k: UNITS[k] for k in dict.fromkeys(names + ["eigenvalues"]) if k in UNITS}


def _state(m, L, n, moments) -> list:
    """The model's (first six) state at the point (L, n): L itself, or ω̃ = I⁻¹L when the
    model's state is the angular velocity (the Jacobians are similar: same eigenvalues)."""
    if m.state_names[0].startswith("omega"):
        L = [Li / Ii for Li, Ii in zip(L, moments)]
    return list(L) + list(n)


def _eigenvalues(scene, L, n, kind: str) -> np.ndarray:
    """The eigenvalues of the Euler–Poisson linearisation at (L, n); _Overflow naming ``kind``
    when the Jacobian's entries are beyond the double range (np.linalg refuses an inf)."""
    f, m = _ep_jacobian(scene.symmetric, scene.effects)
    values = scene.param_values()
    p = [values[name] for name in m.param_names]
    with np.errstate(all="ignore"):  # an overflow is named below, not warned about
        J = np.array(f(_state(m, L, n, scene.body.moments), p), dtype=float)
    _finite(kind, "the Jacobian of the Euler-Poisson linearisation", J)
    return np.linalg.eigvals(J)


def _grows(eig) -> bool:
    eig = np.asarray(eig, dtype=complex)
    scale = max(float(np.max(np.abs(eig))) if eig.size else 0.0, 1e-300)
    return bool(np.max(eig.real) > EIGEN_TOLERANCE * scale)


def _sign_tol(x: float, scale: float) -> int:
    """+1, −1, or 0 when |x| ≤ TOLERANCE · scale (marginal)."""
    if abs(x) <= integrable.TOLERANCE * abs(scale):
        return 0
    return 1 if x > 0 else -1


def _big(x):
    """``x`` as a SymPy Float, whose exponent is unbounded: products and squares of the scene's
    doubles (ω₀² I, p_γ², M g l I₁ at 1e300) are exact in magnitude instead of inf, so a verdict
    read from their ratio is right whatever the scale."""
    return sp.Float(float(x))


def _sign_ratio(x, scale) -> int:
    """_sign_tol for SymPy numbers of any magnitude: the sign of x with |x| ≤ TOLERANCE · |scale|
    marginal, decided on the ratio x / scale (a double of modest size)."""
    if scale == 0:
        return _sign_tol(float(x), 0.0)
    return _sign_tol(float(x / abs(scale)), 1.0)


class _Overflow(ArithmeticError):
    """A quantity of an equilibrium that is not a finite double at the scene's numbers; the
    message is ``<kind>: <quantity> overflows double precision ...``."""


def _finite(kind: str, quantity: str, value):
    """``value`` (a number or an array of real or complex numbers) if every entry is finite,
    else raise _Overflow naming the equilibrium ``kind`` and the ``quantity``."""
    arr = np.asarray(value, dtype=complex)
    if not np.all(np.isfinite(arr)):
        raise _Overflow(f"{kind}: {quantity} overflows double precision (beyond about 1.8e308) "
                        f"at the scene's numbers")
    return value


def _check_finite(e: "Equilibrium") -> None:
    """Every number an equilibrium reports (its values, its eigenvalues) finite, or _Overflow:
    JSON has no infinity, and an inf or nan here would mean a meaningless line of output."""
    for name, v in e.values.items():
        if name == "roots":  # the steady-precession records: each number of each root
            for r in v:
                _finite(e.kind, "a steady-precession root", [r.alpha_dot, r.p_alpha, r.curvature])
        elif v is not None:
            _finite(e.kind, name.replace("_", " "), v)
    _finite(e.kind, "an eigenvalue of the linearisation", e.eigenvalues)


def _norm(v) -> float:
    """|v| without overflow in the squares (math.hypot scales): |(0, 0, 1e300)| = 1e300."""
    return math.hypot(*(float(x) for x in v))


def _axial(sc) -> bool:
    """Gravity absent or its centre of mass on body axis 3 (within TOLERANCE)."""
    p = integrable.parameters(sc)
    r = _norm((p["cx"], p["cy"], p["cz"]))
    return math.hypot(p["cx"], p["cy"]) <= integrable.TOLERANCE * r or r == 0


@dataclass(frozen=True)
class _Top:
    """A symmetric top as the Routh reduction sees it, read off a scene: the symmetry direction
    u (body axes; ``axis`` 0..2 when it is a body axis), the moments across and along it, the
    centre of mass at signed distance l along u, p_γ = I_sym ω̃(0)·u, the tilt β₀ of u from the
    vertical, and the scene's α̇ when its Euler angles are this top's (u = ê₃)."""

    u: tuple
    axis: int | None
    I_perp: float
    I_sym: float
    l: float
    p_gamma: float
    beta0: float
    alpha_dot: float | None


def _top(sc, cls, p) -> _Top:
    I = np.array(sc.body.moments)
    c = np.array([p["cx"], p["cy"], p["cz"]])
    if cls.extra is not None and cls.extra.name == integrable.SPHERE.name:
        u, axis = c / _norm(c), None  # a sphere: the symmetry axis through r_c
    else:
        axis = cls.axes[2]
        u = np.eye(3)[axis]
    i = sc.initial
    n0 = np.array(ZYZ.matrix(i.alpha, i.beta, i.gamma)[2, :], dtype=float).ravel()  # n = Rᵀẑ
    across = cls.axes[0] if axis is not None else 0
    L0 = I * np.array(i.omega)
    if axis == 2:  # the scene's own Euler angles are this top's
        beta0, alpha_dot = i.beta, i.alpha_dot
    else:  # the angle from u to n; atan2 keeps its digits at a small tilt, where arccos loses them
        beta0, alpha_dot = float(np.arctan2(np.linalg.norm(np.cross(n0, u)), n0 @ u)), None
    return _Top(tuple(u), axis, float(I[across]), float(u @ (I * u)), float(c @ u), float(L0 @ u),
                beta0, alpha_dot)


def _equilibria(sc, cls) -> list[Equilibrium]:
    p = integrable.parameters(sc)
    torque = cls.case != "euler" and p["g"] > 0 and p["M"] > 0
    if cls.dissipative:
        return _rest_equilibria(sc, p) if torque else []
    if not torque:
        out = [_free_rotation(sc, k) for k in range(3)]
        if sc.symmetric:
            out.append(_steady_precession(sc, p, _top(sc, cls, p), gravity=False))
        return out
    if cls.case == "lagrange":
        top = _top(sc, cls, p)
        return [_lagrange_vertical(sc, p, top, "sleeping"), _lagrange_vertical(sc, p, top, "hanging"),
                _steady_precession(sc, p, top, gravity=True)]
    return _heavy_vertical(sc, p)


def _free_rotation(sc, k: int) -> Equilibrium:
    """Spin of a free body about principal axis k (0-based) at the scene's |ω̃(0)|."""
    Ivals = sc.body.moments
    i, j = (k + 1) % 3, (k + 2) % 3
    Isym = (I1, I2, I3)
    lam2 = SteadySpin(k, Isym).eigenvalue_squared
    w0 = _norm(sc.initial.omega)
    a = _sign_tol(Ivals[k] - Ivals[i], max(Ivals))
    b = _sign_tol(Ivals[k] - Ivals[j], max(Ivals))
    stable = None if a * b == 0 else (a * b > 0)
    L = [0.0, 0.0, 0.0]
    L[k] = Ivals[k] * w0
    J = _finite("permanent-rotation", "the Jacobian of Euler's equations", _free_jacobian(Ivals, L))
    eig = np.linalg.eigvals(J)
    if stable is False and not _grows(eig) and w0 > 0:
        stable = None  # cannot happen for distinct moments; kept honest
    Ik, Ii, Ij = Isym[k], Isym[i], Isym[j]
    cond = f"(I{k + 1} - I{i + 1})*(I{k + 1} - I{j + 1}) > 0"
    tex = (rf"({_latex(Ik)} - {_latex(Ii)})({_latex(Ik)} - {_latex(Ij)}) > 0"
           rf"\quad\Leftrightarrow\quad \lambda^2 = {_latex(lam2)} < 0")
    return Equilibrium(
        "permanent-rotation", k + 1, cond, stable, tex,
        f"free spin at omega0 = {w0:.6g} rad s^-1 about principal axis {k + 1} (I{k + 1} the "
        + {1: "largest or smallest", -1: "intermediate", 0: "equal to another"}[
            0 if a * b == 0 else (1 if a * b > 0 else -1)] + " moment)",
        "energy-Casimir: E - |L|^2/(2 I_k) has Hessian diag(1/I_i - 1/I_k, 1/I_j - 1/I_k) on the "
        "perturbations; linearisation of Euler's equations",
        {"omega0": w0, "lambda_squared": float(lam2.subs({I1: Ivals[0], I2: Ivals[1], I3: Ivals[2],
                                                           omega0: w0}))},
        list(eig))


def _free_jacobian(I, L) -> np.ndarray:
    """∂L̇/∂L of L̇ = L × I⁻¹L at L (numbers)."""
    f, m = _ep_jacobian(False, ())
    with np.errstate(all="ignore"):  # an overflow is named by the caller, not warned about
        J = np.array(f(_state(m, L, (0.0, 0.0, 1.0), I), list(I)), dtype=float)
    return J[:3, :3]


def _lagrange_vertical(sc, p, top: _Top, kind: str) -> Equilibrium:
    """Sleeping (centre of mass above the pivot) or hanging top of the Lagrange case, from the
    series of V_eff about β = 0 (p_α = p_γ) or β = π (p_α = −p_γ); β is the tilt of the
    symmetry direction u (body axis 3, or the body's own symmetry axis / r̂_c of a sphere)."""
    R = _routh()
    lval = top.l
    pg = top.p_gamma
    # β = 0 puts the centre of mass at height l: above the pivot when l > 0.
    at_zero = (kind == "sleeping") == (lval > 0)
    k2 = R["k2_0"] if at_zero else R["k2_pi"]
    subs = {I1: top.I_perp, Mass: p["M"], g: p["g"], l: lval, p_gamma: pg}
    k2s = k2.subs(subs)
    k2v = float(k2s)
    Mgl = _big(p["M"]) * _big(p["g"]) * _big(lval)
    s = _sign_ratio(k2s, _big(pg) ** 2 / (8 * _big(top.I_perp)) + abs(Mgl) / 2)
    stable = None if s == 0 else s > 0
    threshold2 = sp.factor(R["threshold"] ** 2)  # 4 M g l I₁
    if kind == "sleeping" and at_zero:
        cond = f"p_gamma >= sqrt({sp.sstr(threshold2)})"
        st = R["sleeping"]
        tex = (rf"V_\text{{eff}}\big|_{{p_\alpha = p_\gamma}} = {_latex(st.coefficient(0))} + "
               rf"k_2\beta^2 + k_4\beta^4 + O(\beta^6),\quad k_4\big|_{{k_2 = 0}} = "
               rf"{_latex(st.quartic_at_threshold)};\qquad "
               rf"k_2 = {_latex(k2)} \ge 0 \;\Leftrightarrow\; p_\gamma \ge \sqrt{{{_latex(threshold2)}}}")
    else:
        note = {"sleeping": "l < 0: upright at beta = pi",
                "hanging": "always: with the centre of mass below the pivot both terms are >= 0"}
        cond = f"k2 = {sp.sstr(k2)} >= 0  ({note[kind]})"
        tex = rf"k_2 = {_latex(k2)} \ge 0"
    u = np.array(top.u)
    eig = _eigenvalues(sc, tuple(pg * u), tuple(u if at_zero else -u), kind)
    if stable is False and not _grows(eig):
        stable = None
    where = "beta = 0" if at_zero else "beta = pi"
    return Equilibrium(
        kind, None if top.axis is None else top.axis + 1, cond, stable, tex,
        f"spin p_gamma = I_sym omega.u = {pg:.6g} kg m^2 s^-1 about the vertical symmetry axis at {where}, centre "
        f"of mass {'above' if kind == 'sleeping' else 'below'} the pivot" + _top_note(top),
        "series of V_eff(beta) about the pole with p_alpha = +-p_gamma: V_eff = V0 + k2 eps^2 + ...; "
        "Euler-Poisson linearisation",
        {"p_gamma": pg, "threshold": float(sp.sqrt(abs(4 * Mgl * _big(top.I_perp)))),
         "k2": k2v},
        list(eig))


def _top_note(top: _Top) -> str:
    if top.axis == 2:
        return ""
    where = (f"body axis {top.axis + 1}" if top.axis is not None
             else "the direction of r_c (a spherical body)")
    return (f" (the symmetry axis is {where}: I1 -> {top.I_perp:g}, I3 -> {top.I_sym:g}, "
            f"l -> {top.l:g} in the formulas)")


@dataclass(frozen=True)
class Precession:
    """One steady precession at the tilt β₀, every number of it in one record (so a rate is
    never paired with another root's curvature): the rate ``alpha_dot`` (a root of the
    steady-precession quadratic), ``p_alpha`` there, ``curvature`` = ∂²V_eff/∂β²(β₀) at fixed
    p_α, p_γ, and ``I_perp`` (I₁). The linearised β equation I₁ δβ̈ = −V_eff″ δβ gives the
    eigenvalues ±√(−V_eff″/I₁) and, when V_eff″ > 0, the nutation frequency √(V_eff″/I₁)."""

    alpha_dot: float
    p_alpha: float
    curvature: float
    I_perp: float
    stable: bool | None = None

    @property
    def eigenvalues(self) -> list[complex]:
        lam = cmath.sqrt(-self.curvature / self.I_perp)
        return [lam, -lam]

    @property
    def nutation_frequency(self) -> float | None:
        return math.sqrt(self.curvature / self.I_perp) if self.curvature > 0 else None

    def to_json(self) -> dict:
        return {"alpha_dot": self.alpha_dot, "p_alpha": self.p_alpha,
                "V_eff_second_derivative": self.curvature,
                "nutation_frequency": self.nutation_frequency, "stable": self.stable,
                "eigenvalues": [[float(z.real), float(z.imag)] for z in self.eigenvalues]}


def _double(x) -> float:
    """``x`` (a double or an mpmath number) as a double: ±inf beyond the range."""
    try:
        return float(x)
    except OverflowError:
        return math.copysign(math.inf, x)


def _precession_numbers(num, args, real, lib):
    """(discriminant, rates α̇, V_eff″ at each, p_α at each) of the steady-precession
    quadratic at the scene's numbers, with ``num`` the backend's functions, ``real`` its number
    type and ``lib`` its sqrt/copysign (math, or mpmath for an unbounded exponent)."""
    args = tuple(real(a) for a in args)
    coeffs = [real(x) for x in num["coefficients"](*args)]
    dv = real(num["discriminant"](*args))
    a, b, c = coeffs
    # Δ = b² − 4ac is judged against its own terms (a marginal Δ is a double root); the largest
    # coefficient squared would call a Δ of −1e300 "zero" when M g l = 1e300.
    scale = max(b * b, abs(4 * a * c))
    rates = _quadratic_roots(a, b, c, dv, lib) if dv >= -integrable.TOLERANCE * scale else []
    curv = [real(num["d2V"](*args, ad)) for ad in rates]
    pas = [real(num["p_alpha"](*args, ad)) for ad in rates]
    return dv, rates, curv, pas


def _quadratic_roots(a, b, c, disc, lib=math) -> list:
    """The real roots of a x² + b x + c = 0 with discriminant ``disc`` ≥ 0 (clipped at 0),
    ascending, without the cancellation in −b ± √Δ: the root of larger magnitude q/a with
    q = −(b + sign(b)√Δ)/2, the other c/q. a = 0 leaves the linear root. (At a small tilt the
    slow precession M g l/p_γ is the small root of the two.)"""
    if a == 0:
        return [] if b == 0 else [-c / b]
    root = lib.sqrt(max(disc, 0 * disc))
    q = -(b + (root if b >= 0 else -root)) / 2
    if q == 0:  # b = c = 0: the double root 0
        return [0 * q]
    return sorted({q / a, c / q})


def _steady_precession(sc, p, top: _Top, gravity: bool) -> Equilibrium:
    """Steady precession at the scene's tilt β₀ of the symmetry axis (Lagrange top, free
    symmetric body): one ``Precession`` record per real root α̇, in ascending order."""
    R = _routh()
    b0 = top.beta0
    pg = top.p_gamma
    lval = top.l if gravity else 0.0
    axis = None if top.axis is None else top.axis + 1
    quad, disc = R["quadratic"], R["discriminant"]
    if not gravity:  # the free symmetric body: M g l = 0
        quad, disc = quad.subs(l, 0), sp.factor(disc.subs(l, 0))
    values = {"beta0": b0, "p_gamma": pg}
    if abs(math.sin(b0)) < 1e-9:
        return Equilibrium("steady-precession", axis, f"{sp.sstr(quad)} = 0", None, _latex(sp.Eq(quad, 0)),
                           "the scene's tilt is at a pole: no finite-tilt precession to evaluate",
                           "dV_eff/dbeta = 0", values, [])
    args = (top.I_perp, p["M"], p["g"], lval, pg, b0)
    try:
        dv, rates, curv, pas = _precession_numbers(R["numeric"]["math"], args, float, math)
    except (OverflowError, ZeroDivisionError, ValueError):
        dv = None
    if dv is None or not all(math.isfinite(x) for x in (dv, *rates, *curv, *pas)):
        import mpmath

        with mpmath.workdps(30):  # the same formulas where a double over- or underflows
            dv, rates, curv, pas = _precession_numbers(R["numeric"]["mpmath"], args, mpmath.mpf, mpmath)
    size = max((abs(x) for x in curv), default=0.0)
    # the verdict from the exact-exponent numbers; the record keeps doubles (inf where a number
    # is beyond the double range: _check_finite then names it, exit 3)
    roots = [Precession(_double(ad), _double(pa), _double(c2), top.I_perp,
                        {1: True, -1: False, 0: None}[_sign_ratio(c2, size)])
             for ad, c2, pa in zip(rates, curv, pas)]
    dv = _double(dv)
    values.update(discriminant=dv, alpha_dot_scene=top.alpha_dot, roots=roots,
                  # the records' fields as lists, in the records' order (the earlier keys)
                  alpha_dot_roots=[r.alpha_dot for r in roots],
                  V_eff_second_derivative=[r.curvature for r in roots])
    if not roots:
        stable = None
    elif all(r.stable for r in roots):
        stable = True
    elif any(r.stable is False for r in roots):
        stable = False
    else:
        stable = None
    text = (f"{sp.sstr(quad)} = 0; real alpha_dot iff {sp.sstr(disc)} >= 0; stable where "
            "d2V_eff/dbeta2 > 0")
    tex = (rf"{_latex(quad)} = 0,\quad \Delta = {_latex(disc)} \ge 0,\quad "
           r"\partial^2_\beta V_\text{eff} > 0")
    desc = (f"alpha_dot constant at the tilt beta0 = {b0:.6g} rad with p_gamma = {pg:.6g} "
            f"kg m^2 s^-1: "
            + (f"roots alpha_dot = {', '.join(f'{r.alpha_dot:.6g}' for r in roots)} rad s^-1" if roots
               else "no real root: no steady precession at this tilt"))
    if not gravity:
        desc += " (free symmetric body: every motion is a regular precession)"
    return Equilibrium("steady-precession", axis, text, stable, tex, desc + _top_note(top),
                       "dV_eff/dbeta = 0 with p_alpha = I1 alpha_dot sin^2 beta + p_gamma cos beta; "
                       "V_eff'' evaluated with p_alpha eliminated (no cancellation at a small tilt); "
                       "eigenvalues of the linearised beta equation, per root",
                       values, [z for r in roots for z in r.eigenvalues])


def _vertical_condition(k: int, upright: bool) -> tuple[str, str]:
    i, j = (k + 1) % 3 + 1, (k + 2) % 3 + 1
    h = "" if upright else "-"
    text = (f"omega0**2*(I{k + 1} - I{i}) > {h}M*g*|r_c| and omega0**2*(I{k + 1} - I{j}) > {h}M*g*|r_c| "
            "(energy-Casimir, sufficient)")
    tex = (rf"\omega_0^2(I_{k + 1} - I_{{{i}}}) > {h}Mg|r_c|,\quad "
           rf"\omega_0^2(I_{k + 1} - I_{{{j}}}) > {h}Mg|r_c|")
    return text, tex


def _principal_direction(I, c):
    """If r̂_c is a principal direction of diag(I) (within TOLERANCE): (its moment, the two
    moments perpendicular to it, the body axis 0..2 it lies on or None); else None. A direction
    in a plane of equal moments (I₁ = I₂: any equatorial r_c) is principal too."""
    u = c / _norm(c)
    Iu = I * u
    Iuu = float(u @ Iu)
    if np.linalg.norm(Iu - Iuu * u) > integrable.TOLERANCE * I.max():
        return None
    P = np.eye(3) - np.outer(u, u)
    perp = sorted(np.linalg.eigvalsh(P @ np.diag(I) @ P))[1:]  # drop the 0 along u
    axis = next((k for k in range(3) if np.hypot(*np.delete(u, k)) <= integrable.TOLERANCE), None)
    return Iuu, [float(x) for x in perp], axis


def _heavy_vertical(sc, p) -> list[Equilibrium]:
    """Rotation about the vertical through the pivot with the centre of mass on it (any body):
    about r̂_c when it is a principal direction, at the scene's spin ω₀ = ω̃(0)·r̂_c; else at rest.
    Energy–Casimir: E + a L·n + b|n|² on the leaf is definite iff
    ω₀²(I_u − I_m) > h M g |r_c| for both moments I_m perpendicular to r̂_c (h = ±1)."""
    c = np.array([p["cx"], p["cy"], p["cz"]])
    r = _norm(c)
    u = c / r
    I = np.array(sc.body.moments)
    principal = _principal_direction(I, c)
    out = []
    for kind, upright in (("sleeping", True), ("hanging", False)):
        h = 1.0 if upright else -1.0
        where = "above" if upright else "below"
        if principal is None:
            w0, axis = 0.0, None
            text = (f"at rest with the centre of mass {where} the pivot (no spin: r_c is on no "
                    "principal axis); energy-Casimir: "
                    + ("fails (V maximal)" if upright else "V has a strict minimum, stable"))
            tex = rf"\tilde\omega = 0,\ \tilde n = {'+' if upright else '-'}\hat r_c"
            ec = None if upright else True
            desc = f"at rest, centre of mass {where} the pivot"
        else:
            Iu, perp, axis = principal
            w0 = float(np.dot(sc.initial.omega, u))
            sign = "" if upright else "-"
            if axis is not None:
                text, tex = _vertical_condition(axis, upright)
            else:
                text = (f"omega0**2*(I_u - I_m) > {sign}M*g*|r_c| for both moments I_m perpendicular "
                        "to r_c, I_u = r_c.I.r_c/|r_c|^2 (energy-Casimir, sufficient)")
                tex = rf"\omega_0^2(I_u - I_m) > {sign}Mg|r_c|,\ m \perp \hat r_c"
            W2, MgR = _big(w0) ** 2, _big(p["M"]) * _big(p["g"]) * _big(r)  # no overflow
            marg = [W2 * (_big(Iu) - _big(Im)) - h * MgR for Im in perp]
            scale = W2 * _big(I.max()) + MgR
            ec = True if all(_sign_ratio(x, scale) > 0 for x in marg) else None
            desc = (f"spin omega0 = {w0:.6g} rad s^-1 about "
                    + (f"principal axis {axis + 1}" if axis is not None
                       else "the principal direction along r_c")
                    + f" held vertical, centre of mass {where} the pivot")
        n = h * u  # the upward vertical in body axes: along r_c when upright
        L = I * w0 * u
        eig = _eigenvalues(sc, tuple(L), tuple(n), kind)
        stable = ec
        if stable is None and _grows(eig):
            stable = False
        out.append(Equilibrium(
            kind, None if axis is None else axis + 1, text, stable, tex, desc,
            "energy-Casimir (E + a L.n + b |n|^2 on the leaf; sufficient); instability from an "
            "eigenvalue of the Euler-Poisson linearisation with positive real part",
            {"omega0": w0, "r_c": r}, list(eig)))
    return out


def _rest_equilibria(sc, p) -> list[Equilibrium]:
    """With a dissipative torque only the rest states are equilibria: hanging (stable: E
    decreases, V has a strict minimum) and upright (unstable)."""
    c = np.array([p["cx"], p["cy"], p["cz"]])
    r = _norm(c)
    out = []
    for kind, h in (("sleeping", 1.0), ("hanging", -1.0)):
        n = h * c / r
        eig = _eigenvalues(sc, (0.0, 0.0, 0.0), tuple(n), kind)
        stable = True if h < 0 else (False if _grows(eig) else None)
        axis = next((k + 1 for k in range(3) if np.hypot(*np.delete(c, k)) <= integrable.TOLERANCE * r),
                    None)
        out.append(Equilibrium(
            kind, axis, "at rest (damping -c omega decays any spin, so spinning states are not "
                        "equilibria); " + ("V maximal: unstable" if h > 0 else "V minimal, E decreasing: stable"),
            stable, rf"\tilde\omega = 0,\ \tilde n = {'+' if h > 0 else '-'}\hat r_c",
            f"at rest, centre of mass {'above' if h > 0 else 'below'} the pivot",
            "Lyapunov function E (dE/dt = -c |omega|^2); Euler-Poisson linearisation",
            {"r_c": r}, list(eig)))
    return out
