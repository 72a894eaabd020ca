"""A quaternion's rate and its steps, as attitude texts write them, judged in the four components.

Takes: the rows of a display in quaternions (`derive.lecture.quaternions`) that give the attitude
quaternion's rate (``\\dot{\\mathbf{q}} = \\frac{1}{2}\\boldsymbol\\Omega(\\boldsymbol\\omega)\\mathbf{q}``)
or a step of it (``\\mathbf{q}_{t+1} = e^{\\frac{1}{2}\\boldsymbol\\Omega(\\boldsymbol\\omega)\\Delta t}
\\mathbf{q}_t``, a series in the step ending in ``\\cdots``). Gives: the mixin `QuaternionSteps`:

* a rate q̇ = X holds when X is one of the four forms a unit quaternion's rate takes, ±½ q ⊗ 𝛚 or
  ±½ 𝛚 ⊗ q (the body's rates or the space axes', q turning body to space or back; the set is the
  same under Hamilton's and the JPL product), and fails when X is bilinear in q's and 𝛚's components
  and none of them; the last rate that holds is the text's rate of q from there on;
* a step q_{t+1} = X q_t with the text's rate, X a series ending in ``\\cdots``: X against the
  Taylor series of q(t + Δt) to the order of its shortest sum, q's rates from the text's rate by
  the chain rule, 𝛚's rates their own (zero where the text assumes so); X in closed form, with 𝛚
  constant over the step: holds when it solves the text's rate from q_t (dX/dΔt is the rate at X,
  X = q_t at Δt = 0), and is otherwise `unchecked` — a step that is not exact may be the scheme
  the text chooses (a first-order update), never flagged.

May import: :mod:`derive.lecture.latex_spellings`, :mod:`derive.lecture.quaternion_algebra`, :mod:`derive.lecture.quaternion_reader`, SymPy.
"""
from __future__ import annotations

import functools
import re

import sympy as sp

from derive.lecture.quaternion_algebra import Names, Quat, Unread, components, hamilton, time_rate
from derive.lecture.quaternion_reader import read
from derive.lecture.latex_spellings import BOLD_MARK

# three exact points: rational components, a rational point of the unit sphere for a unit vector
_VALUES = ((sp.Rational(3, 7), sp.Rational(-5, 11), sp.Rational(2, 13), sp.Rational(7, 5), sp.Rational(-4, 9)),
           (sp.Rational(-2, 3), sp.Rational(5, 7), sp.Rational(11, 13), sp.Rational(1, 4), sp.Rational(6, 5)),
           (sp.Rational(9, 8), sp.Rational(1, 6), sp.Rational(-7, 10), sp.Rational(3, 11), sp.Rational(-5, 3)))
_SPHERE = ((sp.Rational(2, 7), sp.Rational(3, 7), sp.Rational(6, 7)),
           (sp.Rational(-1, 3), sp.Rational(2, 3), sp.Rational(2, 3)),
           (sp.Rational(6, 11), sp.Rational(-2, 11), sp.Rational(9, 11)))
_S3 = ((sp.Rational(1, 5), sp.Rational(2, 5), sp.Rational(2, 5), sp.Rational(4, 5)),
       (sp.Rational(2, 9), sp.Rational(-4, 9), sp.Rational(5, 9), sp.Rational(6, 9)),
       (sp.Rational(1, 2), sp.Rational(1, 2), sp.Rational(-1, 2), sp.Rational(1, 2)))
_TINY = sp.Float("1e-20")
_STEP = re.compile(r"^\s*" + BOLD_MARK + r"\s*\{?\s*q\s*\}?\s*_\s*\{\s*([A-Za-z])\s*\+\s*1\s*\}\s*$")


class Point(dict):
    """An exact point: a value for any symbol the reader makes, chosen by the symbol's name (a unit
    vector's three components a rational point of the unit sphere, a unit quaternion's four one of
    the unit 3-sphere), the same across members."""

    def __init__(self, k, units, keep=()):
        super().__init__()
        self.k, self.units, self.keep = k, units, set(keep)

    def get(self, s, default=None):
        if s in self.keep or not isinstance(s, sp.Symbol):
            return default
        if s not in self:
            self[s] = self._value(s)
        return self[s]

    def _value(self, s):
        base, _, axis = s.name.rpartition("_")
        if base == "q" and "q" in self.units and len(axis) == 1 and axis in "wxyz0123":
            return _S3[self.k]["wxyz".find(axis) if axis in "wxyz" else int(axis)]      # a unit quaternion
        if base in self.units and axis and axis in "xyz":
            return _SPHERE[self.k]["xyz".index(axis)]
        h = sum(ord(ch) * (j + 1) for j, ch in enumerate(s.name))
        v = _VALUES[self.k][h % 5] + sp.Rational(h % 17, 19)
        return abs(v) + sp.Rational(1, 3) if s.is_positive else v

    def without(self, var):
        """The same point with ``var`` left free (a limit's variable)."""
        return Point(self.k, self.units, self.keep | {var})

    def put(self, value):
        """``value`` (a scalar or a quaternion in symbols) at this point."""
        if isinstance(value, Quat):
            return Quat(tuple(self.put(c) for c in value.c))
        value = sp.sympify(value)
        return value.xreplace({s: self.get(s, s) for s in value.free_symbols})


