"""The integrable cases' integrals proved along the derived Euler–Poisson equations.

For a case of :mod:`derive.symbolic.integrable` and one of its integrals F (``Integral.formula``
applied to SymPy symbols), ``prove`` computes

    dF/dt = Σ ∂F/∂y · ẏ      (y = L, n; ẏ the rhs of ``models.euler_poisson``)

with the case's relations substituted (``RELATIONS``), and for an integral on a level set
(``Integral.on``, e.g. L·n = 0) divides it by L·n as polynomials in the state. ``markdown``
writes the results for the derivation report. This module loads SymPy and the symbolic models;
the numeric classification in :mod:`derive.symbolic.integrable` does not.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Callable

import sympy as sp

from derive.symbolic import models
from derive.symbolic.effects import GENERAL_GRAVITY
from derive.symbolic.formulations import UNIVERSAL
from derive.symbolic.integrable import (AREA, CASIMIR, ENERGY, EXTRA, RELABELLINGS, RELATIONS,
                                        SPHERE, TOLERANCE, Classification, _area, relabel_spec,
                                        integrals, relabelled)


@dataclass(frozen=True)
class Proof:
    """dF/dt along the Euler–Poisson flow with the case's relations substituted: ``derivative``
    (simplified; 0 proves F conserved) and, for an integral on a level set ("L.n = 0"),
    ``derivative = factor · (L·n)`` with ``remainder`` 0."""

    case: str
    integral: str
    derivative: object
    factor: object = None
    remainder: object = None

    @property
    def holds(self) -> bool:
        if self.factor is not None:
            return self.remainder == 0
        return self.derivative == 0


@functools.lru_cache(maxsize=None)
def _general_model():
    return models.build(UNIVERSAL, False, (GENERAL_GRAVITY,))


def _symbols():
    """(model, {name: parameter symbol}, L, n): L as the model gives it — its state (L1, L2, L3)
    or, when the model's state is the body angular velocity, (I1 ω̃1, I2 ω̃2, I3 ω̃3)."""
    m = _general_model()
    p = {s.name: s for s in m.params}
    first = m.states[0:3]
    if first[0].name.startswith("omega"):
        L = tuple(p[f"I{i + 1}"] * first[i] for i in range(3))
    else:
        L = tuple(first)
    n = tuple(m.states[3:6])
    return m, p, L, n


def relations(case: str) -> dict:
    """The case's relations as a SymPy substitution {symbol: expression}."""
    return _relations(RELATIONS[case])


def proofs(c: Classification) -> dict:
    """{name: Proof} for every integral of a classified scene (``integrals(c)``)."""
    out = {i.name: prove("general", i.name) for i in integrals(c) if i.name in
           (ENERGY.name, AREA.name, CASIMIR.name)}
    extra = c.canonical_extra
    if extra is not None:
        out[c.extra.name] = prove(c.case, extra.name, None, tuple(c.axes))
    return out


def _relations(spec: dict) -> dict:
    _, p, _, _ = _symbols()
    return {p[k]: sp.sympify(v, locals=p) for k, v in spec.items()}


def time_derivative(formula: Callable, subs: dict):
    """dF/dt = Σ ∂F/∂y · ẏ along the derived Euler–Poisson rhs, with ``subs`` applied to the
    parameters, as one cancelled rational expression."""
    m, p, L, n = _symbols()
    F = formula(L, n, p)
    dF = sum((sp.diff(F, y) * f for y, f in zip(m.states[:6], m.rhs[:6])), sp.S.Zero)
    return sp.factor(sp.cancel(sp.together(dF.subs(subs))))


@functools.lru_cache(maxsize=None)
def prove(case: str, integral_name: str | None = None, relations_of: str | None = None,
          axes: tuple = RELABELLINGS[0]) -> Proof:
    """Prove a case's integral (default: its extra one; names in the formulas' axes) along the
    derived equations, with the relations of ``relations_of`` (default: the case itself; another
    case gives a control). With ``axes`` the integral and the relations are first relabelled to
    the body's axes, and the proof runs on the body's own equations. Integrals on a level set
    are divided by L·n as polynomials in the state."""
    integral = (EXTRA[case] if integral_name is None
                else next(i for i in (ENERGY, AREA, CASIMIR, SPHERE, *EXTRA.values())
                          if i.name == integral_name))
    spec = (integral.relations if relations_of is None and integral.relations is not None
            else RELATIONS[relations_of or case])
    subs = _relations(relabel_spec(spec, axes))
    integral = relabelled(integral, axes)
    dF = time_derivative(integral.formula, subs)
    if integral.on is None:
        return Proof(case, integral.name, dF)
    m, p, L, n = _symbols()
    num, den = sp.fraction(sp.together(dF))
    Ln = sp.expand(_area(L, n, p).subs(subs))
    q, r = sp.div(sp.expand(num), Ln, *m.states[:6])
    return Proof(case, integral.name, dF, factor=sp.factor(q / den), remainder=sp.expand(r))


def markdown() -> list[str]:
    """Markdown lines for the derivation report: each case, its extra integral and what the
    proof along the derived Euler–Poisson equations gave."""
    out = ["Integrable cases of the heavy body about a fixed point (classified within the relative "
           f"tolerance {TOLERANCE:g}); each integral's time derivative along the derived "
           "Euler–Poisson equations, with the case's relations substituted:", ""]
    names = {sp.Symbol(f"omega{i}", real=True): rf"\tilde\omega_{i}" for i in (1, 2, 3)}
    names.update({sp.Symbol(c, real=True): f"c_{c[1]}" for c in ("cx", "cy", "cz")})
    for case, integral in EXTRA.items():
        rel = ", ".join(f"{k} = {v}" for k, v in RELATIONS[case].items())
        proof = prove(case)
        if proof.factor is not None:
            result = (rf"$\dot G = {sp.latex(proof.factor, symbol_names=names)}\,(\tilde L\cdot\tilde n)$, zero on "
                      rf"$\tilde L\cdot\tilde n = 0$")
        else:
            result = r"$\dot F = 0$" if proof.holds else rf"$\dot F = {sp.latex(proof.derivative, symbol_names=names)}$"
        out += [f"- **{case}** ({rel}):", "", f"  $$ {integral.latex} $$", "", f"  {result}.", ""]
    return out
