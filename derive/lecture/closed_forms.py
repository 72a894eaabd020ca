"""The derived expressions of `derive analyze`, cached per process: T, V and the Euler–Lagrange
equations in z-y-z angles, the Euler–Poisson model and its Jacobian, the symmetric top's Routh
reduction, and their compact LaTeX display.
"""

from __future__ import annotations

import functools

import sympy as sp

from derive.symbolic import effect_sums as sums
from derive.symbolic import effects as fx
from derive.symbolic import models, stability
from derive.symbolic.formulations import UNIVERSAL
from derive.symbolic.lagrangian import (I1, I2, I3, EulerLagrange, Mass, g, kinetic_energy, l, p_alpha,
                                        p_gamma)
from derive.symbolic.rotations import ANGLES, RATES, ZYZ, alpha_d, beta, gamma_d, trig_reduce


#: Above this many operations (SymPy's count_ops) an expression is displayed as derived:
#: ``_compact`` factors each group of terms, a cost that grows with the expression.
COMPACT_MAX_OPS = 400
#: ... and a group of more terms than this is shown over its common denominator, unfactored.
COMPACT_MAX_TERMS = 6


def _latex(expr) -> str:
    names = {qd: rf"\dot{{{sp.latex(q)}}}" for q, qd in zip(ANGLES, RATES)}
    for i in range(3):
        for s in (sp.Symbol(f"L{i + 1}", real=True), sp.Symbol(f"n{i + 1}", real=True)):
            names[s] = rf"{s.name[0]}_{{{i + 1}}}"
        names[sp.Symbol(f"omega{i + 1}", real=True)] = rf"\tilde{{\omega}}_{{{i + 1}}}"
    for c in ("cx", "cy", "cz"):
        names[sp.Symbol(c, real=True)] = rf"c_{{{c[1]}}}"
    return sp.latex(expr, symbol_names=names)


def _is_variable(s) -> bool:
    """An angle, a rate, a momentum or a state component (not a body or effect parameter)."""
    return s in ANGLES or s in RATES or s in (p_alpha, p_gamma) or s.name[:-1] in ("L", "n", "omega")


def _compact(expr):
    """A shorter equal form of ``expr`` for display only (the numbers never use it): its terms
    grouped by the body and effect parameters they carry, each group over a common denominator
    and factored, with sin² → 1 − cos² tried in its numerator; the result, or ``expr`` itself
    when that is no shorter (SymPy's count_ops). A matrix elementwise. Expressions above
    ``COMPACT_MAX_OPS`` are returned as they are (bounded cost: a few factorisations of small
    polynomials: about 0.05 s for V_eff, 0.3 s for all the expressions of a symmetric top, 0.6 s
    for an asymmetric body; once per process). E.g. the expanded V_eff becomes
    (p_α − p_γ cos β)²/(2 I₁ sin²β) + M g l cos β."""
    if isinstance(expr, sp.MatrixBase):
        return expr.applyfunc(_compact)
    return _compact_cached(sp.sympify(expr))


@functools.lru_cache(maxsize=256)
def _compact_cached(expr):
    if sp.count_ops(expr) > COMPACT_MAX_OPS:
        return expr
    groups: dict[frozenset, list] = {}
    for term in sp.Add.make_args(sp.expand(expr)):
        groups.setdefault(frozenset(x for x in term.free_symbols if not _is_variable(x)), []).append(term)
    parts = []
    for terms in groups.values():
        num, den = sp.fraction(sp.together(sp.Add(*terms)))
        if len(terms) > COMPACT_MAX_TERMS:  # multivariate factoring grows fast with the terms
            parts.append(num / den)
            continue
        tries = [sp.factor(num)] + [sp.factor(sp.expand(num.subs(sp.sin(a) ** 2, 1 - sp.cos(a) ** 2)))
                                    for a in ANGLES if num.has(sp.sin(a))]
        parts.append(min(tries, key=sp.count_ops) / sp.factor(den))
    return min((sp.Add(*parts), expr), key=sp.count_ops)


@functools.lru_cache(maxsize=None)
def _ep_model(symmetric: bool, effects: tuple):
    return models.build(UNIVERSAL, symmetric, effects)


