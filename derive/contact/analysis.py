"""``derive analyze`` for a top on a table: its integrals, sleeping and inversion, derived.

* The sleeping top on a frictionless plane. The centre of mass moves only vertically (no
  horizontal force, horizontal momentum zero), z = z(β) from the height constraint, so
  L = ½ M ż² + T_rot(β, α̇, β̇, γ̇) − M g z(β). α and γ are cyclic; Routh's reduction gives
  V_eff(β) (:func:`reduced_potential`; ż² is kinetic, so it does not enter).
  The upright spin (β = 0, p_α = p_γ = I₃ ω₃) is stable when V_eff''(0) > 0,
  I₃² ω₃² > −4 I₁ M g z''(0), with I₁ about the centre of mass — for the pivoted top it is
  I₁ + M l² about the pivot.
* The tippe top (a sphere, radius r, centre s = α r above the centre of mass). Friction lowers
  E while Jellett's J = L·a stays, so the states friction leads to minimise E at fixed J. Over
  ω, min ½ ωᵀIω with (Iω)·a = J is J²/(2 aᵀ I a) at ω ∥ a; for large J the stable tilts are
  the maxima of f(β) = aᵀ I a. The upright spin is unstable when f'(β)/sin β > 0 at β = 0 and
  the inverted one stable when f'(β)/sin β > 0 at β = π: 1 − α < I₁/I₃ < 1 + α.
  Its final spin follows from J: I₃ ω₃ (s + r) = J₀.
"""
from __future__ import annotations

import functools
import json
import math

import sympy as sp

from derive.contact.equations import I1, I3, MASS, GRAV, OMEGA, contact
from derive.contact.geometry import OFFSET, RADIUS, height_in_angles, vertical_in_body
from derive.contact.integrals import expressions, holds
from derive.contact.friction import NORMAL, power
from derive.contact.laws import LAWS
from derive.contact.scene import ContactScene
from derive.symbolic.lagrangian import kinetic_energy_symmetric, p_alpha, p_gamma
from derive.symbolic.rotations import alpha, alpha_d, beta, beta_d, gamma_d

SPIN, N0, THETA0, RATIO = sp.symbols("omega3 n0 theta0 alpha", real=True)
#: The stem sphere's radius r₂ and the offset s₂ of its centre along ê₃.
STEM_RADIUS, STEM_OFFSET = sp.symbols("r2 s2", real=True)


# The Routhian's simplification is the costly step and its result depends on the shape alone:
# each shape's is derived once per process (every contact scene of that shape asks for it).
@functools.lru_cache(maxsize=None)
def reduced_potential(shape: str) -> sp.Expr:
    """V_eff(β) of the body on a frictionless plane with its centre of mass on a vertical line:
    Routh's reduction of L = ½ M ż² + T_rot − M g z(β), z(β) the height constraint, with
    p_α = ∂L/∂α̇ and p_γ = ∂L/∂γ̇ held (the symbols ``p_alpha``, ``p_gamma``) and β̇ = 0."""
    z = height_in_angles(contact(shape).shape)
    zdot = sp.diff(z, beta) * beta_d
    L = MASS * zdot**2 / 2 + kinetic_energy_symmetric() - MASS * GRAV * z
    rates = sp.solve([sp.diff(L, alpha_d) - p_alpha, sp.diff(L, gamma_d) - p_gamma], [alpha_d, gamma_d], dict=True)[0]
    routhian = (L - p_alpha * alpha_d - p_gamma * gamma_d).subs(rates).subs(beta_d, 0)
    return sp.simplify(-routhian)


@functools.lru_cache(maxsize=None)
def sleeping_condition(shape: str) -> sp.Expr:
    """The upright spin's stability on a frictionless plane, as ``expr > 0`` (ω₃ the spin):
    8 I₁ times the β² coefficient of V_eff at p_α = p_γ = I₃ ω₃."""
    veff = reduced_potential(shape).subs({p_alpha: I3 * SPIN, p_gamma: I3 * SPIN})
    return sp.factor(sp.series(veff, beta, 0, 3).removeO().coeff(beta, 2) * 8 * I1)


