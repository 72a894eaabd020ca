"""A sum's index typed after a symbol without its underscore, where the display writes that symbol indexed.

Takes: a statement of a display and the display's whole LaTeX. Gives: `lost(piece, latex)`, the spans of the
statement where a symbol stands followed by the bare index of a sum of its display (``\\mathbf{ r}\\alpha``
inside ``\\sum^N_{\\alpha} m_{\\alpha} \\mathbf{r}_{\\alpha} \\times (\\boldsymbol{\\omega} \\times \\mathbf{ r}\\alpha)``)
while the same display writes that symbol with the index as its subscript (``\\mathbf{r}_{\\alpha}``): TeX sets
the index as a factor, r times alpha, where the display's own spelling shows the particle's r_alpha is meant;
and `restored(piece, spans)`, the statement with the underscore put back.

Only a Greek index written as a command counts (``\\alpha``, ``\\beta``, ``\\mu``, …), the index of a sum the
display writes (``\\sum_{\\alpha}``, ``\\sum^N_{\\alpha}``), after a single letter, bold or plain, that the display
also writes with ``_{\\alpha}`` or ``_\\alpha``: a Latin index or a Greek letter that is no sum's index may be a
factor the text means. May import: nothing of derive's.
"""
from __future__ import annotations

import re

_GREEK = ("alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "iota", "kappa", "mu", "nu", "xi", "rho",
          "sigma", "tau")
_SUM_INDEX = re.compile(r"\\sum\s*(?:\^\s*(?:\{[^{}]*\}|\\?\w+)\s*)?_\s*\{?\s*\\(" + "|".join(_GREEK) + r")(?![A-Za-z])")
# a single letter, bold or plain, not itself indexed, then the bare index command
_SYMBOL = r"(\\(?:mathbf|boldsymbol|vec|bm)\s*\{\s*([A-Za-z])\s*\}|(?<![\\A-Za-z])([A-Za-z]))"


def _indexed(letter: str, index: str, latex: str) -> bool:
    """The display writes ``letter`` (bold or plain) with ``index`` as its subscript."""
    return re.search(r"(?:\{\s*" + letter + r"\s*\}|(?<![\\A-Za-z])" + letter + r")\s*_\s*\{?\s*\\" + index +
                     r"(?![A-Za-z])", latex) is not None


def lost(piece: str, latex: str) -> list[tuple[int, str]]:
    """(where the underscore belongs, the index) for each symbol ``piece`` writes followed by a sum's bare index."""
    found = []
    for index in dict.fromkeys(m.group(1) for m in _SUM_INDEX.finditer(latex)):
        for m in re.finditer(_SYMBOL + r"\s*\\" + index + r"(?![A-Za-z])", piece):
            letter = m.group(2) or m.group(3)
            if _indexed(letter, index, latex):
                found.append((m.end(1), index))
    return found


def restored(piece: str, spans: list[tuple[int, str]]) -> str:
    """``piece`` with each bare index put back as the subscript of the symbol before it."""
    out, last = [], 0
    for at, index in sorted(spans):
        rest = piece[at:]
        gap = len(rest) - len(rest.lstrip())
        out.append(piece[last:at] + "_{\\" + index + "}")
        last = at + gap + len("\\" + index)
    return "".join(out) + piece[last:]
