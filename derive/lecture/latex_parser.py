"""The fast path of the LaTeX reader (`derive.lecture.latex.parse`): a recursive-descent parser
over the scanner's tokens (sums, products, implicit products, powers, ``\\frac``, ``\\sqrt``,
functions, sums over body axes, matrices, d𝐋/dt and ∂L/∂q̇) that builds SymPy objects directly,
the vocabulary resolving every atom.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass

import sympy as sp

from derive.lecture.vocabulary import (
    ACCELS, DLDT, DLDT_BODY, FUNCTIONS, INVERSES, LAGRANGIAN, LMAG, LVEC, MOMENTUM, OMEGA_VEC, WD, Atom, CrossMatrix,
    Generic, MatProduct, NotRead, Quantity, Tok, Transposed, Unknown, Vocabulary, W)
from derive.lecture import body_dot, gradients
from derive.lecture.abbreviated_trig import abbreviated_trig
from derive.lecture.axis_sums import Axis, range_letters
from derive.lecture.definite_integrals import definite_integral
from derive.lecture.evaluation_points import holds_a_point
from derive.lecture.particle_sums import over_particles
from derive.lecture.written_rates import (NOT_PARTIAL, operand_rate, partial_variable, rate_along, rate_argument,
                                         reading, symbol_rate, written_rate)
from derive.lecture.written_matrices import components, components_follow, cross, frame_label, named_dot, outer, squared_column
from derive.symbolic.rotations import ANGLES, RATES


@dataclass
class Member:
    """One side of a relation: its value and what the notes wrote as a quantity's arguments."""

    value: object
    args: tuple | None = None       # T(α, …), L(β, β̇), ω̃₁(t): the argument symbols written
    pos: int = 0


@dataclass
class Parsed:
    """A formula: members m₀ r₁ m₁ r₂ m₂ … (relations between consecutive members)."""

    members: list
    relations: list


