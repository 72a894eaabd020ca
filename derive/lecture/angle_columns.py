"""A matrix set in angle brackets, ``\\left<\\begin{array}{c} … \\end{array}\\right>``: the column (or
matrix) of components that engineering texts write as ⟨x, y, z⟩, never a comparison with ``<`` and
``>`` nor an inner product (whose two sides an angle bracket around one matrix does not have).

Takes and gives LaTeX: each such pair of angle brackets (``\\left<``, ``\\left\\langle`` or
``\\langle``, closed by the matching right one right after the environment's end) is written as
square brackets, so the matrix is read as any bracketed matrix. Imports nothing of the reader.
"""
from __future__ import annotations

import re

_OPEN = re.compile(r"(?:\\left\s*(?:<|\\langle(?![A-Za-z]))|\\langle(?![A-Za-z]))\s*\\begin\s*\{(array|matrix|smallmatrix)\}")
_CLOSE = re.compile(r"\s*(?:\\right\s*(?:>|\\rangle(?![A-Za-z]))|\\rangle(?![A-Za-z]))")


def squared(latex: str) -> str:
    """The formula with each matrix in angle brackets set in square brackets instead.

    Parameters
    ----------
    latex : str
        One formula.

    Returns
    -------
    str
        The formula; angle brackets around anything but one whole matrix environment are left as written.
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
                end = m.end() + e.end()
                break
        close = _CLOSE.match(latex, end) if end is not None else None
        if close is None:
            continue
        start = latex.index("\\begin", m.start())
        out += latex[i:m.start()] + "\\left[" + latex[start:end] + "\\right]"
        i = close.end()
    return out + latex[i:]
