"""Expressions read into SymPy's sparse polynomial rings and fields of rational functions, where
the zero test's canonical forms cost dicts of monomials instead of rewritten expression trees.

Takes: SymPy expressions. Gives: `free_symbols` and `atoms` (SymPy's, memoised per expression),
`generators` and `in_ring` (a polynomial in symbols, their reciprocals and sin, cos, tan of
symbols as an element of a ring over them: `derive.lecture.zero_test.expanded`), `rational_zero`
(``cancel(together(d)) == 0`` in the field of rational functions) and `trig_zero`
(``trig_reduce(d, angles) == 0`` in the ring). Each gives what the step it stands in for gives;
what it cannot read goes to that step.

May import: SymPy, :mod:`derive.symbolic.rotations` (the cos² replacement `trig_reduce` uses).
"""
from __future__ import annotations

import functools

import sympy as sp
from sympy.polys.fields import field
from sympy.polys.rings import ring

from derive.symbolic.rotations import cos_squares_replaced


def free_symbols(e) -> frozenset:
    """``e.free_symbols``, memoised per expression (a mutable matrix is walked each time): the
    checkers ask again for the symbols of the same sides as they unify, screen and compare them,
    and SymPy walks the whole tree on each call."""
    try:
        return _free_symbols_kept(e)
    except TypeError:
        return frozenset(e.free_symbols)


@functools.lru_cache(maxsize=8192)
def _free_symbols_kept(e) -> frozenset:
    return frozenset(e.free_symbols)


def atoms(e, *types) -> frozenset:
    """``e.atoms(*types)``, memoised per expression and types as `free_symbols` is."""
    try:
        return _atoms_kept(e, types)
    except TypeError:
        return frozenset(e.atoms(*types))


@functools.lru_cache(maxsize=8192)
def _atoms_kept(e, types) -> frozenset:
    return frozenset(e.atoms(*types))


@functools.lru_cache(maxsize=1024)
def polynomial_ring(gens: tuple):
    """SymPy's sparse ring over QQ in ``gens``, per tuple of generators: the one ``ring`` returns
    (SymPy keeps one ring per key) without parsing its options again on each call."""
    return ring(gens, sp.QQ)[0]


@functools.lru_cache(maxsize=1024)
def _rational_field(gens: tuple):
    return field(gens, sp.QQ)[0]


def ring_generators(t) -> list | None:
    """`generators` of t, an atom included (a symbol is its own, a rational has none)."""
    t = sp.sympify(t)
    if t.is_Symbol:
        return [t]
    return [] if t.is_Rational else generators(t)


def generators(d) -> list | None:
    """The generators of d as `zero_test.expanded` reads it, by name; None when d is anything else (a
    function of a sum, a root, a float, a quotient by a sum)."""
    if not isinstance(d, sp.Expr) or d.is_Atom:
        return None
    gens = set()
    for node in sp.preorder_traversal(d):
        if node.is_Symbol and node.is_commutative:
            gens.add(node)
        elif node.is_Add or node.is_Mul or node.is_Rational:
            continue
        elif node.is_Pow and node.exp.is_Integer and (node.exp > 0 or node.base.is_Symbol):
            if node.exp < 0:
                gens.add(1 / node.base)
        elif isinstance(node, (sp.sin, sp.cos, sp.tan)) and node.args[0].is_Symbol:
            gens.add(node)
        else:
            return None
    return sorted(gens, key=sp.default_sort_key)


def in_ring(e, gens: dict, R, memo: dict):
    """e as an element of R, a sparse ring or field over the generators ``gens`` (a SymPy
    generator → R's): e read by `generators` (a reciprocal 1/x one of the ring's generators) or by
    `_rational_generators` (the field divides itself)."""
    if e in gens:
        return gens[e]
    if e in memo:
        return memo[e]
    if e.is_Rational:
        value = R.ground_new(sp.QQ(int(e.p), int(e.q)))
    elif e.is_Add:
        value = R.zero
        for a in e.args:
            value += in_ring(a, gens, R, memo)
    elif e.is_Mul:
        value = R.one
        for a in e.args:
            value *= in_ring(a, gens, R, memo)
    elif e.exp < 0 and 1 / e.base in gens:
        value = gens[1 / e.base] ** int(-e.exp)
    else:
        value = in_ring(e.base, gens, R, memo) ** int(e.exp)
    memo[e] = value
    return value


def rational_zero(d) -> bool:
    """``cancel(together(d)) == 0``: whether d is the zero rational function. Where d is a rational
    function of its symbols with rational coefficients (sums, products and integer powers of them),
    decided in SymPy's sparse field of rational functions over QQ, each operation of d's tree one
    operation there, reduced to lowest terms as `cancel` reduces: both are exact, so both give 0
    for the same d. Anything else (a root, a function, a float, a denominator that vanishes
    identically) goes to `cancel` itself."""
    gens = _rational_generators(d)
    if gens:
        try:
            K = _rational_field(tuple(gens))
            return not in_ring(d, dict(zip(gens, K.gens)), K, {})
        except ZeroDivisionError:
            pass
    return sp.cancel(sp.together(d)) == 0


def _rational_generators(d) -> list | None:
    """The symbols of d, by name, when d is built from them and rationals by sums, products and
    integer powers; None otherwise (and for a number)."""
    gens = set()
    for node in sp.preorder_traversal(d):
        if node.is_Symbol and node.is_commutative:
            gens.add(node)
        elif not (node.is_Add or node.is_Mul or node.is_Rational or node.is_Pow and node.exp.is_Integer):
            return None
    return sorted(gens, key=sp.default_sort_key) or None


def trig_zero(d, angles) -> bool | None:
    """``rotations.trig_reduce(d, angles) == 0``, or None where d is no polynomial (as `generators`
    reads it) without tan: d multiplied out in the ring over its generators, each monomial's
    cos(x)^(2m+e) of an angle x of ``angles`` replaced by cos(x)^e (1 − sin(x)²)^m and x·x⁻¹ by 1.
    That is `trig_reduce`'s remainder modulo cos² + sin² − 1 of d's numerator (its denominator a
    monomial in symbols): the normal form, zero exactly where `trig_reduce` gives 0."""
    gens = generators(d)
    if gens is None or any(isinstance(g, sp.tan) for g in gens):
        return None
    gens = set(gens)
    gens |= {sp.sin(g.args[0]) for g in gens if isinstance(g, sp.cos) and g.args[0] in angles}
    gens = sorted(gens, key=sp.default_sort_key)
    R = polynomial_ring(tuple(gens))
    p = in_ring(d, dict(zip(gens, R.gens)), R, {})
    where = {g: k for k, g in enumerate(gens)}
    pairs = [(where[sp.sin(g.args[0])], k) for k, g in enumerate(gens) if isinstance(g, sp.cos) and g.args[0] in angles]
    inverse = [(where[1 / g], k) for k, g in enumerate(gens) if g.is_Symbol and 1 / g in where]
    out = {}
    for monom, coeff in p.items():
        monom = list(monom)
        for i, k in inverse:
            common = min(monom[i], monom[k])
            monom[i] -= common
            monom[k] -= common
        terms = cos_squares_replaced(monom, coeff, pairs)
        for exps, cf in terms:
            key = tuple(exps)
            out[key] = out.get(key, 0) + cf
    return not any(out.values())
