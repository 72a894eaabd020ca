"""A text's own equation of motion in a variable of its own, carried through its changes of
variable: the part of the notes checker that follows a reduction as the text writes it.

Takes: statements parsed by `derive.lecture.latex` with the text's symbols (`latex.Generic`).
Gives: the mixin `TextMotion` of `derive.lecture.notes_check.Checker`, which

1. **keeps the text's equation for a variable of its own**: ``\\dot u^2 = F(u)`` (or ``\\dot u =
   F(u)``) with u a symbol of the text's, written in the text's names (``a(u-u_1)(u-u_2)(u-u_3)``
   with roots the text names but does not compute), is kept as the text states it for the rest of its
   section, whatever the rest of the checker makes of it;
2. **follows a change of variable**: ``u = S(v)`` with v a name the text has not used yet
   introduces v (not a claim);
   ``\\frac{dx}{d\\tau} = g(x)`` with the text's τ = c·t is kept as ẋ = c·g(x), and a closed form in τ
   (``s = \\sn \\tau``) is put into it as one in c·t;
3. **checks the equation the change gives**: ``\\dot v^n = R(v)`` is the kept equation with
   ``u = S(v)`` and ``\\dot u = S'(v)\\,\\dot v`` put in, ``\\dot v^m = F(S(v)) / S'(v)^m``. A name
   of R the text defines only further on (``where k^2 = …``) is read with that definition, so
   the check waits for the end of the text. R equal to the m-th power's right side under another
   power on the left (``\\dot v = …`` for ``\\dot v^2 = …``) is a typo of the power.
4. **integrates a constant rate**: ``v = v(0) + D`` with D free of the time, for the text's own
   ``\\dot v = c`` (c a nonzero constant), is no change of variable but a solution: v(0) is the
   starting value, so v = v(0) + c t; D = c is a typo mended by the time, any other D fails.

The check compares the two sides at random values of the text's names (an identity in them
holds at every point; a difference shows at almost every one), with mpmath at 50 digits
(SymPy's evalf where the formulas hold a function mpmath's walk does not read).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.mp_values`, SymPy, mpmath.
"""
from __future__ import annotations

import random
import re

import mpmath
import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import mp_values

_BOUNDS = ("<", ">", "≤", "≥")


def top_relations(piece: str) -> list:
    """(start, end) of each relation outside brackets in a statement's LaTeX."""
    out, depth = [], 0
    try:
        toks = lx.scan(piece)
    except lx.NotRead:
        return out
    for tok in toks:
        if tok.kind == "op" and tok.value in "({":
            depth += 1
        elif tok.kind == "op" and tok.value in ")}":
            depth -= 1
        elif tok.kind == "rel" and depth == 0:
            cmd = re.match(r"\\[A-Za-z]+", piece[tok.pos:])
            out.append((tok.pos, tok.pos + (cmd.end() if cmd else 1)))
    return out


_POINTS = 4
"""Random points at which the two sides are compared (an identity holds at all of them)."""
_DIGITS = 50


def _free(obj) -> set:
    return set(obj.free_symbols) if hasattr(obj, "free_symbols") else set()


def _equal(a, b) -> bool:
    """a ≡ b as functions of their free symbols, compared at random points away from 0 and 1:
    with mpmath at `_DIGITS` digits (`derive.lecture.mp_values`) where it reads the formulas, else
    SymPy's evalf to 30 digits; a pole or a value that is not finite is a difference."""
    a = sp.sympify(a)
    diff = a - sp.sympify(b)
    names = sorted(_free(diff), key=str)
    walk = mp_values.walker(names, [diff, a]) if _free(a) <= set(names) else None
    rng = random.Random(20240601)
    for _ in range(_POINTS):
        point = {s: sp.Rational(rng.randint(11, 97), rng.randint(3, 10)) for s in names}
        if walk is None:
            value = sp.N(diff.xreplace(point), 30)
            if not value.is_number or abs(value) > 1e-20 * (1 + abs(sp.N(a.xreplace(point), 30))):
                return False
            continue
        with mpmath.workdps(_DIGITS):
            try:
                value, size = walk(*(mpmath.mpf(p.p) / p.q for p in point.values()))
            except ZeroDivisionError:
                return False
            if not mpmath.isfinite(value) or abs(value) > 1e-20 * (1 + abs(size)):
                return False
    return True


