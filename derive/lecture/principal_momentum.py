"""The angular velocity's letter named by the text's own angular momentum in principal axes.

A text that writes ``\\dot{L}_i \\equiv I_i \\dot{\\Omega}_i`` (or ``L_1 = I_1\\Omega_1``) says what its
letter is: the angular momentum's component about a principal axis is the moment about that axis
times the angular velocity's component, so the letter beside the moment (Landau's Ω, or w, W) is
the body angular velocity, as if the prose had named it. Axes are indexed 1 to 3, i, j, k or x, y, z. The reader's own ω needs no naming (named,
a statement in it that does not hold would be left unchecked, as one in a named letter is). Read from a member of a display's chain
(``=`` or ``\\equiv``) that is the angular momentum's component (L, M, J or H, with an index 1 to 3 or
a letter) next to a member that is the moment with the same index times the other letter with the
same index, the two with the same number of dots, or a rate of the angular momentum's component next to
Euler's equation's shape in the other letter, ``\\dot{L}_x = I_x \\dot{\\Omega}_x + (I_z - I_y)\\Omega_y\\Omega_z``
(the moment times the rate, then the difference of the other two moments times the product of the
letter's other two components: nothing but the angular velocity enters so); a rate written as a fraction of differentials
(``\\frac{d L_1}{dt}``, ``\\frac{\\mathrm{d} \\Omega_1}{\\mathrm{d} t}``) is read as the dotted letter.
Takes the rendered text and its macros; gives the symbols so named, each with its line; `derive.lecture.names` binds
them unless the prose named them otherwise. Gives too `xyz_only`, the letters among I, ω, Ω a text indexes
by x, y, z and never by 1, 2, 3 (its principal axes so named, where its prose says they are principal).
May import: the standard library, :mod:`derive.lecture.differentials`, :mod:`derive.lecture.source`,
:mod:`derive.lecture.statements`.
"""
from __future__ import annotations

import re

from derive.lecture import differentials, source, statements

_DISPLAY = re.compile(r"\$\$(.+?)\$\$|\\\[(.+?)\\\]|(\\begin\{(equation|align|eqnarray|gather)\*?\}.+?\\end\{\4\*?\})", re.S)
_GAP = r"(?:~|\\[,;:!]|\s)*"
_INDEX = r"_\s*\{?\s*(?P<k>[123ijkxyz])\s*\}?"
_AXES = ("123", "ijk", "xyz")
_DOT = r"(?P<d>\\dot(?![A-Za-z])\s*\{?\s*)?"
"""A rate's dot, over its letter braced or not (``\\dot{L}_1``, ``\\dot L_1``, ``\\dot\\Omega_1``)."""
_MOMENTUM = re.compile(_GAP + _DOT + r"(?:L|M|J|H)\s*\}?\s*" + _INDEX + _GAP + "$")
_VELOCITY = r"I\s*_\s*\{?\s*K\s*\}?" + _GAP + _DOT + r"(?P<x>\\Omega|w|W)\s*\}?\s*_\s*\{?\s*K\s*\}?" + _GAP
_OTHER = r"_\s*\{?\s*[AB]\s*\}?" + _GAP
_CROSS = (r"(?P<c>[+-]" + _GAP + r"\(" + _GAP + "I" + _OTHER + "-" + _GAP + "I" + _OTHER + r"\)" + _GAP +
          r"(?P=x)\s*" + _OTHER + r"(?P=x)\s*" + _OTHER + ")?$")
"""Euler's gyroscopic term after the moment times the rate, ``+ (I_z - I_y)\\Omega_y \\Omega_z``: A and B the other axes."""
_MEMBER = re.compile(r"(?<![<>!\\])=|\\equiv(?![A-Za-z])")


def velocity_letters(body: str, macros: dict | None = None) -> list[tuple[int, str]]:
    """``(line, symbol)`` for each angular velocity's component the text's L_i ≡ I_iΩ_i names.

    Parameters
    ----------
    body : str
        The rendered text (`derive.lecture.source.rendered`).
    macros : dict, optional
        The file's own macros (`derive.lecture.source.macros`), expanded in its displays.

    Returns
    -------
    list of tuple
        The display's line and the symbol (``\\Omega_1``; ``\\Omega_`` with no index for axes x, y, z), in
        the text's order.
    """
    out = []
    for m in _DISPLAY.finditer(body):
        line = body.count("\n", 0, m.start()) + 1
        latex = source.normalize(m.group(1) or m.group(2) or m.group(3), macros)
        for st in statements.statements(differentials.dotted(latex)):
            members = _MEMBER.split(st)
            for left, right in zip(members, members[1:]):
                lm = _MOMENTUM.match(left)
                if not lm:
                    continue
                k = lm.group("k")
                a, b = next(axes for axes in _AXES if k in axes).replace(k, "")
                rm = re.match(_GAP + _VELOCITY.replace("K", k) + _CROSS.replace("A", a).replace("B", b), right)
                # the gyroscopic term goes with rates on both sides, as Euler's equation has them
                if rm and bool(rm.group("d")) == bool(lm.group("d")) and (lm.group("d") or not rm.group("c")):
                    # on axes x, y, z the letter is given alone, its axes to be read as principal ones
                    out.append((line, rm.group("x") + "_" + ("" if k in "xyz" else k)))
    return out


def xyz_only(body: str) -> list[str]:
    """The letters among I, ω and Ω the text writes with an index x, y or z and never with 1, 2 or 3."""
    used = {((m.group(1) or "I"), m.group(2) or m.group(3)) for m in
            re.finditer(r"\\(omega|Omega)\s*_\s*\{?\s*([xyz123])|\bI\s*_\s*\{?\s*([xyz123])(?![a-z])", body)}
    return [letter for letter in ("I", "omega", "Omega")
            if {(letter, x) for x in "xyz"} & used and not {(letter, x) for x in "123"} & used]
