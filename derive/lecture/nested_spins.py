"""The angular velocity as spins about the successive axes, each carried by the turns before it.

Takes: a statement of the notes checker (`derive.lecture.notes_check.Checker`) that sets a bold 𝛚
equal to nested spins, ``\\dot a \\hat u + R_u(a) ( \\dot b \\hat v + R_v(b) ( \\dot c \\hat w ) )``: a rate
of an angle times a unit vector of an axis named by its letter (``\\hat x``, ``\\hat{y}``, ``\\hat k``),
plus an elementary rotation (``R_z(\\phi)``, ``R_{y}(\\theta_r)``, ``\\mathrm{rot}(\\hat j, \\theta_y)``)
applied to the spins that come after it, or a matrix the prose names as a turn (``$T_1$ turning by $\\phi$
about z``). Gives: the mixin `NestedSpins`, whose ``_nested_spins``
judges such a statement.

For a rotation that is a product of elementary turns, R = R_u(a) R_v(b) R_w(c), the angular
velocity is ȧ u + R_u(a) (ḃ v + R_v(b) ċ w) in space components, and on the body's axes the same
shape with the turns taken in the other order and inverted; read with passive matrices (a text's
R_u(a) the inverse turn) the body form is again this shape. So in every convention the rotation
applied beside a spin ȧ u is the turn about u by a (or by −a): a rotation about another axis, or by
another of the angles, is a slip under every reading, and the statement `fails`. A statement whose
every level pairs its spin with its own turn holds, as the angular velocity of the product its
matrices name, unless the text writes that product of its turns in another order (then it is left
unchecked). A display whose parentheses open more often than they close is read closing them at its
end (the site's typesetting drops a closing bracket; nothing else reads). Any other shape (two spins
beside one rotation, a rotation with no spin beside it, an angle that is not one letter) is not read.
The spins written out, ȧ u + ḃ R_u(a) v + ċ R_u(a) R_v(b) w (the carrying products may be matrices
the text set equal to products of turns in a display before, ``\\mathrm{E}_y = \\mathrm{rot}(\\hat{j},
\\theta_y)``), hold when the first spin is carried by no turn and each next one by exactly the turns
of the spins before it; any other sum is left to the other rules. Written inside Ṫ = 𝛚 × T, a statement
ending ``(S) \\times X = \\vec{\\omega} \\times X`` (the same X on both sides) is read as 𝛚 = S.
May import: the standard library, :mod:`derive.lecture.latex_spellings`.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from derive.lecture.latex_spellings import BOLD_MARK, VECTOR_MARK


_ANGLE = r"(\\[A-Za-z]+|[A-Za-z])\s*(?:_\s*(?:\{\s*([A-Za-z0-9]+)\s*\}|([A-Za-z0-9])))?"
_UNIT = re.compile(r"\\(?:wide)?hat\s*(?:\{\s*(?:" + BOLD_MARK + r"\s*)?\{?\s*([xyzijk])\s*\}?\s*\}|([xyzijk]))")
_RATE = re.compile(r"\\dot\s*(?:\{\s*" + _ANGLE + r"\s*\}|" + _ANGLE + r")\s*(?:_\s*(?:\{\s*([A-Za-z0-9]+)\s*\}|([A-Za-z0-9])))?")
_TURN = re.compile(r"R\s*_\s*\{?\s*([xyz])\s*\}?\s*\(\s*(-?)\s*" + _ANGLE + r"\s*\)")
_ROT = re.compile(r"\\(?:mathrm|operatorname|text)\s*\{\s*rot\s*\}\s*\(\s*" + _UNIT.pattern + r"\s*,\s*(-?)\s*" + _ANGLE + r"\s*\)")
_NAMED = re.compile(r"([A-Z])\s*(?:_\s*(?:\{\s*([0-9])\s*\}|([0-9])))?(?![A-Za-z0-9{_])")
"""A matrix the text names in its prose (``T_1``): a capital with a digit as its subscript, or alone."""
_OMEGA = re.compile(r"\s*" + VECTOR_MARK + r"\s*\{?\s*\\omega\s*\}?\s*")
_PARTIAL = re.compile(r"\s*" + VECTOR_MARK + r"\s*\{?\s*\\omega\s*\}?\s*_\s*\{?\s*[A-Za-z0-9]\s*\}?\s*")
"""The angular velocity after some of the turns, ``\\vec{\\omega}_p``: a bold ω with a one-letter subscript."""
_PRODUCT_NAME = re.compile(r"(?:\\mathrm\s*\{\s*([A-Z])\s*\}|([A-Z]))\s*(?:_\s*(?:\{\s*([A-Za-z0-9])\s*\}|([A-Za-z0-9])))?(?![A-Za-z0-9{(])")
"""A matrix the text sets equal to a product of turns in its displays, ``\\mathrm{E}_p = \\mathrm{E}_y \\mathrm{rot}(\\hat{k}, \\theta_p)``."""
_CROSSED = re.compile(r"\s*(?:\\left\s*)?\(\s*(?P<s>.+?)\s*(?:\\right\s*)?\)\s*\\times\s*(?P<x>[^=]+?)\s*")
_OMEGA_CROSSED = re.compile(_OMEGA.pattern + r"\\times\s*(?P<x>[^=]+?)\s*")
"""A bracket crossed with a matrix, ``\\left( … \\right) \\times T``, and 𝛚 crossed with one, ``\\vec{\\omega} \\times T``."""
# a rate written d/dt, \frac{d\theta}{dt} (upright d too), is the dotted angle the spins are read in
_WRITTEN_RATE = re.compile(r"\\[dt]?frac\s*\{\s*(?:\\mathrm\s*\{\s*d\s*\}|d)\s*(\\[A-Za-z]+|[A-Za-z])\s*"
                           r"((?:_\s*(?:\{[^{}]*\}|[A-Za-z0-9]))?)\s*\}\s*\{\s*(?:\\mathrm\s*\{\s*d\s*\}|d)\s*t\s*\}")
_SIZES = re.compile(r"\\(?:left|right|bigl|bigr|Bigl|Bigr|biggl|biggr|big|Big|bigg|Bigg)\s*(?=[()])")
_SPACE = re.compile(r"\\[,;:!]|\\quad|\\qquad|~")
_AXIS = {"i": "x", "j": "y", "k": "z"}
_GREEK = {"\\varphi": "\\phi", "\\vartheta": "\\theta"}


class NotNested(Exception):
    """The statement is not nested spins of a shape this rule reads."""


def _angle(m, k: int) -> str:
    """The angle a match spells from group k on: its letter and its subscript."""
    base = _GREEK.get(m.group(k), m.group(k))
    sub = m.group(k + 1) or m.group(k + 2)
    return base + ("_" + sub if sub else "")


@dataclass
class Level:
    """One level of the nesting: its spins (angle, axis) and its applied rotations (turns, level)."""
    spins: list = field(default_factory=list)
    applied: list = field(default_factory=list)


class _Reader:
    def __init__(self, text: str, named: dict):
        self.s, self.k, self.opened, self.named = text, 0, 0, named

    def skip(self):
        while self.k < len(self.s) and self.s[self.k].isspace():
            self.k += 1

    def at(self, ch: str) -> bool:
        self.skip()
        return self.s.startswith(ch, self.k)

    def match(self, pattern):
        self.skip()
        m = pattern.match(self.s, self.k)
        if m:
            self.k = m.end()
        return m

    def level(self) -> Level:
        out = Level()
        self.term(out)
        while self.at("+"):
            self.k += 1
            self.term(out)
        return out

    def term(self, out: Level):
        """A rate and a unit vector (in either order, either in brackets), or turns applied to a
        bracket or to a spin."""
        turns, rate, unit, inner = [], None, None, None
        while True:
            self.skip()
            if self.k >= len(self.s) or self.s[self.k] in "+)":
                break
            m = self.match(_TURN)
            if m:
                turns.append((m.group(1), m.group(2) + _angle(m, 3)))
                continue
            m = self.match(_ROT)
            if m:
                axis = m.group(1) or m.group(2)
                turns.append((_AXIS.get(axis, axis), m.group(3) + _angle(m, 4)))
                continue
            m = self.match(_NAMED)
            if m:
                name = m.group(1) + (m.group(2) or m.group(3) or "")
                if name not in self.named:
                    raise NotNested(f"a matrix {name} the prose does not name a turn")
                turns.append(self.named[name])
                continue
            m = self.match(_RATE)
            if m:
                if rate is not None:
                    raise NotNested("two rates in one term")
                rate = _angle(m, 1) if m.group(1) else _angle(m, 4)
                sub = m.group(7) or m.group(8)
                if sub:
                    if "_" in rate:
                        raise NotNested("a rate with two subscripts")
                    rate += "_" + sub
                continue
            m = self.match(_UNIT)
            if m:
                if unit is not None:
                    raise NotNested("two unit vectors in one term")
                axis = m.group(1) or m.group(2)
                unit = _AXIS.get(axis, axis)
                continue
            if self.at("("):
                self.k += 1
                self.opened += 1
                group = self.level()
                if self.at(")"):
                    self.k += 1
                    self.opened -= 1
                elif self.k < len(self.s):
                    raise NotNested("an unclosed bracket inside the display")
                if inner is not None:
                    raise NotNested("two brackets in one term")
                inner = group
                continue
            raise NotNested(f"cannot read {self.s[self.k:self.k + 12]!r}")
        if inner is not None and not turns and rate is None and unit is None:
            out.spins += inner.spins        # a bracket around spins: the spins themselves
            out.applied += inner.applied
            return
        if rate is not None and unit is not None and inner is None:
            if not turns:
                out.spins.append((rate, unit))
                return
            inner, rate, unit = Level(spins=[(rate, unit)]), None, None     # turns applied to one spin
        if rate is not None or unit is not None or inner is None or not turns:
            raise NotNested("a term that is neither a spin nor turns applied to spins")
        out.applied.append((turns, inner))


def _dotted(latex: str) -> str:
    """``latex`` with each rate of one symbol written d/dt as its dot, ``\\dot{\\theta}``."""
    return _WRITTEN_RATE.sub(lambda m: r"\dot{" + m.group(1) + "}" + m.group(2), latex)


def read(rhs: str, named: dict | None = None) -> tuple[Level, bool]:
    """The nesting a member writes and whether brackets were closed at its end, ``named`` the turns
    the prose gives its matrices' names; NotNested when it is not nested spins."""
    text = _SPACE.sub(" ", _SIZES.sub("", _dotted(rhs))).strip().rstrip(".,;").strip()
    r = _Reader(text, named or {})
    level = r.level()
    r.skip()
    if r.k != len(text):
        raise NotNested("text after the nesting")
    return level, r.opened > 0


