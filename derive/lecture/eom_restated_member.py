"""An equation of motion whose chain restates one member first: ``\\dot{L}_1 \\equiv I_1 \\dot{\\Omega}_1 = \\Omega_2(I_2 - I_3)\\Omega_3``.

A text writes the rate of the angular momentum's component, then what it is in principal axes
(L̇ᵢ = Iᵢω̃̇ᵢ, its own definition or the reader's), then Euler's right side. Of the chain's two
links, the first says one member again in other letters: it holds identically. The chain is then
read as its other link, the equation of motion, by the same test as that equation written alone;
the why says the first link restates a member. A chain whose links are both more than a restatement
is left to the other rules. Gives the mixin `RestatedMember` of the checker
(`derive.lecture.notes_check.Checker`); it overrides `derive.lecture.motion.Motion._eom`, so it
stands before `Motion` in `derive.lecture.reading_rules.ReadingRules`.
May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.comparing`, :mod:`derive.lecture.zero_test`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.comparing import free
from derive.lecture.zero_test import expanded

_READ = ("holds", "typo", "fails")


class RestatedMember:
    """Mixin of the checker: see the module docstring. Uses ``self.claims``, ``self.ctx.subs``,
    ``self._resolve`` and ``self._members_kept``."""

    def _eom(self, line, piece, parsed):
        members = [m.value for m in parsed.members]
        if len(members) != 3 or not all(isinstance(m, sp.Expr) for m in members) or 0 in members:
            return super()._eom(line, piece, parsed)
        same = [k for k in (0, 1) if expanded(sp.sympify(self._resolve(members[k] - members[k + 1]))
                                              .xreplace(self.ctx.subs)) == 0]
        if len(same) != 1:
            return super()._eom(line, piece, parsed)
        keep = [1, 2] if same[0] == 0 else [0, 1]
        if not any(w in free(members[keep[0]] - members[keep[1]]) for w in lx.WD):
            return super()._eom(line, piece, parsed)
        start = len(self.claims)
        super()._eom(line, piece, self._members_kept(parsed, keep))
        for c in self.claims[start:]:
            if c.verdict in _READ:
                c.why += " (the chain's other link restates a member in other letters)"
        return None
