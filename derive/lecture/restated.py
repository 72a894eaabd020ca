"""A relation of the text's own names that it writes again with a name it has since defined put in.

Takes: the members of a relation the checker could not tie to the derivation
(`derive.lecture.textnames.TextNames._undefined`), resolved through the text's definitions.
Gives the mixin `Restated` of `derive.lecture.notes_check.Checker`, whose `_restated` keeps each
such equation ``A = B`` of a first reading and reads a later ``A = B'`` with the same left side as
the same claim restated: it holds when ``B' − B`` expands to zero with the text's definitions put
in (König's ``T = ½ m v_c² + ½ J_C ω²`` written again as ``T = ½ m v_c² + ½ (J_{z'} − m d²) ω²``
after ``J_{z'} = J_C + m d²``); and a later ``X = B'`` that solves an earlier equation of its names for
one of them, X entering it linearly, as the same equation (``\\omega_2 = \\frac{R}{a}\\omega_1`` after
``\\frac{\\omega_1}{\\omega_2} = \\frac{a}{R}``); and a later equation whose two sides' difference is an
earlier one's expanded, up to a non-zero number (a determinant ``= 0`` then written out). That says only that the text agrees with itself; a
restatement that differs says nothing (either of the two may be the one the text meant), so it is
never flagged. Such a verdict's claim is marked `Claim.self_consistent`: it confirms no reading of
the prose's names.

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.zero_test`, :func:`derive.lecture.two_cases.signed`, SymPy.
"""
from __future__ import annotations

import functools
import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import zero_test as zt
from derive.lecture.two_cases import signed


_ROOTS = re.compile(r"(?P<x>[^=]+?)=(?P<v>[^=]*\\(?:pm|mp)(?![A-Za-z])[^=]*)")


