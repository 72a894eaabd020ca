"""Vector algebra as textbooks write it: components, matrices, sums over particles and integrals over the mass.

`derive.lecture.vectors` reads the lecture's own vector notation (m_p, 𝐫_p, Σ_p, Ï, ê_i). Texts
that derive the inertia tensor write the same physics another way: a point mass m at 𝐫 = x x̂ + y ŷ
+ z ẑ, 𝐋 = 𝐫 × 𝐩 with 𝐯 = 𝛚 × 𝐫, ω_x ω_y ω_z, a ``bmatrix`` acting on a column, a determinant with
unit vectors in its first row, Σᵢ mᵢ over particles, ∫ … dm over the body, I_xx = ∫(y² + z²) dm,
𝐓 = d𝐋/dt. This module reads such a statement into SymPy (scalars, 3-vectors as 3×1 matrices,
tensors as 3×3 matrices) through the scanner's whitelist, under one model derived from first
principles (its symbols and derived quantities in `derive.lecture.vector_algebra_model`):

* **the system.** A statement with a sum over particles or an integral over the mass speaks of a
  body: three generic mass points μ_k at 𝐫_k = (x_k, y_k, z_k) (Σᵢ and ∫ dm are both linear in
  the summand, so an identity for generic points is the identity, and three points keep a formula
  that is not linear in the sum from passing). Inside the sum or integral x, y, z, 𝐫 and r are
  the current point's (xᵢ, 𝐫ᵢ, mᵢ with the sum's index too). A statement with a plain m and no
  sum speaks of one point mass m at 𝐫 = (x, y, z) (𝐫ᵢ, mᵢ outside a sum: "the particle in
  question"). Otherwise the system of the previous statement.
* **rigid rotation.** Every point moves with 𝐯 = 𝛚 × 𝐫; 𝐩 = m𝐯; 𝐋 = Σ m 𝐫 × (𝛚 × 𝐫); the
  inertia tensor is 𝐈 = ∂𝐋/∂𝛚 (so 𝐋 = 𝐈𝛚 however a text writes 𝐈); I_xx, I_xy, I_ij are its
  entries, I_𝛚 = 𝛚̂ᵀ𝐈𝛚̂ the moment about the axis of 𝛚, L_x a component of 𝐋, L_𝛚 = 𝐋·𝛚̂.
* **time derivatives.** d/dt moves each point by ṙ = 𝛚 × 𝐫 and 𝛚 by 𝛚̇ = 𝛂 (generic): the
  torque (τ, Γ, or a letter the text sets equal to 𝐫 × 𝐅) is d𝐋/dt and the force 𝐅 is d𝐩/dt —
  the laws of motion, the starting point — so 𝐓 = 𝐈𝛂 is compared with d(𝐈𝛚)/dt = 𝐈𝛂 + 𝛚 × 𝐈𝛚.
* **generic vectors.** Any other bold letter 𝐚 is a generic vector (a_x, a_y, a_z); a relation
  is an identity for all of them only if both sides involve the same ones.

Products: ``×`` (binds tightest), ``\\cdot`` (dot product, a tensor on a vector), juxtaposition
(a scalar factor, matrix products of conforming shapes, 𝐚𝐛 or 𝐚 ⊗ 𝐛 the dyadic 𝐚𝐛ᵀ), ``^T``,
``v^2`` = v·v, ``|v|``, determinants (``vmatrix``, ``|array|``, expanded along a row of unit
vectors), δ_ij, the unit tensor 𝕀.
"""
from __future__ import annotations

import itertools

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.latex_parser import _Parser
from derive.lecture.vector_algebra_model import (  # noqa: F401  (the model's names, used as vector_algebra.X)
    AXIS, E, INTEGRAL, M0, MU, POINTS, R0, RK, TORQUES, UNIT, WD, W, Member, Reading, State, _as_value, _determinant,
    _dot, _juxt, difference, lecture_notation, linear, markers, momentum, prepare, rate, tensor, torque,
)
from derive.lecture.vector_models import _FreeIndex, _is_vector


