"""`derive analyze`: the lecture's analysis of the heavy top, done for the scene's own body.

For a scene (its moments, its effects, its initial state) this derives and evaluates:

1. T, V and L = T − V, in body components and in z-y-z Euler angles;
2. the equations of motion: Euler–Poisson (``models.euler_poisson``, always) and the
   Euler–Lagrange equations 𝕄 q̈ = F in the angles;
3. the cyclic coordinates (α always: V depends on the tilt; γ too for a symmetric body with the
   centre of mass on axis 3) and their momenta;
4. the Routh reduction to β and V_eff(β) when both α and γ are cyclic (``lagrangian.Reduction``);
5. the integrable case and its integrals, proved along the derived equations
   (``derive.symbolic.integrable``);
6. the relative equilibria and their stability, each evaluated at the scene's numbers:

   * sleeping top (spin about the upward vertical through the pivot, centre of mass on it) and
     hanging top (centre of mass below): for the Lagrange top from the series of V_eff about
     β = 0 or π with p_α = ±p_γ (the notes' k₂ ≥ 0, giving p_γ ≥ √(4MglI₁)); for any other body
     with the centre of mass on a principal axis k (spin ω₀ = ω̃_k(0) about it) from the
     energy–Casimir method: E + a L·n + b|n|² restricted to the symplectic leaf is definite iff
     ω₀²(I_k − I_m) > h M g |r_c| for both m ≠ k (h = +1 upright, −1 hanging) — a sufficient
     condition; with the centre of mass on no principal axis only the rest equilibria exist;
   * steady precession at the scene's tilt β₀ (Lagrange top, and the free symmetric body):
     ∂V_eff/∂β = 0 with p_α = I₁ α̇ sin²β₀ + p_γ cos β₀ gives I₁ cos β₀ α̇² − p_γ α̇ + M g l = 0,
     real roots iff p_γ² ≥ 4 M g l I₁ cos β₀; stable where V_eff″(β₀) > 0;
   * permanent rotations of a free body about each principal axis k: energy–Casimir with
     E − |L|²/(2I_k), Hessian diag(1/I_m − 1/I_k): definite iff I_k is the largest or the smallest
     moment; the linearisation has λ² = −ω₀²(I_k − I_i)(I_k − I_j)/(I_i I_j).

   ``stable`` is True when the (sufficient) symbolic condition holds at the scene's numbers,
   False when it fails and the linearisation has an eigenvalue with a positive real part (or
   the condition is also necessary, as k₂ ≥ 0 is), None when marginal (equal within
   ``integrable.TOLERANCE``), when the equilibrium does not exist at the scene's numbers, or
   when the sufficient condition fails but the spectrum is on the imaginary axis. The
   eigenvalues are those of the Euler–Poisson linearisation (L, n block) at the equilibrium, or
   of the reduced β equation for steady precession — there one ``Precession`` record per root
   α̇ holds that root's p_α, V_eff″ (evaluated with p_α eliminated: no cancellation at a small
   tilt), nutation frequency and eigenvalues, so no number is paired with another root's.

Every reported number has its SI unit (``equilibria.UNITS``: the JSON's ``units``, the Markdown
after the number). Expressions are displayed in a compact form (``closed_forms._compact``:
grouped and factored, for display only); the numbers are evaluated from the derived expressions.

This module assembles the analysis and its document; :mod:`derive.lecture.closed_forms` holds the
derived expressions and :mod:`derive.lecture.equilibria` the relative equilibria. All three import
SymPy: the command line and ``derive.analyze`` load this module when an analysis is asked for.
"""

from __future__ import annotations

import json
from dataclasses import dataclass

import numpy as np
import sympy as sp

from derive.errors import IntegrationError
from derive.lecture import own_body
from derive.lecture.closed_forms import _compact, _ep_model, _lagrangian, _latex, _routh
from derive.lecture.equilibria import UNITS, _axial, _check_finite, _equilibria, _Overflow
from derive.sim.scene import load_scene
from derive.symbolic import integrable
from derive.symbolic import effects as fx
from derive.symbolic import integral_proofs
from derive.symbolic.lagrangian import I1, I2, I3, l
from derive.symbolic.rotations import ANGLES


