"""Numbers as worked examples write them: a unit after a number, a thousands separator, ``\\times``
between two numbers.

``0.04050\\text{ kg}\\cdot\\text{m}^2`` is the number 0.04050: a unit is a whitelisted name in
``\\text{…}``/``\\mathrm{…}`` (with ``/``, powers, ``\\cdot`` or spaces between names) right after a
digit, so ``r_{\\text{cm}}`` and words such as ``\\text{constante}`` stay as they are. ``10{,}000`` is
10000 and ``10{,}000 \\times 2\\pi`` a product of numbers; ``0 .8976`` (a space before the decimal
point, which math mode does not set) is 0.8976. A unit typed in plain italic letters after a tie
``~`` after a number or a closed group, at the end of a member, ``m=0.1~kg``, ``\\frac{mgd}{I_z\\dot{\\psi}}~\\frac{rad}{s}``, ``\\frac{2\\pi}{\\dot{\\phi}}~s``
(as notebooks write them), is dropped too: the tie sets a unit apart from the formula, which a product
of symbols never needs. Coherent SI units in square brackets spaced off after a value and closing a member,
``312.5\\,m \\ \\ \\left[\\text{J}\\right]``, are dropped as well (not revolutions or degrees). Takes and gives LaTeX; imports :mod:`derive.lecture.latex_spaces` and :mod:`derive.lecture.latex_spellings` only.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spaces import ONE_SPACE, QUAD, SPACE, SPACE_SYMBOL, TIE
from derive.lecture.latex_spellings import SIZED_CLOSE, SIZED_OPEN

_UNIT = r"(?:kg|m|cm|mm|km|s|ms|min|N|J|kJ|Pa|rad|RPM|rpm|rev|Hz|deg)"
_UNIT_EXPR = _UNIT + r"(?:\s*\^\s*\{?-?\d\}?)?(?:\s*(?:/|\\cdot|" + ONE_SPACE + r")\s*" + _UNIT + r"(?:\s*\^\s*\{?-?\d\}?)?)*"
_UNIT_TOKEN = (r"\\(?:text|mathrm|mbox|textrm)\s*\{\s*" + _UNIT_EXPR + r"\s*\}(?:\s*\^\s*(?:\{\s*-?\d+\s*\}|-?\d))?")
_UNITS = re.compile(r"(?<=\d)" + SPACE + _UNIT_TOKEN + r"(?:\s*(?:\\cdot|" + ONE_SPACE + r")\s*" + _UNIT_TOKEN + r")*")
"""A unit, or a product of units, right after a number: ``2.50\\text{ kg}``, ``0.04\\text{ kg}\\cdot\\text{m}^2``."""
_PLAIN_UNIT = _UNIT + r"(?:\s*\^\s*\{?-?\d\}?)?(?:\s*(?:/|\\cdot)\s*" + _UNIT + r"(?:\s*\^\s*\{?-?\d\}?)?)*"
_TIED_UNIT = re.compile(r"(?<=[\d}])\s*~\s*(?:" + _PLAIN_UNIT + r"|\\[dt]?frac\s*\{\s*" + _PLAIN_UNIT + r"\s*\}\s*\{\s*" + _PLAIN_UNIT + r"\s*\})"
                        + SPACE + r"(?=$|[,;.=)&]|\\\\|" + QUAD + r"|\\text|\\tag|\\label|\\notag|\\nonumber)")
"""A unit in plain letters after a tie that follows a number or a closing brace, closing a member
(a tag or a label after it closes it too): ``0.1~kg``, ``}~\\frac{rad}{s}`` (or ``\\dfrac``), ``}~s``
(``a~s`` stays a product)."""
_SI = r"(?:kg|m|s|N|J|W|Pa|rad)"
_SI_NAME = r"(?:\\(?:text|mathrm|mbox|textrm)\s*\{\s*" + _SI + r"\s*\}|" + _SI + r"(?![A-Za-z]))"
_POWER = r"(?:\s*\^\s*(?:\{\s*-?\d+\s*\}|-?\d))?"


def _units_of(atom: str) -> str:
    """Units built of ``atom`` joined by spaces, ``/`` or ``\\cdot``."""
    return atom + r"(?:" + SPACE + r"(?:/|\\cdot)?" + SPACE + atom + r")*"


_IN_FRACTION = r"(?:" + _SI_NAME + _POWER + r"|\\[dt]?frac\s*\{\s*" + _units_of(_SI_NAME + _POWER) + r"\s*\}\s*\{\s*" \
    + _units_of(_SI_NAME + _POWER) + r"\s*\})"
_IN_BRACKET = r"(?:" + _IN_FRACTION + r"|" + SIZED_OPEN + r"\(\s*" + _units_of(_IN_FRACTION) + r"\s*" + SIZED_CLOSE + r"\)" + _POWER + ")"
_BRACKETED_UNIT = re.compile(r"(?:" + SPACE_SYMBOL + "|" + QUAD + "|" + TIE + r")+\s*" + SIZED_OPEN + r"\[\s*" + _units_of(_IN_BRACKET)
                             + r"\s*" + SIZED_CLOSE + r"\](?=\s*(?:$|[=,;&]|\\\\|" + QUAD + "))")
"""Coherent SI units in square brackets, spaced off after a value and closing a member, as engineering
solutions label a result, ``312.5\\,m \\ \\ \\left[\\text{kg}\\left(\\frac{\\text{m}}{\\text{s}}\\right)^2\\right]``,
``\\left[ J \\right]``: a value in such units is the number written (rev, rpm and degrees are left, since
a value in them is not the number a formula in radians and seconds takes)."""
_THOUSANDS = re.compile(r"(?<=\d)\{,\}(?=\d{3}(?!\d))")
_NUMBER_TIMES = re.compile(r"(?<=\d)\s*\\times\s*(?=\d)")
_SPACED_POINT = re.compile(r"(?<=\d)\s+(?=\.\d)")
_EXP_I = re.compile(r"(?<!\\)((?:\\mathrm\s*\{\s*e\s*\}|(?<![A-Za-z]{2})e)\s*\^\s*\{\s*-?\s*)i")
"""The imaginary unit in an exponent of e, ``e^{i\\Omega t}``, ``e^{-i\\omega t}``: i there is √−1."""
"""A space before a decimal point, ``0 .8976``: math mode sets no space there, so it is the number 0.8976."""


def plain_numbers(latex: str) -> str:
    """The formula with the units after its numbers dropped, ``10{,}000`` and ``0 .8976`` joined and
    ``\\times`` between two numbers read as a product."""
    latex = _SPACED_POINT.sub("", _THOUSANDS.sub("", latex))
    latex = _EXP_I.sub(r"\1\\sqrt{-1}", latex)
    latex = _UNITS.sub(" ", latex)
    latex = _TIED_UNIT.sub(" ", _BRACKETED_UNIT.sub(" ", latex))
    return _NUMBER_TIMES.sub(r" \\cdot ", latex)
