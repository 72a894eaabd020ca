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
it is read as written.

Unit vectors written with a hat and no prime, index or power (``\\hat{z}``, ``\\bm{\\hat{z}}``,
``\\hat{\\mathbf{k}}``) that the text has not defined are tried the same way as the axes of the
space frame, then of the body frame (texts write 𝛚 = θ̇ ê′₂ + φ̇ ẑ + ψ̇ ê₃ with ẑ the vertical). A
statement that holds under neither is flagged only where it fails the same way under both as no
vector at all (a product of two unit vectors, a scalar added to a vector): what fails whichever
frame the hats name is not the reader's choice of frame. May import: the standard library,
`derive.lecture.latex_spellings` and `derive.lecture.vocabulary`.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spellings import BOLD, BOLD_MARK
from derive.lecture.vocabulary import NotRead, scan

# \hat{i}', \hat i', \hat{\mathbf{i}}', \mathbf{\hat{i}}' (any bold face), \hat{\imath}', with ' or ^\prime / ^{\prime}
_PRIMED = re.compile(r"(?:\\hat\s*\{\s*(?:" + BOLD + r"\s*\{\s*([ijkxyz])\s*\}|\\([ij])math|([ijkxyz]))\s*\}"
                     r"|\\hat\s+([ijkxyz])(?![A-Za-z])"
                     r"|" + BOLD + r"\s*\{\s*\\hat\s*\{\s*([ijkxyz])\s*\}\s*\})"
                     r"\s*(?:'|\^\s*\\prime\b|\^\s*\{\s*\\prime\s*\})")
_INDEX = {"i": 1, "j": 2, "k": 3, "x": 1, "y": 2, "z": 3}
_PRIME = r"(?:'|\^\s*\\prime\b|\^\s*\{\s*\\prime\s*\})"
_AXIS = r"_\s*(?:\{\s*([123])\s*\}|([123]))"
# ω₁′ written \omega_1', \omega_{1}^\prime, or \omega'_1 (the prime before the index)
_PRIMED_RATE = re.compile(r"\\omega\s*(?:" + _AXIS + r"\s*" + _PRIME + r"|" + _PRIME + r"\s*" + _AXIS + r")")

# the same letters with no prime, index or power after them: \hat{z}, \hat z, \bm{\hat{z}}, \hat{\mathbf{k}}
_PLAIN = re.compile(r"(?:" + BOLD_MARK + r"\s*\{\s*\\hat\s*\{?\s*([ijkxyz])\s*\}?\s*\}"
                    r"|\\hat\s*\{\s*(?:" + BOLD_MARK + r"\s*\{\s*([ijkxyz])\s*\}|\\([ij])math|([ijkxyz]))\s*\}"
                    r"|\\hat\s+([ijkxyz])(?![A-Za-z]))"
                    r"(?!\s*(?:'|\^|_))")

PLAIN_FRAMES = (
    ("^{0}", "the space frame"),
    ("", "the body frame"),
)
"""The frames tried for hatted letters with no prime, the fixed axes first."""

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


def plain_axes(text: str) -> list[str]:
    """The hatted unit vectors with no prime, index or power a statement writes, as written."""
    return [m.group(0) for m in _PLAIN.finditer(text)] if "hat" in text else []


def in_frame(text: str, mark: str, pattern=_PRIMED) -> str:
    """The statement with each primed unit vector (each of ``pattern``'s) the frame's unit vector
    ê with its index and ``mark`` (``'`` for ê′ᵢ, ``''`` for êᵢ, ``^{0}`` for ê⁰ᵢ); î′ ĵ′ k̂′ are
    axes 1, 2, 3."""
    def unit(m):
        letter = next(g for g in m.groups() if g)
        return rf"\hat{{\mathbf{{e}}}}_{{{_INDEX[letter]}}}{mark} "
    return pattern.sub(unit, text)


