"""Formulas in quaternions as attitude texts write them, read into their four components.

Takes: one member of a display in a text about quaternions (``\\frac{1}{2}\\boldsymbol\\omega
\\mathbf{q}``, ``e^{\\mathbf{u}\\theta}``, ``\\cos\\frac{\\theta}{2} + \\mathbf{u}\\sin\\frac{\\theta}{2}``,
a column ``\\begin{bmatrix}\\cos\\frac{\\theta}{2} \\\\ \\mathbf{u}\\sin\\frac{\\theta}{2}\\end{bmatrix}``
or its four rows, ``\\lim_{\\Delta t\\to 0} …``, a sum ending in ``\\cdots``) and
the text's names (`Names`). Gives: `read`, the member's value: a SymPy scalar or a `Quat` (scalar
part first), products taken by Hamilton's rule or by its reverse (the JPL product, ``jpl=True``).
Anything outside this grammar raises `Unread` naming what stopped it: the caller leaves it
unjudged.

A bold letter is a 3-vector, read as the pure quaternion (0, 𝐯), except the quaternion letters
(q, p), which are generic quaternions of components named as the text names them (q_w, q_x, q_y,
q_z or q_0 … q_3); a column of two rows is (scalar, vector), of four rows the components, of three
a pure quaternion. The exponential of a quaternion a + 𝐯 is e^a (cos‖𝐯‖ + 𝐯/‖𝐯‖ sin‖𝐯‖), its
series' terms the powers of one quaternion, so the rule of the product does not change it.

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
    """e^x of a scalar or a quaternion a + 𝐯: e^a (cos n + 𝐯 sin n / n), n = ‖𝐯‖ (1 + 𝐯 at n = 0)."""
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
    series_var: sp.Symbol | None = None
    truncated: list = field(default_factory=list)     # the last terms before each \cdots met


_BOLD = r"\\(?:mathbf|boldsymbol|bm|vec|pmb)\s*"
_GREEK = {"alpha", "beta", "gamma", "delta", "theta", "vartheta", "phi", "varphi", "psi", "omega", "Omega",
          "lambda", "mu", "nu", "sigma", "tau", "epsilon", "eta", "xi", "rho", "kappa", "chi"}
_SIZES = r"\\(?:left|right|big|Big|bigg|Bigg)[lr]?\s*"
_TOKEN = re.compile(
    r"(?P<space>\s+|\\[,;:!]|\\quad|\\qquad|~)"
    r"|(?P<rowend>\\\\)"
    r"|(?P<norm>\\\||\\lVert|\\rVert)"
    r"|(?P<open>(?:" + _SIZES + r")?[\(\[]|(?:" + _SIZES + r")\\\{)"
    r"|(?P<close>(?:" + _SIZES + r")?[\)\]]|(?:" + _SIZES + r")\\\})"
    r"|(?P<lbrace>\{)|(?P<rbrace>\})"
    r"|(?P<cmd>\\[A-Za-z]+)"
    r"|(?P<num>\d+(?:\.\d+)?)"
    r"|(?P<letter>[A-Za-z])"
    r"|(?P<op>[+\-*/^_!&,|=])")


def tokens(tex: str) -> list[tuple[str, str]]:
    """The member's tokens (kind, text), spaces dropped."""
    out, k = [], 0
    while k < len(tex):
        m = _TOKEN.match(tex, k)
        if not m:
            raise Unread(f"cannot read {tex[k:k + 12]!r}")
        if m.lastgroup != "space":
            text = m.group(0)
            kind = m.lastgroup
            if kind in ("open", "close"):
                text = re.sub(_SIZES, "", text).strip() or text
            out.append((kind, text))
        k = m.end()
    return out


