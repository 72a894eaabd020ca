"""The comparisons of the notes checker: is a claim's value the derived one, and which single edit
of a formula would make it so.

Takes: SymPy expressions and matrices in the derivation's symbols (`derive.lecture.latex`).
Gives: `zero` (the zero test of `derive.lecture.zero_test`: bounded symbolic steps, then seeded
exact or 50-digit numeric points), `quick_equal` (a two-point float screen), `column` (a vector
as a 3-column), `edits` (the single edits a slip may be: a sign, a factor 2 or ½, sin ↔ cos, a
power ±1, an index), `positive_multiple`, `series_order` (the series order of an approximation),
and `not_a_consequence` with `flow_of` (the exact screen of an equation of motion's candidates).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.mp_values`, :mod:`derive.lecture.zero_test`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import functools
import random

import mpmath
import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import mp_values
from derive.lecture import zero_test as zt
from derive.symbolic.lagrangian import I1, I2, I3, Mass, g, l
from derive.symbolic.rotations import ANGLES, RATES


def has_rates(objs, rot) -> bool:
    return any(free(o) & set(rot.RATES) for o in objs)


def free(obj) -> set:
    """The free symbols of an expression or matrix (a new set)."""
    if isinstance(obj, sp.Basic):
        return set(_free_symbols(obj))
    return set(getattr(obj, "free_symbols", set()))


_free_symbols = zt.free_symbols


def column(v):
    """A vector as a 3-column (from a matrix, or a linear form in ê₁ ê₂ ê₃); scalars as 1×1."""
    if isinstance(v, sp.MatrixBase):
        if v.shape == (1, 3):
            return sp.Matrix(v).T
        return sp.Matrix(v).reshape(len(v), 1)
    v = sp.sympify(v)
    if _free_symbols(v) & set(lx.BASIS):
        ex = sp.expand(v)
        coeffs = [ex.coeff(e) for e in lx.BASIS]
        rest = sp.expand(ex - sum(c * e for c, e in zip(coeffs, lx.BASIS)))
        if rest != 0 or any(c.free_symbols & set(lx.BASIS) for c in coeffs):
            raise Mismatch("not a vector: a product of unit vectors, or a scalar added to a vector")
        return sp.Matrix(coeffs)
    return sp.Matrix([v])


class Mismatch(Exception):
    pass


def zero(lhs: sp.Matrix, rhs: sp.Matrix, seed: str) -> tuple[bool, str]:
    """(whether lhs − rhs ≡ 0, how it was shown or the counterexample), memoised: the searches for
    a correction test the same claim again with each candidate of another member."""
    return _zero(sp.ImmutableMatrix(lhs), sp.ImmutableMatrix(rhs), seed)


@functools.lru_cache(maxsize=4096)
def _zero(lhs: sp.ImmutableMatrix, rhs: sp.ImmutableMatrix, seed: str) -> tuple[bool, str]:
    if lhs.shape != rhs.shape:
        return False, f"a {_shape(lhs)} against a {_shape(rhs)}"
    diffs = lhs - rhs
    roots = any(not p.exp.is_Integer for e in (*lhs, *rhs) for p in zt.atoms(sp.sympify(e), sp.Pow))
    # a difference shown non-zero at an exact point goes straight to the numeric test, whose
    # counterexample is the reason given (the symbolic steps could not show it zero); so does one
    # the numeric test's first point shows non-zero, with that point's outcome
    if any(map(zt.surely_nonzero, diffs)):
        steps = [None]
    else:
        found = _counterexample(lhs, rhs, seed, roots)
        if found is not None:
            return _on_principal_branch(lhs, rhs, seed) or found
        steps = [_symbolic_zero(d) for d in diffs]
    if all(steps):
        return True, max(steps, key=zt.SYMBOLIC_STEPS.index)
    if roots:
        real = _real_zero(lhs, rhs, seed)
        if real is not None:
            return real
    out = zt.numeric_zero(lhs, rhs, seed)
    return (out.ok, out.method) if out.ok else _on_principal_branch(lhs, rhs, seed) or (out.ok, out.method)


_BRANCH_POINTS = 60
"""Points drawn for `_on_principal_branch`: enough that a claim agreeing on a principal branch agrees at `zero_test.POINTS` of them."""


def _on_principal_branch(lhs, rhs, seed):
    """(True, how) for a scalar claim with an arctangent (``γ = \\arctan(\\sin γ / \\cos γ)``) whose sides
    agree at `zero_test.POINTS` seeded points and, at every other, differ by a whole number of π: the
    arctangent's value is the principal one, the angle it recovers lies in (−π/2, π/2) where the two
    agree, and which seeded points fall there must not decide the verdict. None otherwise."""
    if lhs.shape != (1, 1) or not any(sp.sympify(e).has(sp.atan, sp.acot) for e in (*lhs, *rhs)):
        return None
    exprs = [sp.sympify(lhs[0]), sp.sympify(rhs[0])]
    symbols = sorted(set().union(*(_free_symbols(e) for e in exprs)), key=lambda x: x.name)
    f = mp_values.evaluator(symbols, exprs)
    rng = random.Random(seed + "branch")
    same = 0
    for _ in range(_BRANCH_POINTS):
        point = [mpmath.mpf(p.p) / p.q for p in zt.sample(symbols, rng)]
        with mpmath.workdps(zt.DIGITS):
            try:
                a, b = (mpmath.mpmathify(v) for v in f(*point))
            except (ZeroDivisionError, ValueError, TypeError, NotImplementedError):
                continue
            if not (mpmath.isfinite(a) and mpmath.isfinite(b)) or mpmath.im(a) or mpmath.im(b):
                return None
            tol = max(1, abs(a), abs(b)) * mpmath.mpf(10) ** (10 - zt.DIGITS)
            turns = (a - b) / mpmath.pi
            if abs(a - b) <= tol:
                same += 1
            elif abs(turns - mpmath.nint(turns)) * mpmath.pi > tol:
                return None     # apart by other than a multiple of π: the usual counterexample stands
    if same < zt.POINTS:
        return None
    return True, (f"on the principal branch of its arctangent (mpmath {zt.DIGITS} digits: the sides agree at "
                  f"{same} points and differ by a multiple of π elsewhere)")


def _counterexample(lhs, rhs, seed, roots):
    """The outcome of the numeric test that decides below (`_real_zero` where roots are, else
    `zero_test.numeric_zero`) when its first point shows the difference non-zero, else None."""
    if roots:
        real = _real_zero(lhs, rhs, seed, points=1)
        if real is not None:
            return real if not real[0] else None
    out = zt.counterexample(lhs, rhs, seed)
    return None if out is None else (out.ok, out.method)


def _real_zero(lhs, rhs, seed, points=zt.POINTS):
    """The numeric test of a formula with roots where they are real: seeded points (``points`` of
    them) at which every radicand is positive (a solution valid for I₁ < I₂, I₃ is compared where
    its roots exist, not on another branch of them); None when no such point turns up."""
    exprs = [sp.sympify(e) for e in (*lhs, *rhs)]
    if any(e.has(sp.zoo, sp.nan) for e in exprs):
        return None       # SymPy's infinity written in: no point is ever used (`mp_values.evaluator`)
    symbols = sorted(set().union(*(_free_symbols(e) for e in exprs)), key=lambda x: x.name)
    bases = sorted({p.base for e in exprs for p in zt.atoms(e, sp.Pow) if not p.exp.is_Integer}, key=sp.default_sort_key)
    f = mp_values.evaluator(symbols, exprs)
    radicands = mp_values.evaluator(symbols, bases)
    rng = random.Random(seed)
    n, used = len(lhs), 0
    # a root one side writes is the branch the text takes: where the other side takes both signs
    # with the motion while the root's does not, the squares agreeing, the claim holds on its branch
    branch = len(lhs) == 1 and (_has_root(lhs[0]) or _has_root(rhs[0]))
    same, flipped, first_miss, signs = 0, 0, None, (set(), set())
    for _ in range(300):
        point = [mpmath.mpf(p.p) / p.q for p in zt.sample(symbols, rng)]
        with mpmath.workdps(zt.DIGITS):
            vals = mp_values.real_values(f, radicands, point)
            if vals is None:
                continue
            if not all(mpmath.isfinite(v) for v in vals):
                continue
            used += 1
            for a, b in zip(vals[:n], vals[n:]):
                tol = max(1, abs(a), abs(b)) * mpmath.mpf(10) ** (10 - zt.DIGITS)
                signs[0].add(mpmath.sign(mpmath.re(a)))
                signs[1].add(mpmath.sign(mpmath.re(b)))
                if abs(a - b) <= tol:
                    same += 1
                elif branch and abs(a + b) <= tol and abs(a) > tol:
                    flipped += 1
                    first_miss = first_miss or abs(a - b)
                else:
                    return False, (f"mpmath {zt.DIGITS} digits where its roots are real: |claim − derived| = "
                                   f"{mpmath.nstr(abs(a - b), 3)} at a sample point")
        if used >= points and (not flipped or same):
            break
    if flipped and not same:
        return (False, f"mpmath {zt.DIGITS} digits where its roots are real: |claim − derived| = "
                       f"{mpmath.nstr(first_miss, 3)} at a sample point") if used >= points else None
    sides = (lhs[0], rhs[0]) if flipped else ()
    rooted = [k for k, side in enumerate(sides) if _has_root(side) and len(signs[k]) == 1]
    # the other side's sign must follow the motion (odd in one of its rates: θ̇ against
    # −√(2(E − U)/I₁), ω̃₁ω̃₃ against √(…)), not one the constants fix, which is the text's to get right
    if flipped and not any(len(signs[1 - k]) > 1 and _odd_in_rates(sides[1 - k], symbols, seed) for k in rooted):
        return False, (f"mpmath {zt.DIGITS} digits where its roots are real: |claim − derived| = "
                       f"{mpmath.nstr(first_miss, 3)} at a sample point")
    if flipped:
        return True, (f"on the branch of its root (mpmath {zt.DIGITS} digits where its roots are real: the "
                      f"derived side takes both signs, the squares agree at {used} points)")
    return (True, f"mpmath {zt.DIGITS} digits at {used} points where its roots are real") if used else None


_RATES = frozenset((*RATES, *lx.W))
"""The rates of the motion: the angles' rates and ω̃ᵢ."""


