"""The zero test of the checkers: is claim − derived identically zero?

Takes: SymPy expressions and matrices. Gives: `symbolic_zero` (bounded symbolic steps, cheapest
first, never an unbounded `simplify`), `bounded_expand` (`expand` within the same bound for
differences with trig functions), `expanded` (`expand`'s result, multiplied out in a polynomial
ring where it can be), `surely_nonzero` (an exact one-point screen that proves a difference
non-zero), `surely_depends` (the same screen for a quotient's dependence on some symbols),
`ratio_varies` and `differs_somewhere` (the numeric test's counterexample, for a quotient that is
no number and a difference that is not zero, where the exact screens cannot evaluate),
`numeric_zero` (seeded random points: exact rationals, or mpmath at `DIGITS` digits) and `sample`
(the seeded points). Used by the lecture's table
(`derive.lecture.verify`) and by the notes checker (`derive.lecture.comparing`); it knows neither.

1. symbolic: the difference is zero as built, or after `expand`; if it has no trig functions,
   and is no polynomial in its symbols and their reciprocals (whose expansion is already
   canonical), after `cancel` (canonical for rational functions) or, for small ones with radicals,
   `simplify`; if it has, after `rotations.trig_reduce` (canonical for polynomials in sin/cos),
   skipped above a few hundred nodes;
2. numeric at `POINTS` seeded random points: exactly, in rationals, when the difference contains
   no function or radical; else with mpmath at `DIGITS` digits (`derive.lecture.mp_values`, the
   values `lambdify` would give), zero meaning below 10⁻⁴⁰ of the sides' size.

May import: :mod:`derive.lecture.mp_values`, :mod:`derive.lecture.sparse_forms`, :mod:`derive.symbolic`, SymPy, mpmath.
"""
from __future__ import annotations

import functools
import random
from dataclasses import dataclass

import mpmath
import sympy as sp
from mpmath import iv, libmp

from derive.lecture import mp_values
from derive.lecture.sparse_forms import (atoms, free_symbols, generators, in_ring, polynomial_ring, rational_zero,
                                         ring_generators, trig_zero)
from derive.symbolic import rotations

SYMBOLIC_STEPS = ("identical", "expand", "cancel", "trig_reduce", "simplify")
"""The symbolic steps, cheapest first (a method's rank)."""
POINTS = 6
DIGITS = 50


@dataclass(frozen=True)
class Outcome:
    ok: bool
    method: str



def _trig_angles(expr) -> tuple:
    return tuple(sorted({f.args[0] for f in atoms(expr, sp.sin, sp.cos, sp.tan)}, key=sp.default_sort_key))


# Size bounds (in expression-tree nodes) of the symbolic steps; larger remainders go to the
# numeric test, which costs milliseconds where a 3-angle `trig_reduce` costs a second.
_EXPAND_MAX_NODES = 400
_TRIG_REDUCE_MAX_NODES = 250
_SIMPLIFY_MAX_NODES = 80        # `simplify` only on small trig-free remainders: unbounded otherwise


def _size(e) -> int:
    return sum(1 for _ in sp.preorder_traversal(e))


def bounded_expand(d):
    """d expanded, except a difference with sin, cos or tan above `_EXPAND_MAX_NODES` nodes: there
    `expand` is no canonical form (an identity in sin² + cos² stays non-zero) and costs seconds on a
    tensor's inverse written out, and `symbolic_zero` would not take the result either, so it is
    left as it is for the screens and the numeric test. Polynomials are always expanded (exact)."""
    if _size(d) > _EXPAND_MAX_NODES and d.has(sp.sin, sp.cos, sp.tan):
        return d
    return expanded(d)


def expanded(d):
    """``sp.expand(d)``; a polynomial with rational coefficients in symbols, their reciprocals and
    sin, cos, tan of symbols (`sparse_forms.generators`) multiplied out in SymPy's sparse polynomial ring
    instead (sums and products of dicts of monomials), each of those taken as one generator. The
    result, the sum of its monomials as SymPy builds it (x·x⁻¹ = 1, sin θ² kept), is the canonical
    sum `expand` reaches by rewriting the expression tree term by term. Kept per expression: a
    statement read again under its second readings expands the same differences."""
    try:
        return _expanded_kept(d)
    except TypeError:           # a mutable matrix: not hashable, expanded as it stands
        return _expanded(d)


