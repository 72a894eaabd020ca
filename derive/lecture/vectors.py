"""Vectors, tensors, sums over particles and frame derivatives: the displays `derive.lecture.latex` refuses.

The scalar reader (`derive.lecture.latex`) reads formulas in the derivation's scalar symbols. The
first pages of a rigid-body lecture are written in vectors instead — T = Σ_p ½ m_p (ω × r_p)·(ω × r_p),
𝐋 = Ï·ω, (d𝐫/dt)_inertial = ω × 𝐫 — and this module reads and checks those, through the same
whitelist (the tokens of `derive.lecture.latex.scan`: never ``eval``, never ``sympify``).

Values are SymPy objects of three shapes: a scalar, a 3-vector (a 3×1 matrix of body components)
and a tensor (a 3×3 matrix). The operations are the usual ones:

* ``a \\times b`` — the cross product (binds tighter than ``\\cdot``: a·b×c = a·(b×c));
* ``a \\cdot b`` — the dot product, or the contraction of a tensor with a vector (Ï·ω = Ï ω,
  ω·Ï = Ïᵀ ω, so ω·Ï·ω = ωᵀ Ï ω);
* ``a b`` of two vectors — the dyadic a bᵀ; ``|v|`` = √(v·v), ``v^2`` = v·v;
* ``\\mathbf{1}`` (𝟙) — the unit tensor; ``\\delta_{ij}`` — Kronecker's delta.

Three models say what the symbols stand for (chosen per statement, see `model_of`):

``particle``
    a system of particles: m_p, 𝐫_p generic (x_p, y_p, z_p), 𝐯_p = ω × 𝐫_p (the velocity of a
    point of a rigid body, the kinematic fact the notes use), ω = (ω̃₁, ω̃₂, ω̃₃) generic. A sum
    over particles Σ_p is read for **two** generic particles: a sum is linear in its summand, so
    the summand identity for a generic particle proves the sum identity, and a second particle
    keeps a formula that is not linear in the sum (a square of a sum) from passing. T ≡ Σ_p ½ m_p v_p²,
    𝐋 ≡ Σ_p m_p 𝐫_p × 𝐯_p, and the tensor Ï ≡ ∂²T/∂ω∂ω (the Hessian of T in ω: independent of
    how the notes write Ï) with components I_xx … I_zz, I_ij (i, j = 1, 2, 3).
``principal``
    body principal axes: Ï = diag(I₁, I₂, I₃), ê_i the body axes, 𝐋 = (I₁ω̃₁, I₂ω̃₂, I₃ω̃₃),
    T = ½ Σ I_i ω̃_i².
``frame``
    derivatives in a rotating frame, with R(t) of the notes' Euler angles (R = body → inertial
    components, ``derive.symbolic.rotations``): in body components the inertial derivative of a
    vector X is Rᵀ d(R X)/dt = Rᵀ Ṙ X + Ẋ and the body derivative ``(dX/dt)_{body}`` is Ẋ; 𝐫 is
    body-fixed (Ẋ = 0), 𝐋 has generic time-dependent body components, ω is the derivation's ω̃
    (angles and rates). ``(d𝐫/dt)_{inertial} = ω × 𝐫`` and the transport theorem
    d𝐋/dt = (d𝐋/dt)_body + ω × 𝐋 are checked that way.

A free body index (``\\hat{\\mathbf{e}}_i``, ``I_{ij}`` outside a sum) means "for i = 1, 2, 3": the
statement is read for each value. The torque τ as a whole side (d𝐋/dt = τ) is the law of motion,
which the derivation starts from: it is not checked.
"""
from __future__ import annotations

import functools
import itertools
import re
from dataclasses import dataclass

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import verify as vf
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3
from derive.symbolic.rotations import ANGLES, RATES, time_derivative

