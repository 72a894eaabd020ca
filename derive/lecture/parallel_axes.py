"""The parallel-axis theorem as texts state it: ``J_{z'} = J_C + m d^2``, ``I_O = I_G + M a^2``.

Takes: a statement of the notes checker (`derive.lecture.notes_check.Checker`) and the claims the
checker gave it. Gives: the mixin `ParallelAxes`, whose ``_parallel_axes`` judges a statement that
sets a moment of inertia (I or J with a subscript naming its axis or point) to the moment of the
same letter about the centre of mass (subscript C, c, G, cm, CM, com) plus the mass times a
distance squared, or the centre of mass's moment to another minus that term: the theorem
I_P = I_G + m d², d the distance between the parallel axes, as every mechanics course states it.
The statement `holds`, its why naming the theorem, where the checker left it `unchecked` (a name
it records, then uses); any other form is left to the checker (a distance written as a sum of
squares is the theorem as well, and is not judged here). May import: the standard library.
"""
from __future__ import annotations

import re

_CENTRE = r"(?:C|c|G|cm|CM|com|\\text\{cm\}|\\mathrm\{cm\})"
_MOMENT = r"([IJ])\s*_\s*(\{[^{}]*(?:\{[^{}]*\}[^{}]*)*\}|[A-Za-z0-9])(\s*\^\s*\{?\s*\\prime\s*\}?|')?"
_TERM = r"([mM])\s*(?:\\[,;!]\s*|\\cdot\s*)?([a-zA-Z])\s*\^\s*\{?\s*2\s*\}?"
_STATED = re.compile(rf"\s*{_MOMENT}\s*=\s*{_MOMENT}\s*([+-])\s*{_TERM}\s*[.,;]?\s*")


def _centre(sub: str) -> bool:
    return re.fullmatch(rf"\{{?\s*{_CENTRE}\s*\}}?", sub) is not None


def theorem(piece: str) -> str | None:
    """Why a statement is the parallel-axis theorem as written, or None when it is not that."""
    m = _STATED.fullmatch(piece)
    if m is None:
        return None
    letter, sub, _, other_letter, other_sub, _, sign, _, _ = m.groups()
    if letter != other_letter or _centre(sub) == _centre(other_sub):
        return None
    if (sign == "+") != _centre(other_sub):
        return None                  # I_P = I_G − m d², I_G = I_P + m d²: not the theorem
    return ("the parallel-axis theorem: the moment about an axis is the moment about the parallel axis through "
            "the centre of mass plus the mass times the square of the distance between the axes")


class ParallelAxes:
    """Mixin of the checker. Uses ``self.claims``."""

    def _parallel_axes(self, line, piece, before) -> None:
        """The claims the checker gave ``piece`` (from ``before`` on), all unchecked, replaced by
        one that holds where the statement is the theorem (see the module docstring)."""
        why = theorem(piece)
        mine = self.claims[before:]
        if why is None or not mine or any(c.verdict != "unchecked" for c in mine):
            return
        mine[0].kind, mine[0].verdict, mine[0].why, mine[0].correction = "parallel axes", "holds", why, None
        del self.claims[before + 1:]
