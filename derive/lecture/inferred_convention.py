"""The convention of a text that states none, read from a formula that holds in one sequence only.

Takes: the `Notes` of a text, a way to read it again in a given sequence, and the checker. Gives:
`inferred`, the claims a careful reader gives: with no convention stated anywhere (no front matter
key, no ``--convention``, nothing `derive.lecture.stated_convention` reads), a display flagged in
z-y-z is read again in the other eleven sequences, from the checker's state just before it
(`ConventionProbe`):

* the first such formula (in the text's order) that holds in exactly one of them sets the text's
  convention: the text is read in that sequence, and the formula's reason says so ("reads the
  text's convention as z-x-z from line N");
* a formula flagged in the sequence read that holds in another is not judged (``unchecked``,
  naming the sequences it holds in): a reader cannot tell a slip from another convention.

A sequence is ruled out when a formula that holds in the sequence read is flagged in it: a text
that writes one formula of z-y-z keeps z-y-z, and its slips stay flagged even when one of them
happens to be another sequence's formula. For a Tait–Bryan sequence (yaw, pitch,
roll) the angles are tried as φ, θ, ψ and as ψ, θ, φ (aerospace texts name the yaw ψ), unless
the text names them. A display is tried only once the text has named an angle (in its math, up to
the display's line: φ, θ, ψ, χ or the angles it names itself): before that no formula of it ties
the angles to anything.

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


def _angles_named(notes, line: int, latex: str) -> bool:
    """Does the text name an angle (`_USUAL`, or its own names) before ``line``, or in ``latex``?"""
    own = [re.escape("\\" + a.split("_")[0]) for a in notes.angles] if (
        "angles" in notes.declared or notes.angles_stated) else []
    angle = re.compile(r"(?:" + "|".join([_USUAL, *own]) + r")(?![A-Za-z])")
    m = angle.search(notes.body)
    return m is not None and notes.body.count("\n", 0, m.start()) < line or angle.search(latex) is not None


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


class ConventionProbe:
    """Mixin of the checker: a display flagged in z-y-z, in a text that states no convention, is
    read again in each other sequence from the checker's state just before it (`probes`: its line
    → the (sequence, angles) it holds in)."""

    def _display_probed(self, item, latex):
        if self.notes.convention_stated or not _angles_named(self.notes, item.line, latex):
            return self._display(item, latex)
        probes = self.__dict__.setdefault("probes", {})
        self.__dict__.pop("probes")
        saved = copy.deepcopy(self, {id(d): d for d in self.derivations})
        self.probes = probes
        start = len(self.claims)
        self._display(item, latex)
        if not any(c.line == item.line and c.verdict in FLAGGED for c in self.claims[start:]):
            return
        holding = set()
        for seq, names in _candidates(self.notes):
            trial = copy.deepcopy(saved, {id(d): d for d in saved.derivations})
            if names and not ("angles" in self.notes.declared or self.notes.angles_stated):
                _first_and_third_swapped(trial)     # what was read with φ first, read with ψ first
            trial._stated_convention(nt.Item("convention", item.line, text=seq,
                                             symbols=names or nt.DEFAULT_ANGLES[seq]))
            at = len(trial.claims)
            trial._display(item, latex)
            said = [c for c in trial.claims[at:] if c.line == item.line]
            if _lines(said).get(item.line, (True, False))[1]:
                holding.add((seq, names))
            if all(trial.d is not d for d in self.derivations):
                self.derivations.append(trial.d)        # what it derived is kept for the next reading
        probes[item.line] = holding


def inferred(notes, parse, check) -> list:
    """The claims of the text (see the module docstring): ``notes`` as read, ``parse(convention)``
    the text read again in a sequence, ``check(notes)`` the checker's claims and its probes."""
    claims, probes = check(notes)
    if notes.convention_stated or not any(probes.values()):
        return claims
    base = _lines(claims)
    readings, lines = {}, {}
    for cand in sorted({cand for found in probes.values() for cand in found}, key=str):
        again = parse(cand[0])
        if cand[1]:
            again.angles, again.angles_stated = tuple(cand[1]), True
        readings[cand] = check(again)[0]
        lines[cand] = _lines(readings[cand])
    flagged = [line for line in sorted(probes) if base.get(line, (False, False))[0]]
    for line in flagged:
        holding = [cand for cand in probes[line] if lines[cand].get(line, (False, False))[1]
                   and not _ruled_out(base, lines[cand])]
        if len({seq for seq, _ in holding}) == 1:
            chosen = holding[0]
            for c in readings[chosen]:
                if c.line == line and c.verdict == "holds":
                    c.why = (f"reads the text's convention as {chosen[0]} from line {line} (the text states "
                             f"none; this formula holds in {chosen[0]}, not in the lecture's z-y-z)"
                             + (f"; {c.why}" if c.why else ""))
            lines[(None, None)] = base
            return _not_judged(readings[chosen], chosen[0], {k: v for k, v in lines.items() if k != chosen})
    return _not_judged(claims, "z-y-z", lines)


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