def difference(a, b):
    """The components of a − b (a quaternion with no vector part against a scalar is that scalar),
    None when one is a quaternion and the other is not."""
    if isinstance(a, Quat) != isinstance(b, Quat):
        if isinstance(a, Quat) and all(c == 0 for c in a.c[1:]):
            a = a.c[0]
        elif isinstance(b, Quat) and all(c == 0 for c in b.c[1:]):
            b = b.c[0]
        else:
            return None
    if isinstance(a, sp.MatrixBase) or isinstance(b, sp.MatrixBase):
        return None
    if isinstance(a, Quat):
        return [sp.sympify(x - y) for x, y in zip(a.c, b.c)]
    return [sp.sympify(a - b)]


def nonzero(values) -> bool:
    """Whether any of the exact values is not zero (to thirty digits)."""
    return any(abs(sp.N(c, 30)) > _TINY for c in values)


def flat(values):
    """The scalars of scalars, quaternions and matrices."""
    for v in values:
        if isinstance(v, Quat):
            yield from v.c
        elif isinstance(v, sp.MatrixBase):
            yield from v
        else:
            yield v


@functools.lru_cache(maxsize=64)
def _q_rates(q: tuple, chain: tuple) -> tuple:
    """q's rates of orders 1 to 3 by the chain rule over ``chain`` (component, its rate), kept: the
    text's names are made again for each member of each link, and these rates only change with
    the text's rate of q."""
    names = Names(defined={}, rates={})
    names.values["rates"] = dict(chain)
    out, value = [], Quat(q)
    for _ in (1, 2, 3):
        value = time_rate(value, names)
        out.append(value)
    return tuple(out)


def step_of(head: str) -> str | None:
    """The step's subscript of a head ``\\mathbf{q}_{t+1}`` (``t``), else None."""
    m = _STEP.match(head)
    return m.group(1) if m else None


