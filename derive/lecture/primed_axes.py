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
the one after the first turn only, look alike, so no reading of them as a frame flags it).

The angular velocity's components written with a prime (``\\omega_1'``, ``\\omega'_2``,
``\\omega_3^\\prime``) are the same choice: the reader takes them on the primed axes ê′ᵢ, and texts
also prime the body's components (ω′ = Rᵀω, "the body-frame components"). A statement writing them
that writes no angle and does not hold on ê′ᵢ is tried with them read as the body components ωᵢ
and kept there if it holds (½(I₁ω₁′² + I₂ω₂′² + I₃ω₃′²), the principal-frame energy, holds only
there unless I₁ = I₂); else it is read as written. A statement in the angles fixes the frame
(ω₁′ = −φ̇ sin θ is a component on ê′₁, and one written with the body's ψ terms is a slip), so
it is read as written. May import: the standard library and :mod:`derive.lecture.vocabulary`.
"""
from __future__ import annotations

import re

from derive.lecture.vocabulary import NotRead, scan

# \hat{i}', \hat i', \hat{\mathbf{i}}', \mathbf{\hat{i}}', \hat{\imath}', with ' or ^\prime / ^{\prime}
_PRIMED = re.compile(r"(?:\\hat\s*\{\s*(?:\\mathbf\s*\{\s*([ijkxyz])\s*\}|\\([ij])math|([ijkxyz]))\s*\}"
                     r"|\\hat\s+([ijkxyz])(?![A-Za-z])"
                     r"|\\mathbf\s*\{\s*\\hat\s*\{\s*([ijkxyz])\s*\}\s*\})"
                     r"\s*(?:'|\^\s*\\prime\b|\^\s*\{\s*\\prime\s*\})")
_INDEX = {"i": 1, "j": 2, "k": 3, "x": 1, "y": 2, "z": 3}
_PRIME = r"(?:'|\^\s*\\prime\b|\^\s*\{\s*\\prime\s*\})"
_AXIS = r"_\s*(?:\{\s*([123])\s*\}|([123]))"
# ω₁′ written \omega_1', \omega_{1}^\prime, or \omega'_1 (the prime before the index)
_PRIMED_RATE = re.compile(r"\\omega\s*(?:" + _AXIS + r"\s*" + _PRIME + r"|" + _PRIME + r"\s*" + _AXIS + r")")

FRAMES = (
    ("'", "the frame after the first two turns (the line of nodes and the symmetry axis among its axes)"),
    ("", "the body frame"),
    ("^{0}", "the space frame"),
)
"""How each frame's unit vector is written for the reader (ê′ᵢ, êᵢ, ê⁰ᵢ) and its name in a why."""


def primed_axes(text: str) -> list[str]:
    """The primed unit vectors a statement writes, as written (empty when there are none)."""
    return [m.group(0) for m in _PRIMED.finditer(text)]


def primed_rates(text: str) -> list[str]:
    """The angular velocity's primed components a statement writes, as written."""
    return [m.group(0) for m in _PRIMED_RATE.finditer(text)]


def in_body(text: str) -> str:
    """The statement with each primed component of the angular velocity the body component ωᵢ."""
    return _PRIMED_RATE.sub(lambda m: rf"\omega_{{{next(g for g in m.groups() if g)}}}", text)


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
            if primed_rates(piece) and not self._writes_angles(piece):
                self._read_rates_or_plain(line, piece, dup, pieces)
            else:
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

    def _read_rates_or_plain(self, line, piece, dup, pieces):
        """The statement as read (ω′ᵢ on ê′ᵢ) where it holds so, else with ω′ᵢ the body components
        where it holds so, else as read (see the module docstring)."""
        before, saved = len(self.claims), self._snapshot()
        for text, frame in ((piece, None), (in_body(piece), "the body components")):
            claims, ctx = self._sandbox(saved, line, text, dup, pieces, judging_only=True)
            if claims and all(c.verdict == "holds" for c in claims):
                for c in claims:
                    c.latex = piece
                    if frame:
                        c.why += f" (reading {', '.join(dict.fromkeys(primed_rates(piece)))} as {frame})"
                self._keep(before, claims, ctx)
                return
        self._read_once_or_twice(line, piece, dup, pieces)

    def _writes_angles(self, piece):
        """Whether the statement writes one of the text's angles or its rate (or cannot be scanned)."""
        try:
            toks = scan(piece)
        except NotRead:
            return True
        names = (t.value.base + ("_" + t.value.sub if t.value.sub else "") for t in toks if t.kind == "atom")
        return any(self.vocab.angle_index(n) is not None for n in names)
