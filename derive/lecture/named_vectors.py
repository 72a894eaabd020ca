"""Statements in a text's named vectors: 𝐋 = 𝐫 × 𝐩, 𝐌_O = 𝐫_O × 𝐅, 𝐯_P = 𝐯_O + 𝛚 × 𝐫_{P/O},
(𝐀 × 𝐁)·(𝐀 × 𝐁) = A²B² − (𝐀·𝐁)², read as statements about vectors in general.

Texts on the laws of a rigid body write many displays with vectors that no model of the reader
ties to the body: a force 𝐅, a moment 𝐌_O about a point, positions 𝐫_{i/O} from a point, a
velocity 𝐯_P of a named point. This module is the model (`Named`, for the grammar of
`derive.lecture.vector_parser`) in which each such vector is a general 3-vector of components of
its own:

* **named vectors.** A bold or arrowed letter with its subscript and primes (𝐌_O, 𝐫', 𝐕, 𝛚) is a
  vector of components (M_O,x, M_O,y, M_O,z); a plain letter written beside the same bold one
  (A beside 𝐀) is its magnitude, any other plain letter a scalar of its own.
* **unit vectors.** A bold hatted letter of no basis (𝐧̂; not î, ĵ, k̂, x̂, ŷ, ẑ, ê) is a unit vector
  of a direction of its own, its components divided by its length.
* **points.** A position written from one named point to another, 𝐫_{A/B}, is 𝐩_A − 𝐩_B (each
  point its own place), so 𝐫_{A/B} = −𝐫_{B/A} and 𝐫_{A/C} = 𝐫_{A/B} + 𝐫_{B/C}.
* **sums.** Σ over an index is read for two generic terms: a letter with that index (𝐅_i, m_α,
  𝐫_{i/O}) is the term's own; a sum is linear in its summand, so two terms prove an identity of sums.
* **rates.** d/dt (or a dot) differentiates each component by the product rule; a mass (m, m_i)
  is constant, every other quantity changes in time with a rate of its own.
* **definitions.** The text's definitions (`Definitions`) put a vector's expression in its place;
  one made about a point (𝐌_O = Σ 𝐫_{i/O} × 𝐅_i) is read about any other point too (𝐌_{O'}).

Takes: a statement's LaTeX. Gives: `read`, its reading under `Named` (`lx.NotRead` when it has
a symbol this model does not know: a basis's unit vector, a tensor, an integral), and `Definitions`.

May import: :mod:`derive.lecture.latex_spellings`, :mod:`derive.lecture.latex`, :mod:`derive.lecture.vector_parser`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import vector_parser as vp
from derive.lecture.latex_spellings import BOLD_MARK, VECTOR_MARK

TERMS = 2
"""How many generic terms a sum is read for."""
_TEXT_WORD = re.compile(r"\\(?:text|mathrm|rm|textrm)\s*\{\s*([A-Za-z]+)\s*\}")
_DOUBLE = re.compile(r"\\(mathbf|boldsymbol|bm|vec)\s*\{\s*\{([^{}]*(?:\{[^{}]*\}[^{}]*)*)\}\s*\}")
# a bold wrapper around what is bold already (\mathbf{\mathbf{r} \times \mathbf{L}}): a group
_WRAPPED = re.compile(BOLD_MARK + r"\s*\{(?=\s*" + VECTOR_MARK + r"\b)")
_NORM = re.compile(r"\|\|([^|]+)\|\|")
_LABEL = re.compile(r"[A-Za-z]+'*|\d+|\\[A-Za-z]+|\^[+-]")
_CONSTANT = ("m", "M")
_BARE_SUM = re.compile(r"\\sum(?:\s*\\limits)?(?!\s*(?:\\limits\s*)?[_^A-Za-z])")
_OVER_I = re.compile(r"_\s*\{?\s*i(?![A-Za-z])")
PLAIN = "plain:"
"""The mark of a plain letter's definition (T = Σ ½ m 𝐯·𝐯) beside a bold one's, in `Definitions`."""
_BASIS = frozenset("ijkxyzIJKXYZe") | {"imath", "jmath"}
"""The letters of a basis's hatted unit vectors (î, x̂, Î, X̂, ê …): no directions of their own."""


