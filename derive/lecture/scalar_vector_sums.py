"""A sum that adds a number over plain letters to a cross product of vectors: a scalar added to a vector.

Takes: a statement of a display. Gives: the mixin `ScalarVectorSums`, which calls the statement `fails` where
one sum (the whole of a member, or what one bracket holds) has among its terms a number over plain letters
(``\\frac{1}{m_a}``: a scalar whatever its letters stand for, since no vector divides) and a cross product whose
last factor is a bold vector and which no dot product follows (``(\\mathbf{I}_a^{-1}(\\mathbf{r}_a \\times
\\mathbf{n})) \\times \\mathbf{r}_a``: a vector), as when a factor j is taken out of j𝐧/m and the 𝐧 left
behind (``j [\\frac{1}{m_a} + … \\times \\mathbf{r}_a]``).

Left alone: a term with a letter over a number or a bold letter in its fraction (``\\frac{j\\mathbf{n}}{m_a}``),
a cross product dotted with a vector (``( … \\times \\mathbf{r}_a) \\cdot \\mathbf{n}``, a scalar), a cross of
plain letters (``2 \\times 3``), and a statement another reader already flagged. May import:
:mod:`derive.lecture.statements`, :mod:`derive.lecture.latex_spellings`.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spellings import VECTOR_MARK
from derive.lecture.statements import top_level

_BOLD = VECTOR_MARK + r"(?![A-Za-z])"
_RECIPROCAL = re.compile(r"\s*[-+]?\s*\\[dt]?frac\s*\{\s*\d+\s*\}\s*\{([^{}]*)\}\s*")
_BOLD_LAST = re.compile(r"\s*" + _BOLD + r"\s*\{[^{}]*\}\s*(?:_\s*(?:\{[^{}]*\}|\w))?\s*")
_SIGNS = re.compile(r"[-+]")
_TIMES = re.compile(r"\\times(?![A-Za-z])")
_DOT = re.compile(r"\\cdot(?![A-Za-z])")
_OPEN = {"(": ")", "[": "]"}


def _groups(member: str) -> list[str]:
    """``member`` and the contents of each of its round and square brackets (``\\left``/``\\right`` dropped)."""
    text = re.sub(r"\\(?:left|right|big|Big|bigg|Bigg)(?![A-Za-z])", "", member)
    out, stack = [text], []
    for i, ch in enumerate(text):
        if ch in _OPEN:
            stack.append((ch, i))
        elif ch in ")]" and stack and _OPEN[stack[-1][0]] == ch:
            out.append(text[stack.pop()[1] + 1:i])
    return out


def _terms(group: str) -> list[str]:
    """The terms of the sum ``group`` writes at its top level (a sign in front of the first is no cut)."""
    cuts = [m.start() for m in top_level(group, _SIGNS) if group[:m.start()].strip()
            and not re.search(r"(?:[=(\[{^_]|\\times|\\cdot)\s*$", group[:m.start()])]
    bounds = [0, *cuts, len(group)]
    return [group[a:b] for a, b in zip(bounds, bounds[1:])]


def _scalar(term: str) -> bool:
    m = _RECIPROCAL.fullmatch(term)
    return m is not None and not re.search(_BOLD + r"|\\hat\b|\\widehat\b", m.group(1))


def _vector(term: str) -> bool:
    crosses = top_level(term, _TIMES)
    return bool(crosses) and not top_level(term, _DOT) and _BOLD_LAST.fullmatch(term[crosses[-1].end():]) is not None


def added(piece: str) -> str | None:
    """The sum in ``piece`` that adds a number over plain letters to a cross product of vectors (its scalar term)."""
    for member in re.split(r"(?<![<>\\])=", piece):
        for group in _groups(member):
            terms = _terms(group)
            scalars = [t for t in terms if _scalar(t)]
            if scalars and any(_vector(t) for t in terms):
                return scalars[0].strip().lstrip("+-").strip()
    return None


class ScalarVectorSums:
    """Mixin of the checker: uses ``self._add`` and ``self.claims``."""

    def _scalar_vector_sum(self, line, piece, before) -> None:
        """``fails`` where one sum adds a number over plain letters to a cross product of vectors."""
        if any(c.verdict in ("typo", "fails") for c in self.claims[before:]):
            return
        scalar = added(piece)
        if scalar is None:
            return
        if all(c.verdict == "unchecked" for c in self.claims[before:]):
            del self.claims[before:]
        self._add(line, piece, "identity", "fails",
                  f"adds {scalar}, a number over plain letters (a scalar), to a cross product of vectors (a vector) "
                  "in one sum: a scalar and a vector are not added")
