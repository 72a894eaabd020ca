"""A text's own bracket for the cross-product matrix: after ``\\mathbf{b} \\times \\mathbf{y} \\equiv
\\left[\\mathbf{b}\\right] \\mathbf{y}``, ``[\\mathbf{b}]`` is the skew-symmetric matrix of 𝐛.

Some texts (an encyclopaedia's inertia matrix among them) write the matrix that takes the cross
product with a vector as the vector in square brackets, and say so in a display: b × y ≡ [b] y.
From that display on, a bracket the text writes acting on a vector (``[r_i - S]\\mathbf{y}``), or
set equal to a written matrix (``[b] \\equiv \\begin{bmatrix}…``), is that matrix, written
``[…]_\\times`` for the formula reader (`derive.lecture.source`); a plain letter inside it that the
text writes bold elsewhere (r_i of 𝐫_i, S of 𝐒) is that vector. Any other bracket is left as it is:
a bracket of a product of brackets may be the text's name for a matrix (``[I_S]``), and grouping.

Takes: the rendered text of the notes (`derive.lecture.source.rendered`). Gives: `marked`, the text
with those brackets marked (on their own lines, so every line keeps its number); and for one formula,
`cross_matrices`, each marked bracket (``[…]_\\times``) in the formula reader's spelling.

May import: the standard library, :mod:`derive.lecture.latex_spellings`.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spellings import BOLD, DEFINES

# a vector: a letter in a bold face or under an arrow
_VECTOR = r"(?:" + BOLD + r"|\\vec(?![A-Za-z]))"
_BOLD = _VECTOR + r"\s*\{?\s*\\?[A-Za-z]+\s*\}?"
# a bracket sized with \\left … \\right or by hand (\\bigl[ … \\bigr]), as plain brackets
_OPEN = r"(?:\\(?:left|[Bb]igg?l?)(?![A-Za-z])\s*)?\["
_CLOSE = r"(?:\\(?:right|[Bb]igg?r?)(?![A-Za-z])\s*)?\]"
_DEFINED = re.compile(r"(?P<a>" + _BOLD + r")\s*\\times\s*(?P<y>" + _BOLD + r")\s*&?\s*(?:" + DEFINES + r"|=)\s*&?\s*"
                      + _OPEN + r"\s*(?P=a)\s*" + _CLOSE + r"\s*(?P=y)")
_BOLD_LETTER = re.compile(_VECTOR + r"\s*\{\s*([A-Za-z])\s*\}")
_BRACKET = re.compile(_OPEN + r"(?P<inner>[^\[\]&\\\n]*(?:" + _VECTOR + r"\s*\{[^{}\n]*\}"
                      r"[^\[\]&\\\n]*)*)" + _CLOSE)
# what makes a bracket the text's matrix: a vector after it, or a written matrix it is set equal to
_ACTS = re.compile(r"\s*(?:" + _BOLD + r"|&?\s*(?:" + DEFINES + r"|=)\s*&?\s*\\begin\{[bpBvV]?matrix\})")
# a symbol inside the bracket: a bold letter or a plain one, with its subscript
_SYMBOL = re.compile(r"(?P<bold>" + _VECTOR + r"\s*\{[^{}]*\})|(?<![\\A-Za-z])(?P<plain>[A-Za-z])(?![A-Za-z])"
                     r"(?P<sub>\s*_\s*(?:\{[^{}]*\}|\w))?")


def marked(body: str) -> str:
    """The text with its brackets for the cross-product matrix written ``[…]_\\times`` after the
    display that defines them (see the module docstring); unchanged when it defines none."""
    found = _DEFINED.search(body)
    if found is None:
        return body
    bold = set(_BOLD_LETTER.findall(body))
    start = body.rfind("\n", 0, found.start()) + 1
    return body[:start] + _BRACKET.sub(lambda m: _marked(m, bold), body[start:])


def _marked(m: re.Match, bold: set) -> str:
    inner = m.group("inner")
    if not _ACTS.match(m.string, m.end()) or not inner.strip():
        return m.group(0)
    plain = [x.group("plain") for x in _SYMBOL.finditer(inner) if x.group("plain")]
    if not all(letter in bold for letter in plain):
        return m.group(0)            # a letter the text never writes bold: not the vector the bracket takes
    vector = _SYMBOL.sub(lambda x: x.group(0) if x.group("bold") else
                         r"\mathbf{" + x.group("plain") + "}" + (x.group("sub") or ""), inner)
    return r"\left[" + vector + r"\right]_\times"


_CROSS = re.compile(r"\s*[_^]\s*(?:\{\s*\\times\s*\}|\\times)")
# a vector written bold or under an arrow, with its subscript, then ^\times: the skew matrix u^× of Hughes' notation
_SYMBOL_CROSS = re.compile(r"(?P<v>" + _VECTOR + r"\s*\{(?:[^{}]|\{[^{}]*\})*\}(?:\s*_\s*(?:\{[^{}]*\}|\w))?)"
                           r"\s*\^\s*(?:\{\s*\\times\s*\}|\\times)(?![A-Za-z])")


def cross_matrices(text: str) -> str:
    """``[\\mathbf{r}]_\\times`` (also ``\\left[ … \\right]_{\\times}``, ``^\\times``) and ``\\mathbf{r}^\\times``
    (a bold or arrowed vector): the cross-product matrix of r, written ``\\crossmatrix\\left( … \\right)``
    for the formula reader.

    Parameters
    ----------
    text : str
        One formula, normalised (`derive.lecture.source.normalize` calls this).

    Returns
    -------
    str
        The formula, each bracket marked with ``_\\times`` or ``^\\times`` written as ``\\crossmatrix``.
    """
    text = _SYMBOL_CROSS.sub(lambda m: r"\crossmatrix\left(" + m.group("v") + r"\right)", text)
    while True:
        m = next((m for m in _CROSS.finditer(text) if text[:m.start()].rstrip().endswith("]")), None)
        if m is None:
            return text
        close = text[:m.start()].rstrip()
        end = len(close) - 1
        right = close.endswith("\\right]")
        depth, k = 0, end
        while k >= 0:
            if text[k] == "]":
                depth += 1
            elif text[k] == "[":
                depth -= 1
                if depth == 0:
                    break
            k -= 1
        if k < 0:
            return text
        left = k - 5 if text[max(k - 5, 0):k] == "\\left" else k
        inner = text[k + 1:end - (6 if right else 0)]
        text = text[:left] + r"\crossmatrix\left(" + inner + r"\right)" + text[m.end():]
