"""A chain headed by a quantity the reader knows, its later members in names the text never tied:
the links among those members that are identities whatever the names stand for.

``\\Omega = \\frac{d\\varphi}{dt} = \\frac{M}{L\\sin\\gamma} = \\frac{m g r \\sin\\gamma}{\\theta_z \\omega
\\sin\\gamma} = \\frac{m g r}{\\theta_z \\omega}``: the reader knows dφ/dt, but every member after it is
written in the text's own names (m, r, θ_z, ω), which no motion it derives ties, so none can be
compared with the head. The chain still states that each member equals the next, and the last link,
the sin γ cancelled, holds whatever those names stand for. Each such link is recorded as holding; a
link that is not an identity stays unread (the names may make it hold), never flagged.

Takes: a statement the checker has read (`derive.lecture.latex`) and the claims it made on it. Gives
the mixin `UntiedLinks` of `derive.lecture.notes_check.Checker`. May import: nothing of its own (the
checker's `_add`, `_one` and `claims`), SymPy.
"""
from __future__ import annotations

import sympy as sp

UNDEFINED = "which the text has not defined"


def identical_as_written(a, b) -> bool:
    """Are two members the same expression as the text writes them, before any of its definitions is
    put in (a definition may itself hold the slip the link repeats)?"""
    try:
        return not isinstance(a, sp.MatrixBase) and not isinstance(b, sp.MatrixBase) and \
            sp.expand(sp.cancel(sp.sympify(a) - sp.sympify(b))) == 0
    except (TypeError, ValueError, sp.SympifyError):
        return False


class UntiedLinks:
    """Mixin of the checker. Uses ``self.claims``, ``self._add`` and ``self._one``."""

    def _named_chain(self, line, piece, members, parsed, rels) -> None:
        """``X = a = b …`` with X a new name of the text's: each member after a checked against a,
        then the links past a that hold whatever the text's names are (`_untied_links`)."""
        start = len(self.claims)
        for k in range(2, len(members)):
            self._one(line, piece, "identity", members[1], members[k], parsed, k, approx=rels[k - 1] == "≈")
        self._untied_links(line, piece, parsed, start)

    def _untied_links(self, line, piece, parsed, start) -> None:
        """Members 2, 3, … of ``parsed``, each against the one before, kept where the two are the
        same expression as written (whatever the text's names stand for), when every claim made on
        the statement since ``start`` is unchecked for names the text has not defined."""
        mine = self.claims[start:]
        members = parsed.members
        if len(members) < 3 or not mine or not all(c.verdict == "unchecked" and UNDEFINED in c.why for c in mine):
            return
        for k in range(2, len(members)):
            if identical_as_written(members[k - 1].value, members[k].value):
                self._add(line, piece, "identity", "holds", f"the link from member {k} to member {k + 1} is an identity "
                          "whatever the text's names stand for (expand); the members after the head cannot be compared "
                          "with it")
