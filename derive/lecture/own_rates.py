"""A function of time the text writes, ``\\phi(t) = …``, and its rate written after it,
``\\dot{\\phi}(t) = …`` (or ``\\dot\\phi(t)``, ``\\frac{d\\phi}{dt}(t)``): the rate is checked as the time
derivative of the text's own function.

A text that solves for an angle often gives the angle and its rate one after the other (the fast
top's ``\\phi(t) = \\Omega_p t - \\frac{\\Omega_p}{\\omega_n}\\sin(\\omega_n t)`` and
``\\dot{\\phi}(t) = \\Omega_p [1 - \\cos(\\omega_n t)]``). The rate holds as the derivative of the
function the text wrote (that is what it is checked against, and the reason says so); when the two
disagree one of them is off and the reader cannot tell which, so the rate is left unchecked, never
flagged. The function's own truth is not decided here.

Takes a statement in the reader's dialect and its vocabulary (the text's symbols are constants);
gives the rate's verdict, if any (none for a statement that is not a rate of a recorded f(t)).
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx

_D = r"(?:\\mathrm\s*\{\s*d\s*\}|\\mathrm\s*d|d)\s*"
# f(t), its rate \dot{f}(t) or \frac{d f}{dt}(t) (as the formula reader reads d/dt: `derive.lecture.written_rates`)
_WRITTEN = re.compile(r"^\s*(?:(?P<dot>\\dot(?![A-Za-z])\s*(?P<brace>\{\s*)?)|(?P<frac>\\[dt]?frac\s*\{\s*" + _D + r"))?"
                      r"(?P<name>\\[A-Za-z]+|[A-Za-z])(?(brace)\s*\})(?(frac)\s*\}\s*\{\s*" + _D + r"t\s*\})\s*"
                      r"(?:\\left\s*)?\(\s*t\s*(?:\\right\s*)?\)\s*=(?P<rhs>[^=<>]+)$")


class OwnRates:
    """The functions of time a text has written (name → (line, value)), and its rates checked."""

    def __init__(self):
        self.functions: dict[str, tuple[int, sp.Expr]] = {}

    def check(self, line: int, text: str, vocab) -> list[tuple[str, str]]:
        """The verdict (verdict, why) of ``\\dot f(t) = …`` against the text's ``f(t)``, in a list
        (empty for anything else); records ``f(t) = …``."""
        m = _WRITTEN.match(text)
        if m is None:
            return []
        try:
            parsed = lx.parse(m.group("rhs"), vocab)
        except (lx.NotRead, lx.Words, ValueError, TypeError):
            return []
        if len(parsed.members) != 1 or not isinstance(parsed.members[0].value, sp.Expr):
            return []
        value, name = parsed.members[0].value, m.group("name")
        if not (m.group("dot") or m.group("frac")):
            if lx.t in value.free_symbols:
                self.functions[name] = (line, value)
            return []
        if name not in self.functions:
            return []
        at, function = self.functions[name]
        if sp.simplify(value - sp.diff(function, lx.t)) == 0:
            return [("holds", f"the time derivative of the text's own {name}(t) (line {at})")]
        return [("unchecked", f"differs from the time derivative of the text's {name}(t) at line {at}: one of "
                             "the two is off, and the reader does not tell which")]
