"""A statement with a definite integral written out (``\\int_0^h \\mathrm{d} z \\int_0^{dz/h}
\\mathrm{d} r \\int_0^{2\\pi} \\mathrm{d}\\phi = \\frac{\\pi d^2 h}{3}``, ``R = \\int_0^h … \\, z =
\\frac{3h}{4}``, ``K(k) = \\int_0^1 \\frac{\\mathrm{d}s}{\\sqrt{…}} = \\int_0^{\\pi/2} \\frac{\\mathrm{d}\\phi}{\\sqrt{…}}``).

Takes: a statement of the notes checker (`derive.lecture.notes_check.Checker`) whose text holds an
integral with both bounds written (`derive.lecture.definite_integrals`). Gives: the mixin
`IntegralClaims`, whose ``_definite_integral`` judges the links of the statement's chain that put
an integral beside a value it works out to: a closed form in no name the integral does not have
(its value, not a condition such as ∫ρ dV = M that sets a name), or, in a chain whose first member
is a name (``V = \\int_0^R 2\\pi r\\,dr = \\pi R^2 H``), in no name the text has not used before it, or a
second integral in the same names. Such a link `holds` when SymPy finds the two equal, or where an
integral stays unevaluated, when they agree to 30 digits at three points; it `fails` when both sides are closed forms that
differ at a point of positive values (the text's settings put in first), its why giving the
integral's value as written. A numeric disagreement is never a flag (a point may leave the
integral's domain). Nothing else of the statement is read: a name set to an integral (``I_1 =
\\int …``) is neither a setting nor a definition, since a text's integral may leave out a density
or a Jacobian its name means; the statement stays `unchecked`, saying so. A chain the text sets over
two displays (the second begins with ``=``, nothing read between them) links the integral closing
the first to the second's first member: that link is judged as above and given to the display that
writes the integral, whose value as written it is (its first members may stay unread, ``\\int … d^3 r``);
two integrals there are not judged (unequal, either display may hold the slip; equal, they may share it),
but the first is carried on: each integral of a chain ``∫ … = ∫ … = value`` set over three displays is
judged against the value, the verdict given to the display that writes it.
May import: sympy, :mod:`derive.lecture.latex`, :mod:`derive.lecture.definite_integrals`,
:mod:`derive.lecture.notes_claims`, :mod:`derive.lecture.statements`.
"""
from __future__ import annotations

import copy
import functools
import random
import re

import mpmath
import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.definite_integrals import DEFINITE
from derive.lecture.notes_claims import Claim
from derive.lecture.statements import top_level

_DIGITS = 30
_GOES_ON = re.compile(r"\s*=(?!=)")
_NOT_COMPARED = ("a definite integral beside no value it works out to (a name set to it keeps the text's meaning, "
                 "which may hold a density or a Jacobian the integral leaves out): not compared")


_EQUALS = re.compile(r"(?<![<>!\\])=(?!=)")


def _members(text):
    """The chain's members, cut at each ``=`` outside brackets and braces (a statement the parser refused)."""
    bounds = [0, *(p for m in top_level(text, _EQUALS) for p in (m.start(), m.end())), len(text)]
    return [text[bounds[k]:bounds[k + 1]] for k in range(0, len(bounds), 2)]


def _last_member(text):
    """The last member the chain writes, or None."""
    found = [m for m in _members(text) if m.strip()]
    return found[-1] if found else None


def _first_member(text):
    """The first member of a row that goes on with ``=``, or None."""
    found = [m for m in _members(text) if m.strip()]
    return found[0] if found else None


def _spans(text, parsed):
    """Each member's source text, from its position to the next member's."""
    starts = [m.pos for m in parsed.members] + [len(text)]
    return [text[starts[k]:starts[k + 1]] for k in range(len(parsed.members))]


def _points(names, count=3):
    """``count`` points of positive values below 1 (an elliptic modulus stays in its domain), the
    same for every run (a verdict never depends on a draw)."""
    rng = random.Random(20261130)
    return [{s: sp.Rational(rng.randint(11, 89), 97) for s in names} for _ in range(count)]


