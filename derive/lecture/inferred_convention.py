"""The convention of a text that states none, read from a formula that holds in one sequence only.

Takes: the `Notes` of a text, a way to read it again in a given sequence, and the checker. Gives:
`inferred`, the claims a careful reader gives: with no convention stated anywhere (no front matter
key, no ``--convention``, nothing `derive.lecture.stated_convention` reads), the text is read in
z-y-z and a display is read again in the sequences not yet ruled out, from the checker's state
just before it (`ConventionProbe`), until the text has shown its convention:

* a display flagged in z-y-z (one of the angles, or any once the text has named an angle: ṙ = R 𝐕_b
  after R in the angles) is read again in each sequence not ruled out, after the displays of the
  angles that held as read before it, each from its own state: the first of them flagged there rules
  the sequence out (all ruled out: the text has shown z-y-z, nothing more is read again and its
  slips stay flagged). The first that holds in exactly one sequence stops the probing; the text is
  then read whole in that sequence, unless a display that holds in z-y-z is flagged there, and the
  formula's reason says so ("reads the text's convention as z-x-z from line N", the first display
  that holds in it and not in z-y-z);
* a formula flagged in the sequence read that holds in another not ruled out is not judged
  (``unchecked``, naming the sequences it holds in): a reader cannot tell a slip from another
  convention.

A formula without the angles that holds (Euler's equations in ω) reads alike in every sequence and
rules out none; so does a display read in the text's own frames (Kane's hatted unit vectors and
direction cosine matrices, `derive.lecture.frame_displays`), which is neither probed nor evidence.
For a Tait–Bryan sequence (yaw, pitch, roll) the angles are tried as φ, θ, ψ and as ψ, θ, φ
(aerospace texts name the yaw ψ), unless the text names them. A text that names none is read
in z-y-z with α, β, γ (and φ, θ, ψ) as its angles; one that writes its angles so (the rates of α,
β, γ and of none of φ, θ, ψ) is read so in every other sequence too, α, β, γ its first, second and
third angles: a display differs between two readings by the sequence only, and z-y-z's body rates
in α, β, γ rule the others out. A display is tried only once the text has named an angle (in its
math, up to the display's line: φ, θ, ψ, χ or the angles it names itself, α, β, γ when it writes
them so): before that no formula of it ties the angles to anything. A display read again seeks no
correction (typo and fails alike are flagged there).

May import: the standard library (`copy`, `re`), SymPy, :mod:`derive.lecture.notes`, :mod:`derive.symbolic`.
"""
from __future__ import annotations

import copy
import re

import sympy as sp

from derive.lecture import notes as nt
from derive.symbolic.lagrangian import ACCELS
from derive.symbolic.rotations import ANGLES, RATES

FLAGGED = ("typo", "fails")


def _lines(claims) -> dict:
    """Line → (flagged, holds): any statement of it flagged; none flagged and one holds."""
    out: dict = {}
    for c in claims:
        flagged, holds = out.get(c.line, (False, False))
        out[c.line] = (flagged or c.verdict in FLAGGED, holds or c.verdict == "holds")
    return {line: (f, h and not f) for line, (f, h) in out.items()}


def _candidates(notes) -> list:
    """(sequence, angles or None) to try: the eleven other sequences, a Tait–Bryan one under both
    orders of the usual names when the text names its angles nowhere."""
    named = "angles" in notes.declared or notes.angles_stated
    out = []
    for seq in nt.CONVENTIONS:
        if seq == "z-y-z":
            continue
        if named:
            out.append((seq, tuple(notes.angles)))
        else:
            out.append((seq, None))
            if seq in nt.TAIT_BRYAN:
                out.append((seq, ("psi", "theta", "phi")))
    return out


_USUAL = r"\\(?:var)?(?:phi|theta|psi)|\\chi"
_RATE = r"\\d?dot\s*\{?\s*\\(?:%s)(?![A-Za-z])"
_ZYZ_RATES, _USUAL_RATES = re.compile(_RATE % "alpha|beta|gamma"), re.compile(_RATE % "(?:var)?(?:phi|theta|psi)")


def _z_y_z_names(notes) -> bool:
    """Does a text that names no angles write them as the z-y-z reading names them, α, β, γ: the
    rate of one of them and of none of φ, θ, ψ (a text differentiates its angles; α is often an
    angular acceleration, a φ a phase)?"""
    return not ("angles" in notes.declared or notes.angles_stated) and \
        _ZYZ_RATES.search(notes.body) is not None and _USUAL_RATES.search(notes.body) is None


def _angle(notes) -> re.Pattern:
    """An angle's name: `_USUAL`, or the reading's: the text's own, or α, β, γ (`_z_y_z_names`)."""
    own = [re.escape("\\" + a.split("_")[0]) for a in notes.angles] if (
        "angles" in notes.declared or notes.angles_stated or _z_y_z_names(notes)) else []
    return re.compile(r"(?:" + "|".join([_USUAL, *own]) + r")(?![A-Za-z])")