class QuaternionSteps:
    """Mixin of the checker (through `derive.lecture.quaternions.Quaternions`). Uses ``self._q_names``,
    ``self._q_units``, ``self._q_rules``, ``self._q_style``."""

    _q_rule: dict = {}
    """The text's rate of q, by the product's rule (True for JPL): a quaternion in symbols."""

    def _q_with_rates(self, names: Names) -> Names:
        """``names`` with the rates the chain rule needs: q's from the text's rate, 𝛚's its own."""
        chain = {}
        omega = components("omega", "xyz")
        for order in (1, 2, 3):
            lower = omega if order == 1 else names.rates[("omega", order - 1)]
            chain.update((lo, hi) for lo, hi in zip(lower, names.rates[("omega", order)]) if isinstance(lo, sp.Symbol))
        rule = self._q_rule.get(names.jpl)
        if rule is not None and self._q_style:
            chain.update(zip(components("q", self._q_style), rule.c))
        names.values["rates"] = chain
        if rule is not None and self._q_style:
            for n, value in enumerate(_q_rates(components("q", self._q_style), tuple(chain.items())), 1):
                names.values[("q", n)] = value
        return names

    def _q_rate_claim(self, tex):
        """(verdict, why) of q̇ = ``tex``; a rate that holds becomes the text's rate of q."""
        if not self._q_style:
            raise Unread("the quaternion's components, which the text does not name")
        q = Quat(components("q", self._q_style))
        values, verdicts = {}, []
        for jpl in self._q_rules:
            value = read(tex, self._q_names(jpl))
            if not isinstance(value, Quat):
                raise Unread("a rate that is not a quaternion")
            # the one angular velocity the rate is written in (𝛚, or 𝛚_b labelled)
            bases = {s.name[:-2] for c in value.c for s in sp.sympify(c).free_symbols
                     if s not in q.c and s.name[-2:] in ("_x", "_y", "_z")}
            if len(bases) != 1 or not next(iter(bases)).startswith("omega"):
                raise Unread("a rate not in one angular velocity omega")
            base = bases.pop()
            w = Quat((0, *components(base, "xyz")))
            forms = [hamilton(q, w).scaled(sp.Rational(1, 2)), hamilton(w, q).scaled(sp.Rational(1, 2))]
            forms += [f.scaled(-1) for f in forms]
            values[jpl] = value
            if any(not nonzero_at_points(value, f, self._q_units()) for f in forms):
                verdicts.append("holds")
            elif _bilinear(value, q.c, w.c[1:]):
                verdicts.append("fails")
            else:
                raise Unread("a rate in other terms than q and omega")
        if all(v == "holds" for v in verdicts):
            self._q_rule = {**self._q_rule, **values}
            return "holds", ("one of the four forms of a unit quaternion's rate, ±½ q ⊗ 𝛚 or ±½ 𝛚 ⊗ q (the body's "
                             "rates or the space axes', q turning body to space or back)")
        if all(v == "fails" for v in verdicts):
            return "fails", ("none of the four forms of a unit quaternion's rate, ±½ q ⊗ 𝛚 or ±½ 𝛚 ⊗ q, whatever "
                             "the axes of 𝛚 and the way q turns")
        raise Unread("a rate that holds with one rule of the product and not the other")

    def _q_step_claim(self, tex, step):
        """(verdict, why) of q_{step+1} = ``tex``, a step of the text's rate of q."""
        results = []
        for jpl in self._q_rules:
            if self._q_rule.get(jpl) is None:
                raise Unread("a step of q, whose rate the text has not given in a form read")
            names = self._q_names(jpl)
            names.step = step
            names.truncated = []
            value = read(tex, names)
            if not isinstance(value, Quat):
                raise Unread("a step that is not a quaternion")
            if not only_omega(value, self._q_style):
                raise Unread("a step in vectors whose rates the text does not give")
            scalars = {s for s in flat([value]) for s in sp.sympify(s).free_symbols
                       if not re.search(r"_[xyzw0-3]$", s.name) and not re.search(r"_[xyz]$", s.name)}
            if len(scalars) != 1:
                raise Unread("a step in no single variable")
            var = scalars.pop()
            cut = [c for c in flat(names.truncated) if c != 0 and sp.sympify(c).has(var)]
            if cut:
                order = min(sp.Poly(sp.expand(c), var).degree() for c in cut)
                results.append(self._q_series_step(tex, names, var, order))
                if results[-1] == "fails" and any(r != 0 for r in names.rates[("omega", 1)]):
                    still = self._q_names(jpl)
                    still.rates.update({("omega", n): (0, 0, 0) for n in (1, 2, 3)})
                    still.step = step
                    if self._q_series_step(tex, self._q_with_rates(still), var, order) == "holds":
                        raise Unread("it holds only where omega is constant over the step, which the text has not said")
            else:
                if any(r != 0 for r in names.rates[("omega", 1)]):
                    raise Unread("a step in closed form while the text lets omega vary over it")
                results.append(self._q_exact_step(tex, names, var))
        if all(r == "holds" for r in results):
            return "holds", "the step of the text's rate of q, over Δt" if not names.truncated else \
                "the Taylor series of q over the step, with the text's rate of q, to the order of its shortest sum"
        if all(r == "fails" for r in results):
            return "fails", ("not the Taylor series of q over the step: with the text's rate of q and the chain rule "
                             "its terms differ, component by component")
        raise Unread("not the exact step of the text's rate of q: an approximation the text may choose")

    def _q_series_step(self, tex, names, var, order):
        exact, term = Quat(components("q", self._q_style)), Quat(components("q", self._q_style))
        for n in range(1, order + 1):
            term = names.values[("q", n)].scaled(var ** n / sp.factorial(n))
            exact = exact + term
        for k in range(3):
            point = Point(k, self._q_units(), keep=(var,))
            d = difference(read(tex, names, point), point.put(exact))
            low = [sp.series(c, var, 0, order + 1).removeO() for c in d]
            if any(nonzero(sp.Poly(sp.expand(c), var).all_coeffs()) for c in low):
                return "fails"
        return "holds"

    def _q_exact_step(self, tex, names, var):
        comps = components("q", self._q_style)
        rule = self._q_rule[names.jpl]
        for k in range(3):
            point = Point(k, self._q_units(), keep=(var,))
            value = read(tex, names, point)
            rate = point.put(Quat(tuple(sp.sympify(c).xreplace(dict(zip(comps, value.c))) for c in rule.c)))
            start = Quat(tuple(sp.sympify(c).subs(var, 0) for c in value.c))
            gap = difference(Quat(tuple(sp.diff(c, var) for c in value.c)), rate)
            if nonzero([c.subs(var, sp.Rational(2 + k, 7)) for c in gap]) or nonzero(difference(start, point.put(Quat(comps)))):
                return "not exact"
        return "holds"


def nonzero_at_points(a, b, units) -> bool:
    """Whether two values in symbols differ at one of the three exact points."""
    return any(nonzero(difference(Point(k, units).put(a), Point(k, units).put(b))) for k in range(3))


def _bilinear(value: Quat, q, w) -> bool:
    """Whether each component is a sum of (number) q_i w_j and nothing else."""
    for c in value.c:
        c = sp.expand(c)
        if c.free_symbols - set(q) - set(w):
            return False
        for term in sp.Add.make_args(c):
            if term == 0:
                continue
            poly = sp.Poly(term, *q, *w)
            (degrees,) = poly.monoms()
            if sum(degrees[:len(q)]) != 1 or sum(degrees[len(q):]) != 1:
                return False
    return True


def only_omega(value, style) -> bool:
    """Whether the only vectors in ``value`` (a quaternion in symbols) are q, 𝛚 and 𝛚's rates, the
    ones whose rates the chain rule knows."""
    q = set(components("q", style)) if style else set()
    return all(s in q or not re.search(r"_[xyz]$", s.name) or re.fullmatch(r"omegad*_[xyz]", s.name)
               for c in flat([value]) for s in sp.sympify(c).free_symbols)
