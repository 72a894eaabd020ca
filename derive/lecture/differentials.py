"""A derivative's differentials as texts write them, rewritten to the one form the formula reader reads.

* ``dx = v_x``, ``d\\varphi = p + …``: a simulation's derivative, written as code names it, is the
  rate ẋ when no differential stands anywhere else in the formula;
* ``\\frac{d(m v)}{dt}``, ``\\frac{d^2(x)}{dt^2}``, ``\\frac{d\\left(\\delta\\omega_1\\right)}{dt}``,
  ``\\frac{\\mathrm{d}(\\delta\\omega_1)}{\\mathrm{d}t}``: the rate of a bracket, in italic or upright
  differentials, is ``\\frac{d}{dt}`` of the bracket (the second rate, ``\\frac{d^2}{dt^2}``);
* ``\\frac{\\text{d}\\vec{H}}{\\text{d}t}``: the differential set as text is the upright d, ``\\mathrm{d}``;
* ``\\frac{\\mathrm{d}\\,\\omega}{\\mathrm{d}\\,t}``: a small space after the upright d sets nothing apart
  (it is the differential of what follows), ``\\mathrm{d} t``;
* ``\\frac{dq}{\\mathrm{d}t}``, ``\\frac{{}^A d\\hat{b}_x}{\\mathrm{d}\\,t}``: one derivative whose numerator sets
  the italic d and whose denominator the upright one is read in one spelling, the italic ``dt``.

Takes and gives one formula's LaTeX (`derive.lecture.source.normalize` calls `written`; `dotted` is for
the shape readers that know a rate only by its dot, ``\\frac{\\mathrm{d}\\phi}{\\mathrm{d}t}`` as
``\\dot{\\phi}``); imports `derive.lecture.latex_spaces` only (what a space is).
"""
from __future__ import annotations

import re

from derive.lecture.latex_spaces import ONE_SPACE

_D = r"(?:d|\\(?:mathrm|operatorname|text|rm)\s*(?:\{\s*d\s*\}|d))"      # italic or upright
_CODE_RATE = re.compile(r"^\s*d\s*(\\[A-Za-z]+|[A-Za-z])((?:_(?:\{[^{}]*\}|[A-Za-z0-9]))?)\s*=(?!=)(.*)$", re.S)
_DIFFERENTIAL_LETTER = re.compile(r"(?<![A-Za-z\\])d(?![A-Za-z]{2})")
# d in text before what it differentiates, or closing a fraction's numerator (d/dt written as an operator)
_TEXT_D = re.compile(r"\\text(?:rm)?\s*\{\s*d\s*\}(?=\s*[A-Za-z\\{(}])")
_SPACED_D = re.compile(r"\\mathrm\s*\{\s*d\s*\}" + ONE_SPACE + "+")
# a fraction whose numerator opens with the italic d (after a frame's prescript, ^A d) over an upright dt
_MIXED_D = re.compile(r"(\\frac\s*\{\s*(?:\^\s*(?:\{[^{}]*\}|[A-Za-z])\s*)?d(?![A-Za-z]{2})(?:[^{}]|\{[^{}]*\})*\}\s*\{\s*)"
                      r"\\mathrm\{d\}\s*(t\s*(?:\^\s*\{?\s*2\s*\}?\s*)?\})")
_BRACKET_RATE = re.compile(r"\\frac\s*\{\s*" + _D + r"\s*(\^\s*\{?\s*2\s*\}?\s*)?(?:\\left\s*)?"
                           r"\(((?:[^(){}]|\([^(){}]*\))*?)(?:\\right\s*)?\)\s*\}"
                           r"\s*\{\s*" + _D + r"\s*t\s*(?(1)\^\s*\{?\s*2\s*\}?\s*|)\}")

_ITALIC_OR_UPRIGHT = r"\{?\s*(?:d|\\mathrm\s*\{\s*d\s*\})\s*\}?"
# the first rate of one plain symbol with its index, d x_1 / dt (no mark, no bracket: those are other rates)
_ONE_SYMBOL_RATE = re.compile(r"\\frac\s*\{\s*" + _ITALIC_OR_UPRIGHT + r"\s*(\\[A-Za-z]+|[A-Za-z])(?![A-Za-z])\s*"
                              r"(_\s*(?:\{[^{}]*\}|[A-Za-z0-9]))?\s*\}\s*\{\s*" + _ITALIC_OR_UPRIGHT + r"\s*t\s*\}")


def dotted(text: str) -> str:
    """``text`` with each first rate of one plain symbol written as a fraction, ``\\frac{d x_1}{dt}`` or
    ``\\frac{\\mathrm{d} x_1}{\\mathrm{d} t}``, written with the dot, ``\\dot{x}_1``."""
    return _ONE_SYMBOL_RATE.sub(lambda m: r"\dot{" + m.group(1) + "}" + (m.group(2) or ""), text)


def _code_rate(text: str) -> str:
    """``dx = v_x``: the rate of the one symbol after d, when no other differential stands in the formula."""
    m = _CODE_RATE.match(text)
    if not m or _DIFFERENTIAL_LETTER.search(m.group(3)):
        return text
    return r"\dot{" + m.group(1) + "}" + m.group(2) + " =" + m.group(3)


def written(text: str) -> str:
    """The formula with its derivatives' differentials in the reader's form (see the module docstring)."""
    text = _code_rate(_TEXT_D.sub(r"\\mathrm{d}", text) if "text" in text else text)
    text = _MIXED_D.sub(r"\1d\2", _SPACED_D.sub(r"\\mathrm{d} ", text))
    return _BRACKET_RATE.sub(lambda m: (r"\frac{d^2}{dt^2}(" if m.group(1) else r"\frac{d}{dt}(") + m.group(2) + ")",
                             text)