def _odd_in_rates(e, symbols, seed) -> bool:
    """``e`` changes sign with the motion: turning one rate of it (θ̇, or ω̃₁ of ω̃₁ω̃₃) the other way
    turns its sign, at a seeded point where it is not zero — a sign that energies and other even
    functions of the rates, and the constants, never have."""
    e = sp.sympify(e)
    rates = sorted(_free_symbols(e) & _RATES, key=lambda x: x.name)
    if not rates:
        return False
    f = mp_values.evaluator(symbols, [e, *(e.xreplace({r: -r}) for r in rates)])
    rng = random.Random(seed + "odd")
    for _ in range(50):
        point = [mpmath.mpf(p.p) / p.q for p in zt.sample(symbols, rng)]
        with mpmath.workdps(zt.DIGITS):
            try:
                a, *turned = (mpmath.mpmathify(v) for v in f(*point))
            except (ZeroDivisionError, ValueError, TypeError):
                continue
            if not (mpmath.isfinite(a) and all(map(mpmath.isfinite, turned))) or abs(a) < mpmath.mpf(10) ** -20:
                continue
            return any(abs(a + b) <= abs(a) * mpmath.mpf(10) ** (10 - zt.DIGITS) for b in turned)
    return False


def _has_root(e) -> bool:
    """A square root (a power ½ of something not a number) in the claim's side."""
    return any(p.exp == sp.Rational(1, 2) and not p.base.is_number for p in zt.atoms(sp.sympify(e), sp.Pow))


