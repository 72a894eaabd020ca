"""A vector written as the tuple of its components, ``\\bm{J} = (I_1\\omega_1, I_2\\omega_2, I_3\\omega_3)``.

Takes and gives one formula's LaTeX (`derive.lecture.source.normalize` calls `as_columns`): a
bracket of three members separated by top-level commas, right after ``=`` whose left neighbour is a
bold or arrowed symbol (``\\mathbf{r}``, ``\\vec{\\omega}_{B}``, ``{\\bf n}``), and ending its member
(the formula's end, a relation, a comma, a full stop, a row's end), is that vector's column,
``\\begin{pmatrix} … \\\\ … \\\\ … \\end{pmatrix}``. A tuple beside anything else (a point named by
a plain letter, an open interval, a function's arguments) is left as written, and so is a tuple of
numbers alone (``\\mathbf{e}_Z = (0, 0, 1)``): a unit vector in its own frame's coordinates, which a
text goes on to write in another frame, so it is no definition of the vector.

Imports nothing of derive's.
"""
from __future__ import annotations

import re

_BOLD_BEFORE = re.compile(r"\{?\s*(?:\\(?:bm|mathbf|boldsymbol|vec)\s*\{(?:[^{}]|\{[^{}]*\})*\}|\\bf\s*[A-Za-z])\s*\}?"
                          r"(?:\s*_\s*(?:\{[^{}]*\}|[A-Za-z0-9]))?\s*=\s*$")
_NUMBER = re.compile(r"[-+]?\s*\d+(?:\.\d*)?")
_AFTER = re.compile(r"\s*(?:$|=|,|\.|\\\\|&|\\quad|\\qquad)")


def _closing(text: str, k: int) -> tuple[int, list[int]] | None:
    """The index of the bracket closing the one at ``k`` and the top-level commas inside it."""
    depth, commas = 0, []
    for j in range(k, len(text)):
        c = text[j]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
            if depth == 0:
                return (j, commas) if c == ")" else None
        elif c == "," and depth == 1 and text[j - 1] != "\\":      # \\, is a thin space
            commas.append(j)
    return None


def as_columns(text: str) -> str:
    """``text`` with each vector written as a tuple of three components as its column (see the module
    docstring); unchanged when it writes none."""
    if "=" not in text or "," not in text:
        return text
    k = text.find("(")
    while k != -1:
        found = _closing(text, k)
        if found is not None and len(found[1]) == 2 and _BOLD_BEFORE.search(text[:k]) and \
                _AFTER.match(text, found[0] + 1):
            end, (a, b) = found
            parts = [text[k + 1:a].strip(), text[a + 1:b].strip(), text[b + 1:end].strip()]
            if all(parts) and not all(_NUMBER.fullmatch(p) for p in parts):
                column = r"\begin{pmatrix} " + r" \\ ".join(parts) + r" \end{pmatrix}"
                text = text[:k] + column + text[end + 1:]
        k = text.find("(", k + 1)
    return text
