"""Texts in operator notation (Sussman & Wisdom's functional style): D, 𝒜, the orientation matrix.

Takes: one statement's LaTeX and what the text says its operators are
(`derive.lecture.operator_prose.Declarations`). Gives: `evaluate`, the statement's members as
numbers on one instant of one motion (`derive.lecture.motion_jets`).
May import: the standard library, :mod:`derive.lecture.motion_jets`, :mod:`derive.lecture.vocabulary`,
:mod:`derive.lecture.latex_spaces`.

What such a text writes, and what it is read as (a quantity with a prime is on the principal
axes, one without on the inertial axes, when the text says primes mark principal-axis
components):

=====================================  ================================================
written                                read as
=====================================  ================================================
``D X`` (``$D$ is the time derivative``)  dX/dt, binding to the next factor (``D\\mathbf{M}\\mathbf{L}'`` = (D**M**) **L**′)
``\\mathbf{M}`` (the orientation matrix)  R(q) of the convention, body → inertial
``\\mathscr{A}(v)``, ``\\mathscr{A}^{-1}(m)``  the cross-product matrix of v; the vector of m
``X^{\\mathscr{T}}``, ``X^T``, ``X^{-1}``   transpose, inverse
``\\boldsymbol{\\omega}'``, ``\\omega^a``   𝛚′ (principal axes), its component on axis a
``\\mathbf{L}'``, ``L_a``; ``\\mathbf{L}``  **I**′𝛚′, its components; **M** **I**′𝛚′
``\\mathbf{T}'``, ``T_a``; ``\\mathbf{T}``, ``T_z``  the torque **I**′D𝛚′ + 𝛚′ × **I**′𝛚′, on the principal, the inertial axes
``\\mathbf{I}'``; ``A``, ``B``, ``C``     diag(A, B, C); the principal moments the text names
``p_\\phi``, ``\\partial_{\\dot\\phi} L``  the momentum of the angle, 𝐋·(its axis)
``\\partial_{1,k} V(t; q_0, q_1, q_2)``    ∂V/∂q_k = −Q_k (the torque's generalised force, SICM's slot 1, index k from 0)
``\\vec{u}``, ``\\mathbf{v}``, ``R``       vectors and a rotation the text leaves arbitrary
=====================================  ================================================
"""
from __future__ import annotations

import random
import re
from dataclasses import dataclass


from derive.lecture import motion_jets as mj
from derive.lecture import vocabulary
from derive.lecture.latex_spaces import QUAD_NAMES, SPACE_NAMES
from derive.lecture.latex_spellings import DIGITS


class NotHandled(Exception):
    """The statement uses something this reading does not know: the general reader takes it."""


_GREEK = {"omega", "theta", "phi", "psi", "varphi", "vartheta", "alpha", "beta", "gamma", "tau", "Gamma"}
_BOLD = ("mathbf", "boldsymbol", "vec", "bm", "pmb")
# A decorated symbol in braces of its own (``{\\mathbf{L}}'``): the braces add nothing to the one symbol it is.
_DECORATED_IN_BRACES = re.compile(r"\{\s*(\\(?:" + "|".join(_BOLD + ("mathrm", "dot", "ddot")) + r")\s*\{[^{}]*\})\s*\}")
_SKIP = SPACE_NAMES | QUAD_NAMES | {"left", "right", "big", "Big", "bigg", "Bigg", "bigl", "bigr", "Bigl", "Bigr",
                                   "displaystyle"}


# ---- reading a statement -------------------------------------------------------------------------
@dataclass
class Tok:
    kind: str          # atom, num, op, cmd, rel, env
    value: object
    bold: bool = False
    primes: int = 0
    sub: str = ""
    sup: str = ""
    dots: int = 0
    roman: bool = False


def group(s: str, i: int) -> tuple[str, int]:
    """The vocabulary's braced group or single token at s[i], unread as :class:`NotHandled`."""
    try:
        return vocabulary.group(s, i)
    except vocabulary.NotRead as exc:
        raise NotHandled(str(exc)) from None


def _plain(s: str) -> str:
    s = re.sub(r"\\(mathrm|text|mathit|rm|mathscr|mathcal)\s*", "", s)
    return re.sub(r"\\([A-Za-z]+)", r"\1", s.replace("{", "").replace("}", "").replace(" ", ""))


