"""Letters the prose sets equal to the numbered principal moments: "($A = I_1 = I_2$, $C = I_3$)".

Takes: the rendered text (`derive.lecture.source.rendered`), the file's macros and the `Names` the
prose and the formulas gave (`derive.lecture.names.learn`, `derive.lecture.formula_names.learn`).
Gives: `learn`, which binds a letter the text gives a principal moment in running prose, written
as an equality of names in its inline math:

* the math is inline and is a chain of single symbols joined by ``=`` (or a sign of definition,
  ``\\equiv``, ``:=``) and nothing else (``A = I_1 = I_2``, ``I_3 = C``, ``A \\equiv I_1 = I_2``);
* one of its symbols is the text's own letter: plain (no bold, accent or dot), not one of the
  numbered moments, not an angle, not named by the prose or the front matter already, and not met
  in the text's math before this sentence (a letter already in use may mean something else there);
* the others are principal moments of one kind: I₁, or I₂, or I₃, or the equal pair I₁ = I₂ (a
  letter set equal to both I₁ and I₃ is a condition, never a name) — numbered moments the text has
  left to their usual meaning, or symbols its names make principal moments (``I_x = I_y = I`` in a
  text that says its axes are principal, `derive.lecture.names`).

The letter is then the transverse moment I₁ (``A = I_1 = I_2``, ``A = I_1``), the second moment I₂
or the axial moment I₃ (``C = I_3``), as "the principal moments $A$, $B$, $C$" would bind it
(`derive.lecture.names`, a name learned from the prose: a statement that fails only with it is
left unchecked). Whether the sentence states the equality as a case ("with $I_3 = C$") or in
passing changes nothing: the symbols on the two sides are the same quantity either way.

May import: :mod:`derive.lecture.names`, :mod:`derive.lecture.latex`, :mod:`derive.lecture.source`,
:mod:`derive.lecture.latex_spellings`.
"""
from __future__ import annotations

import re

from derive.lecture import latex as lx
from derive.lecture import names as nm
from derive.lecture import source
from derive.lecture.latex_spellings import DEFINES

_KIND = {frozenset("1"): "transverse moment", frozenset("2"): "second moment", frozenset("3"): "axial moment",
         frozenset("12"): "transverse moment"}
"""The numbered moments a chain names (their indices) → the meaning of the letter set equal to them."""
_INDEX = {"transverse moment": "1", "second moment": "2", "axial moment": "3"}
"""The meanings of the text's names that are principal moments → their index."""
_EQUALS = re.compile(r"(?<![<>!:\\])=|" + DEFINES)
_OTHER = re.compile(r"\\(?:approx|simeq|sim|neq|ne|geq?|leq?|ll|gg|propto|to)(?![A-Za-z])|(?<!\\)[<>]|[,;]")


def _single(latex: str):
    """The one atom ``latex`` is, or None."""
    try:
        toks = lx.scan(latex)
    except (lx.NotRead, ValueError, IndexError, KeyError, TypeError):
        return None
    return toks[0].value if len(toks) == 1 and toks[0].kind == "atom" else None


def _keys(latex: str) -> set:
    """The symbols of a formula, as (base, index), or none when it cannot be scanned."""
    try:
        return {(t.value.base, t.value.sub) for t in lx.scan(latex) if t.kind == "atom"}
    except (lx.NotRead, ValueError, IndexError, KeyError, TypeError):
        return set()


def _plain(atom) -> bool:
    """A symbol written bare: no bold, dot, prime, hat, tilde, superscript or mark."""
    return not (atom.bold or atom.dots or atom.primes or atom.hat or atom.tilde or atom.sup or atom.mark)


def _moment(atom, names: nm.Names) -> str | None:
    """The index (1, 2, 3) of a principal moment: a numbered moment written plain that the text left
    to its usual meaning (``I_1``, ``I_{3}``), or a symbol the text's names make one (``I_x`` of a
    text that says its axes are principal); "" for a numbered moment the text gave another meaning;
    None for any other symbol."""
    plain = _plain(atom)
    meaning = names.meaning(atom)
    if meaning in _INDEX:
        return _INDEX[meaning] if plain else ""
    if plain and atom.base == "I" and atom.sub in ("1", "2", "3"):
        return atom.sub if meaning is None else ""
    return None


def _letter(atom, names: nm.Names, angles) -> bool:
    """Can ``atom`` be the text's own letter for a moment (see the module docstring)?"""
    return _plain(atom) and _moment(atom, names) is None and atom.base not in angles and names.meaning(atom) is None \
        and (atom.base, "plain" if not atom.sub else "vector") not in names.letters


def learn(names: nm.Names, body: str, angles=(), macros: dict | None = None) -> None:
    """Add to ``names`` the letters the prose sets equal to a principal moment (see the module
    docstring). ``angles``: the text's angle names; ``macros``: the file's own macros."""
    met: set = set()
    for m in source.MATH.finditer(body):
        inline = m.group("i")
        raw = inline if inline is not None else next((m.group(g) for g in ("d", "b", "eb") if m.group(g)), "")
        latex = source.normalize(raw, macros)
        if inline is not None:
            _bind_equal(names, latex, met, angles, body.count("\n", 0, m.start()) + 1)
        met |= _keys(latex)


def _bind_equal(names: nm.Names, latex: str, met: set, angles, line: int) -> None:
    if _OTHER.search(latex):
        return
    members = [_single(p.strip()) for p in _EQUALS.split(latex)]
    if len(members) < 2 or any(a is None for a in members):
        return
    kinds = [_moment(a, names) for a in members]
    if "" in kinds:
        return                  # the text's I₁ is something else of its own: its letter is no moment of ours
    own = [a for a, k in zip(members, kinds) if k is None]
    moments = frozenset(k for k in kinds if k is not None)
    if len(own) != 1 or moments not in _KIND:
        return
    letter = own[0]
    if (letter.base, letter.sub) in met or not _letter(letter, names, angles):
        return
    nm.bind(names, [letter], _KIND[moments], f"line {line}")