class _Parser:
    components_in_rates = True      # d𝛚₁/dt is the scalar ω̇₁ (a grammar of vectors reads 𝛚₁ its own way)

    def __init__(self, toks: list[Tok], vocab: Vocabulary, source: str):
        self.toks, self.vocab, self.source, self.i = toks, vocab, source, 0
        self.args = None

    # helpers
    def peek(self, k=0):
        j = self.i + k
        return self.toks[j] if j < len(self.toks) else None

    def fail(self, why, tok=None):
        tok = tok or self.peek()
        col = (tok.pos + 1) if tok else len(self.source) + 1
        raise NotRead(f"cannot parse at column {col}: {why}", col)

    def take(self, kind, value=None):
        tok = self.peek()
        if tok is None or tok.kind != kind or (value is not None and tok.value != value):
            self.fail(f"expected {value or kind}")
        self.i += 1
        return tok

    def at(self, kind, value=None):
        tok = self.peek()
        return tok is not None and tok.kind == kind and (value is None or tok.value == value)

    # grammar
    def chain(self) -> Parsed:
        members, rels = [self.member()], []
        while self.at("rel"):
            rels.append(self.take("rel").value)
            members.append(self.member())
        if self.peek() is not None:
            self.fail(f"unexpected {self.peek().value!r}")
        return Parsed(members, rels)

    def member(self) -> Member:
        pos = self.peek().pos if self.peek() else len(self.source)
        self.args = None
        if self.peek() is None or self.at("rel"):
            self.fail("a side of a relation is empty")
        value = self.expr({})
        return Member(value, self.args, pos)

    def expr(self, env):
        sign = 1
        if self.at("op", "+"):
            self.i += 1
        elif self.at("op", "-"):
            self.i += 1
            sign = -1
        total = self.signed(sign, self.term(env))
        while self.at("op", "+") or self.at("op", "-") or self.at("cmd", "pm"):
            op = self.take(self.peek().kind).value
            if op == "pm":
                self.fail("± is not a single formula")
            total, rhs = self.summands(total, self.term(env))
            total = total + rhs if op == "+" else total - rhs
        return total

    def signed(self, sign, value):
        return sign * value

    def summands(self, a, b):
        """Two terms made ready to add (see `_summands`)."""
        return _summands(a, b)

    def _starts_factor(self):
        tok = self.peek()
        if tok is None:
            return False
        if tok.kind in ("num", "atom", "func", "begin"):
            return True
        if tok.kind == "op" and tok.value in "({":
            return True
        return tok.kind == "cmd" and tok.value in ("frac", "dfrac", "tfrac", "sqrt", "sum", "partial", "int") | FUNCTIONS.keys()

    def term(self, env):
        value = self.operand(env)
        while True:
            if self.at("cmd", "cdot") or self.at("op", "*"):
                self.i += 1
                value = self.dotted(value, self.operand(env))
            elif self.at("cmd", "times"):
                value = cross(self, value, env)
            elif self.at("cmd", "otimes"):
                self.i += 1
                value = outer(value, self.operand(env), self.peek())
            elif self.at("op", "/"):
                self.i += 1
                value = value / self.operand(env)
            elif self._starts_factor():
                value = self.juxtaposed(value, self.operand(env))
            else:
                return value

    def operand(self, env):
        """An operand of a product (·, /, juxtaposition)."""
        return self.factor(env)

    def dotted(self, a, b):
        dot = body_dot.dot(a, b)
        return dot if dot is not None else named_dot(a, b, _mul)

    def juxtaposed(self, a, b):
        return _mul(a, b) if (dot := body_dot.row_on_column(a, b)) is None else dot

    def factor(self, env):
        if self.at("op", "-"):
            self.i += 1
            return -self.factor(env)
        base = self.primary(env)
        while self.at("op", "^"):
            self.i += 1
            if self._transpose_mark():
                base = self.transposed(base)
                continue
            base = self.power(base, self.group_or_token(env))
        return base

    def transposed(self, base):
        return base.T if isinstance(base, sp.MatrixBase) else Transposed(base)

    def power(self, base, exp):
        if (isinstance(base, sp.MatrixBase) or not getattr(base, "is_commutative", True)) and not isinstance(exp, sp.Integer):
            self.fail("a power of a matrix other than a whole number")
        vector = exp == 2 and (base is LVEC or base is OMEGA_VEC)      # 𝐋², 𝛚²: the vector dotted with itself
        return (LMAG ** 2 if base is LVEC else body_dot.dot(base, base)) if vector else squared_column(base, exp, self.vocab)

    def _transpose_mark(self) -> bool:
        """^T, ^{T}, ^\\top, ^\\intercal after a matrix: its transpose (never a power T)."""
        tok = self.peek()
        if tok is not None and tok.kind == "atom" and tok.value.base in ("T", "top", "intercal") \
                and not tok.value.sub and not tok.value.dots:
            self.i += 1
            return True
        if tok is not None and tok.kind == "op" and tok.value == "{":
            inner, close = self.peek(1), self.peek(2)
            if inner is not None and inner.kind == "atom" and inner.value.base in ("T", "top", "intercal") \
                    and close is not None and close.kind == "op" and close.value == "}":
                self.i += 3
                return True
        return False

    def group_or_token(self, env):
        """A superscript or a function argument written without braces: one token or a group."""
        if self.at("op", "{") or self.at("op", "("):
            return self.paren(env)
        tok = self.peek()
        if tok is not None and tok.kind == "num":
            self.i += 1
            # ^23 means ^{2}3 in TeX: one digit only
            digits = tok.value
            if len(digits) > 1 and digits.isdigit():
                self.toks.insert(self.i, Tok("num", digits[1:], tok.pos + 1))
                return sp.Integer(digits[0])
            return sp.Rational(digits)
        if tok is not None and tok.kind == "atom":
            self.i += 1
            return self.atom(tok, env)
        if tok is not None and tok.kind == "op" and tok.value == "-":
            self.i += 1
            return -self.group_or_token(env)
        self.fail("expected an exponent")

    def paren(self, env):
        open_ = self.take("op").value
        close = ")" if open_ == "(" else "}"
        value = self.expr(env)
        if not self.at("op", close):
            self.fail("expected a closing bracket")
        self.i += 1
        return value

    def atom(self, tok, env):
        value = self.vocab.resolve(tok.value, env)
        if value is None:
            raise Unknown(f"unknown symbol {tok.value.text}", tok.pos + 1)
        return value

    def primary(self, env):
        tok = self.peek()
        if tok is None:
            self.fail("the formula ends too early")
        if tok.kind == "num":
            self.i += 1
            return sp.Rational(tok.value)
        if tok.kind == "atom" and (rate := written_rate(self.toks, self.i)) is not None:      # dx/dt
            return self._rate_written(*rate)
        if tok.kind == "atom":
            self.i += 1
            value = self.atom(tok, env)
            # a quantity written with its arguments: T(α, β, …), V_eff(β), ω̃₁(t)
            if self.at("op", "(") and (isinstance(value, Quantity) or value in W) and self._argument_list():
                return value
            if self.at("op", "(") and (value in ANGLES or value in RATES or value in ACCELS) and self._of_time():
                return value                    # θ(t), θ̇(t): an angle or its rates written as functions of the time
            trig = self._abbreviated_trig(tok, env) if isinstance(value, Generic) else None
            if trig is not None:
                return trig
            inner = self.peek(1)
            if self.at("op", "(") and isinstance(value, Generic) and tok.value.bold and \
                    not (inner is not None and inner.kind == "atom" and inner.value.bold):   # 𝐀(𝐁) is a product
                kept = self.args
                if self._argument_list():       # 𝐒(φ, θ): a matrix of the text's, with what it depends on
                    self.args = kept
                    return value
            own = isinstance(value, Generic) or type(value) is sp.Symbol and value.name in ("A", "B", "C")
            if self.at("op", "(") and own and (self._listed_arguments() or self._of_time()):
                return value                    # f₁(ω₁, ω₂, ω₃), C(φ, θ, ψ), R(t): a name with what it depends on
            if self.at("op", "(") and (value in W or value in WD or isinstance(value, Generic)):
                at = self._at_a_time(tok, value)
                if at is not None:
                    return at
            return value
        if tok.kind == "op" and tok.value in "({":
            value = components(self, env) if components_follow(self.toks, self.i) else self.paren(env)
            if self.at("op", "_"):
                self.fail("a subscript on a bracket")
            return value
        if tok.kind == "op" and tok.value == "|":
            self.i += 1
            value = self.expr(env)
            self.take("op", "|")
            plain_omega = isinstance(value, Generic) and (self.vocab.generic.get(value) or Atom("")).base == "omega" \
                and not self.vocab.generic[value].sub and not self.vocab.generic[value].dots
            if value is OMEGA_VEC or plain_omega:
                return sp.sqrt(body_dot.dot(OMEGA_VEC, OMEGA_VEC))     # |𝛚|, |ω|: the angular velocity's magnitude
            return LMAG if value is LVEC else sp.Abs(value)      # |𝐋|: the angular momentum's magnitude
        if tok.kind == "begin":
            value = self.matrix(env)
            self.i += frame_label(self.toks, self.i, self.__dict__.setdefault("frames", set()))
            return value
        if tok.kind == "cmd" and tok.value == "det" and (after := self.peek(1)) is not None and after.kind == "begin":
            self.i += 1                          # \det before a written square matrix: its determinant
            value = self.matrix(env)
            if not isinstance(value, sp.MatrixBase) or not value.is_square:
                self.fail("a determinant of what is not a square matrix", tok)
            return value.det()
        if tok.kind == "cmd":
            name = tok.value
            self.i += 1
            if name in ("frac", "dfrac", "tfrac"):
                return self.frac(env, tok)
            if name == "sqrt":
                return sp.sqrt(self.group_or_token(env))
            if name in FUNCTIONS:
                power = None
                if self.at("op", "^"):
                    self.i += 1
                    power = self.group_or_token(env)
                if self.at("op", "("):
                    arg = self.paren(env)
                else:
                    arg = self.factor_no_implicit(env)
                if power == -1 and name in INVERSES:       # \tan^{-1}: the arctangent, as texts write it
                    return INVERSES[name](arg)
                return FUNCTIONS[name](arg) ** power if power is not None else FUNCTIONS[name](arg)
            if name == "sum":
                return self.sum(env, tok)
            if name == "int":
                return definite_integral(self, env, tok)
            self.fail(f"'\\{name}' here")
        self.fail(f"unexpected {tok.value!r}")

    _abbreviated_trig = abbreviated_trig

    def _at_a_time(self, tok, value):
        """ω_y(0), u(t_1): a function of time at a time given by a number or a symbol other than
        t — the text's own symbol for that value (ω_y(0) is an initial value, not ω_y × 0)."""
        inner = self.peek(1)
        close = self.peek(2)
        if inner is None or close is None or close.kind != "op" or close.value != ")":
            return None
        if inner.kind == "num" and "." in str(inner.value) and getattr(self.peek(3), "value", None) == "^":
            return None                    # m (0.04)^2: a decimal raised to a power is a factor, no time
        if inner.kind == "num":
            label = inner.value
        elif inner.kind == "atom" and inner.value.bold:
            return None                # 𝐀(𝐁): a product of the text's matrices, not a time
        elif inner.kind == "atom" and inner.value.base != "t" or (inner.kind == "atom" and inner.value.sub):
            label = inner.value.text
        else:
            return None
        self.i += 3
        if not self.vocab.open:
            raise Unknown(f"unknown symbol {tok.value.text}({label})", tok.pos + 1)
        return self.vocab._generic(tok.value.with_(sup=f"({label})"))

    def factor_no_implicit(self, env):
        """The argument of sin/cos written without brackets: one factor (sin β cos γ = sin(β)·cos(γ)),
        with the time after it (cos Ωt = cos(Ω t): a rate times the time, as texts write it)."""
        arg, tok = self.primary(env), self.peek()
        if tok is not None and tok.kind == "atom" and tok.value.text.strip() == "t":
            self.i += 1
            arg = arg * self.vocab.resolve(tok.value, env)
        return arg

    def _listed_arguments(self) -> bool:
        """At '(': two or more bare symbols separated by commas, read as arguments (a product is
        never written so)."""
        j = self.i + 2
        if not (j < len(self.toks) and self.toks[j].kind == "op" and self.toks[j].value == ","):
            return False
        kept, listed = self.args, self._argument_list()
        self.args = kept
        return listed

    def _of_time(self) -> bool:
        """At '(': the time alone, ``(t)``, read as the argument of the name before it."""
        inner, close = self.peek(1), self.peek(2)
        timed = inner is not None and inner.kind == "atom" and inner.value.with_(text="") == Atom("t") \
            and close is not None and (close.kind, close.value) == ("op", ")")
        self.i += 3 if timed else 0
        return timed

    def _argument_list(self) -> bool:
        """At '(': if what follows is a list of bare symbols, read it as arguments and say so."""
        j, args = self.i + 1, []
        while j < len(self.toks):
            tok, rate = self.toks[j], rate_argument(self.toks, j)
            if rate is not None:
                tok, j = self.toks[rate[0]], rate[1] - 1      # dα/dt among the arguments: the rate of α
            if tok.kind != "atom":
                return False
            try:
                args.append(self.vocab.resolve(tok.value))
            except NotRead:
                return False
            if args[-1] is None or (rate is not None and args[-1] not in ANGLES):
                return False
            args[-1] = RATES[ANGLES.index(args[-1])] if rate is not None else args[-1]
            nxt = self.toks[j + 1] if j + 1 < len(self.toks) else None
            if nxt is not None and nxt.kind == "op" and nxt.value == ",":
                j += 2
                continue
            if nxt is not None and nxt.kind == "op" and nxt.value == ")":
                self.i, self.args = j + 2, tuple(args)
                return True
            return False
        return False

    def frac(self, env, tok):
        # d𝐋/dt and ∂L/∂q̇ first: they are quantities, not quotients.
        num_start = self.i
        special = self._derivative()
        if special is not None:
            return special
        self.i = num_start
        num = self.braced(env)
        den = self.braced(env)
        return num / den

    def braced(self, env):
        if self.at("op", "{"):
            return self.paren(env)
        return self.group_or_token(env)

    def _derivative(self):
        """\\frac{d X}{dt} or \\frac{\\partial L}{\\partial \\dot q}: the quantity, or None."""
        toks = self.toks
        num, k = braced_tokens(toks, self.i)
        if num is None:
            return None
        den, k2 = braced_tokens(toks, k)
        if den is None:
            return None
        is_d = lambda tk: tk.kind == "atom" and tk.value.base == "d" and not tk.value.sub and not tk.value.bold
        if len(den) == 2 and is_d(den[0]) and den[1].kind == "atom" and den[1].value.base == "t" and den[1].value.sub \
                and num and is_d(num[0]):
            raise NotRead("a derivative in a frame (d/dt with the frame's label on t)")   # dH/dt_b, never H/t_b
        if (gradient := gradients.of_energy(self.vocab.resolve, num, den)) is not None:
            self.i = k2                               # dT/d𝛚: the kinetic energy's gradient, 𝐋
            return gradient
        if (rate := written_rate(toks, self.i - 1)) is not None:
            return self._rate_written(*rate)
        if (along := rate_along(self.vocab.resolve, num, den)) is not None:
            self.i = k2                               # dx/dy of the text's own x and y: ẋ/ẏ
            return along
        is_partial = lambda tk: tk.kind == "cmd" and tk.value == "partial"  # noqa: E731
        var = partial_variable(self.vocab.resolve, den)
        if var is not NOT_PARTIAL:
            if len(num) == 1 and is_partial(num[0]) and isinstance(var, sp.Symbol):
                self.i = k2                               # ∂/∂v of what follows
                return sp.Derivative(self.term({}), var, evaluate=False)
            if len(num) == 2 and is_partial(num[0]) and num[1].kind == "atom" and isinstance(var, sp.Symbol):
                top = self.vocab.resolve(num[1].value)
                if top is LAGRANGIAN and var in RATES:
                    self.i = k2
                    return MOMENTUM[RATES.index(var)]
                if isinstance(top, sp.Symbol) and not num[1].value.bold:
                    self.i = k2
                    return sp.Derivative(top, var, evaluate=False)
            if num and is_partial(num[0]):
                raise NotRead(f"cannot parse at column {num[0].pos + 1}: a partial derivative of this form", num[0].pos + 1)
        return None

    def _rate_written(self, x, n, end):
        """dⁿx/dtⁿ written d/dt (`derive.lecture.written_rates`), read as ẋ, ẍ are (ẋ(0) too)."""
        self.i = end
        if x is None:                               # the operator d/dt: of what follows it
            return self._evaluated(operand_rate(self, n))
        tok = self.toks[x]
        value = symbol_rate(reading(self), tok, n, self.vocab if self.components_in_rates else None)
        at = self._at_a_time(Tok("atom", tok.value.with_(dots=tok.value.dots + n), tok.pos), value) \
            if self.at("op", "(") and (value in WD or isinstance(value, Generic)) else None
        return at if at is not None else self._evaluated(value)

    def _evaluated(self, value):
        """A derivative followed by a bracket holding a time: evaluated at a point (φ̇(t + T)), which
        is not read; a bracket of other quantities after it multiplies it."""
        if self.at("op", "(") and holds_a_point(self.toks, self.i):
            self.fail("a derivative evaluated at a point")
        return value

    def sum(self, env, tok):
        """Σ over a body-axis index i (or ij) = 1, 2, 3: the summand (one term) read once per value."""
        names, sub_tok = self.sum_index(tok)
        index = "".join(names)
        upper = self.group_or_token(env) if self.at("op", "^") and self.take("op") else None
        written = range_letters(index, upper, self.source, sub_tok.pos)      # Σ_{a=1}^3: a body axis, any letter
        letters = written or [ch for ch in index if ch in "ijkn"]
        if not letters or any(ch not in "ijkn" + "".join(written) for ch in index.replace("=", "").rstrip("0123456789")):
            raise NotRead(f"cannot parse at column {sub_tok.pos + 1}: sums over {index!r} (not a body axis) "
                          "are not read", sub_tok.pos + 1)
        start = self.i
        total = sp.S.Zero
        for values in itertools.product(tuple(map(Axis, (1, 2, 3))) if written else (1, 2, 3), repeat=len(letters)):
            self.i = start
            inner = {**env, **dict(zip(letters, values))}
            total = total + self.sum_term(inner, written)
        return total

    def sum_index(self, tok):
        """The letters under a Σ (``_{ij}``, ``_{i=1}``), or i over particles (`over_particles`); its first token."""
        if not self.at("op", "_"):
            return over_particles(self.toks, self.i) or self.fail("a sum without its index", tok), tok
        self.i += 1
        sub_tok = self.peek()
        if not self.at("op", "{"):
            return [self.take("atom").value.base], sub_tok
        self.i += 1
        names = []
        while not self.at("op", "}"):
            if self.peek() is None:
                self.fail("unbalanced '{'", tok)
            if self.peek().kind == "atom":
                names.append(self.peek().value.base + self.peek().value.sub)
            self.i += 1
        self.i += 1
        return names, sub_tok

    def sum_term(self, env, written=()):
        value = self.factor(env)
        while (self.at("cmd", "cdot") or self._starts_factor()) and (written or not self.at("cmd", "sum")):
            if self.at("cmd", "cdot"):
                self.i += 1
            value = _mul(value, self.factor(env))
        return value