PARTICLES = 2
M_P = sp.symbols(f"m_p1:{PARTICLES + 1}", positive=True)
R_P = [sp.Matrix(sp.symbols(f"x_p{k} y_p{k} z_p{k}", real=True)) for k in range(1, PARTICLES + 1)]
R_B = sp.Matrix(sp.symbols("x_b y_b z_b", real=True))          # a body-fixed point 𝐫
L_B = sp.Matrix(sp.symbols("L_b1:4", real=True))               # 𝐋's body components (time-dependent)
LD_B = sp.Matrix(sp.symbols("Ld_b1:4", real=True))             # their rates
W = sp.Matrix(lx.W)
AXES = {"x": 0, "y": 1, "z": 2, "1": 0, "2": 1, "3": 2}
FRAMES = {"body": "body", "b": "body", "rot": "body", "rotating": "body", "inertial": "inertial",
          "space": "inertial", "fixed": "inertial", "lab": "inertial", "s": "inertial"}
_UNIT = re.compile(r"\\(?:mathbf|mathbb|boldsymbol|bm)\s*\{\s*(?:\\(?:mathbb|mathbf)\s*\{\s*)?1\s*\}(?:\s*\})?")


class _Law:
    """τ as a whole side: the law of motion d𝐋/dt = τ."""


LAW = _Law()


class _FreeIndex(Exception):
    def __init__(self, letter):
        super().__init__(letter)
        self.letter = letter


def _is_tensor(v) -> bool:
    return isinstance(v, sp.MatrixBase) and v.shape == (3, 3)


def _is_vector(v) -> bool:
    return isinstance(v, sp.MatrixBase) and v.shape == (3, 1)


# ---- the models -----------------------------------------------------------------------------------
class Model:
    """What the symbols of one statement stand for (see the module docstring)."""

    def __init__(self, name: str, derivation=None):
        self.name, self.d = name, derivation

    # particle references
    def velocity(self, k):
        return W.cross(R_P[k])

    @functools.cached_property
    def kinetic(self):
        if self.name == "principal":
            return sp.Rational(1, 2) * sum(m * w**2 for m, w in zip(self.moments, lx.W))
        return sum(sp.Rational(1, 2) * M_P[k] * self.velocity(k).dot(self.velocity(k)) for k in range(PARTICLES))

    @property
    def moments(self):
        return (I1, I2, I3)

    @functools.cached_property
    def tensor(self) -> sp.Matrix:
        if self.name == "principal":
            return sp.diag(*self.moments)
        return sp.hessian(self.kinetic, list(lx.W)).applyfunc(sp.expand)

    @functools.cached_property
    def momentum(self) -> sp.Matrix:
        if self.name == "principal":
            return sp.Matrix([m * w for m, w in zip(self.moments, lx.W)])
        if self.name == "frame":
            return L_B
        return sum((M_P[k] * R_P[k].cross(self.velocity(k)) for k in range(PARTICLES)), sp.zeros(3, 1))

    @property
    def omega(self) -> sp.Matrix:
        if self.name == "frame":
            return sp.Matrix(self.d.omega)
        return W

    # frame derivatives
    def dt(self, e):
        """d/dt of an expression in the angles, rates and 𝐋's body components (the
        derivation's chain rule, with 𝐋's components as three more coordinates)."""
        return time_derivative(e, coords=(*ANGLES, *L_B), rates=(*RATES, *LD_B), accels=ACCELS)

    def derivative(self, X: sp.Matrix, frame: str) -> sp.Matrix:
        """Body components of (dX/dt) in the inertial frame (Rᵀ d(R X)/dt) or the body frame (Ẋ)."""
        Xd = X.applyfunc(self.dt)
        if frame == "body":
            return Xd
        R = self.d.conv.matrix()
        return R.T * (R.applyfunc(self.dt) * X) + Xd


def model_of(toks, sticky: str | None) -> str:
    """frame (a time derivative of a vector), principal (I₁ I₂ I₃, I_i or ê_i), particle (m_p,
    𝐫_p, 𝐯_p, δ_ij, 𝟙, I_ij, Σ_p, or a particle statement earlier in the section), else principal."""
    atoms = [t.value for t in toks if t.kind == "atom"]
    if any(t.kind == "cmd" and t.value == "frac" for t in toks) and _has_time_derivative(toks):
        return "frame"
    if any(a.base == "I" and len(a.sub) == 1 for a in atoms) or any(a.base == "e" and (a.hat or a.bold) for a in atoms):
        return "principal"
    if any(_particle_atom(a) for a in atoms) or any(a.base == "I" and len(a.sub) == 2 for a in atoms):
        return "particle"
    return sticky or "principal"