def _symbolic_zero(d):
    """`zero_test`'s bounded symbolic steps; None (the numeric test decides) where they cannot apply
    (trig_reduce refuses a sine nested in a sine's argument)."""
    try:
        return zt.symbolic_zero(d)
    except (sp.PolynomialError, sp.polys.polyerrors.GeneratorsError, TypeError, ValueError):
        return None


def not_a_consequence(r, euler) -> bool:
    """Whether an equation of motion's residual r is proved to be neither a multiple of one of
    Euler's equations ``euler`` nor zero once ω̃̇ is taken from them (`flow_of`): both leave r = 0
    after that substitution, and an exact point (`zero_test.surely_nonzero_with_roots`) shows it
    is not. r = q Rᵢ with q free of ω̃, ω̃̇ gives r(flow) = q Rᵢ(flow) = 0, Rᵢ being linear in ω̃̇ᵢ."""
    try:
        flow = flow_of(tuple(euler))
    except (sp.PolynomialError, TypeError, ValueError, ZeroDivisionError):
        return False
    return all(lx.WD[i] in flow for i, R in enumerate(euler) if R != 0) and \
        zt.surely_nonzero_with_roots(r.xreplace(flow))


@functools.lru_cache(maxsize=256)
def flow_of(euler: tuple) -> dict:
    """ω̃̇ᵢ as Euler's equation i gives it (Rᵢ = 0, Rᵢ linear in ω̃̇ᵢ), for each Rᵢ that has it,
    memoised: every candidate correction of an equation of motion is checked against the same."""
    flow = {}
    for i, R in enumerate(euler):
        coef = sp.diff(R, lx.WD[i])
        if coef != 0:
            flow[lx.WD[i]] = sp.cancel(lx.WD[i] - R / coef)
    return flow


