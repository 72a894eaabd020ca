"""The cosine and sine as engineering texts abbreviate them: ``c(\\psi)``, ``s(\\theta)``, ``c_{\\psi}``,
``s_\\theta``, and ``c\\theta``, ``s\\psi`` where the text defines that shorthand.

Takes: the formula reader (`derive.lecture.latex_parser`) at an atom ``c`` or ``s``.
Gives: `abbreviated_trig`, a method of that reader: cos or sin of one of the text's angles, or None
(the reader's position unchanged) when the atom is no such abbreviation.

May import: :mod:`derive.lecture.vocabulary`, :mod:`derive.symbolic.rotations`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture.vocabulary import NotRead
from derive.symbolic.rotations import ANGLES


def abbreviated_trig(self, tok, env):
    """``c(\\psi)``, ``s(\\theta)``, ``c_{\\psi}``, ``s_\\theta``: the cosine and sine of an angle
    as engineering texts abbreviate them (only with one of the text's angles as argument)."""
    a = tok.value
    if a.base not in ("c", "s") or a.dots or a.bold or a.hat or a.tilde or a.primes or a.sup:
        return None
    f = sp.cos if a.base == "c" else sp.sin
    if a.sub:
        k = self.vocab.angle_index(a.sub)
        return f(ANGLES[k]) if k is not None else None
    nxt = self.peek(0)
    if getattr(self.vocab.names, "trig_letters", False) and nxt is not None and nxt.kind == "atom" \
            and not nxt.value.sub and not nxt.value.dots and not nxt.value.bold:
        k = self.vocab.angle_index(nxt.value.base)         # cθ, sψ: the text's own shorthand
        if k is not None:
            self.i += 1
            return f(ANGLES[k])
    if not self.at("op", "("):
        return None
    start = self.i
    try:
        arg = self.paren(env)
    except NotRead:
        self.i = start
        return None
    if arg in ANGLES:
        return f(arg)
    self.i = start
    return None
