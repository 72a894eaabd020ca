"""A name the text defines at the end of a chain, by a factor it shares with the member before.

Takes: a display's LaTeX read by `derive.lecture.latex`. Gives the mixin `ChainEndNames` of
`derive.lecture.notes_check.Checker`, whose `_named_at_chain_end` reads
``L_z = \\omega \\sum_i m_i r_i^2 = J_z \\omega`` — a chain whose last member is a name of the text's
met there for the first time times a factor of the member before it — as the definition
J_z = Σᵢ mᵢ rᵢ² (the member before divided by that factor), recorded for the displays after it.
Nothing is judged here: the chain's own claims are read as before.

May import: :mod:`derive.lecture.latex`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import latex as lx


class ChainEndNames:
    """Mixin of the checker. Uses ``self.vocab`` and ``self.ctx``."""

    def _named_at_chain_end(self, latex: str) -> None:
        """Record ``N = B / c`` for a chain ``… = B = N c`` (N a new name of the text's, c ≠ 1 a
        factor whose symbols B has, B free of N); nothing for any other display."""
        try:
            parsed = lx.parse(latex, self.vocab)
        except lx.NotRead:
            return
        members = parsed.members
        if len(members) < 3 or set(parsed.relations) != {"="}:
            return
        last, before = sp.sympify(members[-1].value), sp.sympify(members[-2].value)
        if not isinstance(last, sp.Mul) or isinstance(before, sp.MatrixBase):
            return
        earlier = set().union(*(sp.sympify(m.value).free_symbols for m in members[:-1]))
        new = [s for s in last.free_symbols - earlier
               if isinstance(s, lx.Generic) and s.is_commutative and s not in self.ctx.defs]
        if len(new) != 1 or not last.has(new[0]):
            return
        (name,) = new
        factor = sp.cancel(last / name)
        if factor.has(name) or factor == 1 or not factor.free_symbols or \
                not factor.free_symbols <= before.free_symbols:
            return
        value = sp.cancel(before / factor)
        if value.has(name) or sp.expand(value * factor - before) != 0 or \
                not value.free_symbols.isdisjoint(factor.free_symbols):
            return
        self.ctx.defs[name] = value
