r"""Reference frames in Kane's notation: hatted unit vectors and direction cosine matrices.

Texts after Kane and Levinson name a frame by a capital letter, its unit vectors by the hatted small
letter (``\hat{n}_x``, ``\hat{a}_1``), and write ``{}^A\mathbf{C}^N`` for the direction cosine matrix
of A in N, whose i-th row holds the components in N of A's i-th unit vector (``[a] = C [n]``).

Takes: the statements of one display. Gives `Frames`, the text's orientation algebra: every frame
letter the text writes stands for an orientation (an exact rational rotation of its own until the
text states one), its unit vectors are rows of that matrix, ``{}^F\mathbf{C}^G`` is C_F C_Gᵀ, and
`Frames.read` evaluates a statement: sums, products of scalars and vectors, ``\cdot`` and ``\times``
of unit vectors, written matrices (of scalars, or a column of unit vectors), products of DCMs,
``^T`` and ``^{-1}``, and ``\ldots`` between two DCMs of a chain (the frames between them: the chain
telescopes). A statement giving all three unit vectors of one frame in another's, with numbers and
the sines and cosines of one angle (``\hat{a}_x = \cos\theta \hat{n}_x + \sin\theta \hat{n}_y``, or
the matrix form), states that frame's orientation: a simple orientation about the axis the two
frames share, held to the right-hand sense (``passive(axis, θ)``), which then orients the frame.
A derivative's differentials may be italic or upright (``\frac{{}^A d\bar{u}}{dt}``,
``\frac{\mathrm{d} u_1}{\mathrm{d} t}``); the rate of one name so written is its dot (``\dot{u}_1``).

May import: :mod:`derive.lecture.latex_spellings`, :mod:`derive.lecture.vocabulary`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture.latex_spellings import BOLD
from derive.lecture.vocabulary import NotRead
from derive.symbolic.rotations import passive, skew, trig_reduce

_UNIT = r"\\hat\s*\{\s*([a-z])\s*\}\s*_\s*\{?\s*([xyz123])\s*\}?"
# the matrix's C in any bold face (\mathbf{C}, \boldsymbol{C}, \bm C): the same symbol
_DCM = r"\^\s*\{?\s*([A-Z])\s*\}?\s*" + BOLD + r"\s*(?:\{\s*C\s*\}|C(?![A-Za-z]))\s*\^\s*\{?\s*([A-Z])\s*\}?"
_GREEK = ("alpha beta gamma delta epsilon zeta eta theta vartheta iota kappa lambda mu nu xi pi rho sigma "
          "tau upsilon phi varphi chi psi omega").split()
_FRAME = r"\^\s*\{?\s*([A-Z])\s*\}?"
# the differential d, italic or upright (\mathrm{d}), and a fraction's denominator dt in either
_D = r"(?:d(?![a-z])|\\mathrm\s*\{\s*d\s*\})"
_DT = r"\{\s*(?:d|\\mathrm\s*\{\s*d\s*\})\s*t\s*\}"
# each kind of token and its pattern, tried in this order
_KINDS = [
    ("unit", re.compile(_UNIT)),
    ("dcm", re.compile(_DCM)),
    ("ang", re.compile(_FRAME + r"\s*\\(bar|hat)\s*\{\s*\\(omega|alpha)\s*\}\s*" + _FRAME)),
    ("rate", re.compile(r"\\frac\s*\{\s*" + _FRAME + r"\s*" + _D + r"((?:[^{}]|\{[^{}]*\})*)\}\s*" + _DT)),
    ("ddt", re.compile(r"\\frac\s*\{\s*" + _D + r"((?:[^{}]|\{[^{}]*\})*)\}\s*" + _DT)),
    ("env", re.compile(r"\\begin\s*\{\s*[bp]matrix\s*\}")),
    ("func", re.compile(r"\\(?:cos|sin)(?![A-Za-z])")),
    ("greek", re.compile(r"\\(" + "|".join(_GREEK) + r")(?![A-Za-z])")),
    ("vecname", re.compile(r"\\bar\s*\{\s*([a-z])\s*\}")),
    ("dot", re.compile(r"\\dot\s*\{\s*([a-z])\s*\}")),
    ("num", re.compile(r"\d+(?:\.\d+)?")),
    ("post", re.compile(r"\^\s*\{\s*(T|-1|2)\s*\}|\^\s*([T2])")),
    ("op", re.compile(r"\\(?:cdot|times|ldots|neq|ne)(?![A-Za-z])|[-+=(){}|]")),
    ("sub", re.compile(r"_\s*\{\s*([A-Za-z0-9]+)\s*\}|_\s*([A-Za-z0-9])")),
]
# what a ddt token differentiates when it is one name with its index (u_1): its rate is that name's dot
_ONE_NAME = re.compile(r"\s*([a-z])\s*(?:_\s*\{\s*([A-Za-z0-9]+)\s*\}|_\s*([A-Za-z0-9]))?\s*")
_DROP = re.compile(r"\{\}(?=\s*\^)|\\left(?![A-Za-z])|\\right(?![A-Za-z])|\\[,;!]|\\quad|\\textrm\{\.\}|[.,]\s*$")
AXES = {"x": 0, "y": 1, "z": 2, "1": 0, "2": 1, "3": 2}


def uses_frames(text: str) -> bool:
    """Whether a statement writes a frame's hatted unit vector, a direction cosine matrix, an angular
    velocity or acceleration of one frame in another, or a derivative seen from a frame."""
    return any(p.search(text) for k, p in _KINDS if k in ("unit", "dcm", "ang", "rate"))


class Vec:
    """A vector: its components (a 1×3 row) in the frame all others are written in."""

    def __init__(self, row):
        self.row = sp.Matrix(row).reshape(1, 3)


class Vecs:
    """A written column of vectors (``[\\hat{a}_x; \\hat{a}_y; \\hat{a}_z]``): a row per vector."""

    def __init__(self, rows):
        self.rows = sp.Matrix(rows)


def generic(letter: str) -> sp.Matrix:
    """An exact rational rotation of its own for a frame whose orientation the text has not stated
    (Cayley's (1 − K)⁻¹(1 + K) of a skew K drawn from the letter): proper and orthogonal, with no
    special axis, so a relation that holds for it holds for a general orientation only by chance."""
    k = ord(letter)
    K = skew([sp.Rational(k % 7 + 1, 5), sp.Rational(-(k % 5 + 2), 7), sp.Rational(k % 3 + 1, 3)])
    return (sp.eye(3) - K).inv() * (sp.eye(3) + K)


def reduced(e):
    """An entry in its canonical form in the sines and cosines of its angles (cos²θ + sin²θ is 1):
    the coefficients a frame's unit vectors have in a stated frame's come back as written."""
    e = sp.expand(e)
    angles = sorted({a for f in e.atoms(sp.sin, sp.cos) for a in f.args[0].free_symbols}, key=str)
    if not angles or any(f.args[0] not in angles for f in e.atoms(sp.sin, sp.cos)):
        return e
    return trig_reduce(e, angles)


def is_zero(d) -> bool | None:
    """True when d is 0 as a polynomial in sines and cosines, False when it is not, None unknown."""
    d = sp.expand(d)
    if d == 0:
        return True
    angles = sorted({a for f in d.atoms(sp.sin, sp.cos) for a in f.args[0].free_symbols}, key=str)
    if any(len(f.args[0].free_symbols) != 1 or f.args[0] not in angles for f in d.atoms(sp.sin, sp.cos)):
        return None
    return trig_reduce(d, angles) == 0


def matrix_of(v):
    """A value as a matrix of scalars (a vector: its row; a column of vectors: their rows)."""
    if isinstance(v, Vec):
        return v.row
    if isinstance(v, Vecs):
        return v.rows
    if isinstance(v, sp.MatrixBase):
        return sp.Matrix(v)
    return sp.Matrix([[v]])


def kind_of(v) -> str:
    """scalar, vector, vectors (a written column of them) or matrix."""
    return "vector" if isinstance(v, Vec) else "vectors" if isinstance(v, Vecs) else \
        "matrix" if isinstance(v, sp.MatrixBase) else "scalar"


def one_kind(values) -> bool:
    """Whether the members are of one kind, a written 0 standing for the zero of any."""
    return len({kind_of(v) for v in values if not (kind_of(v) == "scalar" and v == 0)}) <= 1


def zero_as(v, like):
    """A written 0 as the zero of ``like``'s kind and shape; any other value as it is."""
    if kind_of(v) != "scalar" or v != 0 or kind_of(like) == "scalar":
        return v
    zeros = sp.zeros(*matrix_of(like).shape)
    return Vec(zeros) if isinstance(like, Vec) else Vecs(zeros) if isinstance(like, Vecs) else zeros


def settled(m: sp.Matrix) -> sp.Matrix:
    """Functions of time and their derivatives as plain symbols (the zero test takes symbols)."""
    rates = {d: sp.Symbol(f"{d.expr.func.__name__}_d{d.derivative_count}", real=True)
             for d in m.atoms(sp.Derivative)}
    m = m.xreplace(rates)
    return m.xreplace({f: sp.Symbol(f.func.__name__, real=True) for f in m.atoms(sp.core.function.AppliedUndef)})


def matrices(a, b):
    """Two values of one kind as matrices of one shape (a written 0 taken as the other's zero), or
    None when they are not of one kind."""
    a, b = zero_as(a, b), zero_as(b, a)
    if kind_of(a) != kind_of(b):
        return None
    ma, mb = settled(matrix_of(a)), settled(matrix_of(b))
    return None if ma.shape != mb.shape else (ma, mb)


def equal(a, b) -> bool | None:
    """Whether two values are equal entry by entry (None: not of one kind, or undecided)."""
    both = matrices(a, b)
    if both is None:
        return None
    found = [is_zero(x - y) for x, y in zip(*both)]
    return None if None in found else all(found)


class Frames:
    """The orientations of the text's frames (see the module docstring), kept across displays."""

    def __init__(self):
        self.of: dict[str, sp.Matrix] = {}      # frame letter → its unit vectors' rows in one common frame
        self.relations: list[str] = []         # the relations between the members last read
        self.stated: set[str] = set()           # frames whose orientation the text has stated
        self.stated_in: dict[str, str] = {}     # each, the frame it was stated in
        self.simple = 0                         # simple orientations the text has stated in the right-hand sense

    def angles(self) -> set:
        """The symbols the stated orientations carry (a relation in others is about an orientation
        the text has not stated to the reader)."""
        return set().union(*(m.free_symbols for m in self.of.values())) if self.of else set()

    def frame(self, letter: str) -> sp.Matrix:
        if letter not in self.of:
            self.of[letter] = generic(letter)
        return self.of[letter]

    def unit(self, letter: str, axis: str) -> Vec:
        return Vec(self.frame(letter.upper())[AXES[axis], :])

    def dcm(self, f: str, g: str) -> sp.Matrix:
        return self.frame(f) * self.frame(g).T

    # -- reading a statement
    def read(self, text: str) -> list:
        """The members of a relation ``m₀ = m₁ = …`` as values; `NotRead` for anything else."""
        toks = tokens(text)
        self._toks, self._at, self._bars, self.relations = toks, 0, 0, []
        members = [self._sum()]
        while self._peek() in (("op", "="), ("op", "\\neq")):
            self.relations.append(self._peek()[1])
            self._at += 1
            members.append(self._sum())
        if self._at != len(toks):
            raise NotRead("a frame statement the reader does not follow")
        return members

    def _peek(self):
        return self._toks[self._at][:2] if self._at < len(self._toks) else (None, None)

    def _sum(self):
        sign = 1
        if self._peek() in (("op", "-"), ("op", "+")):
            sign = -1 if self._peek()[1] == "-" else 1
            self._at += 1
        total = scale(sign, self._product())
        while self._peek() in (("op", "-"), ("op", "+")):
            sign = -1 if self._peek()[1] == "-" else 1
            self._at += 1
            total = add(total, scale(sign, self._product()))
        return total

    def _product(self):
        """Dot and cross products of juxtaposed factors: ``a \\times v \\hat{b}`` is a × (v b̂)."""
        value = self._juxtaposed()
        while self._peek() in (("op", "\\cdot"), ("op", "\\times")):
            val = self._peek()[1]
            self._at += 1
            value = (dot if val == "\\cdot" else cross)(value, self._juxtaposed())
        return value

    def _juxtaposed(self):
        value = self._factor()
        while True:
            kind, val = self._peek()
            if kind == "op" and val == "\\ldots":
                value = self._ellipsis(value)
            elif kind in ("unit", "dcm", "env", "func", "greek", "num", "name", "ang", "rate", "ddt", "vecname", "dot") \
                    or (kind, val) == ("op", "(") or ((kind, val) == ("op", "|") and not self._bars):
                value = times(value, self._factor())
            else:
                return value

    def _ellipsis(self, value):
        """``^Y C^X \\ldots ^C C^B``: the DCMs of the frames between X and C, i.e. ^X C^C."""
        before = self._toks[self._at - 1]
        after = self._toks[self._at + 1] if self._at + 1 < len(self._toks) else (None, None, None)
        if before[0] != "dcm" or after[0] != "dcm":
            raise NotRead("an ellipsis not between two direction cosine matrices")
        self._at += 1
        return times(value, self.dcm(before[2][1], after[2][0]))

    def _factor(self):
        value = self._primary()
        while self._peek()[0] == "post":
            power = self._toks[self._at][1]
            self._at += 1
            if power == "T" and isinstance(value, sp.MatrixBase):
                value = value.T
            elif power == "-1" and isinstance(value, sp.MatrixBase) and value.shape == (3, 3):
                value = inverse(value)
            elif power == "2" and not isinstance(value, (sp.MatrixBase, Vec, Vecs)):
                value = value**2
            else:
                raise NotRead("a power of a frame quantity the reader does not take")
        return value

    def _primary(self):
        if self._at >= len(self._toks):
            raise NotRead("a frame statement ends early")
        kind, val, extra = self._toks[self._at]
        self._at += 1
        if kind == "unit":
            return self.unit(*extra)
        if kind == "dcm":
            return self.dcm(*extra)
        if kind == "num":
            return sp.Rational(val)
        if kind in ("greek", "name"):
            return self.scalar(val)
        if kind == "func":
            arg = self._factor()
            if isinstance(arg, (sp.MatrixBase, Vec, Vecs)):
                raise NotRead("a sine of what is not a scalar")
            return (sp.cos if val == "\\cos" else sp.sin)(arg)
        if kind == "env":
            return self._written(extra)
        if (kind, val) == ("op", "(") or (kind, val) == ("op", "{"):
            inner = self._sum()
            if self._peek() != ("op", ")" if val == "(" else "}"):
                raise NotRead("an unclosed bracket")
            self._at += 1
            return inner
        return self._moving(kind, val, extra)

    def scalar(self, name: str):
        """A name of the text's: a constant here."""
        return sp.Symbol(name, real=True)

    def _moving(self, kind, val, extra):
        """A token of the notation of motion (rates, angular velocities): read by a moving model only."""
        raise NotRead("a frame statement the reader does not follow")

    def _written(self, entries):
        values = [[self._entry(e) for e in row] for row in entries]
        flat = [v for row in values for v in row]
        if all(isinstance(v, Vec) for v in flat) and all(len(r) == 1 for r in values):
            return Vecs([v.row for v in flat])
        if any(isinstance(v, (Vec, Vecs, sp.MatrixBase)) for v in flat) or len({len(r) for r in values}) != 1:
            raise NotRead("a written matrix of mixed entries")
        return sp.Matrix(values)

    def _entry(self, text):
        """One entry of a written matrix, read on its own."""
        kept = self._toks, self._at, self._bars, self.relations
        try:
            members = self.read(text)
        finally:
            self._toks, self._at, self._bars, self.relations = kept
        if len(members) != 1:
            raise NotRead("a relation inside a written matrix")
        return members[0]


def tokens(text: str) -> list:
    """(kind, value, extra) of a statement; `NotRead` at anything outside the notation."""
    text = _DROP.sub(" ", text).strip()
    out, at = [], 0
    while at < len(text):
        if text[at:].strip() == "":
            break
        if text[at:].lstrip().startswith("&"):
            at = text.index("&", at) + 1          # an alignment point outside a written matrix
            continue
        while text[at].isspace():
            at += 1
        kind, m = next(((k, p.match(text, at)) for k, p in _KINDS if p.match(text, at)), (None, None))
        if m is None:
            name = re.match(r"([A-Za-z])(?![A-Za-z])", text[at:])
            if name:
                out.append(("name", name.group(1), None))
                at += name.end()
                continue
            raise NotRead(f"a symbol the frame reader does not know at {text[at:at + 12]!r}")
        val = m.group(0)
        if kind == "env":
            body, end = _environment(text, m.end())
            out.append(("env", "matrix", [[c.strip() for c in r.split("&")] for r in _rows(body)]))
            at = end
            continue
        if kind == "sub":
            if not out or out[-1][0] not in ("greek", "name", "dot"):
                raise NotRead("a subscript on what is not a name")
            k, v, e = out[-1]
            out[-1] = (k, v + "_" + (m.group(1) or m.group(2)), e)
        elif kind in ("greek", "vecname", "dot"):
            out.append((kind, m.group(1), None))
        elif kind == "post":
            out.append(("post", m.group(1) or m.group(2), None))
        elif kind == "op":
            out.append(("op", {"\\ne": "\\neq"}.get(val, val), None))
        elif kind == "ddt" and _ONE_NAME.fullmatch(m.group(1)):
            one = _ONE_NAME.fullmatch(m.group(1))
            sub = one.group(2) or one.group(3)
            out.append(("dot", one.group(1) + ("_" + sub if sub else ""), None))
        else:
            out.append((kind, val, m.groups()))
        at = m.end()
    return out


def _environment(text: str, start: int) -> tuple[str, int]:
    """The body of a matrix environment opened before ``start`` and where its end closes it."""
    depth, at = 1, start
    pattern = re.compile(r"\\(begin|end)\s*\{\s*[bp]matrix\s*\}")
    while True:
        m = pattern.search(text, at)
        if not m:
            raise NotRead("an unclosed matrix")
        depth += 1 if m.group(1) == "begin" else -1
        if depth == 0:
            return text[start:m.start()], m.end()
        at = m.end()


def _rows(body: str) -> list[str]:
    return [r for r in re.split(r"\\\\", body) if r.strip()]


def scale(k, v):
    return v if k == 1 else times(sp.Integer(k), v)


def add(a, b):
    if isinstance(a, Vec) and isinstance(b, Vec):
        return Vec(a.row + b.row)
    if isinstance(a, Vecs) and isinstance(b, Vecs) and a.rows.shape == b.rows.shape:
        return Vecs(a.rows + b.rows)
    if isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase) and a.shape == b.shape:
        return a + b
    if not any(isinstance(v, (Vec, Vecs, sp.MatrixBase)) for v in (a, b)):
        return a + b
    raise NotRead("a sum of a vector and what is not one")


