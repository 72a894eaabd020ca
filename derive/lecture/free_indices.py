"""Components in index notation equated across unlike free indices: ``y_i = R_{ij}(\\vartheta, \\hat n)``.

Gives the mixin `FreeIndices` of `derive.lecture.notes_check.Checker`, whose `_free_indices_unlike`
flags a display once it is read. May import: the standard library, :mod:`derive.lecture.statements`.

In index notation both sides of an equation carry the same free indices: ``y_i = R_{ij} x_j`` (j
summed) holds as a statement about every i, while ``y_i = R_{ij}`` sets a vector's component equal
to a matrix's entry, which no choice of the names can mean. Only what is unambiguous is compared:
two neighbouring members of a chain that are each one symbol with a subscript of the index letters
i, j, k, l alone (its arguments after it allowed, ``R_{ij}(\\vartheta, \\hat n)``, sized or not), each letter once
in it, one of them with two or more indices, their sets of letters different. A product or a sum
(where a repeated letter is summed), a subscript with any other letter or a digit (``v_x``, ``E_k``
beside ``I_{1k}``, a particle's ``m_a``) and a member with only one index on both sides (``m_i =
m_j``, a statement for every pair) are never compared.

A sum over a letter its summand never carries, ``\\sum_i I_{nn}\\omega_{km}\\omega_{kn}`` beside a member whose
free indices are m and n, adds three equal terms and leaves k free: the text meant the letter the
summand carries and its neighbour does not (``\\sum_k``), a typo mended by that letter. Only a member
that is one explicit sum over one letter (``\\sum_i``, ``\\sum^3_i``) of one product is read, beside a
neighbour whose letters are index letters (i to n) with each summed letter written under its sum,
and only where exactly one letter of the summand is missing from the neighbour's free ones.
"""
from __future__ import annotations

import re

from derive.lecture.statements import statements, top_level

_INDEX = frozenset("ijkl")
_EQUALS = re.compile(r"(?<![<>!\\:])=")
_LONE = re.compile(r"^\s*(?:\\[A-Za-z]+\s*\{\s*)*[A-Za-z]'?\s*\}*\s*_\s*(\{[^{}]*\}|[A-Za-z0-9])\s*'?\s*"
                   r"((?:\\left\s*)?\((?:[^()]|\([^()]*\))*\))?\s*$")
"""One symbol (in \\bm, \\hat, … or bare) with a subscript, and the arguments written after it (in plain or
sized brackets, ``R_{ij}\\left(\\vartheta, \\hat n\\right)``)."""


def indices(member: str) -> frozenset | None:
    """The free indices of a member that is one component in index notation, else None."""
    m = _LONE.match(member)
    if not m:
        return None
    letters = [c for tok in m.group(1).strip("{}").replace(",", " ").split() for c in tok]
    if not letters or any(c not in _INDEX for c in letters) or len(set(letters)) != len(letters):
        return None     # another label, a digit, or a repeated (summed) letter: not compared
    return frozenset(letters)


def unlike(piece: str) -> tuple[str, str] | None:
    """(a member, the next) of the statement's chain whose free indices differ, else None."""
    eqs = top_level(piece, _EQUALS)
    bounds = [0, *(p for m in eqs for p in (m.start(), m.end())), len(piece)]
    members = [piece[bounds[k]:bounds[k + 1]].strip() for k in range(0, len(bounds), 2)]
    for a, b in zip(members, members[1:]):
        x, y = indices(a), indices(b)
        if x is not None and y is not None and x != y and max(len(x), len(y)) >= 2:
            return a, b
    return None


_LETTERS = frozenset("ijklmn")
_SUM = re.compile(r"^\s*\\sum\s*(?:\^\s*\{?\s*\w+\s*\}?\s*)?_\s*(?:\{\s*([a-z](?:\s*,\s*[a-z])*)\s*\}|([a-z]))"
                  r"\s*(?:\^\s*\{?\s*\w+\s*\}?)?")
_SUBSCRIPT = re.compile(r"_\s*(?:\{([^{}]*)\}|([A-Za-z0-9]))")


def _free(member: str) -> tuple[frozenset, frozenset, str] | None:
    """(the letters summed, the free index letters, the summand) of a member that is sums (or none)
    before one product in index letters; None for anything else."""
    summed, rest = set(), member
    while (m := _SUM.match(rest)) is not None:
        summed |= set((m.group(1) or m.group(2)).replace(",", " ").split())
        rest = rest[m.end():]
    if "\\sum" in rest or top_level(rest, re.compile(r"(?<![_^{(\[,])[+\-−]")):
        return None
    letters = [c for m in _SUBSCRIPT.finditer(rest) for c in (m.group(1) or m.group(2)).replace(",", "")
               if not c.isspace()]
    if not letters or any(c not in _LETTERS for c in letters):
        return None
    return frozenset(summed), frozenset(letters) - summed, rest


def absent_sum(piece: str) -> tuple[str, str] | None:
    """(the member, its correction) where one member sums over a letter its summand does not carry
    and the neighbour's free indices say which letter it meant (the module docstring); else None."""
    eqs = top_level(piece, _EQUALS)
    bounds = [0, *(p for m in eqs for p in (m.start(), m.end())), len(piece)]
    members = [piece[bounds[k]:bounds[k + 1]].strip() for k in range(0, len(bounds), 2)]
    for k, member in enumerate(members):
        read = _free(member)
        if read is None or len(read[0]) != 1 or not read[1]:
            continue
        (letter,), free, summand = read
        if letter in {c for m in _SUBSCRIPT.finditer(summand) for c in (m.group(1) or m.group(2))}:
            continue                # the summand carries the sum's letter: an ordinary sum
        for other in (members[k - 1] if k else None, members[k + 1] if k + 1 < len(members) else None):
            near = _free(other) if other is not None else None
            if near is None:
                continue
            meant = free - near[1]
            if len(meant) == 1 and near[1] <= free:
                (y,) = meant
                fix = _SUM.sub(lambda m: m.group(0).replace(letter, y), member, count=1)
                return member, fix
    return None


def _shown(s: frozenset) -> str:
    return ", ".join(sorted(s))


class FreeIndices:
    """Mixin of the checker. Uses ``self.claims`` and ``self._add``."""

    def _free_indices_unlike(self, item, latex, start) -> None:
        """Flag a statement of the display that equates components of unlike free indices, unless
        the display's reading flagged it already."""
        if any(c.verdict in ("typo", "fails") for c in self.claims[start:]):
            return
        for piece in statements(latex):
            pair = unlike(piece)
            if pair is not None:
                a, b = pair
                self._add(item.line, piece, "indices", "fails", (
                    f"equates {a} (free indices {_shown(indices(a))}) with {b} (free indices {_shown(indices(b))}): "
                    "the members of an equation in index notation carry the same free indices"))
                return
            absent = absent_sum(piece)
            if absent is not None:
                member, fix = absent
                self._add(item.line, piece, "indices", "typo", (
                    f"{member} sums over a letter its summand does not carry, which leaves another free that "
                    "the member beside it does not have: the sum is over the letter the summand carries"),
                    piece.replace(member, fix, 1))
                return
