"""A one-coordinate system in the text's own names: its Lagrangian L(q, q̇) and its functions of q.

Takes: one statement's LaTeX and what the text has defined so far (`Defined`). Gives: the
statement's members as SymPy expressions in q, q̇, q̈ and the text's parameters (`read`).
May import: the standard library, sympy, :mod:`derive.lecture.operator_notation` (`NotHandled`:
a statement this reading leaves to the general reader), :mod:`derive.lecture.latex_spaces`.

A body with one coordinate (a hoop rolling on the floor through an angle θ, a pendulum) is
described by functions the text names: ``I_P(\\theta) = 2mR(R - a\\cos\\theta)``, ``x_C =
a\\sin\\theta - \\theta R`` (an expression in the coordinate), ``V(\\theta)`` (left unknown),
``I_{P_0}(\\theta, \\theta_0) = …``. Read as:

============================================  =============================================
written                                       read as
============================================  =============================================
``f(\\theta)``, ``f(\\theta_0)``, ``x_C(\\theta)``  the text's function at that argument (an expression in θ: θ replaced)
``f'(\\theta)``, ``I'_{p}(\\theta)``          its derivative with respect to its argument
``y_C^2(\\theta)``                            (y_C(θ))²
``V(\\theta)``, never defined                  an unknown function of θ (any function: the statement must hold for all)
``m R^2 (\\dot\\theta)^2``                      a product: a lone rate in brackets after a symbol no function of the text's
``\\frac{\\partial X}{\\partial \\theta}``, ``\\partial X/\\partial\\dot\\theta``   partial derivatives, q̇ independent of q
``\\frac{d}{dt} X``, ``\\frac{dX}{dt}``         d/dt: ∂X/∂q q̇ + ∂X/∂q̇ q̈
``X \\right|_{\\theta = \\theta_0}``            X at θ = θ₀
``p_\\theta``                                 ∂L/∂q̇ of the text's Lagrangian
============================================  =============================================
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

import sympy as sp

from derive.lecture.latex_spaces import QUAD_NAMES, SPACE_NAMES
from derive.lecture.operator_notation import NotHandled, group
from derive.lecture.latex_spellings import DIGITS

_GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "vartheta", "iota", "kappa",
          "lambda", "mu", "nu", "xi", "rho", "sigma", "tau", "phi", "varphi", "chi", "psi", "omega", "Gamma",
          "Delta", "Theta", "Lambda", "Phi", "Psi", "Omega"}
_SKIP = SPACE_NAMES | QUAD_NAMES | {"left", "big", "Big", "bigg", "Bigg", "bigl", "bigr", "Bigl", "Bigr", "biggl",
                                   "biggr", "displaystyle", "cdot"}


@dataclass
class Defined:
    """What the text has defined: its coordinate, its functions and symbols (name → (parameters,
    body); a symbol has none), the names met so far and its Lagrangian's name."""

    q: sp.Symbol
    functions: dict = field(default_factory=dict)
    met: set = field(default_factory=set)
    lagrangian: str | None = None

    @property
    def qd(self):
        return sp.Symbol(self.q.name + "_d", real=True)

    @property
    def qdd(self):
        return sp.Symbol(self.q.name + "_dd", real=True)


@dataclass
class Atom:
    name: str           # base with subscript: "I_P_0", "x_C", "theta_0"
    primes: int = 0
    dots: int = 0


def _sub(s: str) -> str:
    s = re.sub(r"\\(mathrm|text|rm)\s*", "", s)
    s = re.sub(r"\\([A-Za-z]+)", r"\1", s).replace("{", "").replace("}", "").replace(" ", "")
    if not re.fullmatch(r"[A-Za-z0-9_]+", s):
        raise NotHandled(f"a subscript {s!r}")
    return s


def _atom(s: str, i: int) -> tuple[Atom, int]:
    m = re.match(r"\\(dot|ddot)\s*", s[i:])
    if m:
        inner, j = group(s, i + m.end())
        atom, k = _atom(inner.strip(), 0)
        if inner.strip()[k:].strip():
            raise NotHandled("a dot over more than a symbol")
        atom.dots += 1 if m.group(1) == "dot" else 2
    else:
        m = re.match(r"\\([A-Za-z]+)", s[i:])
        if m and m.group(1) in _GREEK:
            atom, j = Atom(m.group(1)), i + m.end()
        elif i < len(s) and s[i].isascii() and s[i].isalpha():
            atom, j = Atom(s[i]), i + 1
        elif i < len(s) and s[i] == "{":
            inner, j = group(s, i)
            atom, k = _atom(inner.strip(), 0)
            if inner.strip()[k:].strip():
                raise NotHandled("a group that is not one symbol")
        else:
            raise NotHandled(f"cannot read {s[i:i + 10]!r}")
    subbed = "_" in atom.name
    while j < len(s):
        k = j
        while k < len(s) and s[k] == " ":
            k += 1
        if k < len(s) and s[k] == "'":
            atom.primes, j = atom.primes + 1, k + 1
        elif k < len(s) and s[k] == "_" and not subbed:
            sub, j = group(s, k + 1)
            atom.name, subbed = atom.name + "_" + _sub(sub), True
        else:
            break
    return atom, j