class TextMotion:
    """Mixin of the checker: see the module docstring. Uses ``self.vocab``, ``self.ctx`` (defs),
    ``self.tex`` and ``self._add``; keeps the section's equations and changes in ``self.ctx``
    (``own_motion``, ``changes``) and the checks waiting for the end of the text
    (``change_checks``, ``later_defs``)."""

    def _rate_power(self, m):
        """Ẋ^n with X a symbol of the text's: (X, Ẋ, n); None for anything else."""
        base, n = (m.base, m.exp) if isinstance(m, sp.Pow) else (m, sp.S.One)
        if not isinstance(base, lx.Generic) or not (n.is_Integer and n > 0):
            return None
        undotted = self.vocab.undotted(base)
        if undotted is None or undotted[1] != 1:
            return None
        return undotted[0], base, int(n)

    def _text_motion(self, line, piece, parsed) -> bool:
        """Items 1 to 4 of the module docstring; True when the statement is done."""
        if not hasattr(self, "change_checks"):
            self.change_checks, self.later_defs = [], {}
        members = [m.value for m in parsed.members]
        if len(members) > 2 and parsed.relations[0] == "=" and set(parsed.relations[1:]) <= set(_BOUNDS) \
                and not any(isinstance(m, sp.MatrixBase) for m in members):
            return self._function_then_bound(line, piece, parsed)
        if len(members) != 2 or parsed.relations != ["="] or any(isinstance(m, sp.MatrixBase) for m in members):
            return False
        left, right = members
        if self._function_of_the_text(line, piece, members):
            return True
        timed = self._in_time(right)
        if lx.t in _free(timed) and lx.t not in _free(left) and self._own_solution(line, piece, left, timed):
            return True
        self._later_definition(left, right)
        along = self._rate_along(left)
        if along is not None and not _free(right) & {lx.t}:
            self.ctx.own_motion[along[0]] = (1, along[1] * right, line)    # dx/dτ = g(x): ẋ = τ̇ g(x)
            return False
        rate = self._rate_power(left)
        if rate is not None:
            var, dot, n = rate
            if var in self.ctx.changes:
                self._add(line, piece, "identity", "unchecked", "waits for the end of the text")
                old, change, change_line = self.ctx.changes[var]
                self.change_checks.append((self.claims[-1], var, dot, n, right, (old, change, change_line),
                                           self.ctx.own_motion[old]))
                self.settings_only = False
                return True
            if dot not in _free(right) and not isinstance(var, lx.Quantity):
                before = self.ctx.own_motion.get(var)
                self.ctx.own_motion[var] = (n, right, line)
                if before is not None and before[0] == n:
                    return self._by_roots(line, piece, var, before, right)
            return False
        if left in self.ctx.own_motion and isinstance(left, lx.Generic):
            n, eq, _ = self.ctx.own_motion[left]
            new = [s for s in _free(right) if isinstance(s, lx.Generic) and s not in self.ctx.defs
                   and s not in _free(eq) and s not in self.ctx.own_motion and self.vocab.undotted(s) is None]
            if len(new) == 1 and lx.t not in _free(right) and self._initial_value(new[0], left) and \
                    self._constant_rate_solution(line, piece, left, right, new[0]):
                return True
            if len(new) == 1 and lx.t not in _free(right):
                self.ctx.changes[new[0]] = (left, right, line)
                self._add(line, piece, "change of variable", "unchecked",
                          f"introduces {self.tex(new[0])} by {self.tex(left)} = {self.tex(right)}: "
                          f"the text's equation for {self.tex(left)} (line {self.ctx.own_motion[left][2]}) is carried to it")
                self.settings_only = False
                return True
        return False

    def _initial_value(self, symbol, var) -> bool:
        """Whether ``symbol`` is ``var``'s value at t = 0 as the text writes it (v(0) for v)."""
        written = self.tex(symbol).replace(" ", "")
        return "^{(0)}" in written and written.replace("^{(0)}", "", 1) == self.tex(var).replace(" ", "")

    def _constant_rate_solution(self, line, piece, var, right, start) -> bool:
        """``v = v(0) + D`` with D free of t, for the text's own ``dv/dt = c``, c a nonzero constant: a
        solution the rate's integral v(0) + c t decides; D = c (the time dropped) is a typo mended by
        the time, any other D fails. A rate that depends on v or on t, or is zero, is read as before
        (False)."""
        n, eq, eq_line = self.ctx.own_motion[var]
        if n != 1 or eq == 0 or _free(eq) & {var, lx.t} or any(self.vocab.undotted(s) is not None for s in _free(eq)):
            return False
        lost = sp.simplify(right - start - eq) == 0
        why = (f"the text's rate of {self.tex(var)} (line {eq_line}) is the constant {self.tex(eq)}, so "
               f"{self.tex(var)} = {self.tex(start)} + ({self.tex(eq)}) t; as written it does not change in time")
        if lost:
            term = self.tex(eq * lx.t)
            self._add(line, piece, "solution", "typo", why + "; one edit (the time after the rate) makes it hold",
                      f"{self.tex(var)} = {self.tex(var)}(0) " + (term if term.startswith("-") else "+ " + term))
        else:
            self._add(line, piece, "solution", "fails", why)
        self.settings_only = False
        return True

    def _linear_in_time(self, y):
        """c of the text's y defined as c·t (its τ = p t), else None."""
        value = self.ctx.defs.get(y)
        if value is None or lx.t not in _free(value):
            return None
        c = sp.cancel(value / lx.t)
        return c if lx.t not in _free(c) and c != 0 else None

    def _rate_along(self, m):
        """``dx/dτ`` read as ẋ/τ̇ (`derive.lecture.written_rates.rate_along`) with τ = c·t: (x, c)."""
        num, den = m.as_numer_denom() if isinstance(m, sp.Mul) else (m, sp.S.One)
        if not (isinstance(num, lx.DT) and isinstance(den, lx.DT)):
            return None
        x, y = num.args[0], den.args[0]
        c = self._linear_in_time(y) if isinstance(x, lx.Generic) else None
        return None if c is None else (x, c)

    def _in_time(self, value):
        """``value`` with the text's names defined as c·t put in (sn τ with τ = p t is sn(p t))."""
        rep = {y: self.ctx.defs[y] for y in _free(value) if isinstance(y, lx.Generic) and self._linear_in_time(y) is not None}
        return value.xreplace(rep) if rep and hasattr(value, "xreplace") else value

    def _own_solution(self, line, piece, left, right) -> bool:
        """``u = u_1 + (u_2-u_1)\\sn^2(c t)``, ``\\theta = \\arccos[…]``, ``\\sin v = \\sn(c t)``: a closed
        form the text gives for its own equation ``\\dot u^n = F(u)``, written for u, for a name it
        defined u by (u = cos θ) or for a variable of its change (u = S(v)). Solved for that name,
        carried to u(t), and put into the equation: holds when u̇(t)ⁿ = F(u(t)) at random values of
        the names (with those the text defines further on). Only a solution that holds is taken."""
        for var, (n, eq, eq_line) in self.ctx.own_motion.items():
            ways = [(var, var)]
            ways += [(x, d) for x, d in [(x, self.ctx.defs.get(var)) for x in _free(self.ctx.defs.get(var, 0))]
                     if x in self.d.rot.ANGLES]
            ways += [(v, change) for v, (old, change, _) in self.ctx.changes.items() if old == var]
            for name, carried in ways:
                if _free(left) != {name}:
                    continue
                try:
                    roots = [left] if left == name else sp.solve(sp.Eq(left, sp.Symbol("_r")), name)
                except (NotImplementedError, TypeError, ValueError):
                    continue
                for root in roots:
                    value = root.xreplace({sp.Symbol("_r"): right}) if left != name else right
                    u_t = carried.xreplace({name: value}) if name != var else value
                    known = _free(eq) | {lx.t}
                    u_t = self._later_names(u_t, known | _free(u_t) - set(self.later_defs) - set(self.ctx.defs))
                    if u_t is None:
                        continue
                    lhs = sp.diff(u_t, lx.t) ** n
                    rhs = self._later_names(eq.xreplace({var: u_t}), known)
                    # u̇ = √F(u) is solved on the branch of the root the text takes: its square is
                    branch = rhs is not None and n % 2 == 1 and any(
                        p.exp == sp.Rational(1, 2) for p in sp.sympify(rhs).atoms(sp.Pow)) and _equal(lhs ** 2, rhs ** 2)
                    if rhs is not None and (_equal(lhs, rhs) or branch):
                        how = f" through {self.tex(name)}" if name != var else ""
                        self._add(line, piece, "solution", "holds",
                                  f"put into the text's equation for {self.tex(var)} (line "
                                  f"{eq_line}){how}: it solves it (equal at random values of its names"
                                  + (", squared: the root's branch is the text's)" if branch and not _equal(lhs, rhs) else ")"))
                        self.settings_only = False
                        return True
        return False

    def _function_then_bound(self, line, piece, parsed) -> bool:
        """``G(-1) = -(\\beta + b\\Omega)^2 < 0``: the text's function at an argument, then a bound on
        the value. Two claims: the equality (as `_function_of_the_text` takes it) and the bound,
        decided by the orderings the text states or left ``unchecked``. False (nothing said) when
        the equality is not the text's function put in."""
        cuts = top_relations(piece)
        if len(cuts) != len(parsed.relations):
            return False
        equality, bound = piece[:cuts[1][0]].strip(), piece[cuts[0][1]:].strip()
        members = [m.value for m in parsed.members]
        if not self._function_of_the_text(line, equality, members[:2]):
            return False
        if not self._ordered(line, bound, members[1:], parsed.relations[1:]):
            self._add(line, bound, "inequality", "unchecked", "a bound the derivation does not decide")
        return True

    def _function_of_the_text(self, line, piece, members) -> bool:
        """``G\\left(\\frac{\\beta}{b\\Omega}\\right) = …`` after the text defined ``G(u) = …``: G at
        that argument, its definition with u put in. Only a statement that then holds in the
        text's names is taken (True); anything else is left to the rest of the checker."""
        applied, where = [], {}
        for k, m in enumerate(members):
            for f in _free(m):
                atom = self.vocab.generic.get(f) if isinstance(f, lx.Generic) else None
                if atom is None or atom.sup or f in self.ctx.defs or not (m == f or isinstance(m, sp.Mul) and f in m.args):
                    continue
                defined = [(s, a) for s, a in self.vocab.generic.items() if s in self.ctx.defs
                           and a == atom.with_(sup=a.sup) and a.sup.startswith("(") and a.sup.endswith(")")]
                if len(defined) != 1:
                    continue
                sym, a = defined[0]
                body = self.ctx.defs[sym]
                var = [x for x in _free(body) if str(x) == a.sup[1:-1]]
                arg = m / f
                if arg == 1 and not re.search(rf"(?<![A-Za-z\\]){re.escape(atom.base)}\s*(\\left)?\(\s*\+?\s*1\s*(\\right)?\)",
                                              piece):
                    continue                # G alone, not G(1): the product reading drops a factor 1
                if len(var) != 1 or f in _free(arg):
                    continue
                applied.append(k)
                where[k] = (body.xreplace({var[0]: arg}), a)
        if not applied:
            return False
        values = [where[k][0] if k in where else m for k, m in enumerate(members)]
        if not all(_equal(values[0], v) for v in values[1:]):
            return False
        names = ", ".join(sorted({f"{a.base}{a.sup}" for _, a in where.values()}))
        self._add(line, piece, "identity", "holds",
                  f"with the text's function {names} put in (equal at random values of its names)")
        self.settings_only = False
        return True

    def _by_roots(self, line, piece, var, before, right) -> bool:
        """``\\dot u^n = c(u-u_1)(u-u_2)(u-u_3)`` after ``\\dot u^n = F(u)``, the roots named by the
        text and not computed: holds when F is a polynomial in u of that degree with leading
        coefficient c (then the factored form is F's, whatever its roots), fails when it is
        not; False (not this statement) for any other right side."""
        _, eq, eq_line = before
        roots, scale = [], sp.S.One
        for f in sp.Mul.make_args(right):
            base, k = f.as_base_exp()
            r = sp.expand(var - base)
            if var in _free(base) and isinstance(r, lx.Generic) and r not in self.ctx.defs \
                    and r not in _free(eq) and k.is_Integer and k > 0:
                roots += [r] * int(k)
            elif var in _free(f):
                return False
            else:
                scale *= f
        if not roots or _free(scale) & set(roots):
            return False
        try:
            poly = sp.Poly(sp.expand(eq), var)
        except sp.PolynomialError:
            return False
        if _free(sp.Matrix(poly.all_coeffs())) & {var}:
            return False
        names = ", ".join(self.tex(r) for r in dict.fromkeys(roots))
        self.settings_only = False
        if poly.degree() == len(roots) and sp.expand(poly.LC() - scale) == 0:
            self._add(line, piece, "identity", "holds",
                      f"the text's {self.tex(eq)} (line {eq_line}) is a polynomial in {self.tex(var)} of degree "
                      f"{len(roots)} with leading coefficient {self.tex(scale)}: its factored form, whatever roots "
                      f"{names} it names")
        else:
            self._add(line, piece, "identity", "fails",
                      f"the text's {self.tex(eq)} (line {eq_line}) is a polynomial in {self.tex(var)} of degree "
                      f"{poly.degree()} with leading coefficient {self.tex(poly.LC())}, not {len(roots)} and "
                      f"{self.tex(scale)}")
        return True

    def _check_changes(self):
        """Item 3, at the end of the text: each held check replaces its placeholder claim."""
        for placeholder, var, dot, n, right, (old, change, change_line), (m, eq, eq_line) in \
                getattr(self, "change_checks", ()):
            derived = eq.xreplace({old: change}) / sp.diff(change, var) ** m     # v̇^m
            claim = self._later_names(right, _free(eq) | _free(change))
            if claim is None:
                placeholder.why = f"uses names the text never defines ({', '.join(sorted(map(str, _free(right))))})"
                continue
            how = (f"{self.tex(old)} = {self.tex(change)} (line {change_line}) put into the text's "
                   f"equation for {self.tex(old)} (line {eq_line})")
            written, _, rest = placeholder.latex.partition("=")
            written = written.strip()
            power = written if n == m else f"{written}^{m}" if n == 1 else self.tex(dot ** m)
            if m == n and _equal(claim, derived) or m != n and _equal(claim ** m, derived ** n):
                placeholder.kind, placeholder.verdict, placeholder.why = "identity", "holds", how
            elif m != n and _equal(claim, derived):
                placeholder.kind, placeholder.verdict = "identity", "typo"
                placeholder.why = f"the left side is {power}, not {written}: {how}"
                placeholder.correction = f"{power} = {rest.strip()}"
            else:
                placeholder.kind, placeholder.verdict = "identity", "fails"
                placeholder.why = f"{how} gives {power} = {self.tex(sp.factor(derived))}"
                placeholder.correction = f"{power} = {self.tex(sp.factor(derived))}"

    def _later_definition(self, left, right):
        """``k^2 = …`` or ``k = …`` for a name a waiting check uses and nothing defined before
        (``where k^2 = …`` after the equation): kept for that check."""
        base, n = (left.base, left.exp) if isinstance(left, sp.Pow) else (left, sp.S.One)
        waiting = set().union(*(_free(c[4]) for c in self.change_checks)) if self.change_checks else set()
        if isinstance(base, lx.Generic) and base in waiting and base not in self.ctx.defs \
                and n.is_Integer and n > 0 and base not in _free(right):
            self.later_defs.setdefault(base, right ** sp.Rational(1, int(n)))

    def _later_names(self, value, known):
        """value with the text's names outside ``known`` replaced by their definitions (as the
        text gives them by its end), or None when one has none."""
        for _ in range(4):
            loose = {s for s in _free(value) if isinstance(s, lx.Generic) and s not in known}
            defs = {**self.later_defs, **self.ctx.defs}
            rep = {s: defs[s] for s in loose if s in defs}
            if len(rep) < len(loose):
                return None
            if not rep:
                return value
            value = value.xreplace(rep)
        return None
