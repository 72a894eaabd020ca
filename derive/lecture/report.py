"""The two Markdown documents: the lecture verification and the derivation.

``documents()`` returns {"lecture-verification.md": …, "derivation.md": …}. Every formula in them
is printed from the derived sympy objects (`sympy.latex`), nothing is typed here. The text is
byte-deterministic: no clock, no unordered iteration (dictionaries are filled in a fixed order),
and sympy's printers order terms canonically — two runs, and runs under different
PYTHONHASHSEED, give identical bytes (the tests check this).

Cost: the verification shares the derivations' caches (one heavy top, one Routh reduction), so
the only large extra is integrating the solids' inertia tensors (about a second in all).
documents() is computed once per process.
"""
from __future__ import annotations

import functools

import sympy as sp

from derive.lecture import claims as lecture
from derive.lecture import targets, verify
from derive.symbolic import inertia, integral_proofs
from derive.symbolic import lagrangian as lg
from derive.symbolic import rotations as rot
from derive.symbolic import stability as stab
from derive.symbolic.stability import sleeping_top

INERTIA_SOLIDS = ("cylinder", "sphere", "cone", "box")
"""Solids of `inertia.SOLIDS` whose tensors derivation.md shows (plus the thin disk)."""


def _tex(obj) -> str:
    return verify.latex(obj)


def _display(lhs: str, obj, rhs_note: str = "") -> str:
    return f"$$ {lhs} = {_tex(obj)}{rhs_note} $$"


# ---- lecture-verification.md ------------------------------------------------------------------
def lecture_verification() -> str:
    results = verify.run()
    claims = {c.id: c for c in lecture.CLAIMS}
    counts = ", ".join(f"{sum(r.verdict == v for r in results)} {v}" for v in verify.VERDICTS)
    mismatched = verify.mismatches(results)
    out = [
        "# Lecture 26 (rigid-body rotation): verification of the slides",
        "",
        "Every formula on the slides of PHY 711 Lecture 26 (a machine transcript of the notes) is",
        "typed as written in `derive/lecture/claims.py` and compared with the result derived independently by",
        "`derive.symbolic.rotations`, `derive.symbolic.inertia`, `derive.symbolic.lagrangian` and `derive.symbolic.stability`",
        "(see `derivation.md`). The difference claim − derived is tested symbolically first (as built,",
        "`expand`, `cancel`, `trig_reduce`, small `simplify`), else at six seeded random points exactly in",
        "rationals or with 50-digit mpmath arithmetic; the *method* column names the step that decided.",
        "",
        "Verdicts: **holds** — the formula as written is right; **typo** — it is wrong as written but the",
        "recorded correction (shown) holds; **fails** — wrong, no slip-level correction.",
        "",
        f"**{len(results)} claims: {counts}.** "
        + ("Every verdict is the expected one (`lecture.EXPECTED`)." if not mismatched
           else "Verdicts differing from `lecture.EXPECTED`: "
           + ", ".join(f"`{i}` (expected {e}, got {g})" for i, e, g in mismatched) + "."),
        "",
        "## Findings",
        "",
    ]
    for r in results:
        if r.verdict == "holds":
            continue
        c = claims[r.id]
        out += [f"### `{r.id}` — {r.verdict}", "", f"*{c.section}*", "", "As in the transcript:", "", "```latex"]
        out += list(c.latex) + ["```"]
        if r.corrected is not None and r.verdict == "typo":
            out += ["", "Corrected:", "", f"$$ {r.corrected.latex} $$"]
        out += ["", f"Derived: $ {verify._shown(r, 'markdown')} $", "", f"Method: {r.method}.", "", r.note, ""]
    out += ["### Notes on claims that hold", ""]
    out += [f"- `{r.id}`: {r.note}." for r in results if r.verdict == "holds" and r.note]
    out.append("")
    out += ["## All claims", "", verify.table("markdown")]
    return "\n".join(out)


