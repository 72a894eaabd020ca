"""Unit vectors written with a prime, î′ ĵ′ k̂′ (or x̂′ ŷ′ ẑ′): a frame the text turned to, tried.

Takes: a statement of the notes checker (`derive.lecture.notes_check.Checker`) that writes the
unit vectors of a frame as hatted letters with a prime (``\\hat{i}'``, ``\\hat{\\mathbf{j}}^\\prime``,
``\\hat{k}'``; x, y, z for i, j, k). Gives: the mixin `PrimedAxes`, which reads such a statement
with the primed axes as the unit vectors of each frame of the angle sequence in turn — the frame
after the first two turns (ê′ᵢ: the line of nodes and the body's symmetry axis, where courses
write ω = θ̇ î′ + φ̇ sin θ ĵ′ + (φ̇ cos θ + ψ̇) k̂′), the body frame (êᵢ), the space frame (ê⁰ᵢ).

Texts prime either of them, and say which in words the reader does not parse, so the statement is
kept under the first frame in which it holds, its why naming that frame. Under none it is read as
written, the primed letters the text's own (a slip and a frame the reader did not try, such as
the one after the first turn only, look alike, so no reading of them as a frame flags it). May
import: the standard library.
"""
from __future__ import annotations

import re

# \hat{i}', \hat i', \hat{\mathbf{i}}', \mathbf{\hat{i}}', \hat{\imath}', with ' or ^\prime / ^{\prime}
_PRIMED = re.compile(r"(?:\\hat\s*\{\s*(?:\\mathbf\s*\{\s*([ijkxyz])\s*\}|\\([ij])math|([ijkxyz]))\s*\}"
                     r"|\\hat\s+([ijkxyz])(?![A-Za-z])"
                     r"|\\mathbf\s*\{\s*\\hat\s*\{\s*([ijkxyz])\s*\}\s*\})"
                     r"\s*(?:'|\^\s*\\prime\b|\^\s*\{\s*\\prime\s*\})")
_INDEX = {"i": 1, "j": 2, "k": 3, "x": 1, "y": 2, "z": 3}

FRAMES = (
    ("'", "the frame after the first two turns (the line of nodes and the symmetry axis among its axes)"),
    ("", "the body frame"),
    ("^{0}", "the space frame"),
)
"""How each frame's unit vector is written for the reader (ê′ᵢ, êᵢ, ê⁰ᵢ) and its name in a why."""


def primed_axes(text: str) -> list[str]:
    """The primed unit vectors a statement writes, as written (empty when there are none)."""
    return [m.group(0) for m in _PRIMED.finditer(text)]


def in_frame(text: str, mark: str) -> str:
    """The statement with each primed unit vector the frame's unit vector ê with its index and
    ``mark`` (``'`` for ê′ᵢ, ``''`` for êᵢ, ``^{0}`` for ê⁰ᵢ); î′ ĵ′ k̂′ are axes 1, 2, 3."""
    def unit(m):
        letter = next(g for g in m.groups() if g)
        return rf"\hat{{\mathbf{{e}}}}_{{{_INDEX[letter]}}}{mark} "
    return _PRIMED.sub(unit, text)


class PrimedAxes:
    """Mixin of the checker. Uses ``_read_once_or_twice``, ``_sandbox``, ``_keep``, ``_snapshot``,
    ``_add`` and ``self.claims``."""

    def _read_axes_or_plain(self, line, piece, dup, pieces):
        """The statement under the first frame in which it holds where it writes primed unit
        vectors, else as read (see the module docstring)."""
        written = primed_axes(piece)
        if not written:
            self._read_once_or_twice(line, piece, dup, pieces)
            return
        before, saved = len(self.claims), self._snapshot()
        for mark, frame in FRAMES:
            claims, ctx = self._sandbox(saved, line, in_frame(piece, mark), dup, pieces, judging_only=True)
            if claims and all(c.verdict == "holds" for c in claims):
                for c in claims:
                    c.latex = piece
                    c.why += f" (reading {', '.join(dict.fromkeys(written))} as the unit vectors of {frame})"
                self._keep(before, claims, ctx)
                return
        self._read_once_or_twice(line, piece, dup, pieces)     # as written: the letters the text's own
