"""A body's constant written ≈ 0 (a principal moment, a length), judged by what the text has said of it.

Gives the mixin `SmallMoments` of `derive.lecture.notes_check.Checker`. "I_x ≈ 0" is decided
two ways, from the text's own statements only:

* **the value the text gave it** (I_x = M(b² + c²)/12, kept across sections in ``ctx.given`` by
  its name as written, so that a second reading of the names finds it too;
  a setting the reader corrected, with its correction): with the small quantities the text states (ε, and the ω̃ᵢ its prose calls
  small) set to 0, the value is still not 0 — the moment is of order one, not ≈ 0; when it
  vanishes there, the approximation holds to leading order (a thin rod's I₃ = m r²/2 with r ≪ L);
* **an ordering the text states** (I_x < I_y < I_z): a moment that is not the smallest cannot be
  ≈ 0, since the one below it would be too and the third, by the triangle inequality of the
  moments (I_k ≤ I_i + I_j for any body), with it: no body has all three ≈ 0.

Otherwise it stays with the reader's general rule (``unchecked`` without a stated small quantity).

May import: :mod:`derive.lecture.latex`, SymPy and the derivation's symbols.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3
from derive.symbolic.rotations import ANGLES, RATES

MOMENTS = (I1, I2, I3)
MOTION = set(lx.W) | set(lx.WD) | set(ANGLES) | set(RATES) | set(ACCELS) | {lx.t}


def written_name(latex: str) -> str:
    """The left side of a statement as written, without spaces and braces (``I_{x} = …`` → ``I_x``):
    the key of what the text set, whichever quantity the reader takes the name for."""
    return re.sub(r"[\s{}]", "", re.split(r"=|\\approx|\\simeq", latex, maxsplit=1)[0])


class SmallMoments:
    """Mixin of the checker. Uses ``self.ctx``, ``self.vocab``, ``self._add`` and ``self.tex``."""

    def _given(self, line, latex):
        """A setting X = value the reader corrected: the text's value of X from here on (``ctx.given``)."""
        try:
            parsed = lx.parse(latex, self.vocab)
        except lx.NotRead:
            return
        if len(parsed.members) == 2 and isinstance(parsed.members[0].value, sp.Symbol):
            self.ctx.given[written_name(latex)] = (parsed.members[1].value, f"line {line}, as corrected")

    def _small_moment(self, line, piece, parsed) -> bool:
        """X ≈ 0 decided by the text's value of X (a constant of the body) or, for a principal moment,
        the text's ordering of the moments (see the module docstring); False when neither decides it."""
        if parsed.relations != ["≈"] or len(parsed.members) != 2 or parsed.members[1].value != 0:
            return False
        moment = parsed.members[0].value
        if not isinstance(moment, sp.Symbol) or moment in MOTION:
            return False
        small = set(self.ctx.small) | set(self.ctx.first_order)
        name = written_name(piece)
        if name in self.ctx.given:
            value, where = self.ctx.given[name]
            if value.free_symbols & (set(MOMENTS) | MOTION):
                return False
            lead = sp.simplify(value.xreplace({s: 0 for s in small}))
            said = f"the text gives {name} = {self.tex(value)} ({where})"
            if lead == 0:
                self._add(line, piece, "approximation", "holds", f"{said}: 0 to leading order in the small quantities it states")
            else:
                names = ", ".join(sorted(self.tex(s) for s in small)) or "none"
                self._add(line, piece, "approximation", "fails",
                          f"{said}, which does not vanish with the small quantities it states ({names}): "
                          f"{self.tex(moment)} is of order one, not ≈ 0")
            return True
        if moment not in MOMENTS:
            return False
        for chain in self.ctx.orderings:
            if moment in chain and chain.index(moment) > 0 and all(m in MOMENTS for m in chain):
                below = chain[chain.index(moment) - 1]
                self._add(line, piece, "approximation", "fails",
                          f"the text orders the moments {' < '.join(self.tex(m) for m in chain)}: with "
                          f"{self.tex(moment)} ≈ 0, {self.tex(below)} ≈ 0 too, and the third moment with them "
                          "(I_k ≤ I_i + I_j for any body): no body has all three ≈ 0")
                return True
        return False