# ---- derivation.md ----------------------------------------------------------------------------
def _rotations_section() -> list[str]:
    out = ["## 1. Rotations and angular velocity", "",
           "The orientation matrix maps body components to inertial ones, $v^0 = R\\,\\tilde v$; the",
           "slides' passive matrices give $\\tilde v = R^T v^0$. Angular velocity in the body frame by",
           "two routes: the notes' sum $\\tilde\\omega = \\dot\\alpha\\,\\hat e^0_{a_1} + \\dot\\beta\\,\\hat e'_{a_2}"
           " + \\dot\\gamma\\,\\hat e_{a_3}$ and the skew matrix $[\\tilde\\omega]_\\times = R^T\\dot R$.", ""]
    for conv in (rot.ZYZ, rot.ZXZ):
        w_sum = conv.omega_body_sum()
        # The z-y-z skew route is already computed (and cached) by the verification.
        w_skew = targets.derived("omega-body") if conv is rot.ZYZ else conv.omega_body_skew()
        # Both routes come out of `trig_reduce`, a canonical form: equal iff identical.
        agree = w_sum == w_skew or (w_sum - w_skew).applyfunc(rot.trig_reduce) == sp.zeros(3, 1)
        out += [f"### {conv.description}", "",
                _display("R(\\alpha, \\beta, \\gamma)", conv.matrix()), "",
                _display("\\tilde{\\omega}_{\\text{sum}}", w_sum), "",
                _display("\\tilde{\\omega}_{\\text{skew}}", w_skew), "",
                f"The two routes {'agree' if agree else 'DISAGREE'} (compared in `trig_reduce`'s canonical form).", "",
                _display("B(q),\\quad \\tilde{\\omega} = B\\dot q,\\quad B", conv.rate_matrix()), "",
                f"Singular set: $\\det B = {_tex(conv.singular_set())} = 0$; off it",
                "", _display("\\dot q = B^{-1}\\tilde{\\omega}", conv.rates_from_omega()), ""]
    return out


def _lagrangian_section() -> list[str]:
    st = sleeping_top()
    red, sys_ = st.reduction, st.reduction.system
    out = ["## 2. Kinetic energy and the heavy symmetric top (z-y-z)", "",
           _display("T", lg.kinetic_energy()), "",
           _display("T\\big|_{I_2 = I_1}", lg.kinetic_energy_symmetric()), "",
           _display("L = T - Mgl\\cos\\beta", sys_.lagrangian), "",
           _display("\\mathbb{M} = \\partial^2 L/\\partial\\dot q\\,\\partial\\dot q", sys_.mass_matrix), "",
           _display("F", sys_.forcing), "",
           _display("\\ddot q = \\mathbb{M}^{-1}F", sys_.accelerations), "",
           "Cyclic coordinates: " + ", ".join(f"${_tex(q)}$" for q in sys_.cyclic) + ", with conserved momenta", ""]
    for q in sys_.cyclic:
        out += [_display(f"p_{{{_tex(q)}}}", sys_.momentum(q)), ""]
    out += [_display("E = \\dot q\\cdot\\partial L/\\partial\\dot q - L", sys_.energy), "",
            "### Routh reduction to β", "",
            _display("\\dot\\alpha", red.rates_from_momenta[rot.alpha_d]), "",
            _display("\\dot\\gamma", red.rates_from_momenta[rot.gamma_d]), "",
            _display("E", red.energy), "",
            _display("V_{\\text{eff}}(\\beta)", red.effective_potential), "",
            _display("E' = E - \\frac{p_\\gamma^2}{2I_3}", red.reduced_energy), "",
            "L with $\\dot\\alpha, \\dot\\gamma$ substituted (an identity — the slides' $L(\\beta,\\dot\\beta)$):", "",
            _display("L\\big|_{p}", red.lagrangian_substituted), "",
            "Routh's Lagrangian for β, $L_\\beta = L - \\dot\\alpha p_\\alpha - \\dot\\gamma p_\\gamma$ "
            "(the centrifugal term has the opposite sign):", "",
            _display("L_\\beta", red.routh_lagrangian), "",
            _display("\\ddot\\beta = -V_{\\text{eff}}'(\\beta)/I_1", red.beta_acceleration), "",
            "### The sleeping top ($p_\\alpha = p_\\gamma$, β → 0)", "",
            _display("V_{\\text{eff}}", st.series, " + O(\\beta^6)"), "",
            _display("k_2", st.coefficient(2)), "", _display("k_4", st.coefficient(4)), "",
            _display("E'", st.reduced_energy_series, " + O(\\beta^4)"), "",
            f"Stable for ${_tex(st.condition)}$; threshold $p_\\gamma^* = {_tex(st.threshold)}$, where "
            f"$k_4 = {_tex(st.quartic_at_threshold)}$ (positive: the threshold itself is stable).", ""]
    return out


