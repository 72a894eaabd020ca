"""Quaternions by their four components, scalar first, and the text's names for them.

Takes: scalars (SymPy), quaternions (`Quat`) and 4 x 4 matrices the reader of
`derive.lecture.quaternion_reader` builds. Gives: Hamilton's product, the norm, the exponential
(of a scalar, of a quaternion, of a matrix whose square is a multiple of the identity), sums and
products across the three kinds, the rate of a value in symbols by the chain rule (`time_rate`),
and `Names`, what the text's names stand for while a display is read.

May import: SymPy.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

import sympy as sp

QUATERNION_LETTERS = ("q", "p")


class Unread(Exception):
    """The member is outside the grammar: ``why`` says what stopped it."""

    def __init__(self, why: str):
        super().__init__(why)
        self.why = why


@dataclass(frozen=True)
class Quat:
    """A quaternion by its components, scalar first."""

    c: tuple

    def __add__(self, o):
        o = as_quat(o)
        return Quat(tuple(a + b for a, b in zip(self.c, o.c)))

    __radd__ = __add__

    def __neg__(self):
        return Quat(tuple(-a for a in self.c))

    def scaled(self, k):
        return Quat(tuple(k * a for a in self.c))


def as_quat(x) -> Quat:
    """A scalar as the quaternion (x, 0, 0, 0); a quaternion unchanged."""
    return x if isinstance(x, Quat) else Quat((x, 0, 0, 0))


def hamilton(a: Quat, b: Quat) -> Quat:
    """Hamilton's product a b (i j = k)."""
    a0, a1, a2, a3 = a.c
    b0, b1, b2, b3 = b.c
    return Quat((a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3,
                 a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
                 a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1,
                 a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0))


def norm(x):
    """‖x‖ of a scalar or a quaternion."""
    if isinstance(x, Quat):
        return sp.sqrt(sum(a ** 2 for a in x.c))
    return sp.Abs(x)


def exponential(x):
    """e^x of a scalar, of a quaternion a + 𝐯: e^a (cos n + 𝐯 sin n / n), n = ‖𝐯‖ (1 + 𝐯 at n = 0),
    or of a square matrix M with M² = −n² I (the omega operator times a step): cos n I + sin n / n M."""
    if isinstance(x, sp.MatrixBase):
        square = (x * x).applyfunc(sp.expand)
        c = -square[0, 0]
        if square != -c * sp.eye(x.shape[0]):
            raise Unread("the exponential of a matrix whose square is not a multiple of the identity")
        if c == 0:
            return sp.ImmutableMatrix(sp.eye(x.shape[0]) + x)
        n = sp.sqrt(c)
        return sp.ImmutableMatrix(sp.cos(n) * sp.eye(x.shape[0]) + sp.sin(n) / n * x)
    if not isinstance(x, Quat):
        return sp.exp(x)
    a, v = x.c[0], x.c[1:]
    n2 = sum(b ** 2 for b in v)
    if n2 == 0:
        return Quat((sp.exp(a), 0, 0, 0))
    n = sp.sqrt(n2)
    s = sp.sin(n) / n
    return Quat((sp.exp(a) * sp.cos(n), *(sp.exp(a) * s * b for b in v)))


@dataclass
class Names:
    """What the text's names stand for, while a display is read.

    ``style``: the subscripts of a quaternion's components, scalar first ("wxyz", "0123"; empty when
    the text's do not say which is the scalar); ``defined``: a name (``theta``, ``bold u``) → the
    LaTeX the text set it to (read in its place); ``rates``: (a name, the order of its rate) → its
    components (zero where the text assumes so); ``jpl``: the product's rule."""

    defined: dict = field(default_factory=dict)
    rates: dict = field(default_factory=dict)
    style: str = "wxyz"
    jpl: bool = False
    values: dict = field(default_factory=dict)        # a name → its value, in symbols (a quaternion's rates)
    step: str | None = None                           # the subscript of the current step (q_t)
    plain_q: bool = False                             # the text's quaternion is the plain letter q
    truncated: list = field(default_factory=list)     # the last terms before each \cdots met


def symbol(key: str) -> sp.Symbol:
    """The text's scalar ``key``: a component (a subscript x, y, z, w or 0 to 3) is any real
    number, any other scalar (an angle, a step) a positive one."""
    return sp.Symbol(key, real=True) if re.search(r"_[xyzw0-3]$", key) else sp.Symbol(key, positive=True)


def components(name: str, style) -> tuple:
    """The components' symbols of the vector or quaternion ``name``, by the text's subscripts."""
    return tuple(symbol(f"{name}_{a}") for a in style)


def applied_key(name: str, bold: bool, argument: str) -> str:
    """How a name written with its argument is kept among the text's names."""
    return ("bold " if bold else "") + name + argument.replace(" ", "")


def time_rate(value, names: Names):
    """The rate of a value in symbols: the chain rule over the components whose rates ``names``
    gives (a quaternion's, from its rate; omega's, its rates or zero)."""
    rates = dict(names.values.get("rates", {}))
    if isinstance(value, Quat):
        return Quat(tuple(time_rate(c, names) for c in value.c))
    if isinstance(value, sp.MatrixBase):
        return sp.ImmutableMatrix(value.applyfunc(lambda c: time_rate(c, names)))
    value = sp.sympify(value)
    return sum((sp.diff(value, s) * r for s, r in rates.items() if value.has(s)), sp.Integer(0))


def plus(a, b):
    """a + b across scalars, quaternions and matrices (a matrix only with a matrix of its shape, or 0)."""
    if isinstance(a, sp.MatrixBase) or isinstance(b, sp.MatrixBase):
        if a == 0 or b == 0:
            return b if a == 0 else a
        if not (isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase)) or a.shape != b.shape:
            raise Unread("a matrix added to what is not a matrix of its shape")
        return sp.ImmutableMatrix(a + b)
    return a + b


def times(a, b):
    """a b where at most one factor is a quaternion (two quaternions multiply by the text's rule)."""
    if isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase):
        return sp.ImmutableMatrix(a * b)
    if isinstance(a, sp.MatrixBase) or isinstance(b, sp.MatrixBase):
        m, k = (a, b) if isinstance(a, sp.MatrixBase) else (b, a)
        if isinstance(k, Quat):
            raise Unread("a matrix and a quaternion in an order that does not multiply")
        return sp.ImmutableMatrix(m * k)
    if isinstance(a, Quat) and isinstance(b, Quat):
        raise Unread("a product of two quaternions whose rule is not set")
    if isinstance(a, Quat):
        return a.scaled(b)
    if isinstance(b, Quat):
        return b.scaled(a)
    return a * b
