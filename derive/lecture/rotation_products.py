r"""Products of a rotation matrix with the text's matrices and vectors, read as identities.

Texts on frames write relations among letters that stand for matrices and vectors, one of them a
rotation matrix: ``R R^T = I``, ``\dot R R^T = -R \dot R^T = -(\dot R R^T)^T``, ``\dot{\mathbf x} =
\dot R \mathbf x(0) = \dot R R^T \mathbf x``, ``R L = R I (R^T R) \omega``, a transformation of the
inertia tensor ``\mathbf I = \mathbf R \mathbf I_B \mathbf R^T``.

Takes: the claims the checker has made (in the order of the text) and the text's body. Gives the
mixin `RotationProducts` of `derive.lecture.notes_check.Checker`, whose `_rotation_products` pass
(run after every statement has been read) does two things:

* **identities.** A statement left unchecked whose every letter is a rotation matrix, a matrix or
  a vector (no component, no unit vector) holds when it holds for every rotation R(t) and every
  value of the other letters, with the text's own definitions put in (a letter set equal to an
  expression by a statement that first writes it, ``\vec L = I \vec\omega``, ``\mathbf x(t) =
  R(t) \mathbf x(0)``, X(0) a constant): it is evaluated on exact rational rotations (rational
  quaternions, R(0) the identity; where the statement takes a rate, their Taylor polynomials about
  the instant) and on generic rational matrices and vectors, in two draws each at its own instant,
  and holds only when every relation of it does. ``I`` written alone in a statement of rotation
  matrices is the identity (``R R^T = I``), and so is ``I`` alone set equal to products of rotations
  (``I = R R^T``: no new letter); a member written as a lone ``0`` beside matrices is their zero
  (``0 = \dot R R^T + (\dot R R^T)^T``). A statement without a rotation in it is left alone (it
  restates what the text set, or relates letters the reader has not tied); one that does not hold
  for every value is left as it was (its letters may stand for particular matrices), unless its
  only letters are one rotation and ``I``, written on both of its two sides, and the text never sets
  that rotation equal to anything (``A = …``): such a statement claims an identity of every
  rotation (``A^{-1} A A^T A (A^T)^{-1} = A^{-1} I (A^T)^{-1}``, which is A = I), and `fails`.
* **an inertia tensor turned.** ``\mathbf I = \mathbf R \mathbf I_B`` (an inertia tensor set equal to
  a product of rotation matrices and the tensor in other axes) fails when the product is not
  symmetric for a symmetric tensor: the inertia tensor is symmetric in any axes, and the tensor in
  turned axes is Q I Qᵀ. Which way the text's R turns is not read, so Q I Qᵀ itself is left alone.

A rotation letter is a capital R, Q, T, C or A (plain or bold, with its subscript) that the text
writes transposed or inverted somewhere, in a text that speaks of rotations or of orthogonal
matrices; a statement writing a matrix as a function of an angle (``R(\theta)``) is not read.
Capital letters are matrices (those the text writes under ``\vec``, and bold L, H, F, are
vectors), small Latin and Greek letters vectors. ``×`` next to a matrix is the matrix product
(some texts write it so); between a vector and a matrix it acts on each column (``\omega \times T``).

May import: :mod:`derive.lecture.latex_spellings`, :mod:`derive.lecture.latex`, :mod:`derive.lecture.vector_parser`, SymPy.
"""
from __future__ import annotations

import functools
import random
import re
from fractions import Fraction

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import vector_parser as vp
from derive.lecture.latex_spellings import BOLD_MARK

_ROTATION = re.compile(r"(?:" + BOLD_MARK + r"\s*\{?\s*([RQTCA])\s*\}?\s*\}?|(?<![\\A-Za-z])([RQTCA]))"
                       r"\s*(?:_\s*(\{[^{}]*\}|[A-Za-z0-9]))?\s*(?:\(\s*t\s*\)\s*)?"
                       r"\^\s*\{?\s*(?:T|t|\\top|\\intercal|\\math(?:rm|sf)\s*\{\s*T\s*\}|-1)\s*\}?(?![A-Za-z])")
