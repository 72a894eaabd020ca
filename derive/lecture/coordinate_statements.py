"""The checker's reading of a one-coordinate system in the text's own names (`derive.lecture.coordinate_functions`).

Takes: the notes and one statement. Gives: the mixin `CoordinateStatements` of
`derive.lecture.notes_check.Checker`. It is on for a text that writes its own Lagrangian of one
coordinate, ``L(\\theta, \\dot\\theta) = …``, and declares no Euler angles in its front matter
(those the general reader's derivation knows); a statement it cannot read goes on to the general
reader.
May import: the standard library, sympy, :mod:`derive.lecture.coordinate_functions`,
:mod:`derive.lecture.operator_notation`, :mod:`derive.lecture.operator_statements`.

Statements, in order:

* ``f(p…) = X`` with f new, or f's new body bringing in an unknown function (the text's second,
  general Lagrangian), and ``X = …`` with X new: a definition (not a claim); the rest of the chain
  is checked against X.
* a relation in which exactly one symbol appears for the first time, linearly
  (``mR^2 = I_C + ma^2``): defines that symbol (not a claim).
* a relation with q̈: the q̈ it gives must be the q̈ of the Euler–Lagrange equation of the text's
  latest Lagrangian (``\\frac{d}{dt}\\frac{\\partial L}{\\partial\\dot q} = \\frac{\\partial L}{\\partial q}``
  is that equation itself).
* any other relation: the two sides must be equal, at four random points, with random smooth
  functions in place of the functions the text leaves unknown (it must hold for all of them).

The coordinate set to a value (``\\theta = \\theta_0``) is a setting, left to the general reader;
a bare ``L`` between members where the text defined ``L(q, \\dot q)`` is skipped (the text may
use the letter for something else there).
"""
from __future__ import annotations

import functools
import random
import re

import sympy as sp
from sympy.core.assumptions import check_assumptions
from sympy.core.function import AppliedUndef

from derive.lecture import coordinate_functions as cf
from derive.lecture.operator_notation import NotHandled
from derive.lecture.operator_statements import _left_side

_D = r"(?:\\mathrm\s*\{\s*d\s*\}|\\mathrm\s*d|d)\s*"
# L(q, \dot q) =, or with the rate written d/dt as the formula reader reads it (`derive.lecture.written_rates`)
_LAGRANGIAN = re.compile(r"(?<![A-Za-z\\])L\s*\(\s*(\\[A-Za-z]+|[A-Za-z])\s*,\s*(?:\\dot\s*\{?\s*\1\s*\}?|\\[dt]?frac\s*\{\s*"
                         + _D + r"\1\s*\}\s*\{\s*" + _D + r"t\s*\}|" + _D + r"\1\s*/\s*" + _D + r"t)\s*\)\s*=")
_SINGLE = re.compile(r"(?<![\\$])\$([^$\n]+?)(?<!\\)\$")
_POINTS = 4
_ERRORS = (NotHandled, TypeError, ValueError, ZeroDivisionError, AttributeError, IndexError, KeyError,
           sp.SympifyError, sp.PolynomialError, NotImplementedError, RecursionError)