def judge(level: Level) -> tuple[list, list] | None:
    """(the turns in order as (axis, angle), the mismatches as (spin, turn)) of a nesting, or None
    when a level is not one spin beside one turn applied to the next level (the last level one spin
    alone)."""
    order, slips = [], []
    while True:
        if len(level.spins) != 1:
            return None
        (angle, axis), = level.spins
        if not level.applied:
            order.append((axis, angle))
            break
        if len(level.applied) != 1:
            return None
        (turns, inner), = level.applied
        if len(turns) != 1:
            return None
        (turn_axis, turn_angle), = turns
        if turn_axis != axis or turn_angle.lstrip("-") != angle:
            slips.append(((angle, axis), (turn_axis, turn_angle)))
        order.append((axis, angle))
        level = inner
    angles = [a for _, a in order]
    if len(order) < 2 or len(set(angles)) != len(angles):
        return None
    return order, slips


def _written_products(body: str, upto: int) -> list:
    """The products of three elementary turns the text writes before its line ``upto``, each as
    its (axis, angle) pairs."""
    out = []
    head = "\n".join(body.splitlines()[:max(upto - 1, 0)])
    pair = rf"(?:{_TURN.pattern})"
    for m in re.finditer(rf"{pair}\s*{pair}\s*{pair}", head):
        found = [(t.group(1), t.group(2) + _angle(t, 3)) for t in _TURN.finditer(m.group(0))]
        out.append([(axis, angle.lstrip("-")) for axis, angle in found])
    return out


