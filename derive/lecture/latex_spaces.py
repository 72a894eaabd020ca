"""What a LaTeX space is, for every reader of the notes: one home for the spacing a formula may set.

Takes and gives nothing at run time: regular-expression fragments (to be joined into a reader's own
patterns) and the names of the spacing commands (for the scanners that walk a formula token by
token). TeX spaces a formula five ways: whitespace, the small spaces (thin ``\\,``, medium ``\\:``,
thick ``\\;``, negative thin ``\\!``), the control space ``\\ ``, the tie ``~``, and the quads
``\\quad`` and ``\\qquad``. The first four set factors apart and are read as a space wherever a
reader recognises a form (``M_z \\, (\\vec F_i)``, ``m \\; v_c^2``, ``2~\\text{kg}``). A quad is the
space a text sets between two statements (``a = b \\quad c = d``), so it is never a space between
factors: `SPACE` leaves it out. `SPACING` takes it in, for where no factor is read across it (the
ends of a statement, the words between two) and for a display read whole, before it is cut into
statements, where a form is anchored at its own signs. The named spaces (``\\thinspace``, ``\\enspace``, …)
are written as these by `derive.lecture.source` before any reader sees a formula.

May import: nothing.
"""
from __future__ import annotations

_SMALL = ",:;!"                  # after a backslash: the thin, medium, thick and negative thin spaces
SPACE_SYMBOL = rf"\\[{_SMALL} ]"
"""One small space (``\\,`` ``\\:`` ``\\;`` ``\\!``) or the control space ``\\ ``: every control symbol that only spaces."""

QUAD = r"\\q?quad(?![A-Za-z])"
"""``\\quad`` or ``\\qquad``: the wide space a text sets between two statements."""

TIE = "~"
"""The tie, an unbreakable interword space."""

ONE_SPACE = rf"(?:\s|{SPACE_SYMBOL}|{TIE})"
"""One space between factors: a whitespace character, a `SPACE_SYMBOL` or the tie ``~``."""

SPACE = ONE_SPACE + "*"
"""Optional space between two factors of one formula (`ONE_SPACE` repeated): never a quad."""

ONE_SPACING = rf"(?:{ONE_SPACE}|{QUAD})"
"""One piece of spacing of any width: `ONE_SPACE` or a `QUAD`."""

SPACING = ONE_SPACING + "*"
"""Optional spacing of any width, quads included: where no factor is read across it (the ends of a
statement, the spacing around a word set between two statements), and where a display is read whole,
before it is cut into statements, by a form anchored at its own signs."""

SPACE_NAMES = frozenset(_SMALL + " ")
"""The names of the `SPACE_SYMBOL` commands, as a scanner meets them after a backslash."""

QUAD_NAMES = frozenset({"quad", "qquad"})
"""The names of the quads, as a scanner meets them after a backslash (it reads a statement already cut
at its top-level quads: one left inside a group only spaces)."""

KERN = r"\\(?:mkern|mskip|kern|hskip)\s*-?\s*(?:\d+\.?\d*|\.\d+)\s*(?:mu|em|ex|pt)(?![A-Za-z])"
"""A kern or a skip by an explicit length (``\\mkern-1.5mu``, ``\\kern0.1em``): typography that only
moves what follows (a transpose's T set closer, ``\\mathbf{M}^{\\mkern-1.5mu\\mathrm{T}}``), dropped
before any reader sees the formula."""