def _shape(m) -> str:
    return "scalar" if m.shape == (1, 1) else ("vector" if m.shape[1] == 1 else f"{m.shape[0]}×{m.shape[1]} matrix")


def quick_equal(a, b) -> bool:
    """A fast float test (two random points) used to screen the single-edit candidates, memoised
    (the same candidate recurs across the cases and searches of one text); the sides evaluated by
    mpmath's walk of `derive.lecture.mp_values` at 30 digits, or by SymPy's evalf to 20 where the
    walk does not read them."""
    a, b = (sp.ImmutableMatrix(x) if isinstance(x, sp.MatrixBase) else x for x in (a, b))
    try:
        hash((a, b))
    except TypeError:
        return _quick_equal.__wrapped__(a, b)
    return _quick_equal(a, b)


@functools.lru_cache(maxsize=4096)
def _quick_equal(a, b) -> bool:
    try:
        A, B = column(a), column(b)
    except Mismatch:
        return False
    if A.shape != B.shape:
        return False
    # the float points first: they reject most candidates for less than the exact evaluation costs
    # (both must pass, so the order leaves the answer as it is)
    if not _floats_agree(A, B):
        return False
    return not any(zt.surely_nonzero(x - y) for x, y in zip(A, B))


def _floats_agree(A, B) -> bool:
    """Whether the columns A and B agree to 1e-9 of their size at two seeded points."""
    syms = sorted((A.free_symbols | B.free_symbols), key=lambda s: s.name)
    walk = mp_values.walker(syms, [*A, *B])
    rng = random.Random(7)
    for _ in range(2):
        point = {s: sp.Float(rng.uniform(0.5, 2.5) if s.is_positive else rng.uniform(0.3, 1.7), 20) for s in syms}
        try:
            if walk is None:
                d = [complex(sp.N(x.xreplace(point) - y.xreplace(point), 20)) for x, y in zip(A, B)]
                size = [abs(complex(sp.N(x.xreplace(point), 20))) + 1 for x in A]
            else:
                with mpmath.workdps(_QUICK_DIGITS):
                    values = walk(*(mpmath.mpf(float(v)) for v in point.values()))
                    d = [complex(x - y) for x, y in zip(values[:len(A)], values[len(A):])]
                    size = [abs(complex(x)) + 1 for x in values[:len(A)]]
        except (TypeError, ValueError, ZeroDivisionError):
            return False
        if any(abs(x) > 1e-9 * s for x, s in zip(d, size)):
            return False
    return True