def prepare(text: str) -> str:
    """The rewrites the scanner needs: a doubled group in a bold face (\\mathbf{{M_{O'}}}) as one,
    a bold face around an expression already bold as a group, a norm ‖𝐚‖ as the bracketed |𝐚| (so
    that two norms side by side are a product), an upright word in a
    subscript as plain letters, and a Σ written without its index over i when the statement writes
    i as a subscript (Σ 𝐫_{i/cm} × mᵢ𝐯_{i/cm})."""
    text = _DOUBLE.sub(r"\\\1{\2}", text)
    if _OVER_I.search(text):
        text = _BARE_SUM.sub(r"\\sum_{i}", text)
    while _WRAPPED.search(text):
        text = _WRAPPED.sub("{", text, count=1)
    return _TEXT_WORD.sub(r"\1", _NORM.sub(r"(|\1|)", text))


def _labels(sub: str) -> list[str]:
    return _LABEL.findall(sub)


def relabelled(sub: str, old: str, new: str) -> str:
    """A subscript with the point label ``old`` written ``new`` (O in 'i/O' to O')."""
    return "/".join(new if part == old else part for part in sub.split("/"))


def _name(base: str, sub: str, primes: int, env: dict) -> str:
    """A symbol's name, with a sum's index put in as the generic term's number."""
    index = env.get("index")
    parts = [f"#{env['term']}" if index is not None and part == index else part for part in _labels(sub)]
    return base + ("_" + ",".join(parts) if parts else "") + "'" * primes


class Named:
    """The grammar's model (`derive.lecture.vector_parser`): named vectors, scalars and sums."""

    vocabulary = False
    free = ""
    matrix_products = False
    rates = True
    frames: dict = {}

    def __init__(self, definitions=None, depth: int = 0):
        self.definitions, self.depth = definitions, depth

    # the values of symbols
    def atom(self, p, a, env, tok):
        if a.hat and a.bold and len(a.base) == 1 and a.base not in _BASIS and \
                not (a.sub or a.sup or a.dots or a.tilde or a.mark):
            return unit(a.base, a.primes)
        if a.hat or a.tilde or a.sup or a.mark or a.base in ("d", "t", vp.INTEGRAL) or not a.base:
            return None                         # unit vectors, other families' symbols, a differential
        bold = a.bold or a.text.startswith("\\vec")
        if a.dots:
            inner = self.atom(p, a.with_(dots=0), env, tok)
            for _ in range(a.dots):
                inner = None if inner is None else rate(inner)
            return inner
        if not bold:
            if _bold_beside(p.toks, a):
                v = self._vector(p, a.base, a.sub, a.primes, env)
                return None if v is None else sp.sqrt(v.dot(v))
            if not re.fullmatch(r"[A-Za-z]|[a-z]+", a.base) or a.base in ("e", "i"):
                return None
            defined = self.definitions.value(self, PLAIN + a.base, a.sub, a.primes, env) if self.definitions else None
            if defined is not None:
                return defined
            name = _name(a.base, a.sub, a.primes, env)
            return sp.Symbol(name, positive=True) if a.base in _CONSTANT else sp.Symbol(name, real=True)
        return self._vector(p, a.base, a.sub, a.primes, env)

    def _vector(self, p, base, sub, primes, env):
        ends = sub.split("/")
        if base == "r" and len(ends) == 2 and all(_labels(e) for e in ends) and not primes:
            return _place(ends[0], env) - _place(ends[1], env)      # 𝐫_{A/B}: from B to A
        defined = self.definitions.value(self, base, sub, primes, env) if self.definitions else None
        if defined is not None:
            return defined
        name = _name(base, sub, primes, env)
        return sp.Matrix([sp.Symbol(f"{name}.{c}", real=True) for c in "xyz"])

    # what the grammar asks of a model
    def summed(self, p, names, upper, env, tok):
        if len(names) != 1 or env.get("index") is not None:
            p.fail("a sum over more than one index, or inside another", tok)
        return [{**env, "index": names[0], "term": k} for k in range(1, TERMS + 1)]

    def points(self):
        return []

    def rate(self, value, frame):
        return rate(value) if frame == "inertial" else None