@functools.lru_cache(maxsize=4096)
def _expanded_kept(d):
    return _expanded(d)


def _expanded(d):
    gens = generators(d)
    if not gens:
        return sp.expand(d)
    R = polynomial_ring(tuple(gens))
    return in_ring(d, dict(zip(gens, R.gens)), R, {}).as_expr()


def expanded_derivative(e, *xs, field=None):
    """``expanded(∂ⁿe/∂x₁…∂xₙ)``; with ``field``, a dict of polynomials by symbol, the same of
    Σ ∂e/∂x · field[x] (d/dt along ẋ = field[x]). A polynomial (as `expanded` reads it) in which
    each x is a generator that no other generator depends on is differentiated in the sparse
    polynomial ring, c·k·x^(k−1)… monomial by monomial; anything else through ``sp.diff``. Either
    way the result is the canonical expanded sum."""
    field = field or {}
    parts = [ring_generators(t) for t in (e, *field.values())]
    if all(g is not None for g in parts):
        gens = sorted(set().union(*parts, xs, field), key=sp.default_sort_key)
        wrt = (*xs, *field)
        if all(x.is_Symbol for x in wrt) and not any(x in g.free_symbols for x in wrt for g in gens if g != x):
            R = polynomial_ring(tuple(gens))
            at = dict(zip(gens, R.gens))
            p = in_ring(e, at, R, {})
            for x in xs:
                p = p.diff(at[x])
            if field:
                p = sum((p.diff(at[x]) * in_ring(v, at, R, {}) for x, v in field.items()), R.zero)
            return p.as_expr()
    d = sp.diff(e, *xs) if xs else e
    if field:
        d = sum((sp.diff(d, x) * v for x, v in field.items()), sp.S.Zero)
    return expanded(d)


def symbolic_zero(d) -> str | None:
    """The first symbolic step showing d = 0, or None (not shown: the numeric test decides). Kept
    per expression: a statement read again (its second readings, the probes of other sequences)
    asks the same differences again."""
    try:
        return _symbolic_zero_kept(d)
    except TypeError:           # a mutable matrix: not hashable, tested as it stands
        return _symbolic_zero(d)


@functools.lru_cache(maxsize=4096)
def _symbolic_zero_kept(d) -> str | None:
    return _symbolic_zero(d)


def _symbolic_zero(d) -> str | None:
    if d == 0:
        return "identical"
    if _size(d) > _EXPAND_MAX_NODES:
        return None
    d = expanded(d)
    if d == 0:
        return "expand"
    if not d.has(sp.sin, sp.cos, sp.tan):
        if generators(d) is not None:            # a polynomial in symbols and their reciprocals,
            return None                           # expanded: canonical, so not 0 as a rational function
        if rational_zero(d):                      # canonical for rational functions
            return "cancel"
        if not _radicals(d) or _size(d) > _SIMPLIFY_MAX_NODES or _nonzero_somewhere(d):
            return None
        return "simplify" if sp.simplify(d) == 0 else None
    if _size(d) > _TRIG_REDUCE_MAX_NODES or _nonzero_somewhere(d):
        return None
    angles = _trig_angles(d)
    zero = trig_zero(d, angles)
    if zero is None:
        zero = rotations.trig_reduce(d, angles) == 0
    return "trig_reduce" if zero else None


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
    return _surely_nonzero(d)


@functools.lru_cache(maxsize=8192)
def _surely_nonzero(d: sp.Expr) -> bool:
    """`surely_nonzero` of an expression, memoised: a candidate recurs across the cases of a text."""
    if d.is_Number:
        return d != 0 and d.is_finite is True
    symbols = sorted(free_symbols(d), key=lambda s: s.name)
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
        value = _enclosure(d, point, {})
        return 0 not in value and libmp.fnan not in value._mpi_   # a NaN end proves nothing
    except (_Outside, ValueError, ZeroDivisionError, TypeError, OverflowError):
        return False
    finally:
        iv.prec = prec