def _quadrature(e):
    """An integral in one variable between numbers, by mpmath's tanh-sinh quadrature of its integrand
    (SymPy's evalf would walk the integrand's tree at every node); None where it is not one."""
    if len(e.limits) != 1 or len(e.limits[0]) != 3 or e.function.free_symbols - {e.limits[0][0]}:
        return None
    x, lo, hi = e.limits[0]
    try:
        f = sp.lambdify(x, e.function, "mpmath", dummify=True)
        with mpmath.workdps(2 * _DIGITS):     # twice the digits: 1 - s² near s = 1 cancels half of them
            return sp.sympify(mpmath.quad(f, [mpmath.mpmathify(sp.N(lo, 2 * _DIGITS)),
                                              mpmath.mpmathify(sp.N(hi, 2 * _DIGITS))]))
    except Exception:  # a bound or an integrand mpmath cannot take: evalf's own quadrature then
        return None


def _value(v, point):
    """v at a point, to ``_DIGITS`` digits, its integrals in one variable by :func:`_quadrature`."""
    found = {}

    def numeric(e):
        found[e] = _quadrature(e) if isinstance(e, sp.Integral) else None
        return found[e] is not None
    return sp.N(v.xreplace(point).replace(numeric, lambda e: found[e]), _DIGITS)


def _agree(a, b, names) -> bool | None:
    """True when a and b agree at every point, False when they differ at one, None where a point gives
    no real value."""
    for point in _points(names):
        x, y = (_value(v, point) for v in (a, b))
        if not (x.is_number and y.is_number) or x.has(sp.I, sp.nan, sp.zoo) or y.has(sp.I, sp.nan, sp.zoo):
            return None
        if abs(x - y) > sp.Float(10) ** (5 - _DIGITS) * (1 + abs(x)):
            return False
    return True


@functools.lru_cache(maxsize=1024)
def _equal(a, b) -> bool:
    """a = b by simplify, then with the trigonometric functions expanded (kept: a probe reads a display again)."""
    d = sp.simplify(a - b)
    return d == 0 or sp.simplify(sp.expand_trig(d)) == 0