def named_turns(body: str, upto: int) -> dict:
    """The matrices the prose before line ``upto`` names as turns, ``$T_1$ turning by $\\phi$ about z``:
    each name's (axis, angle); a name the prose gives two turns is left out."""
    head = "\n".join(body.splitlines()[:max(upto - 1, 0)])
    found = {}
    for m in re.finditer(r"\$\s*" + _NAMED.pattern + r"\s*\$[^$.;]{0,30}?\bby\s+\$\s*" + _ANGLE
                         + r"\s*\$\s+about\s+(?:the\s+)?\$?([xyz])\$?(?![A-Za-z])", head):
        name = m.group(1) + (m.group(2) or m.group(3) or "")
        found.setdefault(name, set()).add((m.group(7), _angle(m, 4)))
    return {name: turns.pop() for name, turns in found.items() if len(turns) == 1}


def off_convention(order: list, convention: str, angles: tuple) -> tuple | None:
    """The first turn (axis, angle) of ``order`` about another axis than the stated ``convention``
    turns that angle about (``angles`` its names, ``phi``), or None."""
    axes = dict(zip(angles, convention.split("-")))
    return next(((axis, angle) for axis, angle in order if axes.get(angle.lstrip("\\"), axis) != axis), None)


def _spell(axis: str, angle: str) -> str:
    return f"R_{axis}({angle})"