def _particle_atom(a) -> bool:
    return (a.base in ("m", "r", "v") and a.sub[:1] == "p") or a.base == "delta" or (a.base == "Xi" and a.bold)


def _has_time_derivative(toks) -> bool:
    for k in range(len(toks) - 6):
        w = toks[k:k + 7]
        if w[0].kind == "cmd" and w[0].value == "frac" and w[2].kind == "atom" and w[2].value.base == "d" \
                and w[3].kind == "atom" and w[3].value.bold:
            return True
    return False


def vectorish(toks) -> bool:
    """Whether a statement is for this reader: a cross product, a tensor, a sum over particles,
    a particle quantity or a time derivative of a vector."""
    for t in toks:
        if t.kind == "cmd" and t.value == "times":
            return True
        if t.kind == "atom":
            a = t.value
            if _particle_atom(a) or (a.base == "I" and (a.bold or a.dots == 2 or len(a.sub) == 2)):
                return True
    return _has_time_derivative(toks)


def prepare(text: str) -> str:
    """𝟙 (``\\mathbf{1}``, ``\\mathbb{1}``) as a symbol the scanner reads; ``\\overleftrightarrow``
    (the dyadic arrow) as bold."""
    text = _UNIT.sub(r"\\mathbf{\\Xi}", text)
    return text.replace("\\overleftrightarrow", "\\mathbf")


# ---- the parser -----------------------------------------------------------------------------------
@dataclass
class VMember:
    value: object
    start: int          # source span of the member
    end: int
    quantity: bool      # a single known quantity (T, 𝐋, Ï, I_ij): member 0 is its definition


