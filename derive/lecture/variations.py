"""δx, a small variation of x: ``\\delta\\omega_1``, ``\\delta \\theta``, ``\\delta\\dot\\omega_1``,
``\\delta x`` (a δ written directly before a symbol, with or without a space) is one symbol of the
text's, never δ times x.

Takes: a formula's LaTeX (the scanner's position after a ``\\delta``) or a text's rendered body.
Gives: `variation_at`, where the varied symbol starts after a δ (the scanner then reads δx as one
atom, marked ``delta``: `derive.lecture.vocabulary.Atom.mark`), and `delta_a_quantity`, whether
the text writes δ alone somewhere (``\\delta = \\pi/2``, ``\\cos(\\Omega t + \\delta)``, "$\\delta$
the phase"): there δ is the text's own quantity and δx reads as δ times x. Kronecker's
``\\delta_{ij}`` is neither, nor δ accented alone in braces (``\\hat{\\delta}``, a symbol of its own).
May import: the standard library, :mod:`derive.lecture.latex_spellings`.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spellings import VECTOR_MARK

# the spaces that may stand between δ and the varied symbol: blanks and the thin spaces
_GAP = re.compile(r"(?:\s|\\[,;:!](?![A-Za-z]))*")
_COMMAND = re.compile(r"\\([A-Za-z]+)")


def variation_at(s: str, j: int, names) -> int | None:
    """Where the symbol a δ ending at ``s[j]`` varies starts: an ASCII letter or a command among
    ``names`` (the Greek letters and the decorations) after the gap; None when none follows."""
    k = _GAP.match(s, j).end()
    if k >= len(s):
        return None
    m = _COMMAND.match(s, k)
    if m:
        return k if m.group(1) in names and m.group(1) != "delta" else None
    return k if s[k].isascii() and s[k].isalpha() else None


_DELTA = re.compile(r"\\delta(?![A-Za-z])")
_ACCENT = re.compile(r"(?:\\(?:hat|widehat|tilde|widetilde|bar|check|breve)|" + VECTOR_MARK + r")\s*\{\s*\Z")


def delta_a_quantity(body: str, names) -> bool:
    """Whether the text writes δ alone anywhere, as ``\\delta`` in its math or as the character δ:
    no index, no symbol and no bracket after it (δ(x) is an operator's or a distribution's, no
    quantity's; the character is read without a space, prose putting a word after it)."""
    for m in _DELTA.finditer(body):
        after = _GAP.match(body, m.end()).end()
        if _ACCENT.search(body[max(0, m.start() - 24):m.start()]) and body[after:after + 1] == "}":
            continue            # δ̂, 𝛅: an accent makes the text's own symbol, not δ alone
        if body[after:after + 1] in ("_", "(") or variation_at(body, m.end(), names) is not None:
            continue
        return True
    return _ALONE.search(body) is not None


# δ in the text's own characters, standing alone ("a phase δ, …"): no letter, index or bracket right after it
_ALONE = re.compile(r"δ(?![\w(\u0300-\u036f])")
