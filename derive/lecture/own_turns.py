r"""A product of single-axis turns held to the turns the text itself writes out.

A text that writes ``\mathbf{R} = \mathbf{R}_x(\phi) \mathbf{R}_y(\theta) \mathbf{R}_z(\psi)`` and, anywhere
(before or after), writes each factor out as a matrix (``\mathbf{R}_x(\phi) = \begin{bmatrix} 1 & 0 & 0
\\ 0 & \cos\phi & -\sin\phi \\ … \end{bmatrix}``) has said which sense its turns have: the active turn
(``-\sin`` above the diagonal of the turning block) or the passive one. The product of its own
turns in the written order is the sequence's rotation R (body → space) or its transpose when the text
is right; written in the order only the other sense makes right (active turns in the order of
passive ones, R_x R_y R_z for a z-y-x sequence), it is neither, and the statement `fails`.

Only a product whose three names the text writes out, each about its own axis and all in one
sense, is judged; any other product is read as before (`derive.lecture.text_matrices`, where a
product of turns takes whichever sense makes it the sequence's rotation).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.source`, :mod:`derive.lecture.stated_convention`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import source
from derive.lecture.stated_convention import elementary

_WRITTEN_TURN = re.compile(
    r"((?:\\(?:mathbf|mathrm|boldsymbol|bm|mathsf)\s*\{\s*[A-Z]\s*\}|[A-Z])\s*_\s*\{?\s*[123xyzXYZ]\s*\}?)"
    r"\s*(?:(?:\\left\s*)?\(\s*[^()=]*\)(?:\s*\\right)?)?\s*=\s*\\begin\{([pbB]?matrix)\}(.*?)\\end\{\2\}", re.S)
"""A name by an axis, its argument if written, set equal to a matrix written out."""


class OwnTurns:
    """Mixin of the checker. Uses ``self.notes``, ``self.d``, ``self._turn_factors``,
    ``self._angle_left_out`` and ``self._turn_at_another_argument``."""

    def _turn_read_apart(self, text: str):
        """(verdict, why) of a product of turns read on its own: one that leaves out an angle its name
        lists (typo), at another argument than its name is bound to (unchecked), or against the sense of
        the turns the text writes out (fails); else None."""
        left_out = self._angle_left_out(text)
        if left_out is not None:
            return left_out
        other = self._turn_at_another_argument(text)
        if other is not None:
            return "unchecked", other
        against = self._turns_against_own(text)
        return None if against is None else ("fails", against)

    def _written_turns(self) -> dict:
        """{name (an atom without its spelling): (axis, active)} of every matrix the text writes out as
        one elementary turn under a name by its axis."""
        if not hasattr(self, "_own_turns"):
            self._own_turns = {}
            user = source.macros(self.notes.body)
            for m in _WRITTEN_TURN.finditer(self.notes.body):
                # the text's spellings of the entries (``\\operatorname{sin}``, its own macros) as the plain ones
                turn = elementary(source.normalize(m.group(3), user))
                try:
                    toks = lx.scan(m.group(1))
                except lx.NotRead:
                    continue
                if turn is None or len(toks) != 1 or toks[0].kind != "atom":
                    continue
                key = toks[0].value.with_(text="")
                had = self._own_turns.get(key)
                # one name written out in two senses or about two axes says no sense
                self._own_turns[key] = (turn[0], turn[2]) if had in (None, (turn[0], turn[2])) else (None, None)
        return self._own_turns

    def _turns_against_own(self, text: str) -> str | None:
        """Why the product of turns in ``text`` is neither R nor Rᵀ with the text's own turns, when the
        other sense would make it one; else None."""
        written = self._written_turns()
        if not written:
            return None
        try:
            toks = lx.scan(text)
        except lx.NotRead:
            return None
        found = self._turn_factors(toks)
        if found is None:
            return None
        own = [written.get(atom.with_(text="")) for atom, *_ in found]
        if any(w is None or w[0] != axis for w, (_, axis, *_) in zip(own, found)) or len({w[1] for w in own}) != 1:
            return None
        rot, R = self.d.rot, self.d.conv.matrix()
        active = own[0][1]

        def product(sense):
            turns = [sp.Matrix(sense(axis, angle)) for _, axis, angle, *_ in found]
            m = turns[0] * turns[1] * turns[2]
            return any(all(rot.trig_reduce(x - y) == 0 for x, y in zip(m, target)) for target in (R, R.T))

        if product(rot.active if active else rot.passive) or not product(rot.passive if active else rot.active):
            return None
        names = [atom.text for atom, *_ in found]
        sense, other = ("active", "passive") if active else ("passive", "active")
        return (f"the text writes {', '.join(names)} out as {sense} single-axis turns, and their product in the "
                f"written order is neither the sequence's rotation R (body → space) nor its transpose: that order "
                f"is the {other} turns' (in the reverse order, {' '.join(reversed(names))}, its own would be)")