_SPEAKS = re.compile(r"rotation|orthogonal", re.I)
_TRANSPOSE = re.compile(r"\^\s*(?:\{\s*(?:t|\\top|\\intercal|\\math(?:rm|sf)\s*\{\s*T\s*\})\s*\}|(?:t|\\top|\\intercal)(?![A-Za-z]))")
_OF_TIME = re.compile(r"(?<=[}A-Za-z'])\s*\(\s*t\s*\)")
_AT_ZERO = re.compile(r"(?<=[}A-Za-z])\s*\(\s*0\s*\)")
_RATE = re.compile(r"\\d?dot|\\frac\s*\{\s*(?:\\mathrm\s*\{\s*d\s*\}|\{?\s*\\mathrm\s*\{?\s*d|d)|d\s*/\s*dt|\\over\s*dt")
"""A rate in a statement (a dot, d/dt): its letters are read as functions of t, else at an instant."""
_OF_ANGLE = re.compile(r"\(\s*-?\s*\\(?:alpha|beta|gamma|theta|vartheta|phi|varphi|psi|chi|eta|xi)(?![A-Za-z])[^()]*\)")
r"""``R(\theta)``, ``R_z(-\phi)``: a matrix as a function of an angle, which this reader does not read."""
_VEC = re.compile(r"\\vec\s*\{?\s*\\?([A-Za-z]+)")
_CONTINUED = re.compile(r"\s*(?:=|\\approx|\\equiv)")
_UNREAD = (lx.NotRead, sp.ShapeError, TypeError, ValueError, AttributeError, IndexError, KeyError,
           ArithmeticError, NotImplementedError)
"""What reading or comparing a statement raises when its parts do not combine (SymPy's own errors)."""
_KINDS = ("unknown", "identity", "new symbol", "definition")
"""The unchecked claims this pass reads (not settings, assumptions or words)."""
_VECTOR_CAPITALS = frozenset("LHF")
_DRAWS = ((3, sp.Rational(2, 3)), (11, sp.Rational(-5, 7)))
"""Two draws of the letters' values (a seed) and the instant each is read at."""
_ORDER = 4
"""The order of the rotations' Taylor polynomials: above any rate a statement writes (ẍ, d/dt of Ṙ)."""
WHY = ("an identity for every rotation matrix {rot}(t) and every matrix and vector the other letters "
       "name{defs}: exact rational rotations and generic matrices and vectors, two draws")
WHY_NOT = ("not an identity of the rotation {rot}: read with I the identity, its two sides, each in {rot}, differ "
           "at exact rational rotations (and the text sets {rot} equal to no particular matrix)")
WHY_TURNED = ("an inertia tensor is symmetric in any axes, and {right} is not for a rotation {rot}: "
              "the tensor in turned axes is Q I Qᵀ (Q the rotation, Qᵀ on the other side)")


def rotation_letters(body: str) -> frozenset:
    """The rotation matrices of a text.

    Parameters
    ----------
    body : str
        The text (its prose and its math).

    Returns
    -------
    frozenset
        The (letter, subscript, bold) of each capital R, Q, T, C, A the text writes transposed or
        inverted, in a text that speaks of rotations or orthogonal matrices; empty otherwise (a bold
        𝐑 and a plain R are two letters: a text may write its rotation R and a position 𝐑).
    """
    if not _SPEAKS.search(body):
        return frozenset()
    return frozenset((m.group(1) or m.group(2), (m.group(3) or "").strip("{} "), m.group(1) is not None)
                     for m in _ROTATION.finditer(body))


def prepared(latex: str) -> str:
    r"""A statement as this reader reads it.

    Parameters
    ----------
    latex : str
        One statement.

    Returns
    -------
    str
        The statement with ``X(t)`` as X, ``X(0)`` as X₀ and every written transpose (``^t``,
        ``^\top``, ``^{\mathrm{T}}``) as ``^T``.
    """
    return _TRANSPOSE.sub("^T", _AT_ZERO.sub("_{0}", _OF_TIME.sub("", latex)))