@dataclass
class Analysis:
    scene: object
    classification: integrable.Classification
    integrals: list
    proofs: dict
    equilibria: list

    @property
    def sections(self) -> list:
        """(title, [Markdown lines]) of the document (derived on demand: JSON does not need them)."""
        sc, cls = self.scene, self.classification
        return [_section_body(sc, cls), _section_energies(sc), _section_equations(sc),
                _section_cyclic(sc, cls), _section_integrals(sc, cls, self.integrals, self.proofs),
                _section_equilibria(self.equilibria)]

    def to_json(self) -> dict:
        c = self.classification
        veff = _effective_potential(self.scene)
        return {
            "case": c.case,
            **({"body_case": c.body_case} if c.body_case else {}),
            "reason": c.reason,
            "dissipative": c.dissipative,
            "integrals": [{"name": i.name, "expression": i.expression, "unit": i.unit,
                           "proved": self.proofs[i.name].holds if i.name in self.proofs else None,
                           **({"on": i.on} if i.on else {})} for i in self.integrals],
            **({"V_eff": sp.sstr(veff)} if veff is not None else {}),
            "equilibria": [e.to_json() for e in self.equilibria],
        }

    def to_markdown(self) -> str:
        title = self.scene.title or self.scene.source
        out = [f"# Analysis: {title}", "",
               f"Scene `{self.scene.source}`. Every formula is derived by `derive` (SymPy) for this "
               "body and these effects, then evaluated at the scene's numbers. Conventions: z-y-z "
               "Euler angles, body principal axes (tilde), n = Rᵀẑ the upward vertical in body "
               "axes, r_c the centre of mass from the pivot.", ""]
        for heading, lines in self.sections:
            out += [f"## {heading}", "", *lines, ""]
        return "\n".join(out).rstrip() + "\n"


def analyze(scene) -> Analysis:
    """Analyse a scene (path, dict or Scene). A scene with terms written by the user
    (``[[potential]]``, ``[[torque]]``) gets :func:`derive.lecture.own_body.analyze` instead.

    Raises
    ------
    SceneError
        Bad input (the scene checks of ``derive simulate``).
    IntegrationError
        A number the analysis must evaluate at the scene's (finite) numbers lies outside the
        double range: ``<file>: analyze: <equilibrium>: <quantity> overflows ...`` (CLI exit 3,
        as ``simulate`` for a state that overflows). The verdicts themselves are evaluated
        scale-free, so this names a reported number (a discriminant, an eigenvalue), never a
        verdict gone wrong in silence.
    """
    sc = load_scene(scene)
    if sc.terms:
        # A body with terms written by the user: its own analysis (integrals by symmetry,
        # rest equilibria at the critical points of V).
        return own_body.analyze(sc)
    cls = integrable.classify(sc)
    ints = integrable.integrals(cls)
    proofs = integral_proofs.proofs(cls)
    try:
        eqs = _equilibria(sc, cls)
        for e in eqs:
            _check_finite(e)
    except _Overflow as exc:
        raise IntegrationError(f"{sc.source}: analyze: {exc}") from None
    except (OverflowError, FloatingPointError, ZeroDivisionError, np.linalg.LinAlgError) as exc:
        # A safety net: every evaluation above is meant to end in _Overflow with its quantity.
        raise IntegrationError(f"{sc.source}: analyze: relative equilibria: a quantity overflows "
                               f"double precision at the scene's numbers ({type(exc).__name__})"
                               ) from None
    return Analysis(sc, cls, ints, proofs, eqs)


# ---------------------------------------------------------------------------------------------
# the document's sections


def _section_body(sc, cls):
    p = integrable.parameters(sc)
    b = sc.body
    lines = [f"Principal moments about the pivot: I1 = {b.I1:g}, I2 = {b.I2:g}, I3 = {b.I3:g} kg m²"
             + (" (symmetric about axis 3)." if sc.symmetric else ".")]
    if sc.gravity is not None:
        lines.append(f"Gravity: M = {p['M']:g} kg, g = {p['g']:g} m/s², r_c = ({p['cx']:g}, "
                     f"{p['cy']:g}, {p['cz']:g}) m.")
    else:
        lines.append("No gravity.")
    if sc.damping is not None:
        lines.append(f"Damping: torque −c ω̃ with c = {sc.damping.c:g} N m s"
                     + ("." if _damped(sc) else " (zero: no term, the body is conservative)."))
    lines += ["", f"**Case: {cls.case}** — {cls.reason}. (Classified within the relative "
                  f"tolerance `integrable.TOLERANCE` = {integrable.TOLERANCE:g}.)"]
    return "Body, effects and integrable case", lines


