"""A solution whose two constants multiply one function: ``c_1 \\exp(\\kappa t) + c_2 \\exp(\\kappa t)``.

Takes: one statement ``x = c_1 f(t) + c_2 g(t)`` of the text, its two constants one letter indexed 1
and 2 (c₁, c₂; C₁, C₂; A₁, A₂), each in its own term. Gives the mixin `ConstantsCollapsed` of
`derive.lecture.notes_check.Checker`, whose `_constants_collapsed` flags it when f and g are one
function of the time t: the constants then enter only as c₁ + c₂, so the family has one free
constant where a text writes two for the two independent solutions of a second-order equation
(e^{κt} and e^{−κt}, cos κt and sin κt). Whatever the equation is, two constants beside one
function is no way of writing a general solution, so the statement `fails`; with f and g different
functions, or any other shape, the rule says nothing.

May import: SymPy, :mod:`derive.lecture.latex`.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx

_INDEXED = re.compile(r"^(?P<letter>[A-Za-z])_\{?(?P<index>[12])\}?$")


def collapsed(left, right) -> tuple[str, sp.Expr] | None:
    """(the constants' letter, the one function) when ``right`` is c₁ f + c₂ f with f a function of
    the time and ``left`` a single unknown; else None."""
    if not isinstance(left, (sp.Symbol, sp.Function)) or not isinstance(right, sp.Add) or len(right.args) != 2:
        return None
    pairs = [_constant_times(term) for term in right.args]
    if None in pairs:
        return None
    (c1, f1), (c2, f2) = pairs
    m1, m2 = _INDEXED.match(c1.name), _INDEXED.match(c2.name)
    if not (m1 and m2) or m1["letter"] != m2["letter"] or {m1["index"], m2["index"]} != {"1", "2"}:
        return None
    if f1 != f2 or lx.t not in f1.free_symbols or left in f1.free_symbols:
        return None
    return m1["letter"], f1


def _constant_times(term) -> tuple[sp.Symbol, sp.Expr] | None:
    """(c, f) for a term c·f with c one symbol that is a factor of it and appears nowhere in f."""
    factors = sp.Mul.make_args(term)
    symbols = [f for f in factors if isinstance(f, sp.Symbol) and _INDEXED.match(f.name)]
    if len(symbols) != 1:
        return None
    c = symbols[0]
    rest = sp.Mul(*[f for f in factors if f is not c])
    return (c, rest) if c not in rest.free_symbols else None


class ConstantsCollapsed:
    """Mixin of the checker. Uses ``self.vocab``, ``self._add`` and ``self.tex``."""

    def _constants_collapsed(self, line, piece, text) -> bool:
        """Flag ``x = c_1 f + c_2 f`` (True when judged)."""
        try:
            parsed = lx.parse(text, self.vocab)
        except (lx.NotRead, lx.Words, ValueError, TypeError):
            return False
        members = parsed.members
        if parsed.relations != ["="]:
            return False
        found = collapsed(members[0].value, members[1].value)
        if found is None:
            return False
        letter, f = found
        self._add(line, piece, "solution", "fails",
                  f"both constants {letter}_1 and {letter}_2 multiply the same function {self.tex(f)}: they enter "
                  f"only as {letter}_1 + {letter}_2, so the family has one free constant, not the two of a "
                  "general solution (its second term needs the other independent solution)")
        return True