class _AParser(_Parser):
    """`derive.lecture.latex_parser._Parser` with the values of this module's model."""

    def __init__(self, toks, source, state: State, system: str):
        super().__init__(toks, lx.Vocabulary(), source)
        self.state, self.system = state, system
        self.generics: set = set()
        self.force_at: list = []                    # token indices of 𝐅
        self.law = self.rated = False
        self.stop_dm = False

    # a chain of members
    def members(self, env):
        out, rels = [], []
        while True:
            if self.peek() is None or self.at("rel"):
                self.fail("a side of a relation is empty")
            start, first = self.peek().pos, self.i
            self.generics, self.force_at, self.law, self.rated = set(), [], False, False
            value = _as_value(self.expr(env))
            end = self.peek().pos if self.peek() else len(self.source)
            literal = value if self.toks[first].kind == "begin" and self.i > first else None
            skip = "a force inside a product (only its law is known)" if self.force_at and self.i - first > 1 else ""
            out.append(Member(value, start, end, skip, frozenset(self.generics), literal, self.law, self.rated))
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
        tok = self.peek()
        if tok is not None and tok.kind == "op" and tok.value == "|":
            return False
        return super()._starts_factor()

    def term(self, env):
        value = self.xterm(env)
        while True:
            if self.at("cmd", "cdot") or self.at("op", "*"):
                self.i += 1
                value = _dot(value, self.xterm(env))
            elif self.at("op", "/"):
                self.i += 1
                value = value / self.xterm(env)
            elif self._starts_factor():
                value = _juxt(value, self.xterm(env))
            else:
                return value

    def xterm(self, env):
        value = self.factor(env)
        while self.at("cmd", "times"):
            self.i += 1
            right = self.factor(env)
            while not isinstance(right, sp.MatrixBase) and self._starts_factor():
                right = _juxt(right, self.factor(env))       # r × m v: the scalar goes with the vector
            if not (_is_vector(value) and _is_vector(right)):
                self.fail("× of something that is not a vector")
            value = value.cross(right)
        return value

    def factor(self, env):
        if self.at("op", "-"):
            self.i += 1
            return -self.factor(env)
        base = self.primary(env)
        while self.at("op", "^"):
            self.i += 1
            if self._transpose_mark():
                if not isinstance(base, sp.MatrixBase):
                    self.fail("a transpose of a scalar")
                base = base.T
                continue
            exp = self.group_or_token(env)
            if _is_vector(base) and exp == 2:
                base = base.dot(base)
            elif isinstance(base, sp.MatrixBase):
                self.fail("a power of a vector or matrix")
            else:
                base = base ** exp
        return base

    def primary(self, env):
        tok = self.peek()
        if tok is not None and tok.kind == "op" and tok.value == "|":
            self.i += 1
            if self.at("begin"):
                value = self.matrix(env, det=True)
            else:
                inner = _as_value(self.expr(env))
                value = sp.sqrt(inner.dot(inner)) if _is_vector(inner) else sp.Abs(inner)
            self.take("op", "|")
            return value
        if tok is not None and tok.kind == "begin":
            return self.matrix(env, det=tok.value == "vmatrix")
        if tok is not None and tok.kind == "atom" and tok.value.base == INTEGRAL and tok.value.bold:
            self.i += 1
            return self.integral(env)
        if tok is not None and tok.kind == "cmd" and tok.value == "sum":
            self.i += 1
            return self.particle_sum(env, tok)
        if tok is not None and tok.kind == "cmd" and tok.value in ("frac", "dfrac", "tfrac"):
            d = self._rate(env)
            if d is not None:
                return d
        return super().primary(env)

    # d/dt
    def _rate(self, env):
        """\\frac{d}{dt} X (X the following product) or \\frac{d X}{dt}: the time derivative, or None."""
        t, i = self.toks, self.i + 1
        if not (i < len(t) and t[i].kind == "op" and t[i].value == "{"):
            return None
        depth, j = 0, i
        while j < len(t):
            if t[j].kind == "op" and t[j].value == "{":
                depth += 1
            elif t[j].kind == "op" and t[j].value == "}":
                depth -= 1
                if depth == 0:
                    break
            j += 1
        den = t[j + 1:j + 5]
        if not (len(den) == 4 and den[0].kind == "op" and den[0].value == "{" and den[1].kind == "atom"
                and den[1].value.base == "d" and not den[1].value.sub and den[2].kind == "atom"
                and den[2].value.base == "t" and not den[2].value.sub and den[3].kind == "op" and den[3].value == "}"):
            return None
        num = t[i + 1:j]
        if not num or num[0].kind != "atom" or num[0].value.base != "d" or num[0].value.sub or num[0].value.bold:
            return None
        self.rated = True
        if len(num) == 1:
            self.i = j + 5
            return rate(self.term(env))
        self.toks = t[:i + 1] + t[i + 2:]              # drop the d: the numerator is what is differentiated
        self.i = i + 1
        value = self.expr(env)
        self.take("op", "}")
        self.i += 4
        return rate(value)

    # matrices and determinants
    def matrix(self, env, det=False):
        tok = self.take("begin")
        if tok.value == "array" and self.at("op", "{"):
            while not self.at("op", "}"):
                self.i += 1
            self.i += 1
        rows, row = [], []
        while True:
            if self.at("end"):
                self.i += 1
                break
            if self.peek() is None:
                self.fail("a matrix without its end", tok)
            if self.at("cmd") and self.peek().value in ("cdots", "ldots", "dots"):
                self.fail("a matrix of any size")
            row.append(_as_value(self.expr(env)))
            if self.at("op", "&"):
                self.i += 1
            elif self.at("op", "\\\\"):
                self.i += 1
                rows.append(row)
                row = []
            elif not self.at("end"):
                self.fail("expected '&', '\\\\' or the end of the matrix")
        if row:
            rows.append(row)
        if len({len(r) for r in rows}) != 1:
            self.fail("rows of different lengths", tok)
        if det:
            return _determinant(rows)
        if any(isinstance(x, sp.MatrixBase) for r in rows for x in r):
            self.fail("a matrix of vectors")
        return sp.Matrix(rows)

    # sums and integrals
    def particle_sum(self, env, tok):
        """Σᵢ over the body's points (the index's upper limit a letter, or mᵢ in the statement)."""
        if not self.at("op", "_"):
            self.fail("a sum without its index", tok)
        self.i += 1
        if self.at("op", "{"):
            self.i += 1
            names = []
            while not self.at("op", "}"):
                if self.peek() is None:
                    self.fail("unbalanced '{'", tok)
                if self.peek().kind == "atom":
                    names.append(self.peek().value.base)
                self.i += 1
            self.i += 1
        else:
            names = [self.take("atom").value.base]
        if len(names) != 1 or len(names[0]) != 1:
            self.fail("a sum over more than one index", tok)
        index = names[0]
        if self.at("op", "^"):
            self.i += 1
            upper = []
            if self.at("op", "{"):
                while not self.at("op", "}"):
                    self.i += 1
                    upper.append(self.peek(-1))
                upper = upper[1:]
            else:
                upper = [self.peek()]
            self.i += 1
            if any(t is not None and t.kind == "num" for t in upper):
                self.fail("a sum over the body's axes", tok)    # Σ_{i=1}^{3}: not over particles
        start, total = self.i, None
        for k in range(POINTS):
            self.i = start
            term = self.term({**env, "point": k, "index": index})
            total = term if total is None else total + term
        return total

    def integral(self, env):
        """∫ … dm over the body: Σ_k μ_k (…) at the body's points."""
        start, total, stop = self.i, None, self.stop_dm
        for k in range(POINTS):
            self.i = start
            self.stop_dm = True
            term = self.term({**env, "point": k, "index": None})
            self.stop_dm = stop
            if not (self.at("atom") and self.peek().value.base == "d"):
                self.fail("an integral without its dm")
            self.i += 2
            term = _juxt(MU[k], term)
            total = term if total is None else total + term
        return total

    # atoms
    def _axis(self, ch, env, tok):
        if ch in AXIS:
            return AXIS[ch]
        if ch in env and isinstance(env[ch], int) and ch != "point":
            return env[ch] - 1
        if ch in "ijkl":
            raise _FreeIndex(ch)
        self.fail(f"the index {ch!r}", tok)

    def _point(self, env):
        k = env.get("point")
        return (M0, R0) if k is None else (MU[k], RK[k])

    def _own(self, sub, env) -> bool:
        """Whether a subscript names the current point (none, or the sum's index; 𝐫ᵢ outside a sum
        is the particle in question)."""
        return sub == "" or sub == env.get("index") or (env.get("point") is None and sub == "i")

    def atom(self, tok, env):
        a = tok.value
        value = self._value(a, env, tok)
        if value is None:
            raise lx.Unknown(f"unknown symbol {a.text}", tok.pos + 1)
        return value

    def _value(self, a, env, tok):
        base, sub, bold = a.base, a.sub, a.bold or a.text.startswith("\\vec")
        if a.dots > 1 or a.primes or a.tilde:
            return None
        if a.dots == 1:
            self.rated = True
            inner = self._value(a.with_(dots=0), env, tok)
            if inner is None:
                return None
            if base == "omega":
                return WD if bold else (WD[AXIS[sub]] if sub in AXIS else None)
            return rate(inner)
        mass, r = self._point(env)
        if a.hat and base in UNIT and (not sub or base == "x"):
            return E[:, self._axis(sub, env, tok) if sub else UNIT[base]]
        if base == "omega":
            n = sp.sqrt(W.dot(W))
            if a.hat:
                return W / n
            if bold:
                return W
            return n if not sub else (W[AXIS[sub]] if sub in AXIS else None)
        if base == "alpha":
            self.rated = True
            return WD if bold else (WD[AXIS[sub]] if sub in AXIS else None)
        if a.hat:
            return None
        if base == "r" and self._own(sub, env):
            return r if bold else sp.sqrt(r.dot(r))
        if base in "xyz" and len(base) == 1 and not bold:
            if self._own(sub, env):
                return r[AXIS[base]]
            if base == "x" and len(sub) == 1:
                return r[self._axis(sub, env, tok)]
            return None
        if base == "m" and not bold and self._own(sub, env):
            return mass
        if base == "v" and self._own(sub, env):
            v = W.cross(r)
            return v if bold else sp.sqrt(v.dot(v))
        if base == "v" and not bold and sub in ("x", "y", "z"):
            return W.cross(r)[AXIS[sub]]
        if base == "p" and bold and self._own(sub, env):
            return mass * W.cross(r)
        if base == "delta" and len(sub) == 2:
            return sp.Integer(int(self._axis(sub[0], env, tok) == self._axis(sub[1], env, tok)))
        system = "body" if sub in ("system", "textsystem", "G", "mathcalG", "mathrmG") else self.system
        point = env.get("point") is not None and sub == env.get("index")
        if base == "L":
            if bold:
                if point:
                    return mass * r.cross(W.cross(r))
                return momentum(system) if sub in ("", "system", "textsystem") else None
            if len(sub) == 1 and sub in AXIS:
                return momentum(self.system)[AXIS[sub]]
            if "omega" in sub:
                return momentum(self.system).dot(W / sp.sqrt(W.dot(W)))
            return None
        if base == "I":
            if a.text.startswith(("\\mathrm", "\\mathbb")) and not sub:
                return sp.eye(3)
            if point:
                return (mass * r.cross(W.cross(r))).jacobian(W)
            if sub in ("", "system", "textsystem", "G", "mathcalG", "mathrmG"):
                return tensor(system)
            if "omega" in sub:
                n = W / sp.sqrt(W.dot(W))
                return (n.T * tensor(self.system) * n)[0, 0]
            if len(sub) == 2 and not bold:
                if (base, sub) in self.state.defs:
                    return self.state.defs[(base, sub)]
                return tensor(self.system)[self._axis(sub[0], env, tok), self._axis(sub[1], env, tok)]
            return None
        if base in self.state.torques or (base == "F" and bold and not sub):
            self.law = True
        if base in self.state.torques:
            if bold and not sub:
                return torque(self.system)
            if not bold and sub in AXIS and len(sub) == 1:
                return torque(self.system)[AXIS[sub]]
            return None
        if base == "F" and bold and not sub:
            self.force_at.append(self.i)
            return rate(linear(self.system))
        if len(base) == 1 and base.isalpha() and base not in "dmt":
            comps = sp.Matrix(sp.symbols(f"{base}_x {base}_y {base}_z", real=True))
            if bold and not sub:
                self.generics.add(base)
                return comps
            if not bold and sub in ("x", "y", "z"):
                self.generics.add(base)
                return comps[AXIS[sub]]
        return None


