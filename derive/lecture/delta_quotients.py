"""A difference quotient that lost the Δ of its interval: ``\\frac{\\Delta x}{\\Delta t} = R\\frac{\\Delta\\vartheta}{t}``.

Takes: one statement's LaTeX. Gives: `slip`, the statement corrected and the reason when it writes a
quotient of differences over an interval, ``\\frac{\\Delta x}{\\Delta t}``, and beside it a difference
over the bare variable of that interval, ``\\frac{\\Delta\\vartheta}{t}``: the same statement divides one
change by the interval and another by the time itself, so the second is a change over a time, not
the rate over the interval the first sets (``R\\frac{\\Delta\\vartheta}{\\Delta t}`` is meant). A
relative change of the variable itself (``\\frac{\\Delta t}{t}``) and a statement with no Δ-quotient
beside it are not read. The reader judges it a typo without reading the rest of the statement.

May import: :mod:`derive.lecture.latex_spaces`.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spaces import SPACE

_DELTA = r"\\(?:Delta|delta)(?![A-Za-z])" + SPACE
_LETTER = r"(?:\\[A-Za-z]+|[A-Za-z])"
_OVER_INTERVAL = re.compile(r"\\[dt]?frac\s*\{" + SPACE + _DELTA + _LETTER + SPACE + r"\}\s*\{" + SPACE + _DELTA
                            + r"(?P<v>" + _LETTER + r")" + SPACE + r"\}")
_OVER_BARE = re.compile(r"\\[dt]?frac\s*\{" + SPACE + _DELTA + r"(?P<x>" + _LETTER + r")" + SPACE + r"\}\s*\{" + SPACE
                        + r"(?P<v>" + _LETTER + r")" + SPACE + r"\}")


def slip(text: str) -> tuple[str, str] | None:
    """(the statement with the interval's Δ put back, why) or None."""
    intervals = {m["v"] for m in _OVER_INTERVAL.finditer(text)}
    for m in _OVER_BARE.finditer(text):
        v, x = m["v"], m["x"]
        if v in intervals and x != v:
            fixed = text[:m.start()] + m.group(0)[:m.start("v") - m.start()] + "\\Delta " + v + text[m.end("v"):]
            return fixed.strip(), (
                f"divides the change in {x} by {v} itself where the same statement divides by the interval "
                f"\\Delta {v}: a rate over the interval needs \\Delta {v} below")
    return None
