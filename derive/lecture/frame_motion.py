r"""Frames in motion in Kane's notation: derivatives seen from a frame, angular velocity and acceleration.

Takes: a statement written with ``\frac{{}^A d\hat{b}_x}{dt}`` (the derivative of a vector seen from
A), ``\frac{{}^A d}{dt} X`` (the same as an operator), ``{}^A\bar{\omega}^B`` and ``{}^A\hat{\omega}^B``
(B's angular velocity in A and its direction), ``{}^A\bar{\alpha}^B``, ``\left| … \right|``,
``\frac{d{}^B\mathbf{C}^A}{dt}`` (the rate of a DCM, or of a scalar, entry by entry),
``\dot{u}_1`` and the text's own vectors ``\bar{u}`` set equal to a sum of unit vectors (a name is a
function of time once the text writes its rate, in this display or one before, else a constant). Gives
`Motion`, the frame algebra of `derive.lecture.frame_algebra` with every frame turning: each frame
letter's unit vectors are turned from a reference about one axis through an angle that is a function
of time, the axis chosen by the letter (frames next in the alphabet turn about different axes), so
one frame turns relative to another about an axis that itself turns. On it:

* the derivative in F of a vector is that of its components in F, put back (``C_Fᵀ d(C_F v)/dt``);
* ``{}^F\bar{\omega}^G`` is Kane's definition, (ġ_y·g_z) g_x + (ġ_z·g_x) g_y + (ġ_x·g_y) g_z with the
  derivatives seen from F, and ``{}^F\bar{\alpha}^G`` its derivative seen from F;
* ``+ \ldots +`` between two angular velocities (or accelerations) of a chain stands for that of the
  frames between them (``{}^B\bar{\omega}^C + \ldots + {}^Y\bar{\omega}^Z``: ``{}^C\bar{\omega}^Y``).

`equal_in_motion` compares two members at three exact points (rationals for the angles, their rates
and the text's names; rational points of the unit circle for the sines and cosines). A relation of
kinematics holds for this motion as for any; one that does not hold is no slip of the text unless
every name of the text in it is one whose rate the text writes (a name with no written rate may be
a constant the text states in words).

May import: :mod:`derive.lecture.frame_algebra`, :mod:`derive.lecture.vocabulary`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import random

import sympy as sp

from derive.lecture.frame_algebra import Frames, Vec, Vecs, matrices, tokens
from derive.lecture.vocabulary import NotRead
from derive.symbolic.rotations import passive

t = sp.Symbol("t", real=True)
MOVING = ("ang", "rate", "ddt", "vecname", "dot")


def moving(text: str) -> bool:
    """Whether a statement is written with the notation of motion (see the module docstring)."""
    try:
        return any(tok[0] in MOVING for tok in tokens(text))
    except NotRead:
        return False


class Motion(Frames):
    """The text's frames, each turning (see the module docstring), and its own vectors."""

    def __init__(self):
        super().__init__()
        self.vectors: dict[str, str] = {}      # the text's \bar{u}: the LaTeX it set it to, read where used
        self.rates: set[str] = set()            # names whose rate (\dot) the text has written

    def frame(self, letter: str) -> sp.Matrix:
        if letter not in self.of:
            q = sp.Function(f"q_{letter}", real=True)(t)
            self.of[letter] = passive("xyz"[ord(letter) % 3], q)
        return self.of[letter]

    def scalar(self, name: str):
        """A name whose rate the text writes is a function of time; any other, a constant."""
        return sp.Function(name, real=True)(t) if name in self.rates else sp.Symbol(name, real=True)

    def read(self, text: str) -> list:
        self.rates |= {tok[1] for tok in tokens(text) if tok[0] == "dot"}
        return super().read(text)

    def seen_from(self, letter: str, v):
        """The derivative of a vector (or a scalar) seen from the frame ``letter``."""
        if isinstance(v, Vec):
            c = self.frame(letter)
            return Vec((c.T * (c * v.row.T).diff(t)).T)
        if isinstance(v, (Vecs, sp.MatrixBase)):
            raise NotRead("a derivative of a matrix in a frame")
        return sp.diff(v, t)

    def omega(self, f: str, g: str) -> Vec:
        """{}^F ω^G by Kane's three measure numbers."""
        gx, gy, gz = (Vec(self.frame(g)[k, :]) for k in range(3))
        d = lambda u: self.seen_from(f, u).row  # noqa: E731
        measure = [(d(gy) * gz.row.T)[0], (d(gz) * gx.row.T)[0], (d(gx) * gy.row.T)[0]]
        return Vec(measure[0] * gx.row + measure[1] * gy.row + measure[2] * gz.row)

    def angular(self, f, g, which="omega"):
        w = self.omega(f, g)
        return w if which == "omega" else self.seen_from(f, w)

    def _moving(self, kind, val, extra):
        if kind == "ang":
            f, mark, which, g = extra
            w = self.angular(f, g, which)
            if mark == "hat":
                return Vec(w.row / _norm(w))
            return w
        if kind == "rate":
            f, inner = extra
            value = self._entry(inner) if inner.strip() else self._factor()
            return self.seen_from(f, value)
        if kind == "ddt":
            inner = extra[0]
            value = self._entry(inner) if inner.strip() else self._factor()
            if isinstance(value, (Vec, Vecs)):
                raise NotRead("the rate of a vector with no frame to see it from")
            return value.diff(t) if isinstance(value, sp.MatrixBase) else sp.diff(value, t)
        if kind == "vecname":
            if val not in self.vectors:
                raise NotRead(f"the text's vector {val} before it is set")
            value = self._entry(self.vectors[val])
            if not isinstance(value, Vec):
                raise NotRead(f"the text's vector {val} set to what is no vector")
            return value
        if kind == "dot":
            return sp.diff(self.scalar(val), t)
        if (kind, val) == ("op", "|"):
            self._bars += 1
            inner = self._sum()
            self._bars -= 1
            if self._peek() != ("op", "|"):
                raise NotRead("an unclosed |")
            self._at += 1
            return _norm(inner) if isinstance(inner, Vec) else sp.Abs(inner)
        if (kind, val) == ("op", "\\ldots"):
            return self._chain_between()
        raise NotRead("a frame statement the reader does not follow")

    def _chain_between(self):
        """``X + \\ldots + Y`` in a sum of angular quantities of a chain: those of the frames between."""
        at = self._at - 1
        before = self._toks[at - 2] if at >= 2 else None
        after = self._toks[at + 2] if at + 2 < len(self._toks) else None
        if not (before and after and before[0] == after[0] == "ang" and before[2][1:3] == after[2][1:3]
                and self._toks[at - 1][:2] == ("op", "+") and self._toks[at + 1][:2] == ("op", "+")):
            raise NotRead("an ellipsis not between two terms of a chain")
        return self.angular(before[2][3], after[2][0], before[2][2])

    def names_in(self, text: str) -> set:
        """The text's scalar names written in a statement (a rate written counts as its name)."""
        return {tok[1] for tok in tokens(text) if tok[0] in ("greek", "name", "dot")}