def _named_before(notes, line: int) -> bool:
    """Has the text named an angle before ``line``? Before that no formula of it ties the angles to
    anything."""
    m = _angle(notes).search(notes.body)
    return m is not None and notes.body.count("\n", 0, m.start()) < line


def _ruled_out(read_lines: dict, other: dict) -> bool:
    """Is a sequence ruled out: a formula that holds as read is flagged in it?"""
    return any(read_lines[line][1] and other.get(line, (False, False))[0] for line in read_lines)


def _first_and_third_swapped(checker) -> None:
    """The checker's state read with the first and third angles (and their rates) swapped: its
    context and vocabulary, as a text naming its yaw ψ gives them."""
    swap = {}
    for q in (ANGLES, RATES, ACCELS):
        swap.update({q[0]: q[2], q[2]: q[0]})

    def swapped(x, depth=0):
        if isinstance(x, sp.Basic):
            return x.xreplace(swap)
        if depth > 4:
            return x
        if isinstance(x, dict):
            return {swapped(k, depth + 1): swapped(v, depth + 1) for k, v in x.items()}
        if isinstance(x, (list, tuple, set)):
            return type(x)(swapped(v, depth + 1) for v in x) if not hasattr(x, "_fields") else x
        return x

    for holder in (checker.ctx, checker.vocab):
        for key, value in vars(holder).items():
            setattr(holder, key, swapped(value))
    checker.notes.angles_stated = True


class _Reading:
    """What the probing knows while the text is read: the candidates not yet ruled out (`open`), the
    lines probed (`probes`: line → candidate → (flagged, holds) there), the displays of the angles
    that hold as read (`shown`: the state before each, to read it again when a candidate needs it),
    each sequence's derivation once made (`derived`), and `done` once the text has shown its
    convention."""

    def __init__(self, notes):
        self.open, self.probes, self.shown, self.derived, self.done = _candidates(notes), {}, [], {}, False


def _snapshot(checker):
    """A copy of the checker to read a display again from; SymPy's expressions are immutable, so
    the copy shares them (and the derivations, the claims already made, which a display read again
    only adds to, and the text's items, frozen, in a list the reader never changes) instead of
    building them again."""
    memo = {id(x): x for x in [*checker.derivations, *checker.claims, checker.notes.items]}
    sp.Basic.__deepcopy__ = lambda expr, memo: expr
    try:
        return copy.deepcopy(checker, memo)
    finally:
        del sp.Basic.__deepcopy__


SEQUENCE_FREE = frozenset({"frame"})
"""Kinds of claim read without the Euler angles' sequence (the text's own frames and their turns)."""