def system_of(toks, state: State) -> str:
    """body (a sum or an integral), single (a plain m), else the previous statement's system."""
    if any(t.kind == "cmd" and t.value == "sum" for t in toks) or \
            any(t.kind == "atom" and t.value.base == INTEGRAL for t in toks):
        return "body"
    if any(t.kind == "atom" and t.value.base == "m" and t.value.sub in ("", "i") and not t.value.bold for t in toks):
        return "single"
    if any(t.kind == "atom" and t.value.sub in ("system", "textsystem") for t in toks):
        return "body"
    return state.system


def learn_torque(toks, state: State) -> None:
    """A bold letter set equal to 𝐫 × 𝐅 is the text's torque."""
    if len(toks) >= 5 and toks[0].kind == "atom" and toks[0].value.bold and toks[1].kind == "rel" \
            and toks[2].kind == "atom" and toks[2].value.base == "r" and toks[3].kind == "cmd" \
            and toks[3].value == "times" and toks[4].kind == "atom" and toks[4].value.base == "F":
        state.torques.add(toks[0].value.base)


def read(text: str, state: State) -> Reading:
    """Read a statement (`lx.NotRead` when it cannot)."""
    text = prepare(text)
    toks = lx.scan_cells(text)
    learn_torque(toks, state)
    system = system_of(toks, state)
    free = ""
    while True:
        try:
            readings = []
            for values in itertools.product((1, 2, 3), repeat=len(free)):
                p = _AParser(list(toks), text, state, system)
                readings.append(p.members(dict(zip(free, values))))
            break
        except _FreeIndex as err:
            if err.letter in free or len(free) >= 2:
                raise lx.NotRead(f"the index {err.letter} is neither summed nor free") from None
            free += err.letter
        except (sp.ShapeError, TypeError, ValueError, AttributeError, IndexError) as err:
            raise lx.NotRead(f"cannot combine its parts ({type(err).__name__})") from None
    return Reading([r[0] for r in readings], readings[0][1], free, text, system)