def _atom(s: str, i: int) -> tuple[Tok, int]:
    """One symbol at s[i] with its decorations, scripts and primes."""
    m = re.match(r"\\([A-Za-z]+)", s[i:])
    if m and m.group(1) in _BOLD + ("mathrm", "dot", "ddot"):
        inner, j = group(s, i + m.end())
        inner = inner.strip()
        while inner.startswith("{") and inner.endswith("}") and group(inner, 0)[1] == len(inner):
            inner = inner[1:-1].strip()
        tok, k = _atom(inner, 0)
        if inner[k:].strip():
            raise NotHandled(f"cannot read {inner!r}")
        if m.group(1) in _BOLD:
            tok.bold = True
        elif m.group(1) == "mathrm":
            tok.roman = True
        else:
            tok.dots += 1 if m.group(1) == "dot" else 2
    elif m and m.group(1) in _GREEK:
        tok, j = Tok("atom", m.group(1)), i + m.end()
    elif i < len(s) and s[i].isascii() and s[i].isalpha():
        tok, j = Tok("atom", s[i]), i + 1
    elif i < len(s) and s[i] == "{":
        inner, j = group(s, i)
        tok, k = _atom(inner.strip(), 0)
        if inner.strip()[k:].strip():
            raise NotHandled("a group that is not one symbol")
    else:
        raise NotHandled(f"cannot read {s[i:i + 10]!r}")
    while j < len(s):
        k = j
        while k < len(s) and s[k] == " ":
            k += 1
        if k < len(s) and s[k] == "'":
            tok.primes, j = tok.primes + 1, k + 1
        elif k < len(s) and s[k] == "_" and not tok.sub:
            sub, j = group(s, k + 1)
            tok.sub = _plain(sub)
        elif k < len(s) and s[k] == "^" and not tok.sup:
            sup, after = group(s, k + 1)
            plain = _plain(sup)
            if re.fullmatch(r"[a-c]", plain):
                tok.sup, j = plain, after            # a component's axis label (ω^a)
            else:
                break
        else:
            break
    return tok, j


def tokens(s: str) -> list[Tok]:
    out, i = [], 0
    while i < len(s):
        ch = s[i]
        if ch.isspace() or ch in "~&":
            i += 1
            continue
        if ch in DIGITS:
            m = re.match(r"[0-9]+(?:\.[0-9]+)?", s[i:])
            out.append(Tok("num", m.group(0)))
            i += m.end()
            continue
        if ch in "+-()=,;^/_":
            out.append(Tok("rel" if ch == "=" else "op", ch))
            i += 1
            continue
        if ch in "{}":
            out.append(Tok("op", "(" if ch == "{" else ")"))
            i += 1
            continue
        if ch == "\\":
            m = re.match(r"\\([A-Za-z]+|.)", s[i:])
            name = m.group(1)
            if name in _SKIP:
                i += m.end()
                continue
            if name == "\\":
                out.append(Tok("op", "\\\\"))
                i += m.end()
                continue
            if name in ("frac", "sin", "cos", "times", "partial", "cdot"):
                out.append(Tok("cmd", name))
                i += m.end()
                continue
            if name in ("begin", "end"):
                env, j = group(s, i + m.end())
                if env.strip() not in ("pmatrix", "bmatrix", "matrix"):
                    raise NotHandled(f"environment {env}")
                out.append(Tok("env", name))
                i = j
                continue
        tok, j = _atom(s, i)
        out.append(tok)
        i = j
    return out