class _VParser(lx._Parser):
    """The grammar of `derive.lecture.latex._Parser` with vector values (see the module docstring)."""

    def __init__(self, toks, vocab, source, model: Model, plain_l_vector: bool):
        super().__init__(toks, vocab, source)
        self.model = model
        self.plain_l_vector = plain_l_vector

    def vchain(self, env):
        members, rels = [], []
        while True:
            start = self.peek().pos if self.peek() else len(self.source)
            before = self.source[:start].rstrip()
            if before.endswith("\\left"):          # the member's span takes its \left along
                start = len(before) - len("\\left")
            if self.peek() is None or self.at("rel"):
                self.fail("a side of a relation is empty")
            first = self.i
            value = self.expr(env)
            single = self.i == first + 1 and self.toks[first].kind == "atom"
            end = self.peek().pos if self.peek() else len(self.source)
            members.append(VMember(value, start, end, single and self._is_quantity(self.toks[first].value)))
            if not self.at("rel"):
                break
            rels.append(self.take("rel").value)
        if self.peek() is not None:
            self.fail(f"unexpected {self.peek().value!r}")
        return members, rels

    @staticmethod
    def _is_quantity(a) -> bool:
        return a.base in ("T", "L") or (a.base == "I" and (a.bold or a.dots == 2 or len(a.sub) == 2))

    # products: × binds tighter than · and juxtaposition
    def term(self, env):
        value = self.xterm(env)
        while True:
            if self.at("cmd", "cdot") or self.at("op", "*"):
                self.i += 1
                value = _dot(value, self.xterm(env))
            elif self.at("op", "/"):
                self.i += 1
                value = value / self.xterm(env)
            elif self._starts_factor() and not self.at("cmd", "sum"):
                value = _juxtapose(value, self.xterm(env))
            elif self.at("cmd", "sum"):
                value = _juxtapose(value, self.xterm(env))
            else:
                return value

    def xterm(self, env):
        value = self.factor(env)
        while self.at("cmd", "times"):
            self.i += 1
            right = self.factor(env)
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
            exp = self.group_or_token(env)
            if _is_vector(base):
                if exp != 2:
                    self.fail("a power of a vector other than 2")
                base = base.dot(base)
            elif isinstance(base, sp.MatrixBase):
                self.fail("a power of a tensor")
            else:
                base = base ** exp
        return base

    def primary(self, env):
        tok = self.peek()
        if tok is not None and tok.kind == "op" and tok.value == "(":
            framed = self._framed_derivative(env)
            if framed is not None:
                return framed
        if tok is not None and tok.kind == "op" and tok.value == "|":
            self.i += 1
            value = self.expr(env)
            self.take("op", "|")
            return sp.sqrt(value.dot(value)) if _is_vector(value) else sp.Abs(value)
        if tok is not None and tok.kind == "cmd" and tok.value == "frac":
            found = self._derivand(self.i + 1)
            if found is not None:
                self.i = found[1]
                return self.model.derivative(found[0], "inertial")
        if tok is not None and tok.kind == "cmd" and tok.value == "sum":
            self.i += 1
            return self.vsum(env, tok)
        return super().primary(env)

    def expr(self, env):
        sign = 1
        if self.at("op", "+"):
            self.i += 1
        elif self.at("op", "-"):
            self.i += 1
            sign = -1
        total = self.term(env)
        if sign == -1:
            total = -_scalar_or_tensor(total)
        while self.at("op", "+") or self.at("op", "-"):
            op = self.take("op").value
            total = _scalar_or_tensor(total)
            rhs = _scalar_or_tensor(self.term(env))
            if isinstance(total, sp.MatrixBase) != isinstance(rhs, sp.MatrixBase) and not (total == 0 or rhs == 0):
                self.fail("a scalar added to a vector or tensor")
            total = total + rhs if op == "+" else total - rhs
        return total

    def paren(self, env):
        open_ = self.take("op").value
        close = ")" if open_ == "(" else "}"
        value = self.expr(env)
        if not self.at("op", close):
            self.fail("expected a closing bracket")
        self.i += 1
        return value

    # time derivatives
    def _derivand(self, k):
        """At toks[k] == '{' of \\frac{d𝐗}{dt} (frame model): (𝐗's body components, index after), or None."""
        t = self.toks
        if self.model.name != "frame" or k + 8 > len(t):
            return None
        o1, d1, x, c1, o2, d2, tt, c2 = t[k:k + 8]
        pattern = (o1.kind == "op" and o1.value == "{" and d1.kind == "atom" and d1.value.base == "d"
                   and not d1.value.sub and x.kind == "atom" and x.value.bold and c1.kind == "op"
                   and c1.value == "}" and o2.kind == "op" and o2.value == "{" and d2.kind == "atom"
                   and d2.value.base == "d" and tt.kind == "atom" and tt.value.base == "t"
                   and c2.kind == "op" and c2.value == "}")
        if not pattern:
            return None
        a = x.value
        if a.base == "r" and not a.sub:
            return R_B, k + 8
        if a.base == "L" and not a.sub:
            return L_B, k + 8
        self.fail(f"the time derivative of {a.text}", x)

    def _framed_derivative(self, env):
        """(d𝐗/dt)_{body|inertial|space…} at '(' (no subscript: inertial)."""
        t, i = self.toks, self.i
        if not (i + 1 < len(t) and t[i + 1].kind == "cmd" and t[i + 1].value == "frac"):
            return None
        found = self._derivand(i + 2)
        if found is None:
            return None
        X, k = found
        if not (k < len(t) and t[k].kind == "op" and t[k].value == ")"):
            return None
        self.i = k + 1
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
            if name not in FRAMES:
                self.fail(f"a derivative in the frame {name!r}")
            frame = FRAMES[name]
        return self.model.derivative(X, frame)

    # sums
    def vsum(self, env, tok):
        """Σ_p over particles (two generic ones) or Σ_i, Σ_ij over body axes (1, 2, 3)."""
        if not self.at("op", "_"):
            self.fail("a sum without its index", tok)
        self.i += 1
        names = []
        if self.at("op", "{"):
            self.i += 1
            while not self.at("op", "}"):
                t_ = self.peek()
                if t_ is None:
                    self.fail("unbalanced '{'", tok)
                if t_.kind == "atom":
                    names.append(t_.value.base + t_.value.sub)
                self.i += 1
            self.i += 1
        else:
            names = [self.take("atom").value.base]
        index = "".join(names)
        if self.at("op", "^"):
            self.i += 1
            self.group_or_token(env)
        if index == "p":
            ranges = [("p", range(PARTICLES))]
        elif index and all(ch in "ijk" for ch in index):
            ranges = [(ch, (1, 2, 3)) for ch in index]
        else:
            self.fail(f"a sum over {index!r}", tok)
        start, total = self.i, None
        for values in itertools.product(*(r for _, r in ranges)):
            self.i = start
            inner = {**env, **{n: v for (n, _), v in zip(ranges, values)}}
            term = self.term(inner)
            total = term if total is None else total + term
        return total

    # atoms
    def atom(self, tok, env):
        a = tok.value
        v = self.vector_atom(a, env, tok)
        if v is not None:
            return v
        if a.sub in ("i", "j") and a.sub not in env:
            raise _FreeIndex(a.sub)
        return super().atom(tok, env)

    def _index(self, ch, env, tok):
        if ch in AXES:
            return AXES[ch]
        if ch in env and ch != "p":
            return env[ch] - 1
        if ch in "ij":
            raise _FreeIndex(ch)
        self.fail(f"the index {ch!r}", tok)

    def _particle(self, env, tok):
        if "p" not in env:
            self.fail("a particle quantity outside a sum over particles", tok)
        return env["p"]

    def vector_atom(self, a, env, tok):
        m = self.model
        plain = not a.hat and not a.tilde and not a.primes and not a.dots
        if a.base == "omega" and not a.sub and not a.dots and not a.tilde:
            return m.omega
        if a.base == "e" and (a.hat or a.bold) and not a.primes and not a.sup and len(a.sub) == 1:
            return sp.eye(3)[:, self._index(a.sub, env, tok)]
        if a.base == "I" and not a.sub and (a.bold or a.dots == 2):
            return m.tensor
        if a.base == "I" and len(a.sub) == 2 and not a.bold:
            return m.tensor[self._index(a.sub[0], env, tok), self._index(a.sub[1], env, tok)]
        if a.base == "I" and a.sub in ("i", "j") and not a.bold:
            return m.moments[self._index(a.sub, env, tok)]
        if a.base == "Xi" and a.bold:
            return sp.eye(3)
        if a.base == "delta" and len(a.sub) == 2:
            return sp.Integer(int(self._index(a.sub[0], env, tok) == self._index(a.sub[1], env, tok)))
        if a.base == "m" and a.sub == "p" and plain:
            return M_P[self._particle(env, tok)]
        if a.base == "r" and plain and a.sub[:1] == "p":
            r = R_P[self._particle(env, tok)]
            if len(a.sub) == 2 and not a.bold:
                return r[self._index(a.sub[1], env, tok)]
            if a.sub == "p":
                return r if a.bold else sp.sqrt(r.dot(r))
        if a.base == "v" and plain and a.sub == "p":
            v = m.velocity(self._particle(env, tok))
            return v if a.bold else sp.sqrt(v.dot(v))
        if a.base == "r" and plain and a.bold and not a.sub:
            return R_B
        if a.base == "L" and plain and not a.sub and (a.bold or self.plain_l_vector):
            return m.momentum
        if a.base == "T" and plain and not a.sub and not a.bold:
            return m.kinetic
        if a.base == "tau" and not a.sub:
            return LAW
        return None


