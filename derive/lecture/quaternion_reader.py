"""Formulas in quaternions as attitude texts write them, read into their four components.

Takes: one member of a display in a text about quaternions (``\\frac{1}{2}\\boldsymbol\\omega
\\mathbf{q}``, ``e^{\\mathbf{u}\\theta}``, ``\\cos\\frac{\\theta}{2} + \\mathbf{u}\\sin\\frac{\\theta}{2}``,
a column ``\\begin{bmatrix}\\cos\\frac{\\theta}{2} \\\\ \\mathbf{u}\\sin\\frac{\\theta}{2}\\end{bmatrix}``
or its four rows, a 4 x 4 matrix and ``\\mathbf{I}_4``, ``\\lim_{\\Delta t\\to 0} …``, a sum ending in
``\\cdots``, a name with its argument the text defined, ``\\boldsymbol\\Omega(\\boldsymbol\\omega)``, and its
rate) and the text's names (`Names`). Gives: `read`, the member's value: a SymPy scalar, a `Quat`
(scalar part first) or a matrix, products of quaternions taken by Hamilton's rule or by its
reverse (the JPL product, ``jpl=True``); `applied_name`, the key of a name with its argument.
Anything outside this grammar raises `Unread` naming what stopped it: the caller leaves it
unjudged.

A bold letter is a 3-vector, read as the pure quaternion (0, 𝐯), except the quaternion letters
(q, p), which are generic quaternions of components named as the text names them (q_w, q_x, q_y,
q_z or q_0 … q_3); a column of two rows is (scalar, vector), of four rows the components, of three
a pure quaternion. The exponential of a quaternion a + 𝐯 is e^a (cos‖𝐯‖ + 𝐯/‖𝐯‖ sin‖𝐯‖), its
series' terms the powers of one quaternion, so the rule of the product does not change it.

May import: :mod:`derive.lecture.quaternion_algebra`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture.quaternion_algebra import (
    QUATERNION_LETTERS, Names, Quat, Unread, applied_key, components, exponential, hamilton, norm, plus, symbol, times,
    time_rate,
)

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
                total = plus(total, times(sign, last))
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
        if isinstance(a, sp.MatrixBase) and isinstance(b, Quat):
            if a.shape != (4, 4):
                raise Unread("a matrix not 4 x 4 on a quaternion")
            return Quat(tuple(a * sp.Matrix(b.c)))
        if isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase):
            if a.shape[1] != b.shape[0]:
                raise Unread("a product of matrices of shapes that do not fit")
            return sp.ImmutableMatrix(a * b)
        if isinstance(a, Quat) and isinstance(b, sp.MatrixBase):
            raise Unread("a quaternion times a matrix")
        return times(a, b)

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
        if isinstance(base, sp.MatrixBase):
            if not (isinstance(exp, sp.Integer) and exp >= 0):
                raise Unread("a matrix to a power that is not a whole number")
            return sp.ImmutableMatrix(base ** int(exp))
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
            return times(num, 1 / den)
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

    def braced(self) -> list[str]:
        """The tokens' texts up to the closing brace (the opening one read), the brace consumed."""
        parts = []
        while self.peek()[0] not in ("rbrace", None):
            parts.append(self.next()[1])
        self.expect("rbrace")
        return parts

    def bold_inner(self) -> str:
        kind, text = self.next()
        if kind == "lbrace":
            parts = self.braced()
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
            return "".join(self.braced())
        return text.lstrip("\\")

    def named(self, name, bold):
        sub = self.subscript()
        if self.peek() == ("open", "(") and self.peek(1) == ("letter", "t") and self.peek(2) == ("close", ")"):
            self.k += 3           # q(t): the name at the current time
        elif self.peek() == ("open", "("):
            key = self.applied(name, bold)
            if key not in self.names.defined:
                raise Unread(f"{name} of an argument (a function of the text's, or its value at another time)")
            return self.read_defined(key, self.names.defined[key])
        if bold:
            if bold and name == "I" and sub in ("4", "4\\times4", "4\\times 4"):
                return sp.ImmutableMatrix(sp.eye(4))
            if sub is not None and not (sub == self.names.step and name in QUATERNION_LETTERS):
                if name in QUATERNION_LETTERS or not re.fullmatch(r"[a-vA-Z]|body|space", sub) or sub in "xyzw":
                    raise Unread(f"the bold {name} with a subscript {sub}")
                return self.bold(name + sub)      # 𝛚_b: a vector of its own, labelled (never a component)
            return self.bold(name)
        if name == "q" and sub is None and self.names.plain_q:
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

    def applied(self, name, bold) -> str:
        """The key of a name written with its argument, ``\\boldsymbol\\Omega(\\boldsymbol\\omega)``."""
        depth, parts = 0, []
        while True:
            kind, text = self.next()
            if kind is None:
                raise Unread("an argument left open")
            depth += kind == "open"
            depth -= kind == "close"
            parts.append(text)
            if depth == 0:
                return applied_key(name, bold, "".join(parts))

    def at_point(self, value):
        """A value in symbols with the point put in."""
        if isinstance(value, Quat):
            return Quat(tuple(self.at_point(c) for c in value.c))
        if isinstance(value, sp.MatrixBase):
            return sp.ImmutableMatrix(value.applyfunc(self.at_point))
        value = sp.sympify(value)
        return value.xreplace({s: self.point.get(s, s) for s in value.free_symbols})

    def rate(self, inner, order):
        name, bold = inner
        if self.peek() == ("open", "("):
            key = self.applied(name, bold)
            if key not in self.names.defined:
                raise Unread(f"the rate of {name}, a function the text has not set")
            value = _Reader(tokens(self.names.defined[key]), self.names, {}, self.reading).whole()
            for _ in range(order):
                value = time_rate(value, self.names)
            return self.at_point(value)
        if bold and name in QUATERNION_LETTERS and (name, order) in self.names.values:
            if self.subscript() not in (None, self.names.step):
                raise Unread(f"the rate of {name} at another step")
            return self.at_point(self.names.values[(name, order)])
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
        if len(rows) == 4 and all(len(r) == 4 for r in rows) and not any(isinstance(e, (Quat, sp.MatrixBase)) for e in entries):
            return sp.ImmutableMatrix(rows)
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


def _is_dot_product(value) -> bool:
    return False


def applied_name(tex: str) -> str | None:
    """The key of a member that is only a name written with its argument (``\\boldsymbol\\Omega(
    \\boldsymbol\\omega)``), as `read` looks it up; None for any other member."""
    try:
        r = _Reader(tokens(tex), Names(), {})
        kind, text = r.peek()
        if kind == "cmd" and text[1:] in ("mathbf", "boldsymbol", "bm", "vec", "pmb"):
            r.next()
            name, bold = r.bold_inner(), True
        elif kind == "letter" or kind == "cmd" and text[1:] in _GREEK:
            r.next()
            name, bold = text.lstrip("\\"), False
        else:
            return None
        if r.peek() != ("open", "("):
            return None
        key = r.applied(name, bold)
        return key if r.k == len(r.t) else None
    except Unread:
        return None


def read(tex: str, names: Names, point: dict | None = None):
    """The value of one member (a scalar or a `Quat`), the symbols of ``point`` put in."""
    return _Reader(tokens(tex), names, point if point is not None else {}).whole()