class Restated:
    """Mixin of the checker. Uses ``self._resolve``, ``self._add``, ``self.claims`` and ``self.tex``."""

    def _holds_as_restated(self, line, piece, why) -> None:
        """``piece`` holds by the text's own earlier equation (`Claim.self_consistent`)."""
        self._add(line, piece, "identity", "holds", why)
        self.claims[-1].self_consistent = True

    def _restated(self, line, piece, members, rels) -> bool:
        """True (and a verdict given) when ``members`` restate an earlier equation of the text's
        with the same left side; else the equation is kept for the later ones and False."""
        if rels != ["="] or len(members) != 2 or getattr(self, "_rereading_later", False):
            return False
        kept = self.__dict__.setdefault("restatable", [])
        left = sp.sympify(members[0])
        right = sp.sympify(self._resolve(members[1]))
        for at, was_left, was_right, _ in kept:
            if at < line and was_left == left and _alike(right, was_right) and sp.expand(right - was_right) == 0:
                self._holds_as_restated(line, piece, f"restates the text's {self.tex(left)} of line {at} "
                                                    "with its own definitions put in (expand)")
                return True
        for at, was_left, was_right, _ in reversed(kept):
            if (at < line and was_left != left and _alike(was_left, was_right, right)
                    and not isinstance(right, sp.MatrixBase)
                    and _solved_for(left, was_left - was_right, right)):
                self._holds_as_restated(line, piece, f"the text's equation of line {at} solved for {self.tex(left)}")
                return True
        for at, was_left, was_right, _ in reversed(kept):
            if at < line and was_left != left and _multiple((left, right), (was_left, was_right)):
                self._holds_as_restated(line, piece, f"the text's equation of line {at} written out (expand), "
                                                    "up to a constant factor")
                return True
        resolved = sp.sympify(self._resolve(left))
        for at, was_left, was_right, _ in list(reversed(kept))[:_STEPS]:
            sides = (resolved, right, sp.sympify(self._resolve(was_left)), was_right) if at < line else ()
            factor = _divided(sides[0] - sides[1], sides[2] - sides[3]) if sides and _scalars(*sides) else None
            if factor is not None:
                self._holds_as_restated(line, piece, f"the text's equation of line {at} with the factor "
                                                    f"${self.tex(factor)}$ its terms share divided out")
                kept.append((line, left, right, _written(members)))    # the text's next step starts here
                return True
        kept.append((line, left, right, _written(members)))
        return False


    def _roots_restated(self, line, piece, text) -> bool:
        """``x = v_1 \\pm v_2`` (two roots on the right, which the scalar reader leaves as written,
        ``\\mp`` taking the other sign): holds when both roots solve the text's latest earlier
        equation in x, or are the two roots of an earlier such statement of x (the same pair written
        another way); else False (not judged: a pair that differs says nothing of which is wrong).
        Either way the pair is kept for the statements after it."""
        m = _ROOTS.fullmatch(text.strip())
        if m is None:
            return False
        try:
            both = [lx.parse(f"{m['x']} = \\left({signed(m['v'], upper)}\\right)", self.vocab) for upper in (True, False)]
        except lx.NotRead:
            return False
        x = both[0].members[0].value
        written = [p.members[1].value for p in both]
        roots = [self._resolve(r) for r in written]
        if not isinstance(x, sp.Symbol) or not _scalars(*roots, *written) or any(r.has(x) for r in written):
            return False
        pairs = self.__dict__.setdefault("root_pairs", [])
        pairs.append((line, x, roots))
        for at, was_left, was_right, as_written in reversed(self.__dict__.get("restatable", [])):
            # as written first (a name the text holds constant while it solves, L_a = I(ω + Ω cos ϑ)
            # for Ω), then with the text's definitions put in
            tries = [(as_written, written), (_written((was_left, was_right)), roots)]
            tries = [(eq, rs) for eq, rs in tries
                     if eq is not None and _scalars(eq, x) and x in eq.free_symbols and not any(r.has(x) for r in rs)]
            if at < line and tries:
                if any(all(_zero(eq.xreplace({x: r})) for r in rs) for eq, rs in tries):
                    self._holds_as_restated(line, piece, f"the two roots of the text's equation of line {at}")
                    return True
                break
        for at, was_x, was_roots in reversed(pairs[:-1]):
            if at < line and was_x == x:
                if any(all(_zero(a - b) for a, b in zip(roots, order))
                       for order in (was_roots, was_roots[::-1])):
                    self._holds_as_restated(line, piece, f"the text's two roots of line {at} written another way")
                    return True
                return False
        return False


_STEPS = 3
"""The text's latest equations a later one may be with a common factor divided out (a step of its own)."""


@functools.lru_cache(maxsize=512)
def _divided(new, old):
    """The factor f ≠ number when ``old = f · new`` (both an equation's two sides' difference) and f is
    a product of the letters and of sines, cosines and exponentials of ``old`` that every one of its
    terms shares (what a text divides out, ``\\sin\\vartheta``, ``\\cos(\\alpha t)``, ``m``), up to a number;
    new a sum of two terms or more; else None."""
    if not _scalars(new, old):
        return None
    new, old = _difference(new, 0), _difference(old, 0)
    if not isinstance(new, sp.Add) or not zt.free_symbols(new) <= zt.free_symbols(old):
        return None
    if not isinstance(old, sp.Add) or len(old.args) != len(new.args):
        return None                       # a shared factor of letters and functions keeps the terms' count
    factor, rest = _shared(old)
    if factor == 1 or not all(b.is_Symbol or isinstance(b, (sp.sin, sp.cos, sp.exp))
                              for b in (f.as_base_exp()[0] for f in sp.Mul.make_args(factor))):
        return None
    if zt.free_symbols(rest) != zt.free_symbols(new) or zt.ratio_varies(rest, new, "divided"):
        return None
    return factor if _number_times(rest, new) else None