@functools.lru_cache(maxsize=None)
def _rotation(name: str, t0, numeric: bool) -> sp.ImmutableMatrix:
    """An exact rotation of t, the identity at t = 0 (a rational quaternion's matrix, its
    coefficients drawn by ``name``): its value at t0 (``numeric``), else its Taylor polynomial about
    t0 to the order `_ORDER`, which gives every rate a statement takes at t0 exactly and multiplies
    as polynomials do. The series is taken on coefficient lists in h = t − t0 (SymPy's derivatives
    of the rational entries cost far more)."""
    rng, order = random.Random(name), 0 if numeric else _ORDER
    c = Fraction(t0.p, t0.q)
    quaternion = [[Fraction(1)]]
    for _ in range(3):
        a, b = Fraction(rng.randint(-9, 9), rng.randint(1, 5)), Fraction(rng.randint(-9, 9), 7)
        quaternion.append([a * c + b * c * c, a + 2 * b * c, b])      # a t + b t² at t = t0 + h
    w, x, y, z = quaternion
    n = _add(_mul(w, w), _mul(x, x), _mul(y, y), _mul(z, z))
    inverse = [1 / n[0]]
    for k in range(1, order + 1):
        inverse.append(-sum(n[j] * inverse[k - j] for j in range(1, min(k, len(n) - 1) + 1)) / n[0])
    rows = [[_add(_mul(w, w), _mul(x, x), _neg(_mul(y, y)), _neg(_mul(z, z))),
             _scaled(2, _add(_mul(x, y), _neg(_mul(w, z)))), _scaled(2, _add(_mul(x, z), _mul(w, y)))],
            [_scaled(2, _add(_mul(x, y), _mul(w, z))), _add(_mul(w, w), _neg(_mul(x, x)), _mul(y, y), _neg(_mul(z, z))),
             _scaled(2, _add(_mul(y, z), _neg(_mul(w, x))))],
            [_scaled(2, _add(_mul(x, z), _neg(_mul(w, y)))), _scaled(2, _add(_mul(y, z), _mul(w, x))),
             _add(_mul(w, w), _neg(_mul(x, x)), _neg(_mul(y, y)), _mul(z, z))]]
    h = lx.t - t0
    return sp.ImmutableMatrix(3, 3, lambda i, j: sum(sp.Rational(f.numerator, f.denominator) * h**k for k, f in
                                                     enumerate(_mul(rows[i][j], inverse)[:order + 1])))


def _mul(a, b):
    out = [Fraction(0)] * (len(a) + len(b) - 1)
    for i, u in enumerate(a):
        for j, v in enumerate(b):
            out[i + j] += u * v
    return out


def _add(*polys):
    out = [Fraction(0)] * max(map(len, polys))
    for p in polys:
        for i, u in enumerate(p):
            out[i] += u
    return out


def _neg(a):
    return [-u for u in a]


def _scaled(k, a):
    return [k * u for u in a]


@functools.lru_cache(maxsize=None)
def _generic(name: str, rows: int, symmetric: bool, constant: bool, t0, numeric: bool) -> sp.ImmutableMatrix:
    """A 3 × 3 matrix (rows = 3) or a column (rows = 1) of t with large random entries drawn by
    ``name``, at t0 when ``numeric``."""
    rng = random.Random(name)
    t = sp.S.Zero if constant else (t0 if numeric else lx.t)
    m = sp.Matrix(3, 3 if rows == 3 else 1, lambda i, j: rng.randint(-10**6, 10**6) + rng.randint(-10**6, 10**6) * t)
    return sp.ImmutableMatrix((m + m.T) if symmetric else m)


class _Model:
    """The grammar's model (`derive.lecture.vector_parser`): each letter's value at one seed."""

    vocabulary = False
    free = ""
    matrix_products = True
    rates = True
    frames: dict = {}

    def __init__(self, rotations, vectors, defs, inertia, draw, numeric=False, identity=False):
        self.rotations, self.vectors, self.defs, self.inertia = rotations, vectors, defs, inertia
        (self.seed, self.t0), self.numeric, self.identity = draw, numeric, identity
        self.used: set = set()
        self.turns: set = set()         # the (letter, subscript, primes) read as rotations

    def rate(self, X, frame):
        """d/dt, in the letters as functions of t only (at an instant there is no rate to take)."""
        if self.numeric or frame == "body" or not isinstance(X, (sp.MatrixBase, sp.Expr)):
            return None
        return X.diff(lx.t)

    def points(self):
        return []

    def summed(self, p, names, upper, env, tok):
        p.fail("a sum", tok)

    def atom(self, p, a, env, tok):
        if a.hat or a.tilde or a.sup or a.dots > 2 or a.base in ("d", "t", "partial") or a.dots and self.numeric:
            return None
        key = (a.base, a.sub, a.primes)
        value = self.value(key, a)
        if value is None:
            return None
        self.used.add(key)
        for _ in range(a.dots):
            value = value.diff(lx.t)
        return value

    def value(self, key, a):
        base, sub, primes = key
        if (base, sub, a.bold) in self.rotations and not primes:
            self.turns.add(key)
            return _rotation(f"{self.seed}R{base}{sub}", self.t0, self.numeric)
        if key in self.defs:
            value = self.defs[key][self.seed]
            return value.subs(lx.t, self.t0) if self.numeric else value
        if base == "I" and not sub and not primes and self.identity:
            return sp.eye(3)
        name, constant = f"{self.seed}{base}{sub}{primes}", sub == "0"    # X(0), X₀: at t = 0
        if len(base) == 1 and base.isupper():
            vector = base in self.vectors or a.bold and base in _VECTOR_CAPITALS
            return _generic(name, 1 if vector else 3, not vector and base in "IJ" and self.inertia, constant, self.t0, self.numeric)
        if base[0].isupper():
            return _generic(name, 3, False, constant, self.t0, self.numeric)             # Ω, Λ: a matrix
        if len(base) == 1 or base in lx.GREEK:
            return _generic(name, 1, False, constant, self.t0, self.numeric)
        return None


