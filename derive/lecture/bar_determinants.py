"""A square array between bars, ``\\left|\\begin{array}{ccc} … \\end{array}\\right|``: a determinant.

Texts that set their matrices in ``array`` (or ``matrix``) write a determinant with bars around the
environment, where others write ``vmatrix``; between bars a square array of two rows or more is no
length of a vector, and a column between bars stays the length it is. Takes and gives LaTeX: each
such pair of bars (``|``, ``\\vert``, ``\\lvert``/``\\rvert``, sized with ``\\left``/``\\right`` or
not) around one whole square environment is written as ``\\begin{vmatrix} … \\end{vmatrix}``, which
the reader takes as the determinant. Imports nothing of the reader.
"""
from __future__ import annotations

import re

_OPEN = re.compile(r"(?:\\left\s*)?(?:\\[lr]?vert(?![A-Za-z])|\|)\s*\\begin\s*\{(array|matrix)\}(\s*\{[^{}]*\})?")
_CLOSE = re.compile(r"\s*(?:\\right\s*)?(?:\\[lr]?vert(?![A-Za-z])|\|)")


def _square(body: str) -> bool:
    """Whether an environment's body has n ≥ 2 rows of n cells each (its nested groups ignored)."""
    flat = re.sub(r"\{[^{}]*\}", "{}", re.sub(r"\{[^{}]*\}", "{}", body))
    rows = [r for r in re.split(r"\\\\(?:\[[^\]]*\])?", flat) if r.strip()]
    return len(rows) >= 2 and all(r.count("&") == len(rows) - 1 for r in rows)


def vertical(latex: str) -> str:
    """The formula with each square array between bars written as a ``vmatrix``.

    Parameters
    ----------
    latex : str
        One formula.

    Returns
    -------
    str
        The formula; bars around anything but one whole square environment are left as written.
    """
    out, i = "", 0
    for m in _OPEN.finditer(latex):
        if m.start() < i:
            continue
        env = re.escape(m.group(1))
        depth, end = 1, None
        for e in re.finditer(r"\\(begin|end)\s*\{" + env + r"\}", latex[m.end():]):
            depth += 1 if e.group(1) == "begin" else -1
            if depth == 0:
                end = m.end() + e.start(), m.end() + e.end()
                break
        close = _CLOSE.match(latex, end[1]) if end is not None else None
        if close is None or not _square(latex[m.end():end[0]]):
            continue
        out += latex[i:m.start()] + "\\begin{vmatrix}" + latex[m.end():end[0]] + "\\end{vmatrix}"
        i = close.end()
    return out + latex[i:]