_QUICK_DIGITS = 30


# ---- single edits ------------------------------------------------------------------------------
def _paths(e, path=()):
    yield path, e
    # inside a derivative the variables are not edited (∂/∂ of a power is no formula)
    if isinstance(e, sp.Derivative):
        yield from _paths(e.expr, path + (0,))
    elif isinstance(e, sp.Basic) and not e.is_Atom:
        for k, a in enumerate(e.args):
            yield from _paths(a, path + (k,))


def _replace(e, path, new):
    if not path:
        return new
    args = list(e.args)
    args[path[0]] = _replace(args[path[0]], path[1:], new)
    return e.func(*args)


_SIBLINGS = None


def _siblings():
    fams = [(I1, I2, I3), lx.W, lx.WD, lx.BASIS, lx.PRIMED, ANGLES, RATES, (lx.Omega1, lx.Omega2)]
    out = {}
    for fam in fams:
        for s in fam:
            out[s] = [x for x in fam if x != s]
    return out


def edits(e):
    """Single edits of an expression: (edited, what was changed)."""
    if isinstance(e, sp.MatrixBase):
        for k in range(len(e)):
            for new, what in edits(e[k]):
                m = sp.Matrix(e)
                m[k] = new
                yield m, f"{what} (entry {k + 1})"
        return
    e = sp.sympify(e)
    sib = _siblings()
    yield -e, "the sign of the whole side"
    yield 2 * e, "a factor 2"
    yield e / 2, "a factor 1/2"
    for path, node in list(_paths(e)):
        if isinstance(node, sp.Add):
            for k, a in enumerate(node.args):
                p = path + (k,)
                yield _replace(e, p, -a), "a sign"
                yield _replace(e, p, 2 * a), "a factor 2"
                yield _replace(e, p, a / 2), "a factor 1/2"
        elif isinstance(node, (sp.sin, sp.cos)):
            other = sp.cos if isinstance(node, sp.sin) else sp.sin
            yield _replace(e, path, other(*node.args)), "sin ↔ cos"
        elif isinstance(node, sp.Pow) and node.exp.is_Integer:
            for d in (1, -1):
                if node.exp + d != 0:
                    yield _replace(e, path, node.base ** (node.exp + d)), "a power"
        elif isinstance(node, sp.Symbol) and node in sib:
            for s in sib[node]:
                yield _replace(e, path, s), "an index"
            if path and not isinstance(_at(e, path[:-1]), sp.Pow):
                yield _replace(e, path, node**2), "a power"


def _at(e, path):
    for k in path:
        e = e.args[k]
    return e


def positive_multiple(a, b) -> bool:
    """Is a = q b with q > 0 a function of the positive parameters only (I₁, I₃, M, g, l)?"""
    if sp.expand(a) == 0 or sp.expand(b) == 0:
        return False
    q = sp.cancel(sp.together(a / b))
    params = (I1, I2, I3, Mass, g, l)
    if not free(q) <= set(params):
        return False
    pos = {s: sp.Symbol(s.name, positive=True) for s in params}
    return bool(q.xreplace(pos).is_positive)


def series_order(value, x) -> int:
    """The order n of the series check: one above the highest power of x the claim keeps."""
    try:
        v = sp.expand(sp.cancel(sp.together(value)))
        deg = sp.Poly(v, x).degree() if v.is_polynomial(x) else 2
    except (sp.PolynomialError, sp.GeneratorsNeeded):
        deg = 2
    return max(deg, 0) + 1