def _scalar_or_tensor(v):
    if v is LAW:
        raise lx.NotRead("the torque inside a formula")
    return v


def _dot(a, b):
    if a is LAW or b is LAW:
        raise lx.NotRead("the torque inside a formula")
    va, vb = _is_vector(a), _is_vector(b)
    ta, tb = _is_tensor(a), _is_tensor(b)
    if va and vb:
        return a.dot(b)
    if ta and vb:
        return a * b
    if va and tb:
        return b.T * a
    if ta and tb:
        return a * b
    if isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase):
        raise lx.NotRead("· of these shapes")
    return a * b


def _juxtapose(a, b):
    if a is LAW or b is LAW:
        raise lx.NotRead("the torque inside a formula")
    if _is_vector(a) and _is_vector(b):
        return a * b.T                          # the dyadic a b
    if isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase):
        raise lx.NotRead("a product of a tensor and a vector without ·")
    return a * b


# ---- reading and checking one statement ----------------------------------------------------------
@dataclass
class Reading:
    members: list       # one list of VMember per value of the free indices
    relations: list
    model: str
    free: str           # the free indices ("", "i", "ij")
    source: str


def read(text: str, vocab, derivation, sticky: str | None = None) -> Reading:
    """Read a statement with this module's grammar (`lx.NotRead` when it cannot)."""
    text = prepare(text)
    toks = lx.scan_cells(text)
    if not vectorish(toks):
        raise lx.NotRead("not a vector formula")
    name = model_of(toks, sticky)
    model = Model(name, derivation)
    plain_l = any(t.kind == "atom" and t.value.base == "I" and (t.value.bold or t.value.dots == 2) for t in toks) \
        or any(t.kind == "cmd" and t.value == "times" for t in toks)
    free = ""
    while True:
        try:
            readings = []
            for values in itertools.product((1, 2, 3), repeat=len(free)):
                p = _VParser(toks, vocab, text, model, plain_l)
                readings.append(p.vchain(dict(zip(free, values))))
            break
        except _FreeIndex as err:
            if err.letter in free or len(free) >= 2:
                raise lx.NotRead(f"the index {err.letter} is neither summed nor free") from None
            free += err.letter
        except (sp.ShapeError, TypeError, ValueError, AttributeError) as err:
            raise lx.NotRead(f"cannot combine its parts ({type(err).__name__})") from None
    return Reading([r[0] for r in readings], readings[0][1], name, free, text)


