"""The letter o typed for the digit 0 among the entries of a matrix of numbers.

Takes: a statement of a display. Gives: the mixin `LetterDigits`, which calls the statement a `typo` where a
matrix (``pmatrix``, ``bmatrix``, ``vmatrix``, ``matrix`` and their kin) has every entry a number (an
integer or a decimal, with a sign, the imaginary unit i, ``\\sqrt{…}`` or ``\\frac{…}{…}`` of such numbers)
but one or more that are the letter o or O alone, and writes the digit 0 elsewhere: an entry a text means as
its own symbol would not stand alone among numbers, so the letter is the digit mistyped. The correction writes
0 there.

Left alone: a matrix with any entry a letter or an expression (``\\begin{bmatrix} R & o \\\\ 0 & 1
\\end{bmatrix}``, a position o beside a block R), a matrix with no 0 written, nested matrices, and a statement
another reader already flagged. May import: nothing of derive's.
"""
from __future__ import annotations

import re

_MATRIX = re.compile(r"\\begin\{([pbvBV]?matrix\*?)\}((?:(?!\\begin\{|\\end\{).)*)\\end\{\1\}", re.S)
_NUMBER = r"[-+]?\s*(?:\d+(?:\.\d+)?\s*)?i?"
_ENTRY = re.compile(r"\s*(?:[-+]?\s*\\(?:sqrt|frac)\s*(?:\{\s*" + _NUMBER + r"\s*\}\s*)+|" + _NUMBER + r")\s*")
_LETTER = re.compile(r"\s*[oO]\s*")


def _entries(body: str) -> list[str]:
    """The matrix's entries, small spaces set between factors (``\\sqrt{2}\\,i``) dropped as TeX sets them."""
    body = re.sub(r"\\[,;:!]", " ", body)
    return [e for row in re.split(r"\\\\", body) for e in row.split("&") if e.strip()]


def mistyped(piece: str) -> list[tuple[int, int]]:
    """The spans of the matrices in ``piece`` whose entries are numbers but for a lone letter o standing for 0."""
    out = []
    for m in _MATRIX.finditer(piece):
        entries = _entries(m.group(2))
        letters = [e for e in entries if _LETTER.fullmatch(e)]
        rest = [e for e in entries if not _LETTER.fullmatch(e)]
        if letters and rest and all(_ENTRY.fullmatch(e) for e in rest) and any(e.strip() == "0" for e in rest):
            out.append(m.span(2))
    return out


def corrected(piece: str, spans) -> str:
    """``piece`` with each lone letter o of those matrices written as the digit 0."""
    for start, end in reversed(spans):
        body = re.sub(r"(^|&|\\\\)(\s*)[oO](\s*)(?=&|\\\\|$)", r"\g<1>\g<2>0\g<3>", piece[start:end])
        piece = piece[:start] + body + piece[end:]
    return piece


class LetterDigits:
    """Mixin of the checker: uses ``self._add`` and ``self.claims``."""

    def _letter_digits(self, line, piece, before) -> None:
        """A typo where a matrix of numbers has the letter o for one of its zeros."""
        if any(c.verdict in ("typo", "fails") for c in self.claims[before:]):
            return
        spans = mistyped(piece)
        if not spans:
            return
        if all(c.verdict == "unchecked" for c in self.claims[before:]):
            del self.claims[before:]
        self._add(line, piece, "symbol", "typo",
                  "writes the letter o among the entries of a matrix of numbers that writes the digit 0 elsewhere: "
                  "the digit mistyped", corrected(piece, spans))