_SCREEN_POINTS = 8
_SCREEN_FUNCTIONS = {**_IV_FUNCTIONS, sp.Abs: abs}


def nonzero_somewhere(d) -> bool:
    """Whether d ≢ 0 is proved at one of a few seeded points (`_nonzero_somewhere`): then no
    identity (``simplify``, ``trig_reduce``) can turn d into 0, and a caller may leave it as it is."""
    return isinstance(d, sp.Expr) and _nonzero_somewhere(d)


@functools.lru_cache(maxsize=8192)
def _nonzero_somewhere(d: sp.Expr) -> bool:
    """Whether interval arithmetic (as in `surely_nonzero`, |x| read too) proves d ≠ 0 at one of a
    few seeded rational points of its domain, each symbol drawn with the sign its assumptions give
    (positive ones in [1/2, 3], others ±[1/5, 2]): then neither `simplify` nor `trig_reduce` (both
    identities) can turn d into 0, and those steps are skipped. `_SCREEN_POINTS` points when d has
    roots (a radicand may be negative at a point: the next one is tried), else two; a symbol
    declared integer or non-real, or an enclosure holding 0 at every point, proves nothing."""
    symbols = sorted(free_symbols(d), key=lambda s: s.name)
    if any(s.is_integer or s.is_rational is False or s.is_real is False for s in symbols):
        return False
    rng = random.Random(len(symbols))
    roots = any(not p.exp.is_Integer for p in atoms(d, sp.Pow))
    prec = iv.prec
    iv.prec = _INTERVAL_BITS
    try:
        for _ in range(_SCREEN_POINTS if roots else 2):
            point = {}
            for s in symbols:
                sign = 1 if s.is_nonnegative else -1 if s.is_nonpositive else rng.choice((-1, 1))
                low = 50 if s.is_nonnegative or s.is_nonpositive else 20
                point[s] = iv.mpf(sign * rng.randint(low, 300 if low == 50 else 200)) / 100
            try:
                value = _enclosure(d, point, {}, _SCREEN_FUNCTIONS)
                if 0 not in value and libmp.fnan not in value._mpi_:
                    return True
            except (_Outside, ValueError, ZeroDivisionError, TypeError, OverflowError):
                continue
        return False
    finally:
        iv.prec = prec


def surely_nonzero_with_roots(d) -> bool:
    """`surely_nonzero`'s exact evaluation, square roots of symbolic radicands included: √X is
    taken as a square root of X's residue modulo 2⁶¹ − 1, so the residue map stays a ring
    homomorphism on the ring `expand`, `together` and `cancel` work in (√X a generator with
    (√X)² = X). A non-zero residue then proves that those steps cannot turn d into 0, at one of a
    few points (a radicand without a square root there moves to the next). False as
    `surely_nonzero` is, and for a root of a number, another root or a zero residue."""
    if not isinstance(d, sp.Expr):
        return False
    symbols = sorted(free_symbols(d), key=lambda s: s.name)
    if len(symbols) > len(_PRIMES) or any(s.is_nonpositive or s.is_integer for s in symbols):
        return False
    angles = _angles(d)
    for shift in range(_ROOT_POINTS):
        try:
            point = _exact_point(d, symbols, shift, angles)
            # positive symbols at squares: a positive factor SymPy splits off a radicand has a root
            point.update({s: point[s] ** 2 % _MODULUS for s in symbols if s in point and s.is_positive})
            return _residue(d, {**point, _ROOTS: True}, {}) != 0
        except _NoRoot:
            continue
        except (_Outside, ValueError, ZeroDivisionError):
            return False
    return False