def _tilt_function():
    """f(β) = aᵀ I a for the sphere, γ = 0 (the body is axisymmetric)."""
    a = contact("sphere").a.subs(dict(zip(sp.symbols("n1 n2 n3", real=True),
                                          vertical_in_body((alpha, beta, sp.S.Zero)))))
    return I1 * (a[0] ** 2 + a[1] ** 2) + I3 * a[2] ** 2


def inversion_conditions() -> tuple[sp.Expr, sp.Expr]:
    """(c₀, c_π): the upright spin is unstable when c₀ > 0, the inverted one stable when c_π > 0
    (f'(β)/sin β at β = 0 and π, with s = α r)."""
    f = _tilt_function()
    ratio = sp.simplify(sp.diff(f, beta) / sp.sin(beta))
    sub = {OFFSET: RATIO * RADIUS}
    return (sp.factor(sp.limit(ratio, beta, 0).subs(sub)), sp.factor(sp.limit(ratio, beta, sp.pi).subs(sub)))


def inversion_interval() -> tuple[sp.Expr, sp.Expr]:
    """The bounds of I₁/I₃ between which the tippe top inverts: (1 − α, 1 + α)."""
    k = sp.Symbol("k", positive=True)
    c0, cpi = (c.subs(I1, k * I3) for c in inversion_conditions())
    lo, hi = sp.solve(c0, k)[0], sp.solve(cpi, k)[0]
    return lo, hi


def final_spin() -> sp.Expr:
    """The spin after inversion from Jellett: ω₃ at β = π when the top started spinning at n₀
    about ê₃ with tilt θ₀, in terms of α = s/r: n₀ (α − cos θ₀)/(1 + α)."""
    J = expressions(contact("sphere"))["jellett"]
    n = sp.symbols("n1 n2 n3", real=True)
    start = J.subs(dict(zip(n, vertical_in_body((alpha, THETA0, sp.S.Zero))))).subs(
        {OMEGA[0]: 0, OMEGA[1]: 0, OMEGA[2]: N0})
    end = J.subs(dict(zip(n, vertical_in_body((alpha, sp.pi, sp.S.Zero))))).subs(
        {OMEGA[0]: 0, OMEGA[1]: 0, OMEGA[2]: SPIN})
    return sp.simplify(sp.solve(sp.Eq(start, end), SPIN)[0].subs(OFFSET, RATIO * RADIUS))


def stem_tilt() -> sp.Expr:
    """cos θ at which a second sphere (radius r₂ centred at s₂ ê₃) is as low as the first: the
    lowest points' heights above the centre of mass, s cos θ − r and s₂ cos θ − r₂, equal at
    cos θ = (r₂ − r)/(s₂ − s); past it (the stem farther out, s₂ > s) the stem is the lower."""
    c = sp.Symbol("c", real=True)
    return sp.solve(sp.Eq(OFFSET * c - RADIUS, STEM_OFFSET * c - STEM_RADIUS), c)[0]


