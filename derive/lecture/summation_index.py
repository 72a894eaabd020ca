"""A sum whose summand does not run with its index: ``\\sum_{i=1}^{n} \\vec{F_n}``.

Takes: one statement's LaTeX. Gives: `slip`, the statement corrected and the reason when a sum's
summand carries the sum's upper limit as its subscript and never its index (Σᵢ₌₁ⁿ F_n is n F_n,
not the sum of the F_i the text means), else None. The reader judges it a typo without reading the
rest of the statement: whatever the sum stands for, a summand that does not change with the
summation index is not what a sum of n terms writes.

May import: the standard library, :mod:`derive.lecture.latex` and :mod:`derive.lecture.latex_spaces`.
"""
from __future__ import annotations

import re

from derive.lecture import latex as lx
from derive.lecture.latex_spaces import QUAD

_SUM = re.compile(r"\\sum(?:\\limits)?\s*_\s*(?:\{\s*([A-Za-z])\s*(?:=\s*[0-9A-Za-z]+\s*)?\}|([A-Za-z]))"
                  r"\s*\^\s*(?:\{\s*([A-Za-z])\s*\}|([A-Za-z]))")
_ENDS = re.compile(r"(?<![<>!\\])=|[+\-]|\\(?:sum|approx|equiv|le|ge|neq)(?![A-Za-z])|" + QUAD + r"|[<>]|\\right")


def _summand_end(text: str, start: int) -> int:
    """Where the summand after ``start`` ends: the next top-level +, −, relation or sum."""
    depth = 0
    for k in range(start, len(text)):
        ch = text[k]
        if ch in "{([":
            depth += 1
        elif ch in "})]":
            if depth == 0:
                return k
            depth -= 1
        elif depth == 0 and k > start and _ENDS.match(text, k):
            return k
    return len(text)


def slip(text: str) -> tuple[str, str] | None:
    """(the statement with the summand's subscript made the index, why) or None."""
    for m in _SUM.finditer(text):
        index, upper = m.group(1) or m.group(2), m.group(3) or m.group(4)
        if index == upper:
            continue
        end = _summand_end(text, m.end())
        summand = text[m.end():end]
        try:
            atoms = [t.value for t in lx.scan(summand) if t.kind == "atom"]
        except lx.NotRead:
            continue
        if not atoms or any(a.base == index or index in a.sub for a in atoms) \
                or not any(a.sub == upper for a in atoms):
            continue
        fixed = re.sub(r"_(\s*\{?\s*)" + upper + r"(?![A-Za-z])", r"_\g<1>" + index, summand)
        return (text[:m.end()] + fixed + text[end:]).strip(), (
            f"the summand's subscript is the sum's upper limit {upper}, not its index {index}: as written every "
            f"term is the same and the sum is {upper} times one of them")
    return None