def surely_depends(a, b, variables) -> bool:
    """Whether a/b provably depends on one of ``variables``: a(P) b(P′) ≠ a(P′) b(P) modulo 2⁶¹ − 1
    at `surely_nonzero`'s exact point P and P′, the same point with those variables alone moved.
    Were a/b = q with q free of them, both sides would be q(P) b(P) b(P′); so a non-zero
    difference proves that no q free of them (`cancel`'s included) has a = q b. False for what
    `surely_nonzero` cannot evaluate exactly, and where the two products agree."""
    if not isinstance(a, sp.Expr) or not isinstance(b, sp.Expr):
        return False
    symbols = sorted(free_symbols(a) | free_symbols(b), key=lambda s: s.name)
    moved = [s for s in symbols if s in set(variables)]
    if not moved or len(symbols) > len(_PRIMES) or any(s.is_nonpositive or s.is_integer for s in symbols):
        return False
    angles = _angles(a + b)
    try:
        here = _exact_point(a + b, symbols, 0, angles)
        there = {**here, **{s: (here[s] * 3 + 1) % _MODULUS for s in moved if s in here}}
        left = _residue(a, here, {}) * _residue(b, there, {})
        right = _residue(a, there, {}) * _residue(b, here, {})
    except (_Outside, ValueError, ZeroDivisionError):
        return False
    return (left - right) % _MODULUS != 0


_RATIO_DRAWS = 40
"""Seeded draws `ratio_varies` makes to find two points where both expressions have real values."""


def ratio_varies(a, b, seed: str) -> bool:
    """Whether a/b takes two values: a(P) b(P′) and a(P′) b(P) differ by more than 10^(10 − `DIGITS`)
    of their size, evaluated with mpmath at `DIGITS` digits at the first two seeded points (`sample`)
    where every radicand is positive and both values are real and finite (the test `numeric_zero`
    takes as a counterexample). Were a = q b for a number q (what `cancel` of a/b finds when it
    returns one: it rewrites by identities only), both products would be q b(P) b(P′). It reads the
    Jacobi functions and roots `surely_depends` cannot; False when no two such points turn up."""
    if not isinstance(a, sp.Expr) or not isinstance(b, sp.Expr) or a.has(sp.zoo, sp.nan) or b.has(sp.zoo, sp.nan):
        return False
    symbols = sorted(free_symbols(a) | free_symbols(b), key=lambda s: s.name)
    if any(s.is_integer or s.is_rational is False or s.is_real is False for s in symbols):
        return False
    bases = sorted({p.base for e in (a, b) for p in atoms(e, sp.Pow) if not p.exp.is_Integer}, key=sp.default_sort_key)
    try:
        f, radicands = mp_values.evaluator(symbols, [a, b]), mp_values.evaluator(symbols, bases)
    except NotImplementedError:
        return False
    rng, found = random.Random(seed), []
    with mpmath.workdps(DIGITS):
        for _ in range(_RATIO_DRAWS):
            point = [mpmath.mpf(p.p) / p.q for p in sample(symbols, rng)]
            try:
                vals = mp_values.real_values(f, radicands, point)
            except (NotImplementedError, ArithmeticError, libmp.NoConvergence):
                return False                  # no value to compare: left to `cancel`
            if vals is not None and all(mpmath.im(v) == 0 and mpmath.isfinite(v) for v in vals):
                found.append([mpmath.re(v) for v in vals])
            if len(found) == 2:
                (a0, b0), (a1, b1) = found
                left, right = a0 * b1, a1 * b0
                return abs(left - right) > max(1, abs(left), abs(right)) * mpmath.mpf(10) ** (10 - DIGITS)
    return False


class _NoRoot(_Outside):
    """A radicand whose residue has no square root modulo the prime (another point may)."""


_ROOT_POINTS = 12
"""The points `surely_nonzero_with_roots` tries: the primes of `_exact_point` turned by one each."""