class NestedSpins:
    """Mixin of the checker. Uses ``self.notes`` and ``_add``."""

    def _nested_spins(self, line, piece) -> bool:
        """Judge 𝛚 = nested spins (see the module docstring); False when the statement is not one."""
        read_as = _as_angular_velocity(piece)
        parts = read_as.split("=")
        products = vars(self).setdefault("spin_products", {})
        if len(parts) == 2 and _PRODUCT_NAME.fullmatch(parts[0].strip()):
            turns = _turns_of(parts[1], products)
            if turns:               # a product of turns the text names, read where a later spin uses it
                products[_product_name(_PRODUCT_NAME.fullmatch(parts[0].strip()))] = turns
            return False
        if len(parts) == 2 and (_OMEGA.fullmatch(parts[0]) or _PARTIAL.fullmatch(parts[0])):
            terms = expanded(parts[1], products)
            order = chained(terms) if terms else None
            if order and not self._off_convention(line, piece, order):
                self._add(line, piece, "identity", "holds",
                          f"the angular velocity of {' '.join(_spell(a, q) for a, q in order)}: each spin about its own "
                          "turn's axis, carried by the turns before it")
                return True
        if len(parts) != 2 or not _OMEGA.fullmatch(parts[0]):
            return False
        named = named_turns(self.notes.body, line) if _NAMED.search(parts[1]) else {}
        if not (_TURN.search(parts[1]) or _ROT.search(parts[1]) or named):
            return False
        try:
            level, closed = read(parts[1], named)
        except NotNested:
            return False
        judged = judge(level)
        if judged is None:
            return False
        order, slips = judged
        closing = " (read closing the brackets the display leaves open at its end)" if closed else ""
        closing += " (the bracket crossed with the matrix read as 𝛚, as Ṫ = 𝛚 × T writes it)" if read_as != piece else ""
        if slips:
            (angle, axis), (turn_axis, turn_angle) = slips[0]
            self._add(line, piece, "identity", "fails",
                      f"the rotation beside the spin about {axis} at the rate of {angle} must be the turn about {axis} "
                      f"by {angle} (in any order of the turns, active or passive), not the turn about {turn_axis} by {turn_angle}"
                      + closing)
            return True
        if self._off_convention(line, piece, order):
            return True
        product = " ".join(_spell(axis, angle) for axis, angle in order)
        written = [p for p in _written_products(self.notes.body, line) if {a for _, a in p} == {a for _, a in order}]
        if any(p != order for p in written):
            self._add(line, piece, "identity", "unchecked",
                      f"the angular velocity of {product}, while the text writes its turns in another order")
            return True
        self._add(line, piece, "identity", "holds",
                  f"the angular velocity of {product}, the product its matrices name: each spin about its own turn's "
                  "axis, carried by the turns before it" + closing)
        return True

    def _off_convention(self, line, piece, order) -> bool:
        """True (the statement left unchecked) when a spin turns one of the angles of the convention the
        text states about another axis: the product the matrices name is then not the text's rotation."""
        off = off_convention(order, self.notes.convention, self.notes.angles) if self.notes.convention_stated else None
        if off is not None:
            self._add(line, piece, "identity", "unchecked", f"the spins name {_spell(*off)}, while the text's "
                      f"{self.notes.convention} sequence turns {off[1]} about another axis")
        return off is not None