VECTORS = (LVEC, OMEGA_VEC, DLDT, DLDT_BODY)


def braced_tokens(toks, k):
    """The tokens inside the braced group at toks[k] == '{' and the index after it; (None, k)
    when there is none or it does not close."""
    if k >= len(toks) or toks[k].kind != "op" or toks[k].value != "{":
        return None, k
    depth = 0
    for j in range(k, len(toks)):
        if toks[j].kind == "op" and toks[j].value == "{":
            depth += 1
        elif toks[j].kind == "op" and toks[j].value == "}":
            depth -= 1
            if depth == 0:
                return toks[k + 1:j], j + 1
    return None, k


def _summands(a, b):
    """A written matrix beside a term in the text's matrix names (``[\\mathbf{R}_1 \\mathbf{I}_2]_\\times +
    [\\mathbf{I}_1]_\\times``) waits as a one-factor `MatProduct`, to be added once the names are put in."""
    pending = lambda x: not isinstance(x, sp.MatrixBase) and (  # noqa: E731
        getattr(x, "is_commutative", True) is False or bool(getattr(x, "has", lambda *_: False)(CrossMatrix)))
    if isinstance(a, sp.MatrixBase) and pending(b):
        a = MatProduct(a)
    elif isinstance(b, sp.MatrixBase) and pending(a):
        b = MatProduct(b)
    return a, b