class _Parser(vp.VectorParser):
    """The vector grammar with × next to a matrix read as the product (on each column, for a
    vector on the left of a matrix)."""

    def xterm(self, env):
        value = self.factor(env)
        while self.at("cmd", "times"):
            self.i += 1
            right = self.factor(env)
            while (not isinstance(right, sp.MatrixBase) or vp._is_tensor(right)) and self._starts_factor():
                right = self.juxtaposed(right, self.factor(env))
            if vp._is_vector(value) and vp._is_vector(right):
                value = value.cross(right)
            elif vp._is_vector(value) and vp._is_tensor(right):
                value = sp.Matrix.hstack(*(value.cross(right[:, j]) for j in range(3)))
            elif vp._is_tensor(value) and isinstance(right, sp.MatrixBase):
                value = value * right
            else:
                self.fail("× of a scalar")
        return value


def _members(text, model):
    """The values of a statement's members and its relations, or None when it is not read."""
    try:
        toks = lx.scan_cells(text)
        p = _Parser(list(toks), lx.Vocabulary(), text, model)
        members, rels = p.members({})
    except _UNREAD:
        return None
    values = [m.value for m in members]
    shapes = [v.shape for v in values if isinstance(v, sp.MatrixBase)]
    if len(set(shapes)) == 1:
        # a member written as a lone 0 beside matrices is their zero (texts write = 0 for a zero matrix)
        values = [sp.zeros(*shapes[0]) if text[m.start:m.end].strip() == "0" and v == 0 and
                  not isinstance(v, sp.MatrixBase) else v for m, v in zip(members, values)]
    return values, rels, members


def _read_all(text, models):
    """The statement read under each model, or None as soon as one draw does not read it (the
    readings after it would be discarded: most statements fail on the first draw as on all)."""
    read = []
    for m in models:
        r = _members(text, m)
        if r is None:
            return None
        read.append(r)
    return read


def _equal(a, b, t0) -> bool:
    """Whether two values are equal at t0 (each entry an exact rational there)."""
    if isinstance(a, sp.MatrixBase) != isinstance(b, sp.MatrixBase):
        return False
    if isinstance(a, sp.MatrixBase) and a.shape != b.shape:
        return False
    d = a - b if isinstance(a, sp.MatrixBase) else sp.Matrix([sp.sympify(a - b)])
    return all(sp.expand(e) == 0 for e in d.subs(lx.t, t0))