class PrimedAxes:
    """Mixin of the checker. Uses ``_read_once_or_twice``, ``_sandbox``, ``_keep``, ``_snapshot``,
    ``_add`` and ``self.claims``."""

    def _read_axes_or_plain(self, line, piece, dup, pieces):
        """The statement under the first frame in which it holds where it writes primed unit
        vectors, else as read (see the module docstring)."""
        written = primed_axes(piece)
        if not written:
            plain = plain_axes(piece)
            if primed_rates(piece) and not self._writes_angles(piece):
                self._read_rates_or_plain(line, piece, dup, pieces)
            elif plain and self._hats_unread(plain):
                self._plain_axes(line, piece, dup, pieces, plain)
            else:
                self._read_once_or_twice(line, piece, dup, pieces)
            return
        names = ", ".join(dict.fromkeys(written))
        readings = [(in_frame(piece, mark), f" (reading {names} as the unit vectors of {frame})") for mark, frame in FRAMES]
        if self._first_that_holds(line, piece, dup, pieces, readings) is not None:
            self._read_once_or_twice(line, piece, dup, pieces)     # as written: the letters the text's own

    def _first_that_holds(self, line, piece, dup, pieces, readings, reset=None):
        """Keep the first of ``readings`` (the statement rewritten, what its why adds) whose claims
        all hold, shown as written, and return None; else every reading's (claims, ctx) as tried.
        ``reset`` runs before each trial (a trial may tie names the next must not see)."""
        before, saved, tried = len(self.claims), self._snapshot(), []
        for text, said in readings:
            if reset is not None:
                reset()
            claims, ctx = self._sandbox(saved, line, text, dup, pieces, judging_only=True)
            if claims and all(c.verdict == "holds" for c in claims):
                for c in claims:
                    c.latex, c.why = piece, c.why + said
                self._keep(before, claims, ctx)
                return None
            tried.append((claims, ctx))
        return tried

    def _read_rates_or_plain(self, line, piece, dup, pieces):
        """The statement as read (ω′ᵢ on ê′ᵢ) where it holds so, else with ω′ᵢ the body components
        where it holds so, else as read (see the module docstring)."""
        rates = ", ".join(dict.fromkeys(primed_rates(piece)))
        readings = [(piece, ""), (in_body(piece), f" (reading {rates} as the body components)")]
        if self._first_that_holds(line, piece, dup, pieces, readings) is not None:
            self._read_once_or_twice(line, piece, dup, pieces)

    def _writes_angles(self, piece):
        """Whether the statement writes one of the text's angles or its rate (or cannot be scanned)."""
        try:
            toks = scan(piece)
        except NotRead:
            return True
        names = (t.value.base + ("_" + t.value.sub if t.value.sub else "") for t in toks if t.kind == "atom")
        return any(self.vocab.angle_index(n) is not None for n in names)

    def _hats_unread(self, written) -> bool:
        """Whether some hatted letter of the statement means nothing to the reader yet."""
        for text in written:
            try:
                toks = scan(text)
            except NotRead:
                return False
            if any(t.kind == "atom" and self.vocab.resolve(t.value) is None for t in toks):
                return True
        return False

    def _plain_axes(self, line, piece, dup, pieces, written):
        """The statement under the first frame in which it holds, or flagged where it fails alike
        as no vector under each; else as read (see the module docstring)."""
        names = ", ".join(dict.fromkeys(written))
        # a trial's reading may tie the text's names in the vocabulary; one not kept leaves none tied
        kept = dict(self.vocab.defined)

        def reset():
            self.vocab.defined.clear()
            self.vocab.defined.update(kept)
        readings = [(in_frame(piece, mark, _PLAIN), f" (reading {names} as the unit vectors of {frame})")
                    for mark, frame in PLAIN_FRAMES]
        before = len(self.claims)
        trials = self._first_that_holds(line, piece, dup, pieces, readings, reset)
        if trials is None:
            return
        reset()
        whys = {tuple(c.why for c in claims) for claims, _ in trials}
        claims, ctx = trials[0]
        if len(whys) == 1 and claims and all(c.verdict == "fails" and "not a vector" in c.why for c in claims):
            for c in claims:
                c.latex = piece
                c.why += f" (whichever frame {names} belongs to: read in the space frame and in the body frame, it fails alike)"
            self._keep(before, claims, ctx)
            return
        self._read_once_or_twice(line, piece, dup, pieces)
