"""A LaTeX source's structure read as the notes reader reads Markdown's.

Takes: the text of a LaTeX source (its comments already blanked). Gives: `as_notes`, the same text
with its inline math ``\\( … \\)`` written ``$ … $`` and its sectioning commands (``\\chapter``,
``\\section``, ``\\subsection``, ``\\subsubsection``, ``\\paragraph``, starred or with a short
title) written as Markdown headings of levels 1 to 5, so that a section's title and what its prose
assumes govern the displays up to the next heading of its level, as in a Markdown text. Every
character keeps its line: ``\\(`` and ``\\)`` become ``$`` and a space, and a heading line is
rewritten in place; a title that runs over several lines stays as it is.
May import: the standard library.
"""
from __future__ import annotations

import re

_LEVELS = {"chapter": 1, "section": 2, "subsection": 3, "subsubsection": 4, "paragraph": 5}
_BRACED = r"\{(?P<title>(?:[^{}\n]|\{(?:[^{}\n]|\{[^{}\n]*\})*\})*)\}"
_HEADING = re.compile(r"^[ \t]*\\(?P<cmd>chapter|section|subsection|subsubsection|paragraph)\*?"
                      r"(?:\[[^\]\n]*\])?\s*" + _BRACED + r"(?P<rest>.*)$", re.M)
_INLINE = re.compile(r"(?<!\\)\\\((?P<math>.+?)(?<!\\)\\\)", re.S)
"""``\\( … \\)``: TeX forbids it inside math, so every one is inline math in running text."""


def _heading(m: re.Match) -> str:
    return "#" * _LEVELS[m.group("cmd")] + " " + m.group("title").strip()


def as_notes(text: str) -> str:
    """``text`` with inline ``\\( … \\)`` as ``$ … $`` and sectioning commands as ``#`` headings."""
    text = _INLINE.sub(lambda m: " $" + m.group("math") + "$ ", text)
    return _HEADING.sub(_heading, text)