def _as_angular_velocity(piece: str) -> str:
    """``\\vec{\\omega} = S`` for a statement ending ``(S) \\times X = \\vec{\\omega} \\times X``, the bracket
    of spins crossed with a matrix as Ṫ = 𝛚 × T writes it; else the statement as it is."""
    parts = piece.split("=")
    crossed = _CROSSED.fullmatch(parts[-2]) if len(parts) > 1 else None
    omega = _OMEGA_CROSSED.fullmatch(parts[-1]) if crossed else None
    if omega is None or _SPACE.sub("", crossed["x"]).replace(" ", "") != _SPACE.sub("", omega["x"]).replace(" ", ""):
        return piece
    return "\\vec{\\omega} = " + crossed["s"]


def _product_name(m) -> str:
    return (m.group(1) or m.group(2)) + (m.group(3) or m.group(4) or "")


def _turns_of(text: str, products: dict) -> list | None:
    """The turns a product of elementary turns and of the text's named products writes, in order;
    None when it is anything else."""
    k, out = 0, []
    text = _SPACE.sub(" ", text).strip()
    while k < len(text):
        if text[k].isspace():
            k += 1
            continue
        m = _TURN.match(text, k)
        if m:
            out.append((m.group(1), m.group(2) + _angle(m, 3)))
        else:
            m = _ROT.match(text, k)
            if m:
                axis = m.group(1) or m.group(2)
                out.append((_AXIS.get(axis, axis), m.group(3) + _angle(m, 4)))
            else:
                m = _PRODUCT_NAME.match(text, k)
                if not m or _product_name(m) not in products:
                    return None
                out += products[_product_name(m)]
        k = m.end()
    return out


def expanded(rhs: str, products: dict) -> list | None:
    """The terms (angle, turns carrying it, axis) of a sum of spins each carried by a product of
    turns (``\\dot{\\theta}_p ( \\mathrm{E}_y \\hat{k} )``); None when the member is not one."""
    text = _SPACE.sub(" ", _SIZES.sub("", _dotted(rhs))).strip().rstrip(".,;")
    terms, depth, start = [], 0, 0
    for k, ch in enumerate(text):
        depth += (ch == "(") - (ch == ")")
        if ch == "+" and depth == 0:
            terms.append(text[start:k])
            start = k + 1
        if ch == "-" or depth < 0:
            return None
    terms.append(text[start:])
    out = []
    for term in terms:
        rate = _RATE.search(term)
        unit = list(_UNIT.finditer(term))
        if rate is None or len(unit) != 1:
            return None
        angle = _angle(rate, 1) if rate.group(1) else _angle(rate, 4)
        sub = rate.group(7) or rate.group(8)
        angle += "_" + sub if sub and "_" not in angle else ""
        rest = (term[:rate.start()] + " " + term[rate.end():]).replace(unit[0].group(0), " ", 1)
        rest = rest.strip()
        while rest.startswith("(") and rest.endswith(")"):
            rest = rest[1:-1].strip()       # the bracket around a carried unit vector, ( E_y k̂ )
        rest = re.sub(r"^\(\s*\)$", "", rest)
        turns = _turns_of(rest, products) if rest else []
        if turns is None or "(" in re.sub(r"R\s*_\s*\{?[xyz]\}?\s*\([^()]*\)|\\\w+\s*\{\s*rot\s*\}\s*\([^()]*\)", "", rest):
            return None
        axis = unit[0].group(1) or unit[0].group(2)
        out.append((angle, turns, _AXIS.get(axis, axis)))
    return out


def chained(terms: list) -> list | None:
    """The turns in order when each term's spin is carried by exactly the turns of the terms before
    it (the first by none); None otherwise."""
    order, carried, left = [], [], list(terms)
    while left:
        found = [t for t in left if t[1] == carried]
        if len(found) != 1:
            return None
        angle, _, axis = found[0]
        left.remove(found[0])
        order.append((axis, angle))
        carried = carried + [(axis, angle)]
    angles = [a for _, a in order]
    return order if len(order) >= 2 and len(set(angles)) == len(angles) else None