def tokens(s: str) -> list:
    out, i = [], 0
    s = re.sub(r"\\mathrm\s*\{\s*d\s*\}", " d ", s)
    while i < len(s):
        ch = s[i]
        if ch.isspace() or ch in "&~":
            i += 1
            continue
        if ch in DIGITS:
            m = re.match(r"[0-9]+(?:\.[0-9]+)?", s[i:])
            out.append(("num", m.group(0)))
            i += m.end()
            continue
        if ch in "+-()=/^,":
            out.append(("rel" if ch == "=" else "op", ch))
            i += 1
            continue
        if ch in "{}":
            out.append(("op", "(" if ch == "{" else ")"))
            i += 1
            continue
        if ch == "\\":
            m = re.match(r"\\([A-Za-z]+|.)", s[i:])
            name = m.group(1)
            if name == "right":
                bar = re.match(r"\\right\s*\|\s*_", s[i:])
                if not bar:
                    i += m.end()
                    continue
                sub, j = group(s, i + bar.end())
                out.append(("at", sub))
                i = j
                continue
            if name in _SKIP:
                i += m.end()
                continue
            if name in ("frac", "sin", "cos", "tan", "sqrt", "partial", "pi"):
                out.append(("cmd", name))
                i += m.end()
                continue
            if name not in _GREEK and name not in ("dot", "ddot"):
                raise NotHandled(f"\\{name}")
        atom, j = _atom(s, i)
        out.append(("atom", atom))
        i = j
    return _rates_folded(out)


def _rates_folded(toks: list) -> list:
    """The tokens with a rate of one symbol written d/dt (``\\frac{d\\theta}{dt}``, ``d\\theta/dt``,
    ``\\frac{d^2\\theta}{dt^2}``) as the dotted symbol, θ̇, θ̈: as the formula reader reads them
    (`derive.lecture.written_rates`)."""
    d, t, opened, closed = ("atom", Atom("d")), ("atom", Atom("t")), ("op", "("), ("op", ")")
    out, k = [], 0
    while k < len(toks):
        for n, shape in ((1, [("cmd", "frac"), opened, d, None, closed, opened, d, t, closed]),
                         (2, [("cmd", "frac"), opened, d, ("op", "^"), ("num", "2"), None, closed, opened, d, t,
                              ("op", "^"), ("num", "2"), closed]),
                         (1, [d, None, ("op", "/"), d, t]),
                         (2, [d, ("op", "^"), ("num", "2"), None, ("op", "/"), d, t, ("op", "^"), ("num", "2")])):
            part = toks[k:k + len(shape)]
            x = shape.index(None)
            if len(part) == len(shape) and part[x][0] == "atom" and \
                    all(want is None or got == want for got, want in zip(part, shape)):
                a = part[x][1]
                out.append(("atom", Atom(a.name, a.primes, a.dots + n)))
                k += len(shape)
                break
        else:
            out.append(toks[k])
            k += 1
    return out