class RotationProducts:
    """Mixin of the checker. Uses ``self.claims``, ``self.notes`` and ``self._inline_claims``."""

    def _rotation_products(self):
        """Read the unchecked statements of a text with rotation matrices (see the module docstring)."""
        body = self.notes.body or ""
        rotations = rotation_letters(body)
        if not rotations:
            return
        vectors = frozenset(v for v in _VEC.findall(body) if len(v) == 1 and v.isupper())
        inertia = "inertia" in body.lower()
        defs, seen, named = {}, set(), []
        bases = {(b, u) for b, u, _ in rotations}
        for claim in self.claims:
            if id(claim) in self._inline_claims or _CONTINUED.match(claim.latex):
                continue
            text = prepared(claim.latex)
            if _OF_ANGLE.search(text):
                seen |= _letters(text)
                continue
            written = _letters(text)
            # a definition the reader judged (L = I omega in the model's own terms) is the text's too
            judged_definition = claim.verdict == "holds" and claim.kind == "definition"
            open_claim = claim.verdict == "unchecked" or judged_definition
            if not {(b, u) for b, u, _ in written} & bases and (not open_claim or claim.kind not in _KINDS):
                seen |= written             # no rotation in it and no definition: nothing to read (cheap test first)
                continue
            letters = (rotations, vectors, defs, inertia)
            rated = _RATE.search(text) is not None
            models = [_Model(*letters, draw, not rated) for draw in _DRAWS]
            read = _read_all(text, models)
            if read is None:
                seen |= _letters(text)
                continue
            used, turns = models[0].used, models[0].turns
            values, rels, members = read[0]
            first = members[0].atom
            key = None if first is None else (first.base, first.sub, first.primes)
            turned = _turned(members, values, turns, used, inertia, claim.latex)
            if key == ("I", "", 0) and turns and used - {key} <= turns and claim.verdict == "unchecked" \
                    and claim.kind in _KINDS and set(rels) <= {"=", "≡"}:
                # I set equal to products of rotations alone (I = R R^T) is the identity, not a new letter
                self._identity(claim, text, read, (letters, rated), used, turns, named)
                if claim.verdict == "holds":
                    seen |= used
                    continue
            if turned is not None and claim.verdict == "unchecked":
                claim.kind, claim.verdict, claim.why = "identity", "fails", turned
            elif open_claim and claim.kind in _KINDS and len(values) == 2 and rels[0] in ("=", "≡") \
                    and key is not None and key not in seen and not first.dots and key not in turns:
                if not rated:       # a definition is kept as a function of t (a later statement may take its rate)
                    read = [_members(text, _Model(*letters, draw)) for draw in _DRAWS]
                defs[key] = {s: r[0][1] for (s, _), r in zip(_DRAWS, read)}     # the text's own definition
                named.append(first.text)
            elif claim.verdict == "unchecked" and claim.kind in _KINDS and set(rels) <= {"=", "≡"} and turns:
                self._identity(claim, text, read, (letters, rated), used, turns, named)
            seen |= used

    def _identity(self, claim, text, read, how, used, turns, named):
        letters, rated = how
        holds = _holds(read)
        if not holds and ("I", "", 0) in used and used - {("I", "", 0)} <= turns:
            read = [_members(text, _Model(*letters, draw, not rated, identity=True)) for draw in _DRAWS]
            holds = all(r is not None for r in read) and _holds(read)
        if holds:
            put = [n for n, k in zip(named, letters[2]) if k in used]
            claim.kind, claim.verdict = "identity", "holds"
            claim.why = WHY.format(rot=_names(turns), defs=f", with the text's {', '.join(put)} put in" if put else "")
        elif _of_the_rotation_alone(text, read, used, turns, self.claims):
            claim.kind, claim.verdict, claim.why = "identity", "fails", WHY_NOT.format(rot=_names(turns))


def _of_the_rotation_alone(text, read, used, turns, claims) -> bool:
    """Whether a statement read with ``I`` the identity, in one rotation and ``I`` alone, relates two
    sides that each write the rotation, of a rotation the text never sets equal to anything: it then
    claims an identity of every rotation, which its sides, unequal at a rational rotation, are not."""
    sides = text.split("=")
    if len(turns) != 1 or len(sides) != 2 or used - {("I", "", 0)} != turns or any(r is None or len(r[0]) != 2 for r in read):
        return False
    (base, sub, _), = turns
    a, b = read[0][0]
    if not all(next(iter(turns)) in _letters(side) for side in sides) or isinstance(a, sp.MatrixBase) != \
            isinstance(b, sp.MatrixBase) or isinstance(a, sp.MatrixBase) and a.shape != b.shape:
        return False
    head = re.compile(r"\s*(?:" + BOLD_MARK + r"\s*\{\s*)?" + base + r"\s*\}?\s*"
                      + (r"_\s*\{?\s*" + re.escape(sub) + r"\s*\}?\s*" if sub else "") + r"(?:\(\s*t\s*\)\s*)?(?:=|\\equiv)")
    return not any(head.match(c.latex) for c in claims)


def _letters(text) -> set:
    """The (letter, subscript, primes) of every symbol a statement writes."""
    try:
        return {(t.value.base, t.value.sub, t.value.primes) for t in lx.scan_cells(text)
                if t.kind == "atom" and not t.value.hat}
    except lx.NotRead:
        return set()


def _holds(read) -> bool:
    try:
        return all(all(_equal(vals[k], vals[k + 1], t0) for k in range(len(vals) - 1))
                   for (vals, _, _), (_, t0) in zip(read, _DRAWS))
    except _UNREAD:
        return False


def _names(turns) -> str:
    return ", ".join(sorted({b + (f"_{s}" if s else "") for b, s, _ in turns}))


def _turned(members, values, turns, used, inertia, latex):
    """Why ``I_A = (rotations and I_B)`` fails (its right side not symmetric), or None."""
    if not inertia or len(values) != 2 or members[0].atom is None:
        return None
    left = members[0].atom
    tensors = {k for k in used if k[0] in ("I", "J") and k not in turns}
    if left.base not in ("I", "J") or len(tensors) != 2 or left.dots or \
            not (used - tensors) or not used - tensors <= turns:
        return None
    right = values[1]
    try:
        if not vp._is_tensor(right) or _equal(right, right.T, _DRAWS[0][1]):
            return None
    except _UNREAD:
        return None
    rot = _names(turns)
    return WHY_TURNED.format(right=latex[latex.index("=") + 1:].strip(), rot=rot)