def _zero(a, b, seed) -> tuple[bool, str]:
    """a = b? Exact for polynomials (the particle and principal models), else `verify`'s test."""
    if isinstance(a, sp.MatrixBase) != isinstance(b, sp.MatrixBase) or \
            (isinstance(a, sp.MatrixBase) and a.shape != b.shape):
        return False, f"a {_shape(a)} against a {_shape(b)}"
    A = sp.Matrix(a) if isinstance(a, sp.MatrixBase) else sp.Matrix([a])
    B = sp.Matrix(b) if isinstance(b, sp.MatrixBase) else sp.Matrix([b])
    diffs = [sp.expand(x - y) for x, y in zip(A, B)]
    if all(d == 0 for d in diffs):
        return True, "exact (expand)"
    if not any(d.has(sp.sin, sp.cos) for d in diffs):
        k = next(n for n, d in enumerate(diffs) if d != 0)
        where = f" (component {k + 1})" if len(diffs) == 3 else (f" (entry {k // 3 + 1},{k % 3 + 1})" if len(diffs) == 9 else "")
        return False, f"exact (expand): claim − derived ≠ 0{where}"
    try:
        steps = [vf._symbolic_zero(d) for d in diffs]
    except (sp.PolynomialError, TypeError, ValueError):
        steps = [None]
    if all(steps):
        return True, steps[0]
    out = vf._numeric_zero(A, B, seed)
    return out.ok, out.method


def _shape(v) -> str:
    if _is_vector(v):
        return "vector"
    if _is_tensor(v):
        return "tensor"
    return "scalar"


WHY = {
    "particle": "sums over particles read for two generic particles (m_p, r_p generic, v_p = ω × r_p for "
                "a rigid body; a sum is linear in its summand, so the summand identity proves it; "
                "Ï ≡ ∂²T/∂ω∂ω)",
    "principal": "in the body's principal axes (Ï = diag(I₁, I₂, I₃), ê_i the body axes)",
    "frame": "with R(t) of the Euler angles: body components of d(R X)/dt = Rᵀ Ṙ X + Ẋ, 𝐫 body-fixed, "
             "ω̃ from the derivation",
}


