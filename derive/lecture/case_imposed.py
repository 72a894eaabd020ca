"""A case of the constants of the motion, imposed: "a top that starts upright has $L_z = Cn$", then
``Cn = L_z = A\\dot\\varphi\\sin^2\\vartheta + Cn\\cos\\vartheta``.

A relation of the text's constants of the motion alone that the prose sets (`derive.lecture.
constant_cases`: ``L_z = Cn``, its L_z and n defined by the rates) picks the motions that have those
constants. Written in the rates, it is one equation between them; where it is of the first degree in
one of the angles' rates (q̇ with a coefficient that is not zero), it gives that rate on those
motions, and a statement of the case can be read there: with the rate put in, every link of the
statement must vanish identically (SymPy's simplification to zero). Such a statement holds in the
case, its ``why`` naming the case and the rate it gave; any other is left as before (unchecked, the
case not imposed): a statement that does not vanish may be one the text writes to an order in a small
quantity (``\\frac{1}{2}Cn\\vartheta^2 = A\\dot\\varphi\\vartheta^2`` for a small tilt), which this
reading never flags.

A case of the free body's constants at an extreme moment (``L^2 = 2I_3T`` with the moments ordered
I₁ < I₂ < I₃, the text's ordering): written in the body rates (T = ½ Σ Iᵢω̃ᵢ², L² = Σ Iᵢ²ω̃ᵢ²) it is
Σ Iᵢ(Iᵢ − I₃)ω̃ᵢ² = 0, a sum of squares whose coefficients keep one sign under the ordering, so each
rate with a coefficient that is not zero vanishes on its motions (the permanent rotation about the
third axis): `rates_zero` gives those rates, and the text's ``\\omega_1 = \\omega_2 = 0`` there holds.

Takes: the checker (its ``vocab``, ``_resolve``, ``_sign``, ``d``, ``tex``). Gives: `in_case`, `rates_zero`.
May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.zero_test`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import zero_test as zt
from derive.symbolic.rotations import RATES

_ERRORS = (lx.NotRead, TypeError, ValueError, AttributeError, KeyError, IndexError, ZeroDivisionError)


def _in_rates(checker, value):
    """``value`` resolved, its body components ω̃ᵢ written in the angles and their rates."""
    e = checker._resolve(sp.sympify(value))
    return e.xreplace({w: checker.d.omega[i] for i, w in enumerate(lx.W)})


def _members(checker, latex: str):
    """The members of the relation ``latex`` (a plain ``=`` chain), resolved, or None."""
    parsed = lx.parse(latex, checker.vocab)
    if len(parsed.members) < 2 or set(parsed.relations) != {"="}:
        return None
    values = [m.value for m in parsed.members]
    if any(not isinstance(v, sp.Basic) or isinstance(v, sp.MatrixBase) for v in values):
        return None
    return [_in_rates(checker, v) for v in values]


def _rate_given(case) -> tuple | None:
    """(rate, its value) from the case ``a - b = 0``: the first of the angles' rates it is of the
    first degree in, with a coefficient that is not zero; None if there is none."""
    for q in RATES:
        if q not in case.free_symbols:
            continue
        poly = sp.Poly(sp.expand(case), q) if case.is_polynomial(q) else None
        if poly is None or poly.degree() != 1:
            continue
        slope, rest = poly.all_coeffs()
        # a slope proved non-zero at a point is not zero: `simplify` is spared it
        if not zt.nonzero_somewhere(slope) and sp.simplify(slope) == 0:
            continue
        return q, sp.simplify(-rest / slope)
    return None


def in_case(checker, latex: str, case_latex: str) -> str | None:
    """The ``why`` of the statement ``latex`` holding in the case ``case_latex`` (see the module
    docstring), or None when the case gives no rate or a link of the statement does not vanish."""
    try:
        case = _members(checker, case_latex)
        if case is None or len(case) != 2:
            return None
        given = _rate_given(case[0] - case[1])
        members = _members(checker, latex) if given is not None else None
        if members is None:
            return None
        rate, value = given
        for a, b in zip(members, members[1:]):
            link = sp.together((a - b).xreplace({rate: value}))
            # a link proved non-zero at a point does not vanish: `simplify` cannot turn it to 0
            if zt.nonzero_somewhere(link) or sp.simplify(link) != 0:
                return None
    except _ERRORS:
        return None
    except sp.PolynomialError:
        return None
    return f"{checker.tex(rate)} = {checker.tex(value)} on the motions of the case"


def rates_zero(checker, case_latex: str) -> frozenset:
    """The body rates ω̃ᵢ the case ``case_latex`` sets to zero (see the module docstring): empty when
    it is not a sum of the rates' squares whose non-zero coefficients all keep one sign under the
    text's orderings."""
    try:
        parsed = lx.parse(case_latex, checker.vocab)
        if len(parsed.members) != 2 or parsed.relations != ["="]:
            return frozenset()
        half = checker.d.forms(lx.T_)[0]
        put = {lx.T_: half, lx.ENERGY: half, lx.LMAG: checker.d.forms(lx.LMAG)[0]}
        a, b = (checker._resolve(sp.sympify(m.value)).xreplace(put) for m in parsed.members)
        poly = sp.Poly(sp.expand(a - b), *lx.W)
    except _ERRORS + (sp.PolynomialError, sp.GeneratorsNeeded):
        return frozenset()
    squares = {(2, 0, 0): lx.W[0], (0, 2, 0): lx.W[1], (0, 0, 2): lx.W[2]}
    if not poly.monoms() or any(m not in squares for m in poly.monoms()):
        return frozenset()
    names = sorted(set().union(*(sp.sympify(c).free_symbols for c in poly.coeffs())), key=lambda x: x.name)
    signs = {checker._sign(sp.factor(c), names) for c in poly.coeffs()}
    if len(signs) != 1 or signs == {"mixed"}:
        return frozenset()
    return frozenset(squares[m] for m in poly.monoms())