class _Reader:
    """Recursive descent over the tokens of one member."""

    def __init__(self, toks, names: Names, point: dict, reading=None):
        self.t, self.k, self.names, self.point = toks, 0, names, point
        self.reading = reading if reading is not None else set()     # the names being read in place

    def peek(self, j=0):
        return self.t[self.k + j] if self.k + j < len(self.t) else (None, None)

    def next(self):
        tok = self.peek()
        self.k += 1
        return tok

    def expect(self, kind, text=None):
        tok = self.next()
        if tok[0] != kind or (text is not None and tok[1] != text):
            raise Unread(f"expected {text or kind}, found {tok[1]!r}")
        return tok

    def whole(self):
        v = self.expr()
        if self.k < len(self.t):
            raise Unread(f"cannot read {self.peek()[1]!r} there")
        return v

    # sums and products
    def expr(self):
        total, sign, last = 0, 1, None
        if self.peek() == ("op", "-"):
            self.next()
            sign = -1
        elif self.peek() == ("op", "+"):
            self.next()
        while True:
            if self.peek() == ("cmd", "\\cdots") or self.peek() == ("cmd", "\\dots") or self.peek() == ("cmd", "\\ldots"):
                self.next()
                self.names.truncated.append(last)
            else:
                last = self.term()
                total = total + _times(sign, last)
            if self.peek() == ("op", "+"):
                self.next()
                sign = 1
            elif self.peek() == ("op", "-"):
                self.next()
                sign = -1
            else:
                return total

    def term(self):
        value = self.factor()
        while True:
            tok = self.peek()
            if tok == ("cmd", "\\otimes") or tok == ("cmd", "\\cdot") and not _is_dot_product(value):
                self.next()
                value = self.product(value, self.factor())
            elif tok[0] is not None and tok not in (("op", "+"), ("op", "-"), ("op", "&"), ("op", "=")) \
                    and tok[0] not in ("close", "rbrace", "norm", "rowend") and tok not in (("cmd", "\\cdots"), ("cmd", "\\dots"),
                                                                             ("cmd", "\\ldots")) \
                    and not (tok[0] == "cmd" and tok[1] in ("\\end", "\\rfloor")):
                value = self.product(value, self.factor())
            else:
                return value

    def product(self, a, b):
        if isinstance(a, Quat) and isinstance(b, Quat):
            return hamilton(b, a) if self.names.jpl else hamilton(a, b)
        return _times(a, b)

    def factor(self):
        base = self.primary()
        while True:
            tok = self.peek()
            if tok == ("op", "^"):
                self.next()
                base = self.power(base, self.group_value())
            elif tok == ("op", "!"):
                self.next()
                if not (isinstance(base, sp.Integer) and base >= 0):
                    raise Unread("a factorial of what is not a whole number")
                base = sp.factorial(base)
            else:
                return base

    def power(self, base, exp):
        if isinstance(base, Quat):
            if not (isinstance(exp, sp.Integer) and exp >= 0):
                raise Unread("a quaternion to a power that is not a whole number")
            out = Quat((1, 0, 0, 0))
            for _ in range(int(exp)):
                out = self.product(out, base)
            return out
        if isinstance(exp, Quat):
            raise Unread("a quaternion in an exponent")
        return base ** exp

    def group_value(self):
        """A braced group, or one token (an exponent, a fraction's part)."""
        if self.peek()[0] == "lbrace":
            self.next()
            v = self.expr()
            self.expect("rbrace")
            return v
        tok = self.peek()
        if tok[0] == "num":
            self.next()
            return sp.Rational(tok[1]) if "." not in tok[1] else sp.nsimplify(tok[1])
        return self.primary()

    def primary(self):
        kind, text = self.peek()
        if kind is None:
            raise Unread("the member ends too soon")
        if kind == "num":
            self.next()
            return sp.Rational(text) if "." not in text else sp.nsimplify(text)
        if kind == "lbrace":
            return self.group_value()
        if kind == "open":
            self.next()
            v = self.expr()
            self.expect("close")
            return v
        if kind == "norm":
            self.next()
            v = self.expr()
            self.expect("norm")
            return norm(v)
        if kind == "letter":
            self.next()
            if text == "e" and self.peek() == ("op", "^"):
                self.next()
                return exponential(self.group_value())
            return self.named(text, bold=False)
        if kind == "cmd":
            return self.command(text)
        raise Unread(f"cannot read {text!r}")

    def command(self, text):
        self.next()
        name = text[1:]
        if name == "frac":
            if self.peek(1) == ("letter", "d") and self.peek(2) in (("rbrace", "}"), ("letter", "t")) \
                    or self.peek(1) == ("cmd", "\\mathrm"):
                raise Unread("a derivative written as a fraction")
            num, den = self.group_value(), self.group_value()
            if isinstance(den, Quat):
                raise Unread("a quaternion in a denominator")
            return _times(num, 1 / den)
        if name in ("sin", "cos", "tan", "exp", "sqrt"):
            power = 1
            if name != "sqrt" and self.peek() == ("op", "^"):
                self.next()
                power = self.group_value()
            arg = self.function_argument()
            if isinstance(arg, Quat) and name != "exp":
                raise Unread(f"\\{name} of a quaternion")
            value = exponential(arg) if name == "exp" else getattr(sp, name)(arg)
            return value if power == 1 else value ** power
        if name in ("mathbf", "boldsymbol", "bm", "vec", "pmb"):
            inner = self.bold_inner()
            return self.named(inner, bold=True)
        if name in ("dot", "ddot", "dddot"):
            order = {"dot": 1, "ddot": 2, "dddot": 3}[name]
            inner = self.accented()
            return self.rate(inner, order)
        if name == "Delta":
            kind, letter = self.peek()
            if kind == "letter":
                self.next()
                return self.scalar("Delta_" + letter)
            raise Unread("a \\Delta before what is not a letter")
        if name == "lim":
            return self.limit()
        if name in _GREEK:
            return self.named(name, bold=False)
        if name == "begin":
            return self.matrix()
        raise Unread(f"cannot read {text!r}")

    def function_argument(self):
        kind, text = self.peek()
        if kind in ("open", "lbrace"):
            return self.primary()
        if kind == "cmd" and text == "\\frac":
            return self.primary()
        return self.factor()

    def bold_inner(self) -> str:
        kind, text = self.next()
        if kind == "lbrace":
            parts = []
            while self.peek()[0] not in ("rbrace", None):
                parts.append(self.next()[1])
            self.expect("rbrace")
            if len(parts) != 1:
                raise Unread(f"cannot read the bold {''.join(parts)!r}")
            text = parts[0]
        if text.startswith("\\") and text[1:] in _GREEK:
            return text[1:]
        if re.fullmatch(r"[A-Za-z]", text):
            return text
        raise Unread(f"cannot read the bold {text!r}")

    def accented(self):
        """What an accent stands over: (name, bold)."""
        kind, text = self.peek()
        if kind == "lbrace":
            self.next()
            inner = self.accented()
            self.expect("rbrace")
            return inner
        self.next()
        if kind == "cmd" and text[1:] in ("mathbf", "boldsymbol", "bm", "vec", "pmb"):
            return self.bold_inner(), True
        if kind == "letter" or kind == "cmd" and text[1:] in _GREEK:
            return text.lstrip("\\"), False
        raise Unread(f"cannot read the rate of {text!r}")

    def subscript(self) -> str | None:
        if self.peek() != ("op", "_"):
            return None
        self.next()
        kind, text = self.next()
        if kind == "lbrace":
            parts = []
            while self.peek()[0] not in ("rbrace", None):
                parts.append(self.next()[1])
            self.expect("rbrace")
            return "".join(parts)
        return text.lstrip("\\")

    def named(self, name, bold):
        sub = self.subscript()
        if self.peek() == ("open", "(") and self.peek(1) == ("letter", "t") and self.peek(2) == ("close", ")"):
            self.k += 3           # q(t): the name at the current time
        elif self.peek() == ("open", "("):
            raise Unread(f"{name} of an argument (a function of the text's, or its value at another time)")
        if bold:
            if sub is not None:
                raise Unread(f"the bold {name} with a subscript {sub}")
            return self.bold(name)
        key = name if sub is None else f"{name}_{sub}"
        if isinstance(self.names.defined.get(key), str):
            return self.read_defined(key, self.names.defined[key])
        return self.scalar(key)

    def bold(self, name):
        defined = self.names.defined.get("bold " + name)
        if isinstance(defined, str):
            return self.read_defined("bold " + name, defined)
        if name in QUATERNION_LETTERS:
            if not self.names.style:
                raise Unread(f"the quaternion {name}, whose components the text does not name")
            return Quat(tuple(self.point.get(s, s) for s in components(name, self.names.style)))
        return Quat((0, *(self.point.get(s, s) for s in components(name, "xyz"))))

    def read_defined(self, key, tex):
        """A name the text set, read as what it was set to (once: a name set in its own terms stops)."""
        if key in self.reading:
            raise Unread(f"{key.split()[-1]} is set in its own terms")
        self.reading.add(key)
        try:
            return _Reader(tokens(tex), self.names, self.point, self.reading).whole()
        finally:
            self.reading.discard(key)

    def rate(self, inner, order):
        name, bold = inner
        key = (name, order)
        if key in self.names.rates:
            comps = self.names.rates[key]
            return Quat((0, *(self.point.get(s, s) for s in comps))) if bold else comps[0]
        raise Unread(f"the rate of {name}, which these rows do not give")

    def scalar(self, key):
        s = symbol(key)
        return self.point.get(s, s)

    def limit(self):
        """``\\lim_{\\Delta t\\to 0} X``: the limit of the rest of the term at 0."""
        self.expect("op", "_")
        self.expect("lbrace")
        prefix = "Delta_" if self.peek() == ("cmd", "\\Delta") else ""
        if prefix:
            self.next()
        kind, letter = self.next()
        if kind != "letter" and not (kind == "cmd" and letter[1:] in _GREEK):
            raise Unread("a limit in what is not a variable")
        var = sp.Symbol(prefix + letter.lstrip("\\"), positive=True)
        self.expect("cmd", "\\to")
        self.expect("num", "0")
        self.expect("rbrace")
        kept = self.point
        # the variable runs to 0: a point that can leave a symbol free does so, any other loses it
        self.point = kept.without(var) if hasattr(kept, "without") else {k: v for k, v in kept.items() if k != var}
        try:
            value = self.term()
        finally:
            self.point = kept
        if isinstance(value, Quat):
            return Quat(tuple(sp.limit(c, var, 0) for c in value.c))
        return sp.limit(value, var, 0)

    def matrix(self):
        env = self.environment()
        if env not in ("bmatrix", "pmatrix", "matrix"):
            raise Unread(f"cannot read the environment {env}")
        rows, row = [], []
        while True:
            tok = self.peek()
            if tok == ("cmd", "\\end"):
                self.next()
                if self.environment() != env:
                    raise Unread(f"a {env} closed by another environment")
                break
            if tok[0] is None:
                raise Unread("a matrix left open")
            if tok == ("op", "&"):
                self.next()
                continue
            if tok[0] == "rowend":
                self.next()
                rows.append(row)
                row = []
                continue
            row.append(self.expr())
        if row:
            rows.append(row)
        entries = [e for r in rows for e in r]
        if len(rows) == 2 and all(len(r) == 1 for r in rows) and not isinstance(rows[0][0], Quat) \
                and isinstance(rows[1][0], Quat) and rows[1][0].c[0] == 0:
            return Quat((rows[0][0], *rows[1][0].c[1:]))
        if len(entries) == 4 and (all(len(r) == 1 for r in rows) or len(rows) == 1) \
                and not any(isinstance(e, Quat) for e in entries):
            transposed = self.peek() == ("op", "^")
            if len(rows) == 1 and not transposed:
                raise Unread("a row of four entries, not a column")
            if transposed:
                self.next()
                self.group_value_transpose()
            return Quat(tuple(entries))
        if len(entries) == 3 and not any(isinstance(e, Quat) for e in entries):
            if self.peek() == ("op", "^"):
                self.next()
                self.group_value_transpose()
            return Quat((0, *entries))
        raise Unread("a matrix that is no quaternion's column")

    def environment(self) -> str:
        self.expect("lbrace")
        parts = []
        while self.peek()[0] not in ("rbrace", None):
            parts.append(self.next()[1])
        self.expect("rbrace")
        return "".join(parts)

    def group_value_transpose(self):
        tok = self.next()
        if tok == ("letter", "T") or tok == ("cmd", "\\top"):
            return
        if tok[0] == "lbrace":
            while self.peek()[0] not in ("rbrace", None):
                self.next()
            self.expect("rbrace")
            return
        raise Unread("a power of a column")


def symbol(key: str) -> sp.Symbol:
    """The text's scalar ``key``: a component (a subscript x, y, z, w or 0 to 3) is any real
    number, any other scalar (an angle, a step) a positive one."""
    return sp.Symbol(key, real=True) if re.search(r"_[xyzw0-3]$", key) else sp.Symbol(key, positive=True)


def components(name: str, style) -> tuple:
    """The components' symbols of the vector or quaternion ``name``, by the text's subscripts."""
    return tuple(symbol(f"{name}_{a}") for a in style)


def _is_dot_product(value) -> bool:
    return False


def _times(a, b):
    if isinstance(a, Quat) and isinstance(b, Quat):
        raise Unread("a product of two quaternions whose rule is not set")
    if isinstance(a, Quat):
        return a.scaled(b)
    if isinstance(b, Quat):
        return b.scaled(a)
    return a * b


def read(tex: str, names: Names, point: dict | None = None):
    """The value of one member (a scalar or a `Quat`), the symbols of ``point`` put in."""
    return _Reader(tokens(tex), names, point if point is not None else {}).whole()
