"""The one grammar of vector notation: a statement's tokens (those of `derive.lecture.latex.scan`)
to SymPy scalars, 3-vectors (3×1 matrices) and 3×3 tensors under a model that gives the symbols
their values.

Both vector readers parse with it: the lecture's own notation (`derive.lecture.vectors`, its
models in `derive.lecture.vector_models`) and textbook vector algebra derived from first
principles (`derive.lecture.vector_algebra_model`). The grammar is the same for both:

* ``a \\times b`` binds tightest (a·b×c = a·(b×c)); ``r \\times m v`` takes the scalar with the vector, and a
  tensor before the vector on its left acts on it first (``I \\omega \\times \\omega`` = (I𝛚) × 𝛚);
* ``a \\cdot b`` — the dot product, a tensor on a vector (Ï·ω = Ïω, ω·Ï = Ïᵀω);
* juxtaposition — a scalar factor, the dyadic 𝐚𝐛ᵀ of two vectors, and (where the model's
  notation writes matrices, ``matrix_products``) the product of conforming matrices;
* ``^T`` a transpose, ``v^2`` = v·v, ``|v|`` = √(v·v), matrices, determinants (``vmatrix``,
  ``|array|``, expanded along a row of unit vectors; ``\\det`` before a 3×3 matrix's letter or bracket);
* sums ``\\sum_i`` (the model says over what), integrals ``∫ … dm`` over the body's mass, and
  time derivatives ``\\frac{d}{dt} X``, ``\\frac{dX}{dt}``, ``(\\frac{dX}{dt})_{body}``.

A model gives: ``atom(parser, atom, env, tok)`` (the value of a symbol, or None), ``summed``
(the environments a sum runs over), ``points`` (an integral's mass points), ``rate(value,
frame)`` (a time derivative; None: not one it reads, the fraction is a quotient), ``frames``
(the frame names a derivative may carry), ``free`` (the letters that may be free indices),
``matrix_products``, ``rates`` (whether the grammar reads time derivatives) and ``vocabulary``
(whether an unknown symbol falls back to the scalar reader's vocabulary).
"""
from __future__ import annotations

import itertools
import re
from dataclasses import dataclass, replace

import sympy as sp

from derive.lecture import gradients
from derive.lecture import latex as lx
from derive.lecture.latex_parser import _Parser, braced_tokens

AXES = {"x": 0, "y": 1, "z": 2, "1": 0, "2": 1, "3": 2}
INTEGRAL = "Lambda"                  # the marker ∫ is read as (a bold Λ, which no text here writes)


class _Law:
    """τ as a whole side: the law of motion d𝐋/dt = τ."""


LAW = _Law()
UNREAD = sp.Symbol("unread_entry")
"""A matrix entry with a symbol no model knows, read in a partial reading (`read`'s ``partial``)."""


class _FreeIndex(Exception):
    def __init__(self, letter):
        super().__init__(letter)
        self.letter = letter


def _is_tensor(v) -> bool:
    return isinstance(v, sp.MatrixBase) and v.shape == (3, 3)


def _is_vector(v) -> bool:
    return isinstance(v, sp.MatrixBase) and v.shape == (3, 1)


@dataclass
class Member:
    value: object
    start: int                                      # source span of the member
    end: int
    atom: object = None                             # the member's Atom when it is a single symbol
    skip: str = ""                                  # why it is not compared (a force inside a product)
    generics: frozenset = frozenset()
    literal: object = None                          # the matrix as written, when the member is one
    law: bool = False                               # a torque or a force in it
    rated: bool = False                             # a time derivative in it (d/dt, a dot, 𝛂)


@dataclass
class Reading:
    members: list       # one list of Member per value of the free indices
    relations: list
    free: str           # the free indices ("", "i", "ij")
    source: str
    model: str          # the model's name
    unread: tuple = ()  # why each matrix entry set aside as `UNREAD` was not read (a partial reading)


