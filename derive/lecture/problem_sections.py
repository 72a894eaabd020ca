"""A new exercise starts afresh: a heading ``EXERCISE 6.8``, ``Problem 2``, ``Aufgabe 3`` ends what the
text defined in its own names in the exercise before.

A problem set's exercises are separate problems: the bar of one (``I_{xx} = 0``, its moment about
its own axis) is not the flywheel of the next (``I_{xx} = I_1``). A definition of the text's own
symbol made in one exercise, kept into the next, would make the next exercise's definition of the
same symbol a claim against it, and a false one. A heading that opens a numbered exercise or
problem (in English, German, French, Spanish, Italian) forgets the definitions of the text's own
symbols; what the reader derives, and what the text tied to it, stands.

Takes: a heading's words. Gives: `starts_a_problem`, and the mixin `ProblemSections` of
`derive.lecture.notes_check.Checker`, whose `_problem_begun` forgets those definitions.

May import: :mod:`derive.lecture.latex`, the standard library.
"""
from __future__ import annotations

import re

from derive.lecture import latex as lx

_PROBLEM = re.compile(r"^\W*(?:problem\s+\d+\W*)?(?:exercises?|problems?|aufgabe|übung|exercices?|ejercicios?|"
                      r"problemas?|esercizio|problème)\s*\d", re.I)
"""The opening of a numbered exercise's heading (``EXERCISE 5.26``, ``Problem 1: EXERCISE 5.13``)."""


def starts_a_problem(heading: str) -> bool:
    """Does a heading with these words open a numbered exercise or problem?"""
    return bool(_PROBLEM.match(heading or ""))


class ProblemSections:
    """Mixin of the checker. Uses ``self.ctx`` and ``self.vocab``."""

    def _problem_begun(self, heading: str) -> None:
        """At the heading of a new exercise: the text's own symbols defined before are no longer so."""
        if not starts_a_problem(heading):
            return
        self.ctx.defs = {k: v for k, v in self.ctx.defs.items() if not isinstance(k, lx.Generic)}
        self.vocab.defined = {k: v for k, v in self.vocab.defined.items() if not isinstance(v, lx.Generic)}
