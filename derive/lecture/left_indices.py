r"""A frame index written on the left of a symbol, as robotics texts write a vector's coordinates in
a frame (``{}_I \mathbf{e}^z_I``, ``{}_B\boldsymbol{\omega}_{IB}``).

Takes: a rendered text. Gives: `dropped`, the text with each such index blanked where the text writes
that symbol in one frame only, so the index names no other quantity and the symbol is read as written
after it. A symbol the text writes in two frames keeps its indices, so that ``{}_I\boldsymbol\omega``
and ``{}_B\boldsymbol\omega`` are never read as one quantity (they stay unread). An index set after a
symbol's own upper index (``\epsilon^I{}_{JK}``) is that symbol's lower index and is left as written.

May import: nothing of the reader.
"""
from __future__ import annotations

import re

# a small space may set the symbol off its index ({}_I \\, \\mathbf{e})
_LEFT = re.compile(r"\{\}_[ \t]*(\{[^{}\n]*\}|\\[A-Za-z]+|[A-Za-z0-9])(?:[ \t]|\\[,:;!])*(\\[A-Za-z]+(?:[ \t]*\{[^{}\n]*\})?|[A-Za-z])")
# what ends a symbol or its index right before ``{}_`` (``\epsilon^I{}_{JK}``); an operator is no symbol
_BEFORE_SYMBOL = re.compile(r"(?:[\w}^_')\]](?<!\\cdot)(?<!\\times)(?<!\\left))[ \t]*\Z")


def dropped(text: str) -> str:
    """``text`` with the left frame index of every symbol written in one frame only blanked (its
    characters as spaces, so that every line and column stays where it was)."""
    found = [m for m in _LEFT.finditer(text) if not _BEFORE_SYMBOL.search(text[max(0, m.start() - 40):m.start()])]
    frames: dict = {}
    for m in found:
        frames.setdefault(_key(m[2]), set()).add(m[1].strip("{} "))
    out, last = [], 0
    for m in found:
        if len(frames[_key(m[2])]) == 1:
            out += [text[last:m.start()], " " * (m.start(2) - m.start())]
            last = m.start(2)
    return "".join(out + [text[last:]])


def _key(symbol: str) -> str:
    """A symbol as the key of its frames: its spelling without spaces."""
    return re.sub(r"\s+", "", symbol)