def read(toks, source, vocab, model, name: str, partial: bool = False) -> Reading:
    """Parse a statement under a model, once per value (1, 2, 3) of each free index it turns out
    to have (`lx.NotRead` when it cannot); with ``partial``, a matrix entry holding a symbol the
    model does not know is `UNREAD` instead, and ``unread`` says why."""
    free = ""
    while True:
        try:
            readings, unread = [], []
            for values in itertools.product((1, 2, 3), repeat=len(free)):
                p = VectorParser(list(toks), vocab, source, model)
                p.partial = partial
                readings.append(p.members(dict(zip(free, values))))
                unread += p.unread
            break
        except _FreeIndex as err:
            if err.letter in free or len(free) >= 2:
                raise lx.NotRead(f"the index {err.letter} is neither summed nor free") from None
            free += err.letter
        except (sp.ShapeError, TypeError, ValueError, AttributeError, IndexError) as err:
            raise lx.NotRead(f"cannot combine its parts ({type(err).__name__})") from None
    reading = Reading([r[0] for r in readings], readings[0][1], free, source, name, tuple(dict.fromkeys(unread)))
    return _summation_convention(reading)


_SUBSCRIPT = re.compile(r"_\s*(?:\{([^{}\\]*)\}|([A-Za-z0-9]))")


def _written(letter: str, src: str) -> int:
    """How many times ``letter`` stands as an index in the subscripts of ``src`` (a sum's range,
    ``k=1``, is not one)."""
    subs = (m.group(1) if m.group(1) is not None else m.group(2) for m in _SUBSCRIPT.finditer(src))
    return sum(sub.split("=")[0].replace(" ", "").replace(",", "").count(letter) for sub in subs)


def _summation_convention(reading: Reading) -> Reading:
    """The summation convention: a free index the first member does not write, written twice in
    each other member that writes it (``\\omega^2 = \\omega_j\\omega_j``), is summed over 1, 2, 3 in
    those members, not a free index the statement holds for at each value."""
    first = reading.members[0]
    spans = [reading.source[m.start:m.end] for m in first]
    dummy = [f for f in reading.free if _written(f, spans[0]) == 0
             and {_written(f, s) for s in spans[1:]} <= {0, 2} and any(_written(f, s) == 2 for s in spans[1:])]
    if not dummy:
        return reading
    kept = "".join(f for f in reading.free if f not in dummy)
    combos = list(itertools.product((1, 2, 3), repeat=len(reading.free)))
    at = {values: members for values, members in zip(combos, reading.members)}
    out = []
    for values in itertools.product((1, 2, 3), repeat=len(kept)):
        env = dict(zip(kept, values))
        rows = [at[tuple(env[f] if f in env else d[dummy.index(f)] for f in reading.free)]
                for d in itertools.product((1, 2, 3), repeat=len(dummy))]
        members = []
        for k, m in enumerate(rows[0]):
            if any(_written(f, spans[k]) for f in dummy):
                m = replace(m, value=sum((row[k].value for row in rows[1:]), rows[0][k].value))
            members.append(m)
        out.append(members)
    return replace(reading, members=out, free=kept)