def _euler_section() -> list[str]:
    out = ["## 3. Euler's equations and steady spin", "",
           _display("\\dot{\\tilde\\omega} = I^{-1}\\left((I\\tilde\\omega)\\times\\tilde\\omega\\right)", stab.euler_rhs()), "",
           "Linearised about steady spin $\\omega_0$ about each principal axis $k$ (cyclic successors $i, j$):",
           "$\\delta\\dot\\omega_i = -\\Omega_i\\,\\delta\\omega_j$, $\\delta\\dot\\omega_j = \\Omega_j\\,\\delta\\omega_i$, "
           "$\\lambda^2 = -\\Omega_i\\Omega_j$.", ""]
    for k in range(3):
        spin = stab.SteadySpin(k)
        oi, oj = spin.frequencies
        out += [f"Axis {k + 1}: $\\Omega_{{{(k + 1) % 3 + 1}}} = {_tex(oi)}$, "
                f"$\\Omega_{{{(k + 2) % 3 + 1}}} = {_tex(oj)}$, $\\lambda^2 = {_tex(spin.eigenvalue_squared)}$", ""]
    return out


def _inertia_section() -> list[str]:
    out = ["## 4. Inertia tensors of uniform solids", "",
           "Integrated over each region (`derive.symbolic.inertia`), axis 3 the symmetry axis; $M$ the mass.", ""]
    for name in INERTIA_SOLIDS:
        solid = inertia.SOLIDS[name]
        out += [f"### {name}", "", f"Volume ${_tex(solid.volume)}$, centre of mass "
                f"${_tex(solid.centre_of_mass.T)}$ in the integration frame.", ""]
        if name == "cone":
            out += [_display("I_{\\text{apex}}", solid.tensor_about_origin), ""]
        out += [_display("I_{\\text{cm}}", solid.about_centre_of_mass), ""]
    out += ["### thin disk (cylinder, H → 0)", "", _display("I_{\\text{cm}}", inertia.thin_disk()), ""]
    left_out = [n for n in inertia.SOLIDS if n not in INERTIA_SOLIDS]
    if left_out:
        out += ["Not shown, to keep `report.documents()` within its time budget (see `derive/lecture/report.py`): "
                + ", ".join(left_out) + " — `inertia.SOLIDS[name].about_centre_of_mass` computes it.", ""]
    return out


def derivation() -> str:
    out = ["# Derivation: rigid-body rotation, symbolically", "",
           "Every expression below is computed by `derive` (sympy) and printed, not typed. Conventions:",
           "z-y-z Euler angles of the notes unless stated; body components carry a tilde; rates are",
           "`alpha_d` = $\\dot\\alpha$ etc.", ""]
    for section in (_rotations_section, _lagrangian_section, _euler_section, _inertia_section,
                    _integrable_section):
        out += section()
    return "\n".join(out)


def _integrable_section() -> list[str]:
    return ["## 5. Integrable cases and their integrals", ""] + integral_proofs.markdown() + [""]


@functools.cache
def _documents() -> tuple[tuple[str, str], ...]:
    return (("lecture-verification.md", lecture_verification()), ("derivation.md", derivation()))


def documents() -> dict[str, str]:
    """{file name: Markdown text} of the two reports (computed once per process)."""
    return dict(_documents())
