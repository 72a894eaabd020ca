"""A text's worked numbers beside a formula in symbols it gives no value.

A display such as ``\\Omega_1 = 0.8976\\omega_1`` comes from a worked case: the number is the
formula's value for moments of inertia (or lengths, masses) that the text gives in a table or in
prose the reader does not read. Compared with the derived formula, whose symbols stay free, such a
statement would be flagged at every sample point although it may well hold for the text's case; it
is therefore left unchecked, naming the symbols whose values it needs. So is a worked number in
whole numbers (``T = \\frac{1}{2}(2)(3)^2 = 9``): its written side has no symbol at all. A statement
in symbols with no decimal number, or whose derived side has no symbol beyond those it writes, is
compared as before.
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


def unchecked(piece: str, written, derived: list, tex, head=None) -> str | None:
    """Why a statement with a decimal number, or with a plain number other than 0 set to a ``head``
    that is one name, is left unchecked: every derived form keeps symbols (other than time) that the
    written side does not have; None when it is compared as usual."""
    # a relation set to 0, or an equation set to 1 (an ellipsoid's), is no worked value: its head is no name
    number = isinstance(head, sp.Symbol) and not _free(written) and written != 0
    if not derived or not (_DECIMAL.search(piece) or number):
        return None
    extra = set()
    for form in derived:
        more = {s for s in _free(form) - _free(written) if s != lx.t and isinstance(s, sp.Symbol)}
        if not more:
            return None
        extra |= more
    return WHY.format(names=", ".join(sorted(tex(s) for s in extra)))