class VectorParser(_Parser):
    """`derive.lecture.latex_parser._Parser` with vector values (see the module docstring)."""

    components_in_rates = False     # d𝛚₁/dt is read as 𝛚₁ is here, as \dot{\boldsymbol\omega}_1 would be

    def __init__(self, toks, vocab, source, model):
        super().__init__(toks, vocab, source)
        self.model = model
        self.generics: set = set()
        self.force_at: list = []                    # token indices of 𝐅
        self.law = self.rated = False
        self.stop_dm = False
        self.bars = 0                   # how many |…| groups the parser is inside: there a bar closes
        self.partial, self.unread = False, []

    # a chain of members
    def members(self, env):
        out, rels = [], []
        while True:
            if self.peek() is None or self.at("rel"):
                self.fail("a side of a relation is empty")
            start, first = self.peek().pos, self.i
            before = self.source[:start].rstrip()
            if before.endswith("\\left"):          # the member's span takes its \left along
                start = len(before) - len("\\left")
            self.generics, self.force_at, self.law, self.rated = set(), [], False, False
            value = _as_value(self.expr(env))
            end = self.peek().pos if self.peek() else len(self.source)
            atom = self.toks[first].value if self.i == first + 1 and self.toks[first].kind == "atom" else None
            literal = value if self.toks[first].kind == "begin" and self.i > first else None
            skip = "a force inside a product (only its law is known)" if self.force_at and self.i - first > 1 else ""
            out.append(Member(value, start, end, atom, skip, frozenset(self.generics), literal, self.law, self.rated))
            if not self.at("rel"):
                break
            rels.append(self.take("rel").value)
        if self.peek() is not None:
            self.fail(f"unexpected {self.peek().value!r}")
        return out, rels

    def _starts_factor(self):
        if self.stop_dm and self.at("atom") and self.peek().value.base == "d" and not self.peek().value.sub:
            nxt = self.peek(1)
            if nxt is not None and nxt.kind == "atom" and nxt.value.base == "m" and not nxt.value.sub:
                return False
        if self.at("cmd", "det"):
            return True                 # \det(A)\det(A^T): a determinant is a factor of a product
        if self.at("op", "|") and not self.bars and not (nxt := self.peek(1)) is None \
                and not (nxt.kind == "op" and nxt.value in "_^"):
            return True                 # m|\vec v|^2: a length between bars is a factor (never a bar closing one)
        return super()._starts_factor()

    # sums and products: × binds tighter than · and juxtaposition
    def signed(self, sign, value):
        return value if sign == 1 else -_not_law(value)

    def summands(self, a, b):
        """Two terms to add: of one kind (a scalar and a vector or tensor only when one is 0)."""
        a, b = _not_law(a), _not_law(b)
        if isinstance(a, sp.MatrixBase) != isinstance(b, sp.MatrixBase):
            if not (a == 0 or b == 0):
                self.fail("a scalar added to a vector or tensor")
            # 0 + 𝐫 × 𝐅: the zero written as a number is the zero of the other term's shape
            a, b = (sp.zeros(*b.shape), b) if not isinstance(a, sp.MatrixBase) else (a, sp.zeros(*a.shape))
        return a, b

    def operand(self, env):
        return self.xterm(env)

    def dotted(self, a, b):
        return _dot(a, b, self.model.matrix_products)

    def juxtaposed(self, a, b):
        return _juxt(a, b, self.model.matrix_products)

    def xterm(self, env):
        value = self.factor(env)
        if _is_tensor(value) and self._starts_factor():
            at = self.i
            right = self.factor(env)
            if _is_vector(right) and self.at("cmd", "times"):
                value = self.juxtaposed(value, right)       # I 𝛚 × 𝛚: the tensor on 𝛚, then crossed
            else:
                self.i = at
        while self.at("cmd", "times"):
            self.i += 1
            right = self.factor(env)
            while (not isinstance(right, sp.MatrixBase) or _is_tensor(right)) and self._starts_factor():
                right = self.juxtaposed(right, self.factor(env))     # r × m v, 𝛚 × I 𝛚 (the tensor on 𝛚)
            if not (_is_vector(value) and _is_vector(right)):
                self.fail("× of something that is not a vector")
            value = value.cross(right)
        return value

    def transposed(self, base):
        if not isinstance(base, sp.MatrixBase):
            self.fail("a transpose of a scalar")
        return base.T

    def power(self, base, exp):
        """v² = v·v; no other power of a vector or a matrix."""
        if _is_vector(base) and exp == 2:
            return base.dot(base)
        if _is_tensor(base) and exp == -1:
            return base.inv()                           # I_b^{-1}: the inverse tensor
        if isinstance(base, sp.MatrixBase):
            self.fail("a power of a vector or matrix")
        return base ** exp

    def primary(self, env):
        tok = self.peek()
        if tok is not None and tok.kind == "op" and tok.value in ("(", "[") and self.model.rates:
            framed = self._framed_rate(env)
            if framed is not None:
                return framed
        if tok is not None and tok.kind == "op" and tok.value == "(" and self._component_follows():
            value = _as_value(self.paren(env))
            axis = self._component_index()
            if not _is_vector(value):
                self.fail("a component of something that is not a vector")
            return value[axis]               # (𝐀 × 𝐁)_x: a component of the bracketed vector
        if tok is not None and tok.kind == "op" and tok.value == "|":
            self.i += 1
            if self.at("begin"):
                value = self.matrix(env, det=True)
            else:
                self.bars += 1
                inner = _as_value(self.expr(env))
                self.bars -= 1
                value = sp.sqrt(inner.dot(inner)) if _is_vector(inner) else sp.Abs(inner)
            self.take("op", "|")
            return value
        if tok is not None and tok.kind == "begin":
            return self.matrix(env, det=tok.value == "vmatrix")
        if tok is not None and tok.kind == "cmd" and tok.value == "det" and self.i + 1 < len(self.toks) \
                and self.toks[self.i + 1].kind == "begin":
            self.i += 1
            return self.matrix(env, det=True)       # \det written before a bracketed matrix
        if tok is not None and tok.kind == "cmd" and tok.value == "det":
            self.i += 1
            value = _as_value(self.factor(env))     # \det A, \det(R - I): the determinant of the matrix that follows
            if not _is_tensor(value):
                self.fail("a determinant of what is not a 3×3 matrix", tok)
            return value.det()
        if tok is not None and tok.kind == "atom" and tok.value.base == INTEGRAL and tok.value.bold:
            self.i += 1
            return self.integral(env)
        if tok is not None and tok.kind == "cmd" and tok.value == "sum":
            self.i += 1
            return self.vsum(env, tok)
        if tok is not None and tok.kind == "cmd" and tok.value in ("frac", "dfrac", "tfrac"):
            gradient = self._gradient(env)
            if gradient is not None:
                return gradient
        if tok is not None and tok.kind == "cmd" and tok.value in ("frac", "dfrac", "tfrac") and self.model.rates:
            start = self.i
            X = self._rate(env)
            value = None if X is None else self.model.rate(X, "inertial")
            if value is not None:
                return value
            self.i = start                              # not a derivative the model reads: a quotient
        return super().primary(env)

    def _component_follows(self) -> bool:
        """Whether the bracket opening here closes with an axis subscript, ``( … )_x``, ``( … )_{2}``."""
        depth = 0
        for k in range(self.i, len(self.toks)):
            t = self.toks[k]
            if t.kind == "op" and t.value in "([{":
                depth += 1
            elif t.kind == "op" and t.value in ")]}":
                depth -= 1
                if depth == 0:
                    save, self.i = self.i, k + 1
                    try:
                        return self._component_index(peek=True) is not None
                    finally:
                        self.i = save
        return False

    def _component_index(self, peek: bool = False) -> int | None:
        """The axis of a subscript ``_x`` or ``_{x}`` at this position (consumed unless ``peek``)."""
        toks, k = self.toks, self.i
        if not (k < len(toks) and toks[k].kind == "op" and toks[k].value == "_"):
            return None
        braced = k + 3 < len(toks) and toks[k + 1].kind == "op" and toks[k + 1].value == "{" \
            and toks[k + 3].kind == "op" and toks[k + 3].value == "}"
        t = toks[k + 2] if braced else (toks[k + 1] if k + 1 < len(toks) else None)
        if t is None or t.kind not in ("atom", "num"):
            return None
        name = t.value if t.kind == "num" else (t.value.base if not (t.value.sub or t.value.bold or t.value.sup
                                                                      or t.value.hat or t.value.dots) else "")
        if name not in AXES:
            return None
        if not peek:
            self.i = k + (4 if braced else 2)
        return AXES[name]

    # time derivatives
    def _gradient(self, env):
        """At \\frac: ``dT/d𝛚``, ``∂T/∂𝛚``, the gradient of a scalar by a vector of the model
        (`derive.lecture.gradients.of_vector`), or None."""
        num, j = braced_tokens(self.toks, self.i + 1)
        den, k = braced_tokens(self.toks, j) if num is not None else (None, j)
        if den is None or not gradients.written(num, den):
            return None
        try:
            value = gradients.of_vector(_as_value(self.atom(num[1], env)), _as_value(self.atom(den[1], env)))
        except (lx.NotRead, TypeError, ValueError):
            return None
        if value is not None:
            self.i = k
        return value

    def _rate(self, env):
        """At \\frac: \\frac{d}{dt} X (X the following product) or \\frac{d X}{dt}: X, or None."""
        t, i = self.toks, self.i + 1
        num, j = braced_tokens(t, i)
        if num is None:
            return None
        den = t[j:j + 4]
        if not (len(den) == 4 and den[0].kind == "op" and den[0].value == "{" and den[1].kind == "atom"
                and den[1].value.base == "d" and not den[1].value.sub and den[2].kind == "atom"
                and den[2].value.base == "t" and not den[2].value.sub and den[3].kind == "op" and den[3].value == "}"):
            return None
        if not num or num[0].kind != "atom" or num[0].value.base != "d" or num[0].value.sub or num[0].value.bold:
            return None
        self.rated = True
        if len(num) == 1:
            self.i = j + 4
            return self.term(env)
        self.i = i + 2                                  # past the d: the numerator is what is differentiated
        value = self.expr(env)
        self.take("op", "}")
        self.i += 4
        return value

    def _framed_rate(self, env):
        """(d𝐗/dt)_{body|inertial|space…} at '(' or '[' (no subscript: inertial), or None."""
        start = self.i
        close = ")" if self.peek().value == "(" else "]"
        # ({d𝐆 \over dt})_{space}: plain TeX's fraction keeps its group inside the bracket
        grouped = self.peek(1) is not None and self.peek(1).kind == "op" and self.peek(1).value == "{"
        nxt = self.peek(2 if grouped else 1)
        if not (nxt is not None and nxt.kind == "cmd" and nxt.value in ("frac", "dfrac", "tfrac")):
            return None
        self.i += 2 if grouped else 1
        X = self._rate(env)
        if X is not None and grouped:
            X = X if self.at("op", "}") else None
            self.i += 1
        if X is None or not self.at("op", close):
            self.i = start
            return None
        self.i += 1
        frame = "inertial"
        if self.at("op", "_"):
            self.i += 1
            word = []
            if self.at("op", "{"):
                self.i += 1
                while self.at("atom"):
                    word.append(self.take("atom").value.base)
                self.take("op", "}")
            else:
                word.append(self.take("atom").value.base)
            name = "".join(word)
            if name not in self.model.frames:
                self.fail(f"a derivative in the frame {name!r}")
            frame = self.model.frames[name]
        value = self.model.rate(X, frame)
        if value is None:
            self.i = start
        return value

    # matrices and determinants
    def matrix(self, env, det=False):
        tok = self.take("begin")
        if tok.value == "array" and self.at("op", "{"):
            while not self.at("op", "}"):
                self.i += 1
            self.i += 1
        rows = self.rows(env, tok)
        if det:
            return _determinant(rows)
        if any(isinstance(x, sp.MatrixBase) for r in rows for x in r):
            self.fail("a matrix of vectors")
        return sp.Matrix(rows)

    def entry(self, env):
        """A matrix entry: one value (a 1×1 product a scalar), never a matrix of any size."""
        if self.at("cmd") and self.peek().value in ("cdots", "ldots", "dots"):
            self.fail("a matrix of any size")
        start = self.i
        try:
            return _as_value(self.expr(env))
        except lx.Unknown as err:
            if not self.partial:
                raise
            self.i, depth = start, 0        # the entry set aside: on to its '&', '\\' or the matrix's end
            while self.peek() is not None and (depth or not (self.at("op", "&") or self.at("op", "\\")
                                                             or self.at("end"))):
                tok = self.take(self.peek().kind)
                depth += (tok.kind == "begin" or tok.value in ("{", "(", "[")) - \
                    (tok.kind == "end" or tok.value in ("}", ")", "]"))
            self.unread.append(err.why)
            return UNREAD

    # sums and integrals
    def vsum(self, env, tok):
        """Σ under a subscript index (and an upper limit): the summand (one product) read once for
        each environment the model's ``summed`` gives."""
        names, _ = self.sum_index(tok)
        upper = []
        if self.at("op", "^"):
            self.i += 1
            upper, after = braced_tokens(self.toks, self.i)
            if upper is None:
                upper, after = [self.peek()], self.i + 1
            self.i = after
        start, total = self.i, None
        for inner in self.model.summed(self, names, upper, env, tok):
            self.i = start
            term = self.term(inner)
            total = term if total is None else total + term
        return total

    def integral(self, env):
        """∫ … dm over the body: Σ_k μ_k (…) at the model's mass points."""
        start, total, stop = self.i, None, self.stop_dm
        points = self.model.points()
        if not points:
            self.fail("an integral over the mass")
        for where, mass in points:
            self.i = start
            self.stop_dm = True
            term = self.term({**env, **where})
            while self.at("op", "+") or self.at("op", "-"):     # ∫ a − b dm: the integrand runs to its dm
                minus = self.take("op").value == "-"
                rest = self.term({**env, **where})
                term, rest = self.summands(term, rest)
                term = term - rest if minus else term + rest
            self.stop_dm = stop
            if not (self.at("atom") and self.peek().value.base == "d"):
                self.fail("an integral without its dm")
            self.i += 2
            term = self.juxtaposed(mass, term)
            total = term if total is None else total + term
        return total

    # atoms
    def atom(self, tok, env):
        if tok.value.mark:          # x̄: the text's own symbol, which no vector model knows
            raise lx.Unknown(f"unknown symbol {tok.value.text}", tok.pos + 1)
        value = self.model.atom(self, tok.value, env, tok)
        if value is not None:
            return value
        if not self.model.vocabulary:
            raise lx.Unknown(f"unknown symbol {tok.value.text}", tok.pos + 1)
        try:
            return super().atom(tok, env)
        except lx.Unknown:
            a = tok.value           # a text's scalar letter beside its vectors in a frame (m of m dV/dt): a constant
            if getattr(self.model, "rates", False) and len(a.base) == 1 and a.base.islower() and \
                    not (a.bold or a.sub or a.sup or a.dots or a.hat or a.primes or a.tilde):
                return sp.Symbol(f"{a.base}_const", positive=True)
            raise

    def axis(self, ch, env, tok) -> int:
        """The body axis (0, 1, 2) an index names: x, y, z, 1, 2, 3 or a summed or free index."""
        if ch in AXES:
            return AXES[ch]
        if ch in env and isinstance(env[ch], int) and ch != "p":
            return env[ch] - 1
        if ch in self.model.free:
            raise _FreeIndex(ch)
        self.fail(f"the index {ch!r}", tok)