class Values:
    """What each symbol of the text stands for on one instant (`motion_jets.Instant`). Symbols the
    text leaves arbitrary — a bold lower-case letter (a vector), a capital letter it calls a
    rotation — get random values, the same for every member of a statement."""

    def __init__(self, decl, instant: mj.Instant, angle_names, names, seed, rotations=False):
        self.decl, self.x, self.angle_names, self.names = decl, instant, angle_names, names
        self.rng = random.Random(seed)
        self.rotations = rotations
        self.arbitrary = {}
        self.free = set()      # the arbitrary symbols a statement used

    def component(self, tok: Tok):
        label = tok.sup or tok.sub
        return self.decl.labels.get(label) if label else None

    def symbol(self, tok: Tok):
        x, d = self.x, self.decl
        b = tok.value
        body_axes = tok.primes > 0 if d.primes_principal else None
        if tok.dots:
            raise NotHandled("a dotted symbol in operator notation")
        if b in d.moments and not tok.bold and not tok.sub and not tok.primes and not tok.roman:
            return mj.Jet([x.moments[d.moments.index(b)]])
        if b in self.angle_names and not tok.bold and not tok.sub and not tok.primes:
            return x.angles[self.angle_names.index(b)]
        if tok.bold and b == d.orientation and not tok.primes and not tok.sub:
            return x.M
        meaning = self.names.get(b)
        k = self.component(tok)
        inertial = "xyz".index(tok.sub) if tok.sub in ("x", "y", "z") and not tok.primes else None
        if meaning in ("angular velocity", "angular momentum", "torque"):
            body = {"angular velocity": x.omega, "angular momentum": x.inertia @ x.omega, "torque": x.torque}[meaning]
            if k is not None and not tok.primes:
                return body[k]
            if inertial is not None and d.labels:
                return (x.M @ body)[inertial]
            if tok.bold and not tok.sub and body_axes is not None:
                return body if body_axes else x.M @ body
            raise NotHandled(f"cannot tell the axes of {b}")
        if b == "I" and tok.bold and tok.primes == 1 and d.primes_principal and not tok.sub:
            return x.inertia
        if b == "p" and tok.sub in self.angle_names and not tok.bold and not tok.primes:
            return x.momenta()[self.angle_names.index(tok.sub)]
        if tok.primes or tok.sub or tok.sup or tok.roman or b in self.names or b == d.derivative:
            raise NotHandled(f"unknown symbol {b}")
        if tok.bold and len(b) == 1 and b.islower():
            kind = "vector"
        elif self.rotations and len(b) == 1 and b.isupper() and b != d.orientation:
            kind = "rotation"
        else:
            raise NotHandled(f"unknown symbol {b}")
        if b not in self.arbitrary:
            if kind == "vector":
                self.arbitrary[b] = mj.jet_array([self.rng.uniform(-1, 1) for _ in range(3)])
            else:
                self.arbitrary[b] = mj.rotation("zxz", [mj.Jet([self.rng.uniform(0.2, 1.3)]) for _ in range(3)])
        self.free.add(b)
        return self.arbitrary[b]


