"""An equation of motion that ends in the value its sides take in the text's case:
``I_3\\dot{\\omega}_3 = (I_1 - I_2)\\omega_1\\omega_2 = 0``.

Texts that look for a rotation at a constant ω̃ (a spin about one principal axis, the start of a
stability argument) write each of Euler's equations and then the value both sides have in the case
the prose considers (ω̃₁ = ω̃₂ = 0). The chain ``A = B = 0`` with ω̃̇ᵢ in it is read as the equation
of motion ``A = B`` it begins with (unless A and B are the same expression, a step of the text's:
then the equation is ``B = 0``, held as Euler's or left unchecked), by the same test as that equation written alone (holds, typo with
its one edit, or fails); the trailing 0 is checked when the section's settings make ``B`` vanish and
is otherwise left unread, as the why says (the case is the prose's, which the reader does not impose).

Gives the mixin `CaseValue` of the checker (`derive.lecture.notes_check.Checker`); it overrides
`derive.lecture.motion.Motion._eom`, so it stands before `Motion` in
`derive.lecture.reading_rules.ReadingRules`.
May import: :mod:`derive.lecture.zero_test`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture.zero_test import expanded

_READ = ("holds", "typo", "fails")


class CaseValue:
    """Mixin of the checker: see the module docstring. Uses ``self.claims``, ``self.ctx.subs``,
    ``self._resolve`` and ``self._members_kept``."""

    def _eom(self, line, piece, parsed):
        members = [m.value for m in parsed.members]
        if len(members) != 3 or list(parsed.relations) != ["=", "="] \
                or not all(isinstance(m, sp.Expr) for m in members) or members[2] != 0 or members[1] == 0:
            return super()._eom(line, piece, parsed)
        start = len(self.claims)
        if expanded(sp.sympify(self._resolve(members[0] - members[1])).xreplace(self.ctx.subs)) == 0:
            self._step_then_equation(line, piece, parsed, start)
            return None
        super()._eom(line, piece, self._members_kept(parsed, [0, 1]))
        vanishes = expanded(sp.sympify(self._resolve(members[1])).xreplace(self.ctx.subs)) == 0
        note = ("its last member 0 too, under the section's settings" if vanishes else
                "checked without its last member 0, the value in a case the prose considers, not read")
        for c in self.claims[start:]:
            if c.verdict in _READ:
                c.why += f" ({note})"
        return None

    def _step_then_equation(self, line, piece, parsed, start):
        """``A = B = 0`` with A and B the same expression (d/dt(I₃ω̃₃) − … = I₃ω̃̇₃ − … = 0): the first
        sign is a step of the text's, so the equation is B = 0, read as Euler's; where it is not one of
        them it stays unchecked (the 0 may be the value in a case the prose considers)."""
        super()._eom(line, piece, self._members_kept(parsed, [1, 2]))
        for c in self.claims[start:]:
            if c.verdict in _READ:
                c.why += " (its first two members the same expression, a step: the equation is the last two)"
            if c.verdict in ("typo", "fails"):
                c.verdict, c.correction = "unchecked", None
                c.why = f"not Euler's equation, perhaps the value in a case the prose considers: {c.why}"