def _not_law(v):
    if v is LAW:
        raise lx.NotRead("the torque inside a formula")
    return v


def _as_value(v):
    if isinstance(v, sp.MatrixBase) and v.shape == (1, 1):
        return v[0, 0]
    return v


def _juxt(a, b, matrix_products=True):
    """a b: a scalar factor, the dyadic 𝐚𝐛ᵀ of two vectors, the product of conforming matrices
    (refused where the notation writes a tensor on a vector with ·)."""
    a, b = _as_value(_not_law(a)), _as_value(_not_law(b))
    if isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase):
        if _is_vector(a) and _is_vector(b):
            return a * b.T                          # the dyadic 𝐚𝐛
        if not matrix_products:
            raise lx.NotRead("a product of a tensor and a vector without ·")
        if a.shape[1] != b.shape[0]:
            raise lx.NotRead("a product of shapes that do not conform")
        return _as_value(a * b)
    return a * b


def _dot(a, b, matrix_products=True):
    """a·b: the dot product of vectors, a tensor on a vector (𝐯·𝐓 = 𝐓ᵀ𝐯), else a product."""
    a, b = _as_value(_not_law(a)), _as_value(_not_law(b))
    if _is_vector(a) and _is_vector(b):
        return a.dot(b)
    if _is_tensor(a) and (_is_vector(b) or _is_tensor(b)):
        return a * b
    if _is_vector(a) and _is_tensor(b):
        return b.T * a
    if isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase) and not matrix_products:
        raise lx.NotRead("· of these shapes")
    return _juxt(a, b, matrix_products)


def _determinant(rows):
    """A 3×3 determinant, expanded along a row of vectors when it has one (the cross product's form)."""
    if len(rows) != 3 or any(len(r) != 3 for r in rows):
        raise lx.NotRead("a determinant that is not 3×3")
    vec = [n for n, r in enumerate(rows) if any(isinstance(x, sp.MatrixBase) for x in r)]
    if not vec:
        return sp.Matrix(rows).det()
    if len(vec) != 1:
        raise lx.NotRead("a determinant with vectors in two rows")
    n = vec[0]
    total = sp.zeros(3, 1)
    for j in range(3):
        minor = sp.Matrix([[rows[a][b] for b in range(3) if b != j] for a in range(3) if a != n])
        if any(isinstance(x, sp.MatrixBase) for x in minor):
            raise lx.NotRead("a determinant of vectors")
        total += (-1) ** (n + j) * minor.det() * rows[n][j]
    return total