def _exact_point(d, symbols, shift=0, angles=None) -> dict:
    """Residues of the point: pᵢ₊ₛ/7 for each symbol (s the shift, the primes in a ring); sin,
    cos, tan of each angle (`_angles`, unless given) from `_CIRCLE`."""
    inv = lambda n: pow(n, -1, _MODULUS)  # noqa: E731
    angles = _angles(d) if angles is None else angles
    if len(angles) > len(_CIRCLE):
        raise _Outside(d)
    primes = _PRIMES[shift:] + _PRIMES[:shift]
    point = {s: p * inv(7) % _MODULUS for s, p in zip(symbols, primes) if s not in angles}
    for x, (a, b, c) in zip(angles, _CIRCLE):
        point[sp.sin(x)], point[sp.cos(x)], point[sp.tan(x)] = a * inv(c), b * inv(c), a * inv(b)
    return point


def _angles(d) -> list:
    """The symbols d takes the sine, cosine or tangent of, by name."""
    return sorted({f.args[0] for f in atoms(d, sp.sin, sp.cos, sp.tan) if f.args[0].is_Symbol}, key=lambda s: s.name)


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
    elif e.is_Pow and e.exp.is_Rational and e.exp.q == 2 and not e.base.is_number and _ROOTS in point:
        value = pow(_root(_residue(e.base, point, memo)), int(e.exp.p), _MODULUS)
    else:
        raise _Outside(e)
    memo[e] = value
    return value


_ROOTS = object()
"""The key of a point at which `_residue` takes square roots of symbolic radicands."""


def _root(x: int) -> int:
    """The square root of x modulo `_MODULUS` that is itself a square, x^((p+1)/4) (p ≡ 3 mod 4):
    multiplicative, so √(ab) = √a √b as SymPy splits a radicand's positive factors (whose values
    `surely_nonzero_with_roots` makes squares); `_NoRoot` if x has none."""
    r = pow(x, (_MODULUS + 1) // 4, _MODULUS)
    if r * r % _MODULUS != x or x == 0:
        raise _NoRoot(x)
    return r


def _enclosure(e, point: dict, memo: dict, functions=_IV_FUNCTIONS):
    """An interval holding e's value at ``point`` (common subexpressions evaluated once), with the
    functions of one argument in ``functions``."""
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
            value = value + _enclosure(a, point, memo, functions)
    elif e.is_Mul:
        value = iv.mpf(1)
        for a in e.args:
            value = value * _enclosure(a, point, memo, functions)
    elif e.is_Pow:
        base = _enclosure(e.base, point, memo, functions)
        if e.exp.is_Integer:
            value = base ** int(e.exp)
        elif e.exp == sp.S.Half and base.a > 0:
            value = iv.sqrt(base)
        elif e.exp.is_Rational and base.a > 0:
            value = iv.exp(iv.log(base) * _enclosure(e.exp, point, memo, functions))
        else:
            raise _Outside(e)
    elif type(e) in functions:
        value = functions[type(e)](_enclosure(e.args[0], point, memo, functions))
    else:
        raise _Outside(e)
    memo[e] = value
    return value


def _radicals(e) -> bool:
    """Whether e has non-integer powers or functions, where `cancel` is not a canonical form."""
    return bool(atoms(e, sp.Function)) or any(not p.exp.is_Integer for p in atoms(e, sp.Pow))


def sample(symbols, rng: random.Random) -> list:
    """Rationals away from 0: positive symbols in [1/2, 3], others ±[1/5, 2]."""
    point = []
    for x in symbols:
        if x.is_positive:
            point.append(sp.Rational(rng.randint(50, 300), 100))
        else:
            point.append(sp.Rational(rng.choice((-1, 1)) * rng.randint(20, 200), 100))
    return point


def counterexample(lhs: sp.Matrix, rhs: sp.Matrix, seed: str) -> Outcome | None:
    """`numeric_zero`'s outcome when the first of its points shows claim − derived ≠ 0, else None.

    The same seeded draws, stopped after one point: where it finds a counterexample, the full test
    (and so the zero test, whose symbolic steps cannot show a non-zero difference zero) ends with
    this very outcome, so a checker may run it before the symbolic steps and skip them for a slip
    or a candidate correction that the one-point screens of `surely_nonzero` cannot read."""
    out, found = _numeric(lhs, rhs, seed, 1)
    return out if found else None


def differs_somewhere(a, b, seed: str) -> bool:
    """Whether `counterexample` finds a point where the scalars, or the matrices of one shape, ``a``
    and ``b`` differ: then ``expand(a − b)``, an identity, is not 0 either, and a caller may skip it."""
    if isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase) and a.shape == b.shape:
        a, b = sp.Matrix(list(a)), sp.Matrix(list(b))
    elif all(isinstance(x, sp.Expr) and not isinstance(x, sp.MatrixBase) for x in (a, b)):
        a, b = sp.Matrix([a]), sp.Matrix([b])
    else:
        return False
    try:
        return counterexample(a, b, seed) is not None
    except (NotImplementedError, TypeError, ValueError, ArithmeticError, libmp.NoConvergence):
        return False                      # no value to compare: left to `expand`


