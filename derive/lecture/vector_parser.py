"""The parser of the vector reader (`derive.lecture.vectors`): a statement's tokens (those of
`derive.lecture.latex.scan`) to SymPy scalars, 3-vectors and 3×3 tensors, with ×, ·, dyadic
products, sums over particles and frame derivatives, under one `Model`.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.latex_parser import _Parser
from derive.lecture.vector_models import (
    AXES, FRAMES, LAW, L_B, M_P, PARTICLES, R_B, R_P, Model, _FreeIndex, _is_tensor, _is_vector,
)

@dataclass
class VMember:
    value: object
    start: int          # source span of the member
    end: int
    quantity: bool      # a single known quantity (T, 𝐋, Ï, I_ij): member 0 is its definition


class _VParser(_Parser):
    """The grammar of `derive.lecture.latex_parser._Parser` with vector values (see the module docstring)."""

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

    def _angular_velocity(self, a) -> bool:
        """The text's letter for the angular velocity (Landau's 𝛀), bold or plain (Ω² = 𝛀·𝛀)."""
        return self._text_letter(a, "angular velocity")

    def _text_letter(self, a, meaning) -> bool:
        """Whether the text names a's letter, as a vector, by this meaning (`derive.lecture.names`)."""
        names = getattr(self.vocab, "names", None)
        return names is not None and not self.vocab.names_off and names.letters.get((a.base, "vector")) == meaning

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
        if (a.base == "omega" or self._angular_velocity(a)) and not a.sub and not a.dots and not a.tilde:
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
        if self._text_letter(a, "angular momentum") and plain and (a.bold and not a.sub or len(a.sub) == 1 and
                                                                   m.name == "particle" and not a.bold):
            return m.momentum if not a.sub else m.momentum[self._index(a.sub, env, tok)]   # Landau's 𝐌, M_i
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
