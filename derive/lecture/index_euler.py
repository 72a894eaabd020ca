r"""Euler's equations written once for axes named by letters: an index form or axes x, y, z.

Takes: a statement of a display the other rules left unchecked. Gives: the mixin `IndexEuler`, which
reads a statement whose subscripts are exactly the three letters i, j, k (``I_i \dot\Omega_i -
(I_j - I_k)\Omega_j\Omega_k = \tau_i``, the text's "for each axis", "(i, j, k) cyclic") or exactly
x, y, z (``I_x \dot\omega_x - (I_y - I_z)\omega_y\omega_z = \tau_x``, the body's axes named by
letters), and that writes a rate of the angular velocity (dotted, or d/dt of one component), moments
I, the angular velocity and perhaps the torque τ and nothing else with a subscript. It puts the axes
1, 2, 3 for the letters, (i, j, k) taking the three cyclic orders of (1, 2, 3) and (x, y, z) the order (1, 2, 3), and the
statement holds when every such instance is one of Euler's equations under the section's settings.

Left alone (unchecked, never flagged): a statement with any instance that is not, since the letters
may name the axes in another order or the text may mean other axes; subscripts beside those three
letters; a statement another rule gave a verdict. May import: :mod:`derive.lecture.differentials`,
:mod:`derive.lecture.latex`, :mod:`derive.lecture.comparing`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import differentials
from derive.lecture import latex as lx
from derive.lecture.comparing import free

_SUB = re.compile(r"(\\[A-Za-z]+|[A-Za-z])(\s*\})?\s*_\s*(\{\s*([A-Za-z0-9]+)\s*\}|([A-Za-z0-9]))")
_BASES = {"I", "\\omega", "\\Omega", "\\tau"}
_LABELS = {("i", "j", "k"): ("123", "231", "312"), ("x", "y", "z"): ("123",)}


def instances(piece: str) -> list[str]:
    """The statement with axes 1, 2, 3 put for its three letters, one per order they may stand
    for; empty when its subscripts are not exactly one of those triples on I, ω, Ω and τ."""
    found = list(_SUB.finditer(piece))
    subs = {m.group(4) or m.group(5) for m in found}
    if not found or any(m.group(1) not in _BASES for m in found):
        return []
    if not re.search(r"\\dot\s*\{?\s*\\(omega|Omega)", differentials.dotted(piece)):
        return []
    for letters, orders in _LABELS.items():
        if subs == set(letters):
            return [_SUB.sub(lambda m, o=order, ls=letters: m.group(0)[:m.start(3) - m.start(0)]
                             + o[ls.index(m.group(4) or m.group(5))], piece) for order in orders]
    return []


class IndexEuler:
    """Mixin of the checker: uses ``self._add``, ``self.claims``, ``self.vocab`` and ``self._eom_check``."""

    def _index_euler(self, line, piece, before) -> None:
        """Holds when every instance of a letter-indexed statement is one of Euler's equations."""
        if any(c.verdict != "unchecked" for c in self.claims[before:]):
            return
        forms = instances(piece)
        if not forms:
            return
        for form in forms:
            try:
                parsed = lx.parse(form, self.vocab)
            except lx.NotRead:
                return
            if len(parsed.members) != 2 or isinstance(parsed.members[0].value, sp.MatrixBase):
                return
            raw = parsed.members[0].value - parsed.members[1].value
            if not free(raw) & set(lx.WD):
                return
            try:
                ok = self._eom_check(raw, candidate=True)[0]
            except (ArithmeticError, TypeError, ValueError, lx.NotRead):
                return
            if not ok:
                return
        del self.claims[before:]
        which = "the three cyclic orders of (1, 2, 3) for (i, j, k)" if len(forms) == 3 else "axes 1, 2, 3 for x, y, z"
        self._add(line, piece, "equation of motion", "holds",
                  f"Euler's equation in every instance, with {which}")