class Parser:
    """Recursive descent over `tokens`: sums, signed products, × between products, D, 𝒜, ∂."""

    def __init__(self, toks, values: Values):
        self.t, self.k, self.v = toks, 0, values

    def peek(self, kind=None, value=None):
        if self.k >= len(self.t):
            return None
        tok = self.t[self.k]
        if (kind and tok.kind != kind) or (value is not None and tok.value != value):
            return None
        return tok

    def peek_at(self, offset, value):
        k = self.k + offset
        return k < len(self.t) and self.t[k].kind == "op" and self.t[k].value == value

    def take(self, kind=None, value=None):
        tok = self.peek(kind, value)
        if tok is None:
            raise NotHandled(f"expected {value or kind}")
        self.k += 1
        return tok

    def members(self):
        out = [self.expr()]
        while self.peek("rel"):
            self.take("rel")
            out.append(self.expr())
        if self.k != len(self.t):
            raise NotHandled("tokens left over")
        return out

    def expr(self):
        sign = -1 if self.peek("op", "-") else 1
        if self.peek("op", "-") or self.peek("op", "+"):
            self.k += 1
        value = self.crossed() * sign if sign < 0 else self.crossed()
        while self.peek("op", "+") or self.peek("op", "-"):
            op = self.take().value
            rhs = self.crossed()
            value = value + rhs if op == "+" else value - rhs
        return value

    def crossed(self):
        value = self.product()
        while self.peek("cmd", "times"):
            self.take()
            value = mj.cross(_vector(value), _vector(self.product()))
        return value

    def product(self):
        value = self.power()
        while self.starts_factor():
            value = _mul(value, self.power())
        return value

    def starts_factor(self):
        tok = self.peek()
        if tok is None:
            return False
        return tok.kind in ("atom", "num", "env") or (tok.kind == "op" and tok.value == "(") or \
            (tok.kind == "cmd" and tok.value in ("frac", "sin", "cos", "partial"))

    def power(self):
        value = self.primary()
        while self.peek("op", "^"):
            self.take()
            sup = self.script()
            if sup in ("T", "top", "intercal"):
                value = _transpose(value)
            elif re.fullmatch(r"-?\d", sup):
                n = int(sup)
                value = _inverse(value) if n == -1 and isinstance(value, mj.Array) else _power(value, n)
            else:
                raise NotHandled(f"superscript {sup}")
        return value

    def script(self) -> str:
        """A superscript as plain text (a group, or one token)."""
        if self.peek("op", "("):
            depth, parts = 0, []
            while True:
                tok = self.take()
                if tok.kind == "op" and tok.value == "(":
                    depth += 1
                    if depth == 1:
                        continue
                elif tok.kind == "op" and tok.value == ")":
                    depth -= 1
                    if depth == 0:
                        break
                parts.append(str(tok.value))
            return "".join(parts)
        tok = self.take()
        if tok.kind == "op" and tok.value == "-":
            return "-" + str(self.take("num").value)
        return str(tok.value)

    def primary(self):
        tok = self.peek()
        if tok is None:
            raise NotHandled("a formula ends early")
        d = self.v.decl
        if tok.kind == "num":
            self.k += 1
            return mj.Jet([int(tok.value)] if tok.value.isdigit() else [float(tok.value)])
        if tok.kind == "op" and tok.value == "(":
            self.k += 1
            value = self.expr()
            self.take("op", ")")
            return value
        if tok.kind == "env":
            return self.matrix()
        if tok.kind == "cmd" and tok.value == "frac":
            self.k += 1
            num = self.braced()
            den = self.braced()
            return _mul(num, _reciprocal(den))
        if tok.kind == "cmd" and tok.value in ("sin", "cos"):
            self.k += 1
            s, c = mj.sin_cos(_scalar(self.power()))
            return s if tok.value == "sin" else c
        if tok.kind == "cmd" and tok.value == "partial":
            return self.partial()
        if tok.kind == "atom" and tok.value == d.derivative and not (tok.bold or tok.sub or tok.primes or tok.sup):
            self.k += 1
            return mj.derivative(self.power())
        if tok.kind == "atom" and tok.roman and tok.value == d.cross and not tok.sub:
            self.k += 1
            inverse = False
            if self.peek("op", "^"):
                self.take()
                if self.script() != "-1":
                    raise NotHandled("a power of the cross-product operator")
                inverse = True
            self.take("op", "(")
            arg = self.expr()
            self.take("op", ")")
            return mj.vee(arg) if inverse else mj.hat(_vector(arg))
        if tok.kind == "atom" and tok.value == "R" and tok.sub in ("x", "y", "z") and not tok.bold and self.peek_at(1, "("):
            self.k += 1                         # R_z(φ): the active turn about z by φ
            return mj.active(tok.sub, _scalar(self.braced()))
        if tok.kind == "atom":
            self.k += 1
            value = self.v.symbol(tok)
            self.at_time()
            return value
        raise NotHandled(f"cannot read {tok.value}")

    def at_time(self):
        """``X(t)``: the symbol at the time t (its value now)."""
        if self.peek("op", "(") and self.k + 2 < len(self.t) and self.t[self.k + 1].kind == "atom" and \
                self.t[self.k + 1].value == "t" and self.t[self.k + 2].kind == "op" and self.t[self.k + 2].value == ")":
            self.k += 3

    def braced(self):
        self.take("op", "(")
        value = self.expr()
        self.take("op", ")")
        return value

    def partial(self):
        """∂_{q̇} L (the momentum of angle q) and ∂_{1,k} V(t; q…) (∂V/∂q_k = −Q_k)."""
        self.take("cmd", "partial")
        self.take("op", "_")
        if self.peek("op", "("):
            self.take()
            first = self.take()
            if first.kind == "num" and self.peek("op", ","):
                self.take()
                k = int(self.take("num").value)
                self.take("op", ")")
                name = self.take("atom")
                if int(first.value) != 1 or name.bold or name.value in self.v.names or name.value in self.v.decl.moments:
                    raise NotHandled("a partial derivative of something other than a potential")
                order = self.arguments()
                if not 0 <= k < len(order):
                    raise NotHandled("a slot the potential does not have")
                return -self.v.x.generalised_forces()[self.v.angle_names.index(order[k])]
            self.take("op", ")")
        else:
            first = self.take("atom")
        if first.kind == "atom" and first.dots == 1 and first.value in self.v.angle_names:
            lag = self.take("atom")
            if lag.value != "L" or lag.bold or lag.sub:
                raise NotHandled("∂ of something other than the Lagrangian")
            return self.v.x.momenta()[self.v.angle_names.index(first.value)]
        raise NotHandled("a partial derivative it does not know")

    def arguments(self) -> list:
        """``(t; θ(t), φ(t), ψ(t))``: the time slot and the angles; the angles in the slot's order."""
        self.take("op", "(")
        seen, depth = [], 1
        while depth:
            tok = self.take()
            if tok.kind == "op" and tok.value == "(":
                depth += 1
            elif tok.kind == "op" and tok.value == ")":
                depth -= 1
            elif tok.kind == "atom" and depth == 1:
                seen.append(tok.value)
        if seen[:1] != ["t"] or sorted(seen[1:]) != sorted(self.v.angle_names):
            raise NotHandled("a potential's arguments are not the time and the angles")
        return seen[1:]

    def matrix(self):
        self.take("env", "begin")
        rows, row, cell = [], [], []
        while not self.peek("env", "end"):
            if self.peek("op", "\\\\"):
                self.take()
                row.append(cell)
                rows.append(row)
                row, cell = [], []
                continue
            if self.peek("op", ";") and self.k + 1 < len(self.t) and self.t[self.k + 1].kind == "op" and \
                    self.t[self.k + 1].value == ";":
                self.k += 2
                row.append(cell)
                cell = []
                continue
            cell.append(self.take())
        self.take("env", "end")
        if cell or row:
            row.append(cell)
            rows.append(row)
        values = [[_scalar(Parser(c, self.v).whole()) for c in r] for r in rows if any(r)]
        if len({len(r) for r in values}) != 1:
            raise NotHandled("a ragged matrix")
        out = mj.Array.of(values)
        if out.shape[1] == 1:
            return out[:, 0]
        if out.shape != (3, 3):
            raise NotHandled("a matrix that is not 3×3")
        return out

    def whole(self):
        value = self.expr()
        if self.k != len(self.t):
            raise NotHandled("tokens left in a cell")
        return value