def _number_times(rest, new) -> bool:
    """Is ``rest`` a non-zero number times ``new`` (both expanded sums)? The number is read off one
    term's coefficient and checked on the whole expansion (no rational function is cancelled)."""
    coefficient, monomial = sp.Add.make_args(new)[0].as_coeff_Mul()
    match = [c for c, m in (t.as_coeff_Mul() for t in sp.Add.make_args(rest)) if m == monomial]
    return len(match) == 1 and match[0] != 0 and sp.expand(rest - match[0] / coefficient * new) == 0


@functools.lru_cache(maxsize=512)
def _shared(old) -> tuple:
    """(the factor every term of ``old`` shares, but numbers; the rest expanded), taken out without
    factoring; once per equation, however many later ones are held against it."""
    powers = [term.as_powers_dict() for term in sp.Add.make_args(old)]
    factor = sp.Mul(*(base**min(p[base] for p in powers) for base in powers[0]
                      if not base.is_number and all(base in p and p[base].is_number and p[base] * powers[0][base] > 0
                                                    for p in powers)))
    return factor, sp.expand(old / factor)


def _written(members):
    """An equation's two sides' difference as written (no definition put in), or None for matrices."""
    left, right = sp.sympify(members[0]), sp.sympify(members[1])
    return left - right if _scalars(left, right) else None


def _zero(d) -> bool:
    """d ≡ 0: `simplify` only where no seeded point proves d ≠ 0 (no identity turns such a d into 0)."""
    return not zt.nonzero_somewhere(d) and sp.simplify(d) == 0


def _scalars(*values) -> bool:
    """Are ``values`` all commuting scalar expressions (no matrix, none of the text's matrix names)?"""
    return all(isinstance(v, sp.Expr) and not isinstance(v, sp.MatrixBase) and v.is_commutative for v in values)


def _multiple(new, old) -> bool:
    """Is the equation ``new`` (its two sides) the equation ``old`` expanded, up to a non-zero
    number (a determinant written out: ``\\det[…] = 0`` then ``\\lambda^2 - c = 0``)?"""
    if not _scalars(*new, *old):
        return False                      # scalars only: the text's matrices do not commute
    new, old = _difference(*new), _difference(*old)
    symbols = zt.free_symbols(new)
    if not symbols or old == 0 or symbols != zt.free_symbols(old):
        return False                      # a number times old has old's symbols, no others
    if zt.surely_depends(new, old, symbols):
        return False                      # new/old proved not a number, at an exact point
    if zt.ratio_varies(new, old, "restated"):
        return False                      # new/old takes two values at two points: not a number
    ratio = sp.cancel(new / old)
    return ratio.is_number and ratio != 0 and ratio.is_finite is True


@functools.lru_cache(maxsize=512)
def _difference(left, right):
    """``left − right`` expanded, once per equation however many later ones it is held against."""
    return sp.expand(left - right)


def _alike(*values) -> bool:
    """Are ``values`` all scalars, or all matrices of one shape (what can be subtracted)?"""
    if all(isinstance(v, sp.Expr) and not isinstance(v, sp.MatrixBase) for v in values):
        return True   # (an immutable matrix is an Expr too)
    return (all(isinstance(v, sp.MatrixBase) for v in values)
            and len({v.shape for v in values}) == 1)


@functools.lru_cache(maxsize=512)
def _solved_for(x, equation, value) -> bool:
    """Is ``x = value`` the equation ``equation = 0`` solved for the symbol x, which enters it linearly?
    Memoised: a text's convention probed reads the same pair again in each sequence it tries."""
    if not isinstance(x, sp.Symbol) or x not in getattr(equation, "free_symbols", ()) or x in value.free_symbols:
        return False
    num = sp.numer(sp.together(equation))
    if not num.is_polynomial(x) or sp.degree(num, x) != 1:
        return False
    a, b = sp.Poly(num, x).all_coeffs()
    d = -b / a - value if a != 0 else None
    return d is not None and _zero(d)