def numeric_zero(lhs: sp.Matrix, rhs: sp.Matrix, seed: str) -> Outcome:
    """claim − derived at `POINTS` seeded random points: exact when the difference is rational
    there, else by mpmath at `DIGITS` digits (relative to the size of the two sides)."""
    return _numeric(lhs, rhs, seed, POINTS)[0]


def _numeric(lhs, rhs, seed, points) -> tuple[Outcome, bool]:
    """`numeric_zero` at its first ``points`` points, and whether it found a counterexample."""
    symbols = sorted(free_symbols(lhs) | free_symbols(rhs), key=lambda x: x.name)
    transcendental = any(e.has(sp.Function) or any(not p.exp.is_Integer for p in atoms(e, sp.Pow))
                         for e in (*lhs, *rhs))
    rng = random.Random(seed)
    if transcendental and any(e.has(sp.zoo, sp.nan) for e in (*lhs, *rhs)):
        return Outcome(False, f"mpmath {DIGITS} digits at 0 points"), False    # a value at no point
    if transcendental:
        f = mp_values.evaluator(symbols, [*lhs, *rhs])
    n, used = len(lhs), 0
    for _ in range(3 * POINTS):                        # the draws do not depend on ``points``
        if used == points:
            break
        point = sample(symbols, rng)
        if not transcendental:
            vals = [e.xreplace(dict(zip(symbols, point))) for e in (*lhs, *rhs)]
            if any(not v.is_Rational for v in vals):
                continue                               # a pole of the formula: draw again
            used += 1
            bad = [a - b for a, b in zip(vals[:n], vals[n:]) if a != b]
            if bad:
                return Outcome(False, f"exact rational: claim − derived = {bad[0]} at a sample point"), True
            continue
        with mpmath.workdps(DIGITS):
            try:
                vals = [mpmath.mpmathify(v) for v in f(*(mpmath.mpf(p.p) / p.q for p in point))]
            except (ZeroDivisionError, ValueError):
                continue
            if not all(mpmath.isfinite(v) for v in vals):
                continue
            used += 1
            for a, b in zip(vals[:n], vals[n:]):
                size = max(1, abs(a), abs(b))
                if abs(a - b) > size * mpmath.mpf(10) ** (10 - DIGITS):
                    return Outcome(False, f"mpmath {DIGITS} digits: |claim − derived| = "
                                           f"{mpmath.nstr(abs(a - b), 3)} at a sample point"), True
    how = f"mpmath {DIGITS} digits" if transcendental else "exact rational"
    return Outcome(used > 0, f"{how} at {used} points"), False


@functools.lru_cache(maxsize=4096)
def entry_zero(d) -> bool:
    """Whether a difference of turn matrices' entries is zero (a number to 30 digits, else by its
    normal form in sin and cos); kept, as the same entries recur in every sequence a text is read in."""
    d = sp.sympify(d)
    if d.is_number:
        return abs(sp.N(d, 30)) < 1e-25
    ring = trig_zero(d, rotations.ANGLES)
    return rotations.trig_reduce(d) == 0 if ring is None else ring
