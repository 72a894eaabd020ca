"""The size of a vector the text names: ``\\vec{M} = \\vec{r}\\times\\vec{F}_{g}; \\qquad M=m\\,g\\,r\\sin\\gamma``.

A display that names a vector of its own (``\\vec{M} = …``, ``\\mathbf{M} = …``) and beside it sets
the plain letter to an expression (``M = m g r \\sin\\gamma``) writes that vector's size: from there on
the plain letter is the text's own quantity, defined by that expression, whatever the reader takes
the letter for in a text that says nothing of it (M the mass, L the Lagrangian). Read as the
reader's own quantity, a later relation in it (dφ/dt = M/(L sin γ), the precession under the
torque M) would be judged against the mass and fail, though the text's torque makes it hold.

Takes: a statement of a display and the display's other statements. Gives: the mixin `VectorSize`
of `derive.lecture.notes_check.Checker`, whose `_vector_size` records the letter as a symbol of the
text's with its definition (the statement itself then unchecked: a definition, not a claim).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.latex_spellings`, the standard library.
"""
from __future__ import annotations

import re

from derive.lecture import latex as lx
from derive.lecture.latex_spellings import VECTOR_MARK

_PLAIN = re.compile(r"\s*([A-Za-z])\s*=(?!=)\s*(.+?)\s*[.,;]?\s*$", re.S)
"""``M = m g r \\sin\\gamma``: a plain letter, without index or accent, set to an expression."""
_NAMED = r"\s*" + VECTOR_MARK + r"\s*\{?\s*{letter}\s*\}?\s*="
"""``\\vec{M} =``: the vector of that letter named by the text."""


def vector_size(piece: str, pieces) -> tuple[str, str] | None:
    """(the letter, its expression) when ``piece`` sets a plain letter whose vector another statement
    of the same display names; None otherwise."""
    m = _PLAIN.fullmatch(piece)
    if not m or re.search(r"(?<![<>!\\])=|\\equiv|\\approx", m.group(2)):
        return None
    named = re.compile(_NAMED.replace("{letter}", m.group(1)))
    if not any(named.match(other) for other in pieces):
        return None
    return m.group(1), m.group(2)


class VectorSize:
    """Mixin of the checker. Uses ``self.vocab``, ``self.ctx`` and ``self._add``."""

    def _vector_size(self, line, piece, pieces) -> bool:
        """Record ``M = …`` beside ``\\vec{M} = …`` as the text's own M (the vector's size); True when so."""
        found = vector_size(piece, pieces)
        if found is None:
            return False
        letter, expression = found
        try:
            atoms = lx.scan(letter)
            value = lx.parse(expression, self.vocab)
        except lx.NotRead:
            return False
        if len(atoms) != 1 or atoms[0].kind != "atom" or len(value.members) != 1:
            return False
        atom = atoms[0].value.with_(text="")
        sym = self.vocab._generic(atom)
        self.vocab.defined[atom] = sym
        self.ctx.defs[sym] = value.members[0].value
        self._add(line, piece, "new symbol", "unchecked", f"defines the text's symbol {letter}, the size of the "
                  f"vector it names beside it (recorded, then used)")
        return True
