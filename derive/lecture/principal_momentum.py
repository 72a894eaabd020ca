"""The angular velocity's letter named by the text's own angular momentum in principal axes.

A text that writes ``\\dot{L}_i \\equiv I_i \\dot{\\Omega}_i`` (or ``L_1 = I_1\\Omega_1``) says what its
letter is: the angular momentum's component about a principal axis is the moment about that axis
times the angular velocity's component, so the letter beside the moment (Landau's Ω, or w, W) is
the body angular velocity, as if the prose had named it. The reader's own ω needs no naming (named,
a statement in it that does not hold would be left unchecked, as one in a named letter is). Read from a member of a display's chain
(``=`` or ``\\equiv``) that is the angular momentum's component (L, M, J or H, with an index 1 to 3 or
a letter) next to a member that is the moment with the same index times the other letter with the
same index, the two with the same number of dots; a rate written as a fraction of differentials
(``\\frac{d L_1}{dt}``, ``\\frac{\\mathrm{d} \\Omega_1}{\\mathrm{d} t}``) is read as the dotted letter.
Takes the rendered text; gives the symbols so named, each with its line; `derive.lecture.names` binds
them unless the prose named them otherwise.
May import: the standard library, :mod:`derive.lecture.differentials`, :mod:`derive.lecture.source`,
:mod:`derive.lecture.statements`.
"""
from __future__ import annotations

import re

from derive.lecture import differentials, source, statements

_DISPLAY = re.compile(r"\$\$(.+?)\$\$|\\\[(.+?)\\\]", re.S)
_GAP = r"(?:~|\\[,;:!]|\s)*"
_INDEX = r"_\s*\{?\s*(?P<k>[123ijk])\s*\}?"
_DOT = r"(?P<d>\\dot(?![A-Za-z])\s*\{?\s*)?"
"""A rate's dot, over its letter braced or not (``\\dot{L}_1``, ``\\dot L_1``, ``\\dot\\Omega_1``)."""
_MOMENTUM = re.compile(_GAP + _DOT + r"(?:L|M|J|H)\s*\}?\s*" + _INDEX + _GAP + "$")
_VELOCITY = r"I\s*_\s*\{?\s*K\s*\}?" + _GAP + _DOT + r"(?P<x>\\Omega|w|W)\s*\}?\s*_\s*\{?\s*K\s*\}?" + _GAP + "$"
_MEMBER = re.compile(r"(?<![<>!\\])=|\\equiv(?![A-Za-z])")


def velocity_letters(body: str) -> list[tuple[int, str]]:
    """``(line, symbol)`` for each angular velocity's component the text's L_i ≡ I_iΩ_i names.

    Parameters
    ----------
    body : str
        The rendered text (`derive.lecture.source.rendered`).

    Returns
    -------
    list of tuple
        The display's line and the symbol (``\\Omega_1``), in the text's order.
    """
    out = []
    for m in _DISPLAY.finditer(body):
        line = body.count("\n", 0, m.start()) + 1
        for st in statements.statements(differentials.dotted(source.normalize(m.group(1) or m.group(2)))):
            members = _MEMBER.split(st)
            for left, right in zip(members, members[1:]):
                lm = _MOMENTUM.match(left)
                if not lm:
                    continue
                rm = re.match(_GAP + _VELOCITY.replace("K", re.escape(lm.group("k"))), right)
                if rm and bool(rm.group("d")) == bool(lm.group("d")):
                    out.append((line, rm.group("x") + "_" + lm.group("k")))
    return out
