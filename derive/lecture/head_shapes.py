"""A chain headed by a name the reader holds in another shape: the links after the head.

Takes: a statement ``H = A = B …`` the checker has read (`derive.lecture.latex`), whose head H the
reader holds as a quantity of one shape (𝐈 read as a moment, a scalar) while every member after
it is of another (a matrix the text sums from its own labelled tensors, ``\\mathbf{I} = \\mathbf{I}_C
+ \\mathbf{I}' = \\begin{pmatrix} … \\end{pmatrix}``). Gives the mixin `HeadShapes` of
`derive.lecture.notes_check.Checker`: the head left unchecked, said so, and each member after the
first compared with the one before it, as a chain with no head is (the text's own matrices put
in). A statement of two members, or one where any member met its head, is left as it was.

May import: nothing of its own (the checker's `_add`, `_one` and `claims`).
"""
from __future__ import annotations

AGAINST = " against a "
WHY = ("its head is held in another shape than the members after it (cannot compare its sides: {why}); "
       "the members after it are compared with each other")


class HeadShapes:
    """Mixin of the checker. Uses ``self.claims``, ``self._add`` and ``self._one``."""

    def _links_past_head(self, line, piece, parsed, start) -> None:
        """Members 2, 3, … of ``parsed`` each against the one before, when every claim made on it
        since ``start`` is unchecked because its head and a member differ in shape."""
        mine = self.claims[start:]
        if len(parsed.members) < 3 or not mine or \
                not all(c.verdict == "unchecked" and AGAINST in c.why for c in mine):
            return
        why = mine[0].why.split(": ", 1)[-1]
        del self.claims[start:]
        self._add(line, piece, "definition", "unchecked", WHY.format(why=why))
        for k in range(2, len(parsed.members)):
            self._one(line, piece, "identity", parsed.members[k - 1].value, parsed.members[k].value, parsed, k)
