"""Check every formula of the lecture (`derive.lecture.claims.CLAIMS`) against the derivation.

For each claim the typed expression is compared with a quantity derived independently by the
core (`targets.DERIVED`, names as in `Claim.target`): the claim's ``given`` definitions are substituted,
frame unit vectors (ê′ᵢ, ê⁰₃) are written in the body basis, each of the slide's ``cases`` is
substituted into both sides, and the difference claim − derived must vanish. The zero test is

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
import random
from dataclasses import dataclass

import mpmath
import sympy as sp
from mpmath import iv

from derive.lecture import claims as lec
from derive.lecture import slides as sl
from derive.lecture.slides import Claim, Correction, Derived
from derive.lecture.targets import SHOWN, derived, frame_vectors
from derive.symbolic import rotations

VERDICTS = ("holds", "typo", "fails")
_SYMBOLIC_STEPS = ("identical", "expand", "cancel", "trig_reduce", "simplify")
_POINTS = 6
_DIGITS = 50


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
    reduced = rotations.trig_reduce(d, _trig_angles(d))
    if reduced == 0:
        return "trig_reduce"
    return None


_PRIMES = (11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97, 101, 103, 107)
# Rational points of the unit circle (sin, cos) = (a/c, b/c), a² + b² = c²: one per angle.
_CIRCLE = ((3, 4, 5), (5, 12, 13), (8, 15, 17), (7, 24, 25), (20, 21, 29), (12, 35, 37), (9, 40, 41), (28, 45, 53))
_MODULUS = 2**61 - 1
_INTERVAL_BITS = 120
_IV_FUNCTIONS = {sp.sin: iv.sin, sp.cos: iv.cos, sp.tan: iv.tan, sp.exp: iv.exp}


class _Outside(Exception):
    """An expression the evaluation at a point does not cover."""


def surely_nonzero(d) -> bool:
    """Whether d ≢ 0 is proved by one evaluation at a point of its domain, where the i-th symbol
    by name is the positive rational pᵢ/7 (pᵢ the i-th prime from 11).

    * A rational function of symbols and of sin, cos, tan of angles that occur only there is
      evaluated exactly, each angle at a point of the unit circle with rational sine and cosine,
      modulo the prime 2⁶¹ − 1: a non-zero residue is a non-zero numerator.
    * Otherwise (sums, products, powers, sin, cos, tan, exp, π of anything) in interval arithmetic
      (mpmath ``iv``, 120 bits): an enclosure that excludes 0 is a proof.

    False for anything else, a symbol declared integer or non-positive, a pole, a root of a
    negative number, a zero residue or an enclosure containing 0. Before the symbolic steps, it
    spares them a difference they cannot show zero (a slip, or a candidate of the search for a
    correction) at the cost of one evaluation.
    """
    if not isinstance(d, sp.Expr):
        return False
    if d.is_Number:
        return d != 0 and d.is_finite is True
    symbols = sorted(d.free_symbols, key=lambda s: s.name)
    if len(symbols) > len(_PRIMES) or any(s.is_nonpositive or s.is_integer for s in symbols):
        return False
    try:
        return _residue(d, _exact_point(d, symbols), {}) != 0
    except (_Outside, ValueError, ZeroDivisionError):
        pass
    point = {s: iv.mpf(p) / 7 for s, p in zip(symbols, _PRIMES)}
    prec = iv.prec
    iv.prec = _INTERVAL_BITS
    try:
        return bool(0 not in _enclosure(d, point, {}))
    except (_Outside, ValueError, ZeroDivisionError, TypeError, OverflowError):
        return False
    finally:
        iv.prec = prec


def _exact_point(d, symbols) -> dict:
    """Residues of the point: pᵢ/7 for each symbol; sin, cos, tan of each angle from `_CIRCLE`."""
    inv = lambda n: pow(n, -1, _MODULUS)  # noqa: E731
    angles = sorted({f.args[0] for f in d.atoms(sp.sin, sp.cos, sp.tan) if f.args[0].is_Symbol}, key=lambda s: s.name)
    if len(angles) > len(_CIRCLE):
        raise _Outside(d)
    point = {s: p * inv(7) % _MODULUS for s, p in zip(symbols, _PRIMES) if s not in angles}
    for x, (a, b, c) in zip(angles, _CIRCLE):
        point[sp.sin(x)], point[sp.cos(x)], point[sp.tan(x)] = a * inv(c), b * inv(c), a * inv(b)
    return point


def _residue(e, point: dict, memo: dict) -> int:
    """e at the exact point, modulo `_MODULUS` (an angle outside sin/cos/tan is `_Outside`)."""
    if e in memo:
        return memo[e]
    if e in point:
        value = point[e]
    elif e.is_Rational:
        value = int(e.p) * pow(int(e.q), -1, _MODULUS) % _MODULUS
    elif e.is_Add:
        value = sum(_residue(a, point, memo) for a in e.args) % _MODULUS
    elif e.is_Mul:
        value = 1
        for a in e.args:
            value = value * _residue(a, point, memo) % _MODULUS
    elif e.is_Pow and e.exp.is_Integer:
        value = pow(_residue(e.base, point, memo), int(e.exp), _MODULUS)
    else:
        raise _Outside(e)
    memo[e] = value
    return value


def _enclosure(e, point: dict, memo: dict):
    """An interval holding e's value at ``point`` (common subexpressions evaluated once)."""
    if e in memo:
        return memo[e]
    if e.is_Symbol:
        value = point[e]
    elif e.is_Rational:
        value = iv.mpf(int(e.p)) / int(e.q)
    elif e is sp.pi:
        value = iv.pi
    elif e.is_Add:
        value = iv.mpf(0)
        for a in e.args:
            value = value + _enclosure(a, point, memo)
    elif e.is_Mul:
        value = iv.mpf(1)
        for a in e.args:
            value = value * _enclosure(a, point, memo)
    elif e.is_Pow:
        base = _enclosure(e.base, point, memo)
        if e.exp.is_Integer:
            value = base ** int(e.exp)
        elif e.exp == sp.S.Half and base.a > 0:
            value = iv.sqrt(base)
        elif e.exp.is_Rational and base.a > 0:
            value = iv.exp(iv.log(base) * _enclosure(e.exp, point, memo))
        else:
            raise _Outside(e)
    elif type(e) in _IV_FUNCTIONS:
        value = _IV_FUNCTIONS[type(e)](_enclosure(e.args[0], point, memo))
    else:
        raise _Outside(e)
    memo[e] = value
    return value


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
        f = sp.lambdify(symbols, [*lhs, *rhs], modules="mpmath", cse=True, docstring_limit=0)
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
        diffs = lhs - rhs
        steps = [None] if any(map(surely_nonzero, diffs)) else [_symbolic_zero(d) for d in diffs]
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