def analyze(sc: ContactScene) -> dict:
    """The analysis of a contact scene, as the JSON of ``derive analyze``.

    Parameters
    ----------
    sc : ContactScene
        The validated scene.

    Returns
    -------
    dict
        ``case`` ("contact"), ``shape``, ``law``; ``integrals`` (name and expression in the
        body-frame symbols n, ω = (w1, w2, w3), v_b, z) the case keeps; ``energy_rate_sliding``
        (Ė = F_t·u_t); ``equilibria`` (the sleeping top: I₃²ω₃² + 4 I₁ M g s > 0, stable with
        the scene's numbers on a frictionless plane, else null); for a tippe top (sphere, s > 0)
        ``inversion``: the interval 1 − α < I₁/I₃ < 1 + α, whether the scene is in it, and the
        final spin n₀(α − cos θ₀)/(1 + α) with the scene's numbers; with a ``stem``, ``stem``:
        cos θ past which the stem is the lower sphere, and that tilt with the scene's numbers.
    """
    c, law = contact(sc.shape), LAWS[sc.law]
    ints = expressions(c)
    names = holds(c, law, sc.symmetric)
    out = {"case": "contact", "shape": sc.shape, "law": sc.law,
           "integrals": [{"name": k, "expression": str(ints[k])} for k in names],
           "energy_rate_sliding": f"dE/dt = {power(law, NORMAL, sp.Matrix(sp.symbols('ut1 ut2 ut3', real=True)))}",
           "equilibria": []}
    num = {I1: sc.I1, I3: sc.I3, MASS: sc.M, GRAV: sc.g, RADIUS: sc.radius, OFFSET: sc.offset}
    if sc.shape != "disc" and sc.symmetric:
        cond = sleeping_condition(sc.shape)
        w = sc.omega[2] if sc.omega is not None else sc.rates[0] + sc.rates[2]
        out["equilibria"].append({"kind": "sleeping", "axis": 3, "condition": f"{cond} > 0",
                                  "stable": bool(cond.subs(num).subs(SPIN, w) > 0)
                                  if law.name == "none" else None})
    if sc.shape == "sphere" and sc.symmetric and sc.offset > 0:
        lo, hi = inversion_interval()
        a = sc.offset / sc.radius
        spin = final_spin()
        n0 = sc.omega[2] if sc.omega is not None else sc.rates[0] + sc.rates[2]
        out["inversion"] = {"condition": f"{lo} < I1/I3 < {hi}",
                            "inverts": bool(lo.subs(RATIO, a) < sc.I1 / sc.I3 < hi.subs(RATIO, a)),
                            "final_spin_expression": str(spin),
                            "final_spin": float(spin.subs({RATIO: a, N0: n0, THETA0: sc.angles[1]}))}
    if sc.stem is not None:
        cos_s = stem_tilt()
        v = float(cos_s.subs({RADIUS: sc.radius, OFFSET: sc.offset, STEM_RADIUS: sc.stem[0],
                              STEM_OFFSET: sc.stem[1]})) if sc.stem[1] != sc.offset else math.nan
        out["stem"] = {"condition": f"cos(theta) < {cos_s}" if sc.stem[1] > sc.offset else f"cos(theta) > {cos_s}",
                       "tilt": math.acos(v) if -1 <= v <= 1 else None}
    return out


def render(sc: ContactScene, fmt: str = "markdown") -> str:
    """``derive analyze``'s text for a contact scene (``json`` or ``markdown``)."""
    res = analyze(sc)
    if fmt == "json":
        return json.dumps(res)
    lines = [f"# {sc.title or 'A body on a table'}: {sc.shape}, {sc.law}", "", "## Integrals", ""]
    lines += [f"- {i['name']}: `{i['expression']}`" for i in res["integrals"]]
    if res["energy_rate_sliding"]:
        lines += ["", f"While sliding: `{res['energy_rate_sliding']}`"]
    for e in res["equilibria"]:
        lines += ["", f"## Sleeping top ({'frictionless plane' if sc.law == 'none' else 'frictionless condition'})",
                  "", f"`{e['condition']}` — stable: {e['stable']}"]
    if "inversion" in res:
        inv = res["inversion"]
        lines += ["", "## Tippe top", "", f"Inverts when `{inv['condition']}`: {inv['inverts']}",
                  f"Final spin `{inv['final_spin_expression']}` = {inv['final_spin']:.6g} rad/s"]
    if "stem" in res:
        st = res["stem"]
        tilt = "never" if st["tilt"] is None else f"θ = {st['tilt']:.6g} rad"
        lines += ["", "## Stem", "", f"The stem is the lower sphere when `{st['condition']}` (from {tilt}); "
                  "a top that turns over onto it spins there at J/(I3 (s2 + r2)), J the stem's Jellett "
                  "integral as the switch leaves it (the final spin above is a top's without a stem)."]
    return "\n".join(lines) + "\n"