def _section_energies(sc):
    T, V, system = _lagrangian(sc.symmetric, _conservative(sc))

    Lv = sp.symbols("L1:4", real=True)
    moments = (I1, I1, I3) if sc.symmetric else (I1, I2, I3)
    Tb = sum((Li ** 2 / (2 * m) for Li, m in zip(Lv, moments)), sp.S.Zero)
    lines = [rf"$$ T = {_latex(Tb)} = \tfrac12\sum_i I_i\tilde\omega_i^2 $$", "",
             "In z-y-z Euler angles (energies in J):", "",
             rf"$$ T = {_latex(_compact(T))} $$", "", rf"$$ V = {_latex(_compact(V))} $$", "",
             rf"$$ L = T - V = {_latex(_compact(system.lagrangian))} $$"]
    return "Kinetic and potential energy, Lagrangian", lines


def _damped(sc) -> bool:
    """The scene's damping acts (a [damping] table with c = 0 adds no term: Scene.effects)."""
    return sc.damping is not None and sc.damping.effect in sc.effects


def _conservative(sc) -> tuple:
    return tuple(e.name for e in fx.lookup(sc.effects) if e.conservative)


def _section_equations(sc):
    m = _ep_model(sc.symmetric, sc.effects)
    lhs = r"\dot{\tilde\omega}" if m.state_names[0].startswith("omega") else r"\dot{\tilde L}"
    lines = ["Euler–Poisson (L = I ω̃ about the pivot, n = Rᵀẑ), derived from the effects registry:", "",
             rf"$$ {lhs} = {_latex(_compact(sp.Matrix(m.rhs[:3])))},\quad "
             rf"\dot{{\tilde n}} = {_latex(_compact(sp.Matrix(m.rhs[3:6])))} $$"]
    _, _, system = _lagrangian(sc.symmetric, _conservative(sc))
    lines += ["", "Euler–Lagrange in z-y-z angles, 𝕄 q̈ = F"
              + (" (conservative part; the damping torque adds Q = Bᵀτ̃)" if _damped(sc) else "")
              + ":", "",
              rf"$$ \mathbb{{M}} = {_latex(_compact(system.mass_matrix))} $$", "",
              rf"$$ F = {_latex(_compact(system.forcing))} $$"]
    return "Equations of motion", lines


def _effective_potential(sc):
    """The Routh reduction's V_eff(β; p_α, p_γ) for the scene's body in its display form
    (``_compact``; M g l = 0 without gravity), or None when α and γ are not both cyclic (the
    body is not symmetric about axis 3 with the centre of mass on it)."""
    if not (sc.symmetric and _axial(sc)):
        return None
    cyc = _lagrangian(sc.symmetric, _conservative(sc))[2].cyclic
    if ANGLES[0] not in cyc or ANGLES[2] not in cyc:
        return None
    veff = _routh()["Veff_display"]
    return veff.subs(l, 0) if sc.gravity is None else veff


def _section_cyclic(sc, cls):
    _, _, system = _lagrangian(sc.symmetric, _conservative(sc))
    cyc = system.cyclic
    lines = ["Cyclic coordinates: " + ", ".join(f"${_latex(q)}$" for q in cyc) + ".", ""]

    for q in cyc:
        lines += [rf"$$ p_{{{_latex(q)}}} = \partial L/\partial\dot{{{_latex(q)}}} = "
                  rf"{_latex(_compact(system.momentum(q)))} $$", ""]
    if _damped(sc):
        lines.append("The damping torque breaks these conservation laws (p_α decays as "
                     "d(L·n)/dt = −c ω̃·n).")
    veff = _effective_potential(sc)
    if veff is not None:
        lines += ["", "Routh reduction (α and γ cyclic) to the β degree of freedom (momenta in "
                      "kg m² s⁻¹, V_eff in J):", "",
                  rf"$$ E' = \tfrac12 I_1\dot\beta^2 + V_\text{{eff}}(\beta),\quad "
                  rf"V_\text{{eff}} = {_latex(veff)} $$"]
        if sc.gravity is None:
            lines.append("(for the conservative part: with damping p_α, p_γ and E′ decay).")
    else:
        lines += ["", "No Routh reduction to one degree of freedom: γ is not cyclic (the body is "
                      "not symmetric about axis 3 with the centre of mass on it); only α is "
                      "eliminated, by p_α = L·n." if ANGLES[0] in cyc else "No cyclic coordinate."]
        if cls.case == "lagrange" and not cls.dissipative:
            lines.append("In Euler angles about the body's own symmetry axis (the Lagrange case "
                         "here, see the integrals) both α and γ are cyclic: the equilibria below use "
                         "that reduction, the moments relabelled.")
    return "Cyclic coordinates, momenta, Routh reduction", lines