class CoordinateStatements:
    """Mixin of the checker (see the module docstring)."""

    @functools.cached_property
    def _cf(self) -> cf.Defined | None:
        body = getattr(self.notes, "body", "")
        m = _LAGRANGIAN.search(body)
        if not m or {"convention", "angles"} & set(self.notes.declared):
            return None                 # a text in Euler angles: the general reader's derivation applies
        defined = cf.Defined(sp.Symbol(m.group(1).lstrip("\\"), real=True))
        self._cf_prose = []             # (line, symbol) the prose introduces ("mass $m$")
        for inline in _SINGLE.finditer(body):
            try:
                toks = cf.tokens(inline.group(1))
            except NotHandled:
                continue
            if len(toks) == 1 and toks[0][0] == "atom":
                self._cf_prose.append((body.count("\n", 0, inline.start()) + 1, toks[0][1].name))
        return defined

    def _coordinate(self, line, piece, text) -> bool:
        """Check the statement as one of the text's one-coordinate system; False when it cannot.
        A statement read again (a second reading of the checker) gets the verdicts of the first."""
        d = self._cf
        if d is None:
            return False
        done = self.__dict__.setdefault("_cf_done", {})
        start = len(self.claims)
        if (line, piece, text) in done:
            for claim in done[(line, piece, text)]:
                self._add(*claim)
            handled = bool(done[(line, piece, text)])
        else:
            d.met |= {name for at, name in self._cf_prose if at < line}
            handled = self._cf_read(line, piece, text)
            done[(line, piece, text)] = [(c.line, c.latex, c.kind, c.verdict, c.why, c.correction)
                                         for c in self.claims[start:]] if handled else []
        for claim in self.claims[start:]:
            claim.sequence_free = True      # the text's own coordinate: no sequence of Euler angles enters
        return handled

    def _cf_read(self, line, piece, text) -> bool:
        d = self._cf
        try:
            members, names, _ = cf.read(text, d)
            form = cf.left_function(text, d)
        except _ERRORS:
            self._cf_meet(text)
            return False
        if len(members) < 2 or members[0] in (d.q, d.qd, d.qdd):
            return False                       # a setting of the coordinate, or no relation
        before = set(d.met)
        d.met |= names
        self.ctx.head = _left_side(text)
        try:
            return self._cf_judge(line, piece, text, members, names, form, before)
        except _ERRORS:
            return False

    def _cf_meet(self, text):
        d = self._cf
        try:
            d.met |= {t[1].name for t in cf.tokens(text) if t[0] == "atom"}
        except NotHandled:
            pass

    def _cf_judge(self, line, piece, text, members, names, form, before) -> bool:
        d = self._cf
        checked = list(enumerate(members))
        defined = None
        if form is not None and members[0] is not None:
            name, params = form
            old = d.functions.get(name)
            unknown = {f.func for f in members[1].atoms(AppliedUndef)} if members[1] is not None else set()
            fresh = isinstance(members[0], AppliedUndef) or members[0] == sp.Symbol(name, positive=True)
            if (old is None and fresh) or (old is not None and unknown - {f.func for f in old[1].atoms(AppliedUndef)}):
                if members[1] is None:
                    return False
                d.functions[name] = (params, members[1])
                if params and d.qd in params:
                    d.lagrangian = name
                defined = name
                checked = checked[1:]
        pairs = _skipping_bare(checked)
        if not pairs:
            if defined is None:
                return False
            self._add(line, piece, "definition", "unchecked", f"defines {defined} (recorded, then used)")
            return True
        verdicts = []
        for (i, a), (j, b) in pairs:
            fresh = sorted(n for n in names - before - {defined} if sp.Symbol(n, positive=True) in (a - b).free_symbols)
            if fresh:
                sym = sp.Symbol(fresh[0], positive=True)
                solved = _solutions(a - b, sym) if len(fresh) == 1 else []
                if len(solved) != 1 or (a - b).has(d.qdd):
                    return False
                d.functions[fresh[0]] = ([], solved[0])
                verdicts.append(("defines", fresh[0]))
                continue
            verdicts.append(self._cf_compare(a, b, f"{text}/{i}/{j}"))
        if any(v[0] == "fails" for v in verdicts):
            k = next(k for k, v in enumerate(verdicts) if v[0] == "fails")
            (i, _), (j, _) = pairs[k]
            self._add(line, piece, verdicts[k][2], "fails", f"as written: member {i + 1} ≠ member {j + 1} ({verdicts[k][1]})")
        elif any(v[0] == "holds" for v in verdicts):
            whys = "; ".join(dict.fromkeys(v[1] for v in verdicts if v[0] == "holds"))
            self._add(line, piece, next(v[2] for v in verdicts if v[0] == "holds"), "holds", whys)
        else:
            what = ", ".join(v[1] for v in verdicts)
            self._add(line, piece, "definition", "unchecked", f"defines {what} (met here first; recorded, then used)")
        return True

    def _cf_compare(self, a, b, seed):
        """(holds|fails, why, kind) of a = b (with q̈: against the text's Lagrangian)."""
        d = self._cf
        diff = sp.expand(a - b)
        kind = "identity"
        if diff.has(d.qdd):
            if d.lagrangian is None:
                raise NotHandled("an equation of motion with no Lagrangian of the text's")
            lag = d.functions[d.lagrangian][1]
            el = sp.diff(sp.diff(lag, d.qd), d.q) * d.qd + sp.diff(lag, d.qd, 2) * d.qdd - sp.diff(lag, d.q)
            mine, theirs = _solutions(diff, d.qdd), _solutions(el, d.qdd)
            if len(mine) != 1 or len(theirs) != 1:
                raise NotHandled("an equation not linear in the acceleration")
            diff = mine[0] - theirs[0]
            kind = "equation of motion"
        zero = _vanishes(diff, seed)
        if kind == "equation of motion":
            why = f"gives the q̈ of the Euler–Lagrange equation of the text's {d.lagrangian}" if zero else \
                f"its {self._cf.q.name}̈ is not that of the Euler–Lagrange equation of the text's {d.lagrangian}"
        else:
            why = "equal with the text's definitions" if zero else "the sides differ at a sample point"
        unknown = sorted({str(f.func) for f in (a - b).atoms(AppliedUndef)})
        if zero and unknown:
            why += f", whatever {', '.join(unknown)} stand for"
        return ("holds" if zero else "fails"), why, kind


def _solutions(e, x) -> list:
    """The x that make e = 0, as `sp.solve` gives them: where e = c₁ x + c₀ with c₁ ≠ 0 free of x (an
    equation of motion in q̈, a relation that defines a new symbol), −c₀/c₁ unless x's assumptions
    rule it out. The quotient is left as it stands (`solve` would `simplify` it): it is compared
    and substituted at numeric points only."""
    c1 = sp.diff(e, x)
    if c1 == 0 or c1.has(x):
        return sp.solve(e, x)
    root = -e.xreplace({x: sp.S.Zero}) / c1
    return [] if check_assumptions(root, **x.assumptions0) is False else [root]


def _skipping_bare(checked):
    """Consecutive pairs of the members that are not a bare function name (None)."""
    kept = [(i, m) for i, m in checked if m is not None]
    return list(zip(kept, kept[1:]))


@functools.lru_cache(maxsize=1024)
def _vanishes(e, seed) -> bool:
    """Zero at random points, with a random smooth function for each unknown one (its points and
    functions drawn from ``seed``: memoised, for each reading of the text in another sequence of
    angles compares the same sides again)."""
    rng = random.Random(seed)
    x = sp.Dummy("x")
    for _ in range(_POINTS):
        f = e
        for fn in sorted({g.func for g in e.atoms(AppliedUndef)}, key=str):
            c = [sp.Float(rng.uniform(-1, 1), 30) for _ in range(4)]
            f = f.replace(fn, sp.Lambda(x, c[0] + c[1] * sp.sin(x) + c[2] * x ** 2 + c[3] * sp.cos(2 * x)))
        f = f.doit()
        values = {s: sp.Float(rng.uniform(0.3, 1.4), 30) for s in f.free_symbols}
        v = complex(f.xreplace(values).evalf(30))
        size = 1 + max((abs(complex(t.xreplace(values).evalf(30))) for t in sp.Add.make_args(sp.expand(f))), default=0)
        if abs(v) > 1e-12 * size:
            return False
    return True