def holds(reading: Reading, k: int, seed: str) -> tuple[bool, str]:
    """Member k against member 0, for each value of the free indices."""
    for n, members in enumerate(reading.members):
        ok, how = _zero(members[k].value, members[0].value, f"{seed}/{n}")
        if not ok:
            where = ""
            if reading.free:
                vals = list(itertools.product((1, 2, 3), repeat=len(reading.free)))[n]
                where = " at " + ", ".join(f"{c} = {v}" for c, v in zip(reading.free, vals))
            return False, how + where
    return True, how


def member_edits(src: str):
    """Single edits of one member's LaTeX, as (edited, what): a sign, a factor ½ or 2, an index,
    the order of a cross product, a power."""
    out = [(e, "the order of a cross product") for e in _cross_swaps(src)]
    lead = re.match(r"\s*-", src)
    out.append((src[lead.end():] if lead else "-" + src, "the sign of the whole side"))
    for m in re.finditer(r"(?<![_^{])[+\-]", src):
        out.append((src[:m.start()] + ("-" if m.group() == "+" else "+") + src[m.end():], "a sign"))
    for m in re.finditer(r"\\frac\s*\{\s*1\s*\}\s*\{\s*2\s*\}", src):
        out.append((src[:m.start()] + src[m.end():], "a factor 1/2"))
        out.append((src[:m.start()] + "2" + src[m.end():], "a factor 4"))
    out.append(("\\frac{1}{2} " + src.lstrip(), "a factor 1/2"))
    out.append(("2 " + src.lstrip(), "a factor 2"))
    for m in re.finditer(r"_\{?\s*([A-Za-z0-9]{1,2})\s*\}?", src):
        sub = m.group(1)
        for pos, ch in enumerate(sub):
            for other in {"i": "j", "j": "i", "1": "23", "2": "13", "3": "12"}.get(ch, ""):
                new = sub[:pos] + other + sub[pos + 1:]
                out.append((src[:m.start(1)] + new + src[m.end(1):], "an index"))
    for m in re.finditer(r"\^\s*\{?\s*2\s*\}?", src):
        out.append((src[:m.start()] + src[m.end():], "a power"))
    seen, unique = {src}, []
    for e, what in out:
        if e not in seen:
            seen.add(e)
            unique.append((e, what))
    return unique


def _operand(src: str, at: int, forward: bool) -> tuple[int, int] | None:
    """The span of the operand of × next to ``at``: one atom or a bracketed group."""
    try:
        toks = lx.scan(src)
    except lx.NotRead:
        return None
    k = next((n for n, t in enumerate(toks) if t.pos == at), None)
    if k is None:
        return None
    j = k + 1 if forward else k - 1
    if not 0 <= j < len(toks):
        return None
    t = toks[j]
    if t.kind == "atom":
        return t.pos, t.pos + len(t.value.text)
    if t.kind == "op" and t.value in ("(", ")"):
        step, depth = (1, 0) if forward else (-1, 0)
        for n in range(j, len(toks) if forward else -1, step):
            if toks[n].kind == "op" and toks[n].value == "(":
                depth += 1
            elif toks[n].kind == "op" and toks[n].value == ")":
                depth -= 1
            if depth == 0:
                lo, hi = sorted((t.pos, toks[n].pos))
                if src[:lo].endswith("\\left"):
                    lo -= 5
                return lo, hi + 1
    return None


def _cross_swaps(src: str):
    """Each ``a \\times b`` of the LaTeX with its operands swapped, the shortest first (the innermost
    product: r × (r × ω) is mended as r × (ω × r) before (r × ω) × r)."""
    swaps = []
    for m in re.finditer(r"\\times", src):
        left, right = _operand(src, m.start(), False), _operand(src, m.start(), True)
        if left and right:
            swaps.append((right[1] - left[0], src[:left[0]] + src[right[0]:right[1]] + src[left[1]:right[0]]
                          + src[left[0]:left[1]] + src[right[1]:]))
    return [e for _, e in sorted(swaps, key=lambda x: x[0])]


def restore(latex: str) -> str:
    """The LaTeX a reader wrote back from `prepare`'s: 𝟙 as ``\\mathbf{1}``."""
    return latex.replace("\\mathbf{\\Xi}", "\\mathbf{1}")
