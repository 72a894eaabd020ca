"""A text's worked numbers beside a formula in symbols it gives no value.

A display such as ``\\Omega_1 = 0.8976\\omega_1`` comes from a worked case: the number is the
formula's value for moments of inertia (or lengths, masses) that the text gives in a table or in
prose the reader does not read. Compared with the derived formula, whose symbols stay free, such a
statement would be flagged at every sample point although it may well hold for the text's case; it
is therefore left unchecked, naming the symbols whose values it needs. So is a worked number in
whole numbers (``T = \\frac{1}{2}(2)(3)^2 = 9``): its written side has no symbol at all. A statement
in symbols with no decimal number, or whose derived side has no symbol beyond those it writes, is
compared as before. A statement whose sides carry decimals of the text's (``0.3404``, the numbers of
a matrix it wrote to four places, or their products) and differ by less than a thousandth of their size
(``R^T R = 1`` for that matrix, off by 0.00004), which the rounding of numbers written to three places
or more can make, is left unchecked too: the rounding is no slip.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx

# a number written with a decimal point, math-mode spaces allowed around it (``0 .8976``, ``2.5``, ``.5``)
_DECIMAL = re.compile(r"\d\s*\.\s*\d|(?<![\w.])\.\d")

WHY = ("a worked value: its number comes from values of {names} that the text gives elsewhere (a table or "
       "prose), not from the formula alone")


def _free(e) -> set:
    return set(getattr(e, "free_symbols", set()))


ROUNDED = ("agrees to the rounding of the decimals it carries: its sides differ by {gap:.2g}, less than a "
           "thousandth of their size, which numbers written to three places or more can make")


def _many_places(q) -> bool:
    """Whether a number is a decimal of three places or more (851/2500 is 0.3404): its denominator is above
    100 and divides a power of ten (1/8 may be a fraction the text means exactly)."""
    return q.q > 100 and any(10 ** k % q.q == 0 for k in range(3, 17))


def rounded(written, derived: list) -> str | None:
    """Why sides in the text's many-place decimals that differ only by their rounding are no slip, or None."""
    sides = [written, *derived]
    if len(derived) != 1 or not any(_many_places(q) for e in sides for q in getattr(e, "atoms", lambda *_: ())(sp.Rational)):
        return None
    try:
        point = {x: sp.Rational(3 + i, 4) for i, x in enumerate(sorted(set().union(*map(_free, sides)), key=str))}
        w, d = (sp.Matrix(e.xreplace(point)) if isinstance(e, sp.MatrixBase) else sp.Matrix([e.xreplace(point)])
                for e in (written, derived[0]))
        if w.shape != d.shape:
            return None
        gap, size = max(abs(float(a - b)) for a, b in zip(w, d)), max(abs(float(a)) for a in (*w, *d))
    except (TypeError, ValueError, ZeroDivisionError, sp.ShapeError):
        return None
    return ROUNDED.format(gap=gap) if 0 < gap < 1e-3 * max(size, 1.0) else None


def unchecked(piece: str, written, derived: list, tex, head=None) -> str | None:
    """Why a statement with a decimal number, or with a plain number other than 0 set to a ``head``
    that is one name, is left unchecked: every derived form keeps symbols (other than time) that the
    written side does not have; None when it is compared as usual."""
    # a relation set to 0, or an equation set to 1 (an ellipsoid's), is no worked value: its head is no name
    number = isinstance(head, sp.Symbol) and not _free(written) and written != 0
    if why := rounded(written, derived):
        return why
    if not derived or not (_DECIMAL.search(piece) or number):
        return None
    extra = set()
    for form in derived:
        more = {s for s in _free(form) - _free(written) if s != lx.t and isinstance(s, sp.Symbol)}
        if not more:
            return None
        extra |= more
    return WHY.format(names=", ".join(sorted(tex(s) for s in extra)))