def _mul(a, b):
    """a·b or a b of scalars (and of a matrix with scalars); a product that involves a vector
    quantity twice, or a matrix and a vector quantity, is the vector reader's
    (`derive.lecture.vectors`): a dot product, or a tensor acting on a vector."""
    vec = lambda x: hasattr(x, "free_symbols") and bool(set(VECTORS) & x.free_symbols)  # noqa: E731
    mat = lambda x: isinstance(x, sp.MatrixBase)  # noqa: E731
    if (vec(a) and vec(b)) or (mat(a) and vec(b)) or (vec(a) and mat(b)):
        raise NotRead("a product of vectors: read as vectors")
    named = lambda x: getattr(x, "is_commutative", True) is False  # noqa: E731  (the text's matrix names)
    if (mat(a) or isinstance(a, MatProduct)) and named(b) or named(a) and (mat(b) or isinstance(b, MatProduct)):
        return MatProduct(*[f for x in (a, b) for f in (x.args if isinstance(x, MatProduct) else (x,))])
    return a * b


# matrices: rows of entries separated by '&'
def _matrix(self, env):
    tok = self.take("begin")
    env_name = tok.value
    if env_name == "vmatrix":
        # a square array between bars is its determinant (entries the scalar reader reads; a row of
        # unit vectors, a cross product's determinant, is the vector reader's)
        rows = self.rows(env, tok)
        if len(rows) != len(rows[0]) or any(isinstance(x, sp.MatrixBase) for row in rows for x in row):
            self.fail("a determinant that is not square, or holds matrices", tok)
        return sp.Matrix(rows).det()
    if env_name not in ("pmatrix", "bmatrix", "matrix", "Bmatrix", "array"):
        self.fail(f"the environment {env_name!r} inside a formula", tok)
    return sp.Matrix(self.rows(env, tok))


def _rows(self, env, tok):
    """A matrix's rows up to its \\end, each entry read by ``self.entry`` (all rows one length)."""
    rows, row = [], []
    while True:
        if self.at("end"):
            self.i += 1
            break
        if self.peek() is None:
            self.fail("a matrix without its end", tok)
        row.append(self.entry(env))
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
    return rows


def _entry(self, env):
    return self.expr(env)


_Parser.matrix = _matrix
_Parser.rows = _rows
_Parser.entry = _entry