def _place(label: str, env: dict) -> sp.Matrix:
    """The place of a named point (a sum's index: the generic term's point)."""
    name = _name("p", label, 0, env)
    return sp.Matrix([sp.Symbol(f"{name}.{c}", real=True) for c in "xyz"])


def _bold_beside(toks, a) -> bool:
    """Whether the statement writes the same letter bold (A beside 𝐀: its magnitude)."""
    return any(t.kind == "atom" and (t.value.bold or t.value.text.startswith("\\vec")) and t.value.base == a.base
               and t.value.sub == a.sub and t.value.primes == a.primes and not t.value.hat for t in toks)


def unit(base: str, primes: int) -> sp.Matrix:
    """A bold hatted letter of no basis (𝐧̂): a unit vector of a direction of its own, so that a
    statement holding only because its length is 1 (𝐧̂·𝐧̂ = 1) holds."""
    name = "hat-" + base + "'" * primes
    v = sp.Matrix([sp.Symbol(f"{name}.{c}", real=True) for c in "xyz"])
    return v / sp.sqrt(v.dot(v))


def rate(e):
    """d/dt by the product rule: each symbol but a mass has a rate of its own (its name dotted)."""
    if isinstance(e, sp.MatrixBase):
        return e.applyfunc(rate)
    e = sp.sympify(e)
    return sp.Add(*[e.diff(s) * sp.Symbol(s.name + "^.", real=True) for s in e.free_symbols
                    if not s.is_positive])


class Definitions:
    """The text's vectors (and plain names, their base marked `PLAIN`) set equal to an expression:
    (base, subscript, primes) → the expression's LaTeX, with the point label it was made about (a
    definition about O read about O' too)."""

    def __init__(self):
        self.table: dict = {}

    def add(self, base, sub, primes, latex) -> None:
        label = sub if re.fullmatch(r"[A-Z]'*", sub) and _mentions_label(latex, sub) else None
        self.table[(base, sub, primes)] = (latex, label)

    def known(self, base, sub, primes) -> bool:
        return (base, sub, primes) in self.table or self._about(base, sub, primes) is not None

    def _about(self, base, sub, primes):
        if not re.fullmatch(r"[A-Z]'*", sub):
            return None
        return next(((latex, label) for (b, s, pr), (latex, label) in self.table.items()
                     if b == base and pr == primes and label is not None and s == label and s != sub), None)

    def value(self, model, base, sub, primes, env):
        """The value of a defined vector (None: not defined), read in a model one level deeper."""
        if model.depth > 3:
            return None
        found = self.table.get((base, sub, primes))
        latex = found[0] if found else None
        if found is None:
            about = self._about(base, sub, primes)
            if about is None:
                return None
            latex = _relabelled_latex(about[0], about[1], sub)
        latex = prepare(latex)
        parser = vp.VectorParser(list(lx.scan_cells(latex)), lx.Vocabulary(), latex, Named(self, model.depth + 1))
        members, _ = parser.members(dict(env))      # inside a sum, at the sum's current term
        return members[0].value if len(members) == 1 else None


_SUBSCRIPT = re.compile(r"_\s*(\{(?:[^{}]|\{[^{}]*\})*\}|[A-Za-z0-9])")


def _mentions_label(latex: str, label: str) -> bool:
    return any(label in m.group(1).strip("{}").split("/") for m in _SUBSCRIPT.finditer(latex))


def _relabelled_latex(latex: str, old: str, new: str) -> str:
    """A definition's LaTeX with the point label ``old`` written ``new`` in its subscripts."""
    def one(m):
        inner = m.group(1)
        body = inner[1:-1] if inner.startswith("{") else inner
        return "_{" + relabelled(body.strip(), old, new) + "}"
    return _SUBSCRIPT.sub(one, latex)


def read(text: str, definitions: Definitions | None = None) -> vp.Reading:
    """A statement read under `Named` (`lx.NotRead` when it cannot be)."""
    text = prepare(text)
    toks = lx.scan_cells(text)
    if not any(t.kind == "atom" and (t.value.bold or t.value.text.startswith("\\vec")) for t in toks):
        raise lx.NotRead("no named vector")
    return vp.read(toks, text, lx.Vocabulary(), Named(definitions), "named")