@functools.lru_cache(maxsize=None)
def _ep_jacobian(symmetric: bool, effects: tuple):
    """The (L, n) block of the Euler–Poisson Jacobian as a NumPy function of (y6, p)."""
    m = _ep_model(symmetric, effects)
    y = m.states[:6]
    J = sp.Matrix(m.rhs[:6]).jacobian(sp.Matrix(y))
    return sp.lambdify((y, m.params), J, "numpy"), m


@functools.lru_cache(maxsize=None)
def _lagrangian(symmetric: bool, effects: tuple):
    """(T, V, EulerLagrange) in z-y-z angles for the body and the conservative effects."""
    effs = fx.lookup(effects)
    sym = sums.Symbols(effs)
    moments = (I1, I1, I3) if symmetric else (I1, I2, I3)
    T = trig_reduce(kinetic_energy(moments))
    V = trig_reduce(sums.potential(effs, ZYZ.matrix(), sym))
    return T, V, EulerLagrange(T - V)


@functools.lru_cache(maxsize=None)
def _routh():
    """The symmetric top's Routh reduction (symbol l; l = 0 is the free symmetric body), the
    steady-precession quadratic and the series of V_eff about β = 0 and π."""
    st = stability.sleeping_top()
    red = st.reduction
    system = red.system
    Veff = red.effective_potential
    # p_α as a function of α̇ at fixed p_γ (γ̇ eliminated): I₁ α̇ sin²β + p_γ cos β.
    pg_of_rate = system.momentum(ANGLES[2]) - p_gamma  # linear in γ̇
    gd = -pg_of_rate.subs(gamma_d, 0) / sp.diff(pg_of_rate, gamma_d)
    pa = sp.factor(trig_reduce(system.momentum(ANGLES[0]).subs(gamma_d, gd)))
    dV = sp.together(sp.diff(Veff, beta).subs(p_alpha, pa))
    num = sp.factor(trig_reduce(sp.numer(dV)))
    # The factor that holds α̇: the steady-precession quadratic (the others are powers of sin β).
    quad = sp.Mul(*[f ** k for f, k in sp.factor_list(num)[1] if f.has(alpha_d)])
    quad = sp.expand(quad)
    if sp.Poly(quad, alpha_d).LC().could_extract_minus_sign():
        quad = -quad
    disc = sp.factor(sp.discriminant(quad, alpha_d))
    d2V = sp.diff(Veff, beta, 2)
    # V_eff″ with p_α = I₁ α̇ sin²β + p_γ cos β eliminated: a polynomial in α̇, cos β, sin β with
    # no 1/sin β left. The form in p_α has terms ~ p_γ²/(I₁ β⁴) that cancel at a small tilt (at
    # β₀ = 1e-4 nothing is left in double precision); this one has none, and it is the one
    # evaluated.
    d2V_rate = sp.factor(trig_reduce(sp.together(d2V.subs(p_alpha, pa))))
    args = (I1, Mass, g, l, p_gamma, beta)
    # Two backends of the same expressions: doubles, and mpmath (an unbounded exponent) for the
    # scenes whose products of doubles overflow (I₁ = 1e300, p_γ = 1e200, which the tests run).
    numeric = {backend: {
        "coefficients": sp.lambdify(args, sp.Poly(quad, alpha_d).all_coeffs(), backend),
        "discriminant": sp.lambdify(args, disc, backend),
        "d2V": sp.lambdify(args + (alpha_d,), d2V_rate, backend),
        "p_alpha": sp.lambdify(args + (alpha_d,), pa, backend)} for backend in ("math", "mpmath")}
    # About β = π, p_α = −p_γ (n = −ê₃ there). V_eff is invariant under β → π − β, p_α → −p_α,
    # l → −l (cos β changes sign, sin²β does not), so the series about π is the series about 0
    # with l → −l (tests/test_analyze.py checks the symmetry on V_eff itself).
    k2_pi = sp.factor(st.coefficient(2).subs(l, -l))
    return {"red": red, "Veff": Veff, "Veff_display": _compact(Veff), "p_alpha_of_rate": pa,
            "quadratic": quad, "discriminant": disc, "d2V": d2V, "d2V_rate": d2V_rate,
            "numeric": numeric, "k2_0": st.coefficient(2), "k2_pi": k2_pi,
            "threshold": st.threshold, "sleeping": st}