def _scalar(x):
    if isinstance(x, mj.Array):
        raise NotHandled("a matrix where a number is meant")
    return mj.Jet.lift(x)


def _vector(x):
    if not isinstance(x, mj.Array) or x.shape != (3,):
        raise NotHandled("a vector is meant")
    return x


def _mul(a, b):
    if isinstance(a, mj.Array) and isinstance(b, mj.Array):
        if a.ndim == 1 and b.ndim == 1:
            raise NotHandled("a product of two vectors")
        return a @ b
    return a * b


def _reciprocal(x):
    return _scalar(x).reciprocal()


def _power(x, n):
    if isinstance(x, mj.Array):
        raise NotHandled("a power of a matrix")
    return mj.Jet.lift(x) ** n


def _transpose(x):
    if not isinstance(x, mj.Array) or x.ndim != 2:
        raise NotHandled("a transpose of something that is not a matrix")
    return x.T


def _inverse(m):
    if m.ndim != 2:
        raise NotHandled("an inverse of a vector")
    cof = mj.Array.of([[m[(i + 1) % 3, (j + 1) % 3] * m[(i + 2) % 3, (j + 2) % 3]
                        - m[(i + 1) % 3, (j + 2) % 3] * m[(i + 2) % 3, (j + 1) % 3] for j in range(3)]
                       for i in range(3)])
    det = sum(m[0, j] * cof[0, j] for j in range(3))
    return cof.T * mj.Jet.lift(det).reciprocal()


def flat(value) -> list:
    """A member's value now (t = t₀), as a list of numbers."""
    if isinstance(value, mj.Array):
        return [mj.Jet.lift(e).value for e in value.ravel()]
    return [mj.Jet.lift(value).value]


def prepared(latex: str) -> str:
    """The statement with a matrix's cells marked (``;;``) and redundant braces around a
    decorated symbol dropped (``{\\mathbf{L}}'`` is ``\\mathbf{L}'``); braces around a function of
    a braced argument stay (``\\frac{1}{\\sin{\\theta}}``: they are the fraction's denominator)."""
    text = re.sub(r"\\begin\{(pmatrix|bmatrix|matrix)\}(.*?)\\end\{\1\}",
                  lambda m: "\\begin{" + m.group(1) + "}" + m.group(2).replace("&", " ;; ") + "\\end{" + m.group(1) + "}",
                  latex, flags=re.S)
    for _ in range(3):
        text = _DECORATED_IN_BRACES.sub(r"\1", text)
    return text


def evaluate(latex: str, values: Values) -> list:
    """The members of a chain ``a = b = c`` as values on ``values``' instant."""
    return Parser(tokens(prepared(latex)), values).members()
