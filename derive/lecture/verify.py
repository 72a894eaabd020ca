"""Check every formula of the lecture (`derive.lecture.claims.CLAIMS`) against the derivation.

For each claim the typed expression is compared with a quantity derived independently by the
core (`targets.DERIVED`, names as in `Claim.target`): the claim's ``given`` definitions are substituted,
frame unit vectors (ê′ᵢ, ê⁰₃) are written in the body basis, each of the slide's ``cases`` is
substituted into both sides, and the difference claim − derived must vanish. The zero test (`derive.lecture.zero_test`) is

1. symbolic, cheapest first and bounded in expression size (never an unbounded `simplify`),
   unless `surely_nonzero` has proved the difference non-zero at one point (then these steps
   cannot succeed and are skipped):
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
from dataclasses import dataclass

import sympy as sp

from derive.lecture import claims as lec
from derive.lecture import slides as sl
from derive.lecture.slides import Claim, Correction, Derived
from derive.lecture.targets import SHOWN, derived, frame_vectors
from derive.lecture.zero_test import SYMBOLIC_STEPS, Outcome, numeric_zero, surely_nonzero, symbolic_zero
from derive.symbolic import rotations

VERDICTS = ("holds", "typo", "fails")


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
    return _substitute(expr, frame_vectors()) if has_frames else expr


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
        rot = rotations
        b, bd = rot.beta, rot.beta_d
        # Euler–Lagrange for one degree of freedom: β̈ = (∂L/∂β − β̇ ∂²L/∂β̇∂β) / ∂²L/∂β̇².
        accel = (sp.diff(expr, b) - bd * sp.diff(expr, bd, b)) / sp.diff(expr, bd, 2)
        return _column(accel), _column(value)
    raise ValueError(f"{claim.id}: unknown mode {claim.mode!r}")


def _compare(claim: Claim, expr, target: str) -> Outcome:
    """Does ``expr`` (the claim, or its correction) equal ``target`` in every case?"""
    lhs0, rhs0 = _sides(claim, _prepared(claim, expr), target)
    if lhs0.shape != rhs0.shape:
        return Outcome(False, f"shape {lhs0.shape} ≠ derived {rhs0.shape}")
    methods = []
    for k, case in enumerate(claim.cases):
        lhs, rhs = lhs0.xreplace(case), rhs0.xreplace(case)
        diffs = lhs - rhs
        steps = [None] if any(map(surely_nonzero, diffs)) else [symbolic_zero(d) for d in diffs]
        if all(steps):
            methods.append(max(steps, key=SYMBOLIC_STEPS.index))
            continue
        numeric = numeric_zero(lhs, rhs, f"{claim.id}/{target}/{k}")
        if not numeric.ok:
            where = f" (case {k + 1} of {len(claim.cases)})" if len(claim.cases) > 1 else ""
            return Outcome(False, numeric.method + where)
        methods.append(numeric.method)
    method = methods[0] if len(set(methods)) == 1 else ", ".join(methods)
    if len(claim.cases) > 1:
        method += f" ({len(claim.cases)} cases)"
    return Outcome(True, method)


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
    rot = rotations
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