class ConventionProbe:
    """Mixin of the checker, for a text that states no convention: a display flagged as read is read
    again in each sequence not yet ruled out, from the checker's state just before it (`probes`),
    after the displays of the angles that held as read before it (`shown`) rule out the sequences
    they are flagged in. Probing stops once the text has shown its convention: every other sequence
    ruled out, or a flagged display that holds in exactly one."""

    def _display_probed(self, item, latex):
        reading = self.__dict__.get("reading") or self.__dict__.setdefault("reading", _Reading(self.notes))
        named = _angle(self.notes).search(latex) is not None
        if self.notes.convention_stated or reading.done or not (named or _named_before(self.notes, item.line)):
            return self._display(item, latex)
        del self.reading
        saved = _snapshot(self)
        self.reading = reading
        start = len(self.claims)
        self._display(item, latex)
        flagged, holds = _lines(self.claims[start:]).get(item.line, (False, False))
        if self.claims[start:] and all(c.kind in SEQUENCE_FREE or c.sequence_free for c in self.claims[start:]):
            return      # read in the text's own frames (Kane's notation) or coordinate: alike in every sequence
        if not (flagged or named and holds):
            return      # a formula without the angles that holds (Euler's equations in ω) reads alike in all
        if holds:
            reading.shown.append((saved, item, latex))      # read again only for a candidate that needs it
            return
        verdicts = reading.probes[item.line] = {}
        for cand in list(reading.open):
            # the displays that held (ω in the rates, most often) before this one, a slip perhaps in
            # the equations of motion: read again first, they rule most sequences out
            if self._ruled_out_by_shown(cand):
                reading.open.remove(cand)
            else:
                verdicts[cand] = self._probed(saved, cand, item, latex)
        reading.done = not reading.open or len({cand[0] for cand in reading.open if verdicts[cand][1]}) == 1

    def _ruled_out_by_shown(self, cand) -> bool:
        """Is ``cand`` ruled out by a display of the angles that held as read before (read again in
        it, in order, until one is flagged)?"""
        for saved, item, latex in self.reading.shown:
            said = self.reading.probes.setdefault(item.line, {})
            if cand not in said:
                said[cand] = self._probed(saved, cand, item, latex)
            if said[cand][0]:
                return True
        return False

    def probes_read(self) -> dict:
        """The lines probed, once the text is read: a candidate a flagged display holds in is read
        again in the displays of the angles that held as read after it too (one that holds only
        where the text holds as read can neither set the convention nor leave a slip unjudged)."""
        reading = self.__dict__.get("reading")
        if reading is None:
            return {}
        held = {line for line, (_, holds) in _lines(self.claims).items() if holds}
        for cand in list(reading.open):
            if any(said.get(cand, (False, False))[1] for line, said in reading.probes.items() if line not in held) \
                    and self._ruled_out_by_shown(cand):
                reading.open.remove(cand)
        return reading.probes

    def _probed(self, saved, cand, item, latex) -> tuple:
        """(flagged, holds) of the display read in ``cand`` from the state ``saved``."""
        seq, names = cand
        reading = self.reading
        trial = _snapshot(saved)
        trial.judging_only = True       # flagged or not is all a probe asks: no correction is sought
        if names and not ("angles" in self.notes.declared or self.notes.angles_stated):
            _first_and_third_swapped(trial)     # what was read with φ first, read with ψ first
        if _z_y_z_names(self.notes):
            trial.notes.aliases = tuple(self.notes.angles)      # α, β, γ read as z-y-z reads them
        trial._stated_convention(nt.Item("convention", item.line, text=seq,
                                         symbols=names or nt.DEFAULT_ANGLES[seq]), reading.derived.get(seq))
        if seq not in reading.derived:
            reading.derived[seq] = trial.d
            self.derivations.append(trial.d)        # what it derived is kept for the next reading
        at = len(trial.claims)
        trial._display(item, latex)
        return _lines([c for c in trial.claims[at:] if c.line == item.line]).get(item.line, (False, False))


def inferred(notes, parse, check) -> list:
    """The claims of the text (see the module docstring): ``notes`` as read, ``parse(convention)``
    the text read again in a sequence, ``check(notes)`` the checker's claims and its probes."""
    claims, probes = check(notes)
    if notes.convention_stated or not probes:
        return claims
    base = _lines(claims)
    tried: dict = {}        # candidate → line → (flagged, holds), at the lines it was probed
    for line, verdicts in probes.items():
        for cand, said in verdicts.items():
            tried.setdefault(cand, {})[line] = said
    for line in sorted(probes):
        if not base.get(line, (False, False))[0]:
            continue
        holding = [cand for cand, (_, holds) in probes[line].items()
                   if holds and not _ruled_out(base, tried[cand])]
        if len({seq for seq, _ in holding}) != 1:
            continue
        chosen = holding[0]
        again = parse(chosen[0])
        if _z_y_z_names(notes):
            again.aliases = tuple(notes.angles)
        if chosen[1]:
            again.angles, again.angles_stated = tuple(chosen[1]), True
        reading = check(again)[0]
        mine = _lines(reading)
        if _ruled_out(base, mine):
            tried[chosen] = mine
            continue        # a display that holds in z-y-z later in the text is flagged in it
        # the reason goes to the first display that holds in the sequence read and not in z-y-z
        line = min((n for n in probes if base.get(n, (False, False))[0] and mine.get(n, (False, False))[1]),
                   default=line)
        for c in reading:
            if c.line == line and c.verdict == "holds":
                c.why = (f"reads the text's convention as {chosen[0]} from line {line} (the text states "
                         f"none; this formula holds in {chosen[0]}, not in the lecture's z-y-z)"
                         + (f"; {c.why}" if c.why else ""))
        tried.pop(chosen)
        tried[(None, None)] = base
        return _not_judged(reading, chosen[0], tried)
    return _not_judged(claims, "z-y-z", tried)


def _not_judged(claims, seq: str, others: dict) -> list:
    """``claims`` (read in ``seq``) with a flagged formula that holds in a sequence not ruled out
    made ``unchecked``, naming those sequences."""
    mine = _lines(claims)
    open_ = {cand: ls for cand, ls in others.items() if not _ruled_out(mine, ls)}
    for c in claims:
        if c.verdict not in FLAGGED:
            continue
        holding = sorted({cand[0] or "z-y-z" for cand, ls in open_.items() if ls.get(c.line, (False, False))[1]}
                         - {seq})
        if holding:
            c.verdict, c.correction = "unchecked", None
            c.why = (f"the text states no convention and this formula holds in {', '.join(holding)}, not in "
                     f"{seq}, as read: not judged (as read in {seq}, {c.why})")
    return claims