def _section_integrals(sc, cls, ints, proofs):
    lines = []
    if cls.body_case is not None:
        lines += [f"The body is a {cls.body_case} body, but this state is off the level where its "
                  "extra integral exists (see the case above): only the integrals every such body "
                  "has are listed.", ""]
    extra = cls.extra.name if cls.extra is not None else None
    for i in ints:
        pr = proofs.get(i.name)
        unit = integrable.pretty_unit(i.unit)
        lines += [f"$$ {i.latex} $$", "",
                  f"Name `{i.name}`" + (f", in {unit}" if unit else " (dimensionless)")
                  + (f"; the simulation writes it as `integral_{i.name}`" if i.name == extra else "")
                  + ".", ""]
        if pr is None:
            continue
        if pr.factor is not None:
            lines.append(rf"Proved: along the derived Euler–Poisson equations with the case's "
                         rf"relations, $dG/dt = {_latex(pr.factor)}\,(\tilde L\cdot\tilde n)$: "
                         rf"conserved on $\tilde L\cdot\tilde n = 0$.")
        else:
            lines.append("Proved: its time derivative along the derived Euler–Poisson equations "
                         + ("(with the case's relations " + ", ".join(
                             f"{k} = {v}" for k, v in integrable.extra_relations(cls).items())
                            + ") " if cls.extra is not None and i.name == cls.extra.name else "")
                         + f"simplifies to {'0' if pr.holds else _latex(pr.derivative)}.")
        lines.append("")
    if cls.dissipative:
        lines.append("Damping: only |n|² = 1 survives.")
    return "Integrals of the motion", lines


def _section_equilibria(eqs):
    lines = []
    verdict = {True: "stable", False: "unstable", None: "undecided / marginal"}
    for e in eqs:
        shown = {k: v for k, v in e.values.items()
                 if k not in ("roots", "alpha_dot_roots", "V_eff_second_derivative")}
        lines += [f"### {e.kind}" + (f", axis {e.axis}" if e.axis else ""), "", e.description + ".", "",
                  f"$$ {e.latex} $$", "", f"Method: {e.method}.", "",
                  f"At the scene's numbers: **{verdict[e.stable]}**. "
                  + ", ".join(f"{k} = {_fmt(v)}{_unit(k) if v is not None else ''}"
                              for k, v in shown.items()) + "."]
        if e.values.get("roots"):
            lines += ["", "| α̇" + _unit("alpha_dot", " [{}]") + " | p_α" + _unit("p_alpha", " [{}]")
                      + " | V_eff″(β₀)" + _unit("V_eff_second_derivative", " [{}]")
                      + " | nutation ω_n = √(V_eff″/I₁)" + _unit("nutation_frequency", " [{}]")
                      + " | eigenvalues" + _unit("eigenvalues", " [{}]") + " | verdict |",
                      "|---|---|---|---|---|---|"]
            lines += [f"| {_fmt(r.alpha_dot)} | {_fmt(r.p_alpha)} | {_fmt(r.curvature)} | "
                      f"{_fmt(r.nutation_frequency) if r.nutation_frequency is not None else '—'} | "
                      f"{', '.join(_fmt(z) for z in r.eigenvalues)} | {verdict[r.stable]} |"
                      for r in e.values["roots"]]
        elif len(e.eigenvalues):
            lines += ["", "Eigenvalues" + _unit("eigenvalues", " [{}]") + ": "
                      + ", ".join(_fmt(z) for z in e.eigenvalues) + "."]
        lines.append("")
    if not eqs:
        lines.append("None: the damping decays every motion to rest, in any orientation.")
    return "Relative equilibria and their stability", lines


def _unit(name: str, form: str = " {}") -> str:
    """The unit of a reported number for Markdown (superscripts) in ``form``; "" if none."""
    unit = integrable.pretty_unit(UNITS.get(name, "1"))
    return form.format(unit) if unit else ""


def _fmt(v) -> str:
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_fmt(x) for x in v) + "]"
    if isinstance(v, complex) or isinstance(v, np.complexfloating):
        return f"{v.real + 0.0:.4g}{v.imag + 0.0:+.4g}i"  # + 0.0: no "-0" from a negative zero
    if isinstance(v, float):
        return f"{v:.6g}"
    return str(v)


def render(scene, fmt: str = "markdown") -> str:
    """The analysis as Markdown (LaTeX formulas) or JSON (the contract in docs/analyze.md)."""
    a = analyze(scene)
    if fmt == "json":
        return json.dumps(a.to_json(), indent=2)
    return a.to_markdown()