def equal_in_motion(a, b) -> bool | None:
    """Whether two values agree at three exact points of the motion: each angle, rate and name put
    at rationals, each angle's sine and cosine at a rational point of the unit circle (exact, so
    a difference that is not 0 there is no rounding); None when they are not of one kind."""
    both = matrices(a, b)
    if both is None:
        return None
    d = both[0] - both[1]
    symbols = sorted(d.free_symbols, key=str)
    angles = {f.args[0] for f in d.atoms(sp.sin, sp.cos)}
    if any(not isinstance(x, sp.Symbol) for x in angles):
        return None
    for k in range(3):
        rng = random.Random(f"frame motion {k}")
        point = {x: sp.Rational(rng.randint(-200, 200), rng.randint(50, 100)) for x in symbols}
        trig = {}
        for x in angles:
            a_, b_, c_ = _CIRCLE[rng.randrange(len(_CIRCLE))]
            trig[sp.sin(x)], trig[sp.cos(x)] = sp.Rational(a_, c_), sp.Rational(b_, c_)
        at = d.xreplace(trig).xreplace(point)
        for e in at:
            e = sp.expand(e)
            if e != 0 and (e.is_Rational or abs(sp.N(e, 50)) > sp.Float(10) ** -40):
                return False
    return True


_CIRCLE = ((3, 4, 5), (5, 12, 13), (8, 15, 17), (7, 24, 25), (20, 21, 29), (12, 35, 37))


def _norm(v: Vec):
    return sp.sqrt(sp.expand((v.row * v.row.T)[0]))
