"""What a text's hat map says a symbol is: ``R^T \\dot R = \\widehat{\\Omega}`` makes Ω the body angular velocity.

Takes: the rendered text of the notes. Gives: `body_velocities(body)`, the (line, LaTeX) of each
symbol that a statement of the text puts under a hat map as the body angular velocity of its
rotation matrix R (body → space).

A hat map is any of ``\\hat{X}``, ``\\widehat{X}``, ``X^\\times``, ``[X]_\\times`` (the skew matrix
of X, ``\\hat{X} Y = X \\times Y``); the statements read as defining the body angular velocity are

* ``R^T \\dot R = \\hat{X}`` (or ``R^\\top``, ``R^{-1}``; either side first), and
* ``\\dot R = R \\hat{X}``,

for one matrix letter R, plain or bold. The space angular velocity, ``\\dot R R^T = \\hat{x}`` or
``\\dot R = \\hat{x} R``, is not read here. X must be one symbol (``\\widehat{\\mathbb{I}^{-1}\\Pi}`` names
none).

May import: the standard library, :mod:`derive.lecture.latex_spellings`, :mod:`derive.lecture.latex_spaces` and :mod:`derive.lecture.source`.
"""
from __future__ import annotations

import re

from derive.lecture import source
from derive.lecture.latex_spaces import ONE_SPACING
from derive.lecture.latex_spellings import BOLD_MARK

_MATRIX = r"(?:\\(?:mathbf|boldsymbol|mathrm|bm)\{([A-Z])\}|([A-Z]))"
_SYMBOL = r"(\\?[A-Za-z]+|" + BOLD_MARK + r"\{\\?[A-Za-z]+\})"
_HAT = (r"(?:\\(?:wide)?hat\{" + _SYMBOL + r"\}|\\(?:wide)?hat" + _SYMBOL + r"(?![A-Za-z])"
        r"|\\crossmatrix\(" + _SYMBOL + r"\)|" + _SYMBOL + r"\^\{?\\times\}?)")
_TRANSPOSE = r"\^\{?(?:T|\\top|\\intercal|-1)\}?"
_DOT = r"\\dot\{?" + _MATRIX + r"\}?"
# spacing, quads too, and the sizing of a bracket, dropped: a display is read whole here, before it is cut
# into statements, so a quad may space one statement (R^T \dot R = \quad \hat\Omega); the forms anchor at = and a hat
_SPACING = re.compile(ONE_SPACING + r"+|\\left(?=\()|\\right(?=\))")


def _forms() -> list[re.Pattern]:
    body_rate = _MATRIX + _TRANSPOSE + _DOT             # R^T Ṙ
    return [re.compile(r"(?<![\\A-Za-z])" + body_rate + "=" + _HAT),
            re.compile(_HAT + "=" + body_rate + r"(?![A-Za-z])"),
            re.compile(r"(?<![\\A-Za-z])" + _DOT + "=" + _MATRIX + _HAT)]


_FORMS = _forms()


def body_velocities(body: str) -> list[tuple[int, str]]:
    """(line, LaTeX) of the symbols the text's hat maps make body angular velocities (see the
    module docstring), in the order of the text."""
    out = []
    for m in source.MATH.finditer(body):
        raw = next(g for g in (m.group("d"), m.group("b"), m.group("eb"), m.group("i")) if g is not None)
        if "dot" not in raw or not ("hat" in raw or "times" in raw or "×" in raw):
            continue                # no rate of a matrix and no hat: nothing to normalise
        math = _SPACING.sub("", source.normalize(raw))
        line = body.count("\n", 0, m.start()) + 1
        for form in _FORMS:
            for hit in form.finditer(math):
                got = [g for g in hit.groups() if g]
                letters = [g for g in got if re.fullmatch(r"[A-Z]", g)]
                symbols = [g for g in got if not re.fullmatch(r"[A-Z]", g)]
                if len(set(letters)) == 1 and len(symbols) == 1:
                    out.append((line, symbols[0]))
    return out
