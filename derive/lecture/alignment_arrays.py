"""An ``array`` used as an alignment: a display whose rows are an ``array`` at its top level.

Takes: the LaTeX of one display. Gives: `unwrapped`, the display with such an array's
``\\begin{array}{ll}`` and ``\\end{array}`` dropped, so that its rows are cut at ``\\\\`` and its
``&`` are alignment marks, as in ``aligned``. May import: the standard library.

Texts written for MathJax (notebooks, Markdown pages) often align a chain with
``\\begin{equation}\\begin{array}{ll} R & = A B \\\\ & = C \\end{array}\\end{equation}``: an array
whose first row states a relation outside every brace and nested environment, and which stands at
the display's top level (not an operand in brackets, not inside a matrix). Such an array is an
alignment, not a matrix. An array inside ``\\left( … \\right)`` or a ``bmatrix`` stays a matrix, and an
array without a relation in its first row (a list of names) stays as written.
"""
from __future__ import annotations

import re

_BEGIN = re.compile(r"\\begin\{array\}\s*\{[^{}]*\}")
_RELATION = re.compile(r"(?<![<>!\\])=|\\(?:approx|equiv|simeq|le|ge|leq|geq)(?![A-Za-z])|(?<!\\)[<>]")


def unwrapped(latex: str) -> str:
    """The display with every alignment array's delimiters dropped (see the module docstring)."""
    out, pos = [], 0
    for m in _BEGIN.finditer(latex):
        if m.start() < pos or not _top_level(latex, m.start()):
            continue
        end = _matching_end(latex, m.end())
        if end is None or not _RELATION.search(_first_row(latex[m.end():end])):
            continue
        out.append(latex[pos:m.start()] + " ")
        out.append(latex[m.end():end])
        pos = end + len("\\end{array}")
        out.append(" ")
    out.append(latex[pos:])
    return "".join(out)


def _top_level(s: str, i: int) -> bool:
    """Whether position i is outside every brace, bracket, ``\\left`` and environment but the
    display's own (``equation``, ``align``, …) — the array is the display's body, not an operand."""
    depth = 0
    envs = 0
    k = 0
    while k < i:
        if s.startswith("\\begin{", k):
            name = s[k + 7:s.find("}", k)]
            envs += name not in _DISPLAYS
        elif s.startswith("\\end{", k):
            name = s[k + 5:s.find("}", k)]
            envs -= name not in _DISPLAYS
        elif s.startswith("\\left", k) and not s.startswith("\\leftarrow", k):
            depth += 1
        elif s.startswith("\\right", k) and not s.startswith("\\rightarrow", k):
            depth -= 1
        elif s[k] in "{([" and (k == 0 or s[k - 1] != "\\"):
            depth += 1
        elif s[k] in "})]" and (k == 0 or s[k - 1] != "\\"):
            depth -= 1
        k += 1
    return depth == 0 and envs == 0


_DISPLAYS = {"equation", "equation*", "align", "align*", "gather", "gather*", "displaymath", "math",
             "multline", "multline*", "flalign", "flalign*"}


def _matching_end(s: str, start: int) -> int | None:
    """The index of the ``\\end{array}`` that closes an array opened just before ``start``."""
    level = 1
    for m in re.finditer(r"\\(begin|end)\{array\}", s[start:]):
        level += 1 if m.group(1) == "begin" else -1
        if level == 0:
            return start + m.start()
    return None


def _first_row(body: str) -> str:
    """The array's first non-empty row, without what nested environments and braces hold."""
    flat, depth, env, k = [], 0, 0, 0
    while k < len(body):
        if body.startswith("\\begin{", k):
            env += 1
        elif body.startswith("\\end{", k):
            env -= 1
        ch = body[k]
        if ch == "{" and (k == 0 or body[k - 1] != "\\"):
            depth += 1
        elif ch == "}" and (k == 0 or body[k - 1] != "\\"):
            depth -= 1
        elif depth == 0 and env == 0:
            flat.append(ch)
        k += 1
    rows = [r for r in "".join(flat).split("\\\\") if r.strip()]
    return rows[0] if rows else ""