class IntegralClaims:
    """The mixin's judging of a statement that writes a definite integral out."""

    def _definite_integral(self, line, piece, text) -> bool:
        """Judge the statement when it holds a definite integral (True: it is the integral rule's). A
        row of the display that goes on with ``=`` after a row ending in an integral continues from that
        integral: its first member is the value the integral works out to."""
        tail, self._integral_tail = getattr(self, "_integral_tail", None), None
        if tail is not None and tail[0] == line and _GOES_ON.match(piece):
            text = tail[1] + " " + piece
        elif tail is not None and _GOES_ON.match(piece) and self._display_goes_on(tail[0], line):
            self._across_displays(tail, piece, line)
        if DEFINITE.search(text) is None:
            return False
        try:
            parsed = lx.parse(text, self.vocab)
        except lx.NotRead as err:
            self._add(line, piece, "unknown", "unchecked", err.why)
            last = _last_member(text)
            if last is not None and DEFINITE.search(last):
                self._integral_tail = (line, last, self.claims[-1])
            return True
        spans, done = _spans(text, parsed), False
        # a chain that names what it works out (V = ∫ … = value) says the value is the integral's, so
        # the value's names the text has used before are not set by it
        named = len(parsed.members) > 2 and isinstance(parsed.members[0].value, lx.Generic) and not DEFINITE.search(spans[0])
        if DEFINITE.search(spans[-1]):
            self._integral_tail = (line, spans[-1], None)
        for k, rel in enumerate(parsed.relations):
            if rel != "=" or not (DEFINITE.search(spans[k]) or DEFINITE.search(spans[k + 1])):
                continue
            a, b = parsed.members[k].value, parsed.members[k + 1].value
            if not DEFINITE.search(spans[k]):
                a, b = b, a                     # a: an integral
            verdict = self._integral_link(sp.sympify(a), sp.sympify(b), bool(DEFINITE.search(spans[k + 1]))
                                          and bool(DEFINITE.search(spans[k])),
                                          self._written_before(line) if named and k else set())
            if verdict is not None:
                self._add(line, piece, "identity", *verdict)
                done = True
        if not done:
            self._add(line, piece, "unknown", "unchecked", _NOT_COMPARED)
            if self._integral_tail is not None:
                self._integral_tail = (line, spans[-1], self.claims[-1])
        return True

    def _display_goes_on(self, before, line) -> bool:
        """The display at ``line`` follows the one at ``before`` with nothing the reader takes between them
        and begins with ``=``: one chain the text sets over two displays."""
        items = self.notes.items
        return any(a.line == before and b.line == line and a.kind == b.kind == "display" and _GOES_ON.match(b.latex)
                   for a, b in zip(items, items[1:]))

    def _across_displays(self, tail, piece, line):
        """Judge the link between the integral closing the display before and this display's first member,
        given to the display that writes the integral (the value its integral is claimed to work out to).
        ``tail``: (that display's line, its integral member, its unjudged claim or None). When this display
        opens with an integral too, the earlier integral is carried on to the value the chain reaches
        (``∫ … = ∫ … = value`` over three displays claims each integral works out to the value)."""
        first = _first_member(piece)
        if first is None:
            return
        carried = getattr(self, "_integral_carried", None)
        earlier = carried[1] if carried is not None and carried[0] == tail[0] else []
        if DEFINITE.search(first):
            # the integral-to-integral link itself is not judged (equal, they may share a slip; unequal,
            # either display may hold it): each is judged against the value the chain reaches
            self._integral_carried = (line, [*earlier, tail])
            return
        self._integral_carried = None
        self._value_link(tail, first, None)
        for each in earlier:
            self._value_link(each, first, tail[0])

    def _value_link(self, tail, first, through):
        """Judge the integral of ``tail`` against ``first``, a member in no integral, and give the verdict
        to the integral's display (``through``: the line of the last integral the chain went through,
        None when the value follows the integral's own display, whose claim is then added when it left
        none to replace)."""
        member = _GOES_ON.sub("", tail[1], count=1)
        # read on a copy of the vocabulary: the next display's names are met when its own reading meets them
        vocab = copy.copy(self.vocab)
        vocab.generic, vocab._atoms_met, vocab.defined = dict(vocab.generic), dict(vocab._atoms_met), dict(vocab.defined)
        try:
            a, b = (sp.sympify(lx.parse(m, vocab).members[0].value) for m in (member, first))
            verdict = self._integral_link(a, b, False)
        except (lx.NotRead, ArithmeticError, TypeError, ValueError, AttributeError, IndexError, KeyError,
                NotImplementedError, RecursionError, sp.SympifyError):
            return          # a member the parser or SymPy cannot take: the link stays unjudged
        if verdict is None:
            return
        way = "into the next display" if through is None else f"through the integral of line {through} to its value"
        claim = Claim(tail[0], f"{member.strip()} = {first.strip()}", "identity", *verdict[:1], None,
                      verdict[1] + f" (a chain the text carries on {way})")
        at = next((k for k, c in enumerate(self.claims) if c is tail[2]), None)
        if at is None:
            if through is None:
                self.claims.append(claim)
        elif tail[2].why == _NOT_COMPARED:     # the integral's value found: no longer beside no value
            self.claims[at] = claim
        else:
            self.claims.insert(at + 1, claim)

    def _written_before(self, line) -> set:
        """The symbols of the text's math on lines before ``line`` (read again: a probe of this display
        may have met its own names already)."""
        keys = set()
        for item in self.notes.items:
            if item.line < line and item.latex:
                try:
                    keys |= {t.value.with_(text="") for t in lx.scan(item.latex) if t.kind == "atom"}
                except lx.NotRead:
                    continue
        return {s for s, key in self.vocab.generic.items() if key.with_(text="") in keys}

    def _integral_link(self, a, b, both, known=frozenset()):
        """(verdict, why) of a = b, a an integral as SymPy read it, or None where it is not compared;
        ``known``: names b may hold that a lacks (the text's earlier names, in a chain that names its value)."""
        names_a, names_b = a.free_symbols, b.free_symbols
        if any(isinstance(s, lx.Quantity) for s in names_a | names_b) or not names_b - names_a <= set(known) \
                or (both and names_a != names_b):
            return None
        given = {s: v for s, v in self.ctx.subs.items() if s in names_a}
        a, b = a.xreplace(given), b.xreplace(given)
        names = a.free_symbols | b.free_symbols
        worked = "SymPy works the integral out"
        if not a.has(sp.Integral) and not b.has(sp.Integral):
            if _equal(a, b):
                return "holds", f"a definite integral written out: {worked} (simplify)"
            if _agree(a, b, names) is False:
                return "fails", (f"a definite integral written out: {worked} to {sp.latex(a)} as written, "
                                 f"not {sp.latex(b)}")
            return None
        if _agree(a, b, names):
            return "holds", f"a definite integral written out, evaluated numerically ({_DIGITS} digits at 3 points)"
        return None