def times(a, b):
    scalar = lambda v: not isinstance(v, (Vec, Vecs, sp.MatrixBase))  # noqa: E731
    if scalar(a) and scalar(b):
        return a * b
    if scalar(a) or scalar(b):
        k, v = (a, b) if scalar(a) else (b, a)
        return Vec(k * v.row) if isinstance(v, Vec) else Vecs(k * v.rows) if isinstance(v, Vecs) else k * v
    if isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase) and a.shape[1] == b.shape[0]:
        return a * b
    if isinstance(a, sp.MatrixBase) and isinstance(b, Vecs) and a.shape[1] == b.rows.shape[0]:
        return Vecs(a * b.rows)
    raise NotRead("a product the frame reader does not take")


def dot(a, b):
    if isinstance(a, Vec) and isinstance(b, Vec):
        return (a.row * b.row.T)[0, 0]
    if not any(isinstance(v, (Vec, Vecs, sp.MatrixBase)) for v in (a, b)):
        return a * b
    raise NotRead("a dot product of what is not two vectors")


def cross(a, b):
    if isinstance(a, Vec) and isinstance(b, Vec):
        return Vec(a.row.cross(b.row))
    raise NotRead("a cross product of what is not two vectors")


def inverse(m: sp.Matrix) -> sp.Matrix:
    """M⁻¹ by the adjugate over a determinant the trigonometric reduction makes a number."""
    det = sp.expand(m.det())
    angles = sorted({a for f in det.atoms(sp.sin, sp.cos) for a in f.args[0].free_symbols}, key=str)
    det = trig_reduce(det, angles) if angles else det
    if not det.is_number or det == 0:
        raise NotRead("the inverse of a matrix whose determinant is not a number")
    return m.adjugate() / det


def simple_turn(c: sp.Matrix):
    """(axis, angle, right-handed) when C turns about one shared axis through one angle: numbers and the
    sines and cosines of that angle, the axis's row and column those of the identity; else None."""
    symbols = c.free_symbols
    if len(symbols) != 1:
        return None
    q = next(iter(symbols))
    if any((e.subs({f: 0 for f in e.atoms(sp.sin, sp.cos)}).free_symbols) for e in c):
        return None
    for k, axis in enumerate("xyz"):
        if list(c[k, :]) == [int(i == k) for i in range(3)] and list(c[:, k]) == [int(i == k) for i in range(3)]:
            if equal(c, passive(axis, q)):
                return axis, q, True
            if equal(c, passive(axis, -q)):
                return axis, q, False
            return axis, q, None
    return None
