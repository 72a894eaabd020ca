"""A statement the text's settings already give: the motion it has just described, checked.

A text that sets the angles or their rates (``θ = θ₀``, ``\\dot\\phi = \\omega_p``, ``\\dot\\psi =
\\omega_s``: a regular precession) and then writes what follows from them (``ω₁ = ω_p \\sin θ₀
\\sin ψ``, ``ω₃ = ω_p \\cos θ₀ + ω_s``) states a consequence, not another setting. With the
settings put into the derivation's ω̃(q, q̇) — an angle set to a constant has no rate, a rate set to
a constant no acceleration — such a statement holds when its two sides then agree. Nothing is ever
judged wrong here: a statement that does not agree is left to the rest of the reader, and so is one
that writes a set angle or rate itself (a rate is never checked against the rate the text stated).

Takes: the checker (its ``ctx.subs``, ``ctx.stated``, ``d.omega``, ``_resolve``, ``tex``). Gives:
`under_settings` and `stated_angles`.

May import: :mod:`derive.lecture.latex`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import latex as lx
from derive.symbolic.lagrangian import ACCELS
from derive.symbolic.rotations import ANGLES, RATES


def _constant(value) -> bool:
    free = set(sp.sympify(value).free_symbols)
    return not free & ({lx.t} | set(ANGLES) | set(RATES) | set(ACCELS) | set(lx.W) | set(lx.WD))


def settled(subs: dict) -> dict:
    """The settings with what they imply: an angle set to a constant has no rate or acceleration,
    a rate set to a constant no acceleration."""
    out = dict(subs)
    for q, dq, ddq in zip(ANGLES, RATES, ACCELS):
        if q in subs and _constant(subs[q]):
            out.setdefault(dq, sp.S.Zero)
            out.setdefault(ddq, sp.S.Zero)
        if dq in subs and _constant(subs[dq]):
            out.setdefault(ddq, sp.S.Zero)
    return out


def stated_angles(checker) -> dict:
    """The angles and rates the text has set: its settings (``ctx.subs``), the rates of the motion
    it describes (``ctx.motion``) and the angles it gives (``ctx.angles_stated``), with where."""
    out = {s: (v, checker.ctx.stated.get(s, "stated")) for s, v in checker.ctx.subs.items()
           if s in ANGLES or s in RATES}
    for s, (v, line) in {**checker.ctx.motion, **checker.ctx.angles_stated}.items():
        if s in ANGLES or s in RATES:
            try:
                out.setdefault(s, (checker._resolve(v), f"line {line}"))
            except (TypeError, ValueError, AttributeError, lx.NotRead):
                continue
    return out


def under_settings(checker, a, b) -> str | None:
    """The ``why`` of ``a = b`` holding once the angles and rates the text has set are put into
    ω̃(q, q̇); None when no such setting is used or the sides do not agree."""
    stated = stated_angles(checker)
    if not stated:
        return None
    try:
        e = checker._resolve(sp.sympify(a) - sp.sympify(b))
    except (TypeError, ValueError, AttributeError, lx.NotRead):
        return None
    if isinstance(e, sp.MatrixBase) or set(e.free_symbols) & (set(lx.WD) | set(stated)):
        return None                      # a stated rate or angle is never checked against itself
    e = e.xreplace({w: checker.d.omega[i] for i, w in enumerate(lx.W)})
    full = settled({**checker.ctx.subs, **{s: v for s, (v, _) in stated.items()}})
    put = e
    for _ in range(3):
        put = put.xreplace(full)
    used = [s for s in (*ANGLES, *RATES) if s in stated and s in e.free_symbols]
    if not used or set(put.free_symbols) & (set(RATES) | set(ACCELS)):
        return None                      # a rate the settings leave free: not their consequence
    if sp.simplify(sp.expand_trig(put)) != 0:
        return None
    named = ", ".join(f"{checker.tex(s)} = {checker.tex(stated[s][0])} ({stated[s][1]})" for s in used)
    return f"follows from what the text set before it ({named}) in ω̃(q, q̇)"