class Reader:
    """Recursive descent into SymPy (see the module docstring)."""

    def __init__(self, toks, defined: Defined):
        self.t, self.k, self.d = toks, 0, defined
        self.names = set()            # the names this statement uses
        self.bare = []                # members that are a function's bare name (L for L(q, q̇))

    def peek(self, kind=None, value=None):
        if self.k >= len(self.t):
            return None
        tok = self.t[self.k]
        if (kind and tok[0] != kind) or (value is not None and tok[1] != value):
            return None
        return tok

    def take(self, kind=None, value=None):
        tok = self.peek(kind, value)
        if tok is None:
            raise NotHandled(f"expected {value or kind}")
        self.k += 1
        return tok

    def members(self) -> list:
        out = [self.member()]
        while self.peek("rel"):
            self.take()
            out.append(self.member())
        if self.k != len(self.t):
            raise NotHandled("tokens left over")
        return out

    def member(self):
        start = self.k
        value = self.expr()
        if self.k == start + 1 and self.t[start][0] == "atom" and self.t[start][1].name in self.d.functions \
                and self.d.functions[self.t[start][1].name][0]:
            self.bare.append(len(self.bare))
            return None                              # L written bare where L(q, q̇) was defined
        while self.peek("at"):
            value = self.evaluated(value, self.take()[1])
        return value

    def evaluated(self, value, where):
        m = re.fullmatch(r"\s*(.+?)\s*=\s*(.+?)\s*", where)
        if not m:
            raise NotHandled("an evaluation bar without q = value")
        left = Reader(tokens(m.group(1)), self.d).expr()
        right = Reader(tokens(m.group(2)), self.d).expr()
        if left != self.d.q:
            raise NotHandled("an evaluation at something other than the coordinate")
        return value.subs(self.d.q, right)

    def expr(self):
        sign = 1
        if self.peek("op", "-") or self.peek("op", "+"):
            sign = -1 if self.take()[1] == "-" else 1
        value = sign * self.term()
        while self.peek("op", "+") or self.peek("op", "-"):
            op = self.take()[1]
            value = value + self.term() if op == "+" else value - self.term()
        return value

    def term(self):
        value = self.power()
        while True:
            if self.peek("op", "/"):
                self.take()
                value = value / self.power()
            elif self.starts():
                value = value * self.power()
            else:
                return value

    def starts(self):
        tok = self.peek()
        return tok is not None and (tok[0] in ("atom", "num") or tok == ("op", "(") or
                                    (tok[0] == "cmd" and tok[1] in ("frac", "sin", "cos", "tan", "sqrt", "partial", "pi")))

    def power(self):
        value = self.primary()
        if self.peek("op", "^"):
            self.take()
            value = value ** self.exponent()
        return value

    def exponent(self):
        if self.peek("op", "("):
            self.take()
            value = self.expr()
            self.take("op", ")")
            return value
        tok = self.take()
        if tok[0] == "num":
            return sp.Integer(tok[1])
        raise NotHandled("an exponent")

    def primary(self):
        tok = self.peek()
        if tok is None:
            raise NotHandled("a formula ends early")
        if tok[0] == "num":
            self.k += 1
            return sp.Rational(tok[1])
        if tok == ("op", "("):
            self.k += 1
            value = self.expr()
            self.take("op", ")")
            return value
        if tok[0] == "cmd":
            self.k += 1
            if tok[1] == "pi":
                return sp.pi
            if tok[1] in ("sin", "cos", "tan"):
                return getattr(sp, tok[1])(self.power())
            if tok[1] == "sqrt":
                return sp.sqrt(self.power())
            if tok[1] == "frac":
                return self.fraction()
            if tok[1] == "partial":
                raise NotHandled("∂ outside a fraction")
        if tok[0] == "atom":
            self.k += 1
            return self.symbol(tok[1])
        raise NotHandled(f"cannot read {tok[1]}")

    def group_tokens(self) -> list:
        """The tokens of a braced group (the reader's '(' … ')')."""
        self.take("op", "(")
        depth, out = 1, []
        while True:
            tok = self.take()
            if tok == ("op", "("):
                depth += 1
            elif tok == ("op", ")"):
                depth -= 1
                if depth == 0:
                    return out
            out.append(tok)

    def fraction(self):
        num, den = self.group_tokens(), self.group_tokens()
        if den[:1] == [("cmd", "partial")] or den[:1] == [("atom", Atom("d"))]:
            return self.derivative(num, den)
        return self.sub_read(num) / self.sub_read(den)

    def sub_read(self, toks):
        r = Reader(toks, self.d)
        value = r.expr()
        if r.k != len(toks):
            raise NotHandled("tokens left in a group")
        self.names |= r.names
        return value

    def derivative(self, num, den):
        """∂X/∂q, ∂X/∂q̇, dX/dt, and d/dt followed by its operand."""
        partial = den[0][0] == "cmd"
        if not num or num[0] not in (("cmd", "partial"), ("atom", Atom("d"))):
            raise NotHandled("a derivative's numerator")
        rest = den[1:]
        if len(rest) == 1 and rest[0][0] == "atom":
            var = rest[0][1]
        elif len(rest) == 3 and rest[0] == ("op", "(") and rest[2] == ("op", ")") and rest[1][0] == "atom":
            var = rest[1][1]
        else:
            raise NotHandled("a derivative's variable")
        operand = self.sub_read(num[1:]) if num[1:] else self.power()
        if not partial:
            if var.name != "t" or var.dots:
                raise NotHandled("d/d of something other than t")
            return self.time_derivative(operand)
        if var.name != self.d.q.name or var.primes:
            raise NotHandled("∂ with respect to something other than the coordinate")
        return sp.diff(operand, self.d.qd if var.dots == 1 else self.d.q)

    def time_derivative(self, e):
        q, qd, qdd = self.d.q, self.d.qd, self.d.qdd
        if e.has(qdd):
            raise NotHandled("d/dt of an acceleration")
        return sp.diff(e, q) * qd + sp.diff(e, qd) * qdd

    def arguments(self):
        """``(θ)``, ``(θ, θ₀)``, ``(θ, \\dot θ)``: a list of symbols, or None (a product follows)."""
        k = self.k
        if not self.peek("op", "("):
            return None
        toks, j = [], k + 1
        while j < len(self.t) and self.t[j] != ("op", ")"):
            toks.append(self.t[j])
            j += 1
        if j >= len(self.t) or not toks or len(toks) % 2 == 0:
            return None
        if any(t[0] != "atom" for t in toks[::2]) or any(t != ("op", ",") for t in toks[1::2]):
            return None
        atoms = [t[1] for t in toks[::2]]
        if any(a.primes or a.name.split("_")[0] != self.d.q.name or a.dots > 1 for a in atoms):
            return None
        self.k = j + 1
        return [self.symbol(a) for a in atoms]

    def symbol(self, a: Atom):
        d = self.d
        if a.name == d.q.name and not a.primes:
            return (d.q, d.qd, d.qdd)[a.dots]
        if a.dots:
            raise NotHandled(f"a dot over {a.name}")
        if a.name == "p_" + d.q.name and d.lagrangian and not a.primes:
            self.names.add(a.name)
            return sp.diff(d.functions[d.lagrangian][1], d.qd)
        power = None
        if self.peek("op", "^") and self.k + 1 < len(self.t) and self.t[self.k + 1][0] == "num" and \
                self.k + 2 < len(self.t) and self.t[self.k + 2] == ("op", "("):
            self.k += 1
            power = sp.Integer(self.take("num")[1])      # y_C^2(θ): the power of the function's value
        before = self.k
        args = self.arguments()
        if args is not None and not self.called(a, args):
            self.k, args = before, None                  # m R^2 (θ̇)^2: a product, R is no function
        if power is not None and args is None:
            self.k -= 2
        self.names.add(a.name)
        value = self.applied(a, args)
        return value ** power if power is not None and args is not None else value

    def called(self, a: Atom, args) -> bool:
        """Whether ``a(args)`` is a call: of a function the text defined, of an expression in q at a
        point, of an unknown function (``V(\\theta)``, ``L(\\theta, \\dot\\theta) =``); a bracket
        holding a lone rate after any other symbol is a factor (``m R^2 (\\dot\\theta)^2``)."""
        d = self.d
        if a.name in d.functions:
            params, body = d.functions[a.name]
            return bool(params) or body.has(d.q)
        return len(args) > 1 or self.t[0] == ("atom", a) or not args[0].has(d.qd, d.qdd)

    def applied(self, a: Atom, args):
        d = self.d
        x = sp.Dummy("x")
        if a.name in d.functions:
            params, body = d.functions[a.name]
            if args is None:
                if params and not set(params) <= {d.q, d.qd}:
                    raise NotHandled(f"{a.name} without its arguments")
                args = list(params)            # L for L(q, q̇), f for f(q): the function itself
            if len(args) != len(params):
                if not params and len(args) == 1:
                    params = [d.q]                       # x_C = (expression in q), written x_C(θ₀)
                else:
                    raise NotHandled(f"{a.name} with {len(args)} arguments")
            if a.primes:
                if len(params) != 1:
                    raise NotHandled("a prime on a function of several arguments")
                body = sp.diff(body, params[0], a.primes)
            return body.xreplace(dict(zip(params, args))) if args else body
        if args is not None:
            if len(args) != 1:
                if a.primes:
                    raise NotHandled("a prime on an unknown function of several arguments")
                return sp.Function(a.name)(*args)
            f = sp.Function(a.name)(x)
            if a.primes:
                f = sp.diff(f, x, a.primes)
            return f.subs(x, args[0])
        if a.primes:
            raise NotHandled(f"a prime on {a.name}")
        return sp.Symbol(a.name, positive=True)


def read(latex: str, defined: Defined) -> tuple[list, set, list]:
    """The members of a chain as SymPy (None for a function's bare name), the names it uses and
    the indices of the bare members."""
    r = Reader(tokens(latex), defined)
    members = r.members()
    return members, r.names, r.bare


def left_function(latex: str, defined: Defined):
    """``f(p₁, …) =`` or ``X =`` at the start: (name, parameters as symbols) — a definition's
    form — or None."""
    depth, cut = 0, None
    for i, ch in enumerate(latex):
        depth += ch in "{(" and 1 or (-1 if ch in "})" else 0)
        if ch == "=" and depth == 0:
            cut = i
            break
    toks = tokens(latex[:cut]) if cut is not None else []
    if not toks or toks[0][0] != "atom" or toks[0][1].primes or toks[0][1].dots:
        return None
    name = toks[0][1].name
    if len(toks) == 1:
        return name, []
    r = Reader(toks, defined)
    r.k = 1
    args = r.arguments()
    if args is None or r.k != len(toks) or len(set(args)) != len(args) or any(a not in (defined.q, defined.qd)
                                                                                and not a.is_Symbol for a in args):
        return None
    return name, args
