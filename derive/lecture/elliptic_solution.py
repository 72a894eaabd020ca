"""The free body's motion solved in Jacobi's elliptic functions, as a text writes it:
``\\omega_1 = A_1\\cn\\tau,\\ \\omega_2 = A_2\\sn\\tau,\\ \\omega_3 = A_3\\dn\\tau`` with the text's
τ = λ t and modulus k (``k^2 = …``).

A display whose rows each give a body rate ωᵢ (the reader's principal components) as a function of
time holding sn, cn or dn is a claimed solution of Euler's free equations, not a definition of the
model's ωᵢ. When its rows give all three, each chain position is put into Iᵢ ω̇ᵢ = (Iⱼ − Iₖ) ωⱼ ωₖ
(cyclic), with sn′ = cn dn, cn′ = −sn dn, dn′ = −k² sn cn and the text's own k² and τ = λ t, and,
where the rates hold the model's T and L, into the integrals 2T = Σ Iᵢωᵢ² and L² = Σ Iᵢ²ωᵢ². The rows
hold when all vanish at random points of the free body's region (I₁ < I₂ < I₃, 2I₁T < L² < 2I₃T)
where every root's radicand is positive; otherwise they are left unchecked, never flagged, since
the text may order its moments otherwise and its roots' branches rest on that order. A row alone,
a modulus the text never gives, or a name not tied to the model leaves the rows unchecked, naming
what stopped them.
Takes the checker's context and vocabulary; gives claims; imports nothing of the checker.
"""
from __future__ import annotations

import random
import re

import mpmath
import sympy as sp

from derive.lecture import elliptic, mp_values
from derive.lecture import latex as lx
from derive.symbolic.lagrangian import I1, I2, I3

_WRITTEN = re.compile(r"\\(?:sn|cn|dn)\b|\{(?:sn|cn|dn)\}")
_JACOBI = (elliptic.JacobiSN, elliptic.JacobiCN, elliptic.JacobiDN)
_MOMENTS = (I1, I2, I3)
# the free body's two integrals in its body rates w: the model's kinetic energy and |L|, squared
_INTEGRALS = {"T": lambda w: (sum(i * x ** 2 for i, x in zip(_MOMENTS, w)) / 2, 1),
              "|L|": lambda w: (sum(i ** 2 * x ** 2 for i, x in zip(_MOMENTS, w)), 2)}


def _free(e) -> set:
    return getattr(e, "free_symbols", set())


class EllipticSolution:
    """Mixin of the checker: see the module docstring. Uses ``self.vocab``, ``self.ctx`` (defs),
    ``self.tex``, ``self._in_time`` and ``self._add``."""

    def _elliptic_solution(self, line, pieces) -> bool:
        """The display read as the module says; False (read as before) when it is not of that shape."""
        if not any(_WRITTEN.search(p) for p in pieces):
            return False
        rows, read = [], lx.parse_all(pieces, self.vocab)
        if read is None:
            return False
        for piece, parsed in zip(pieces, read):
            members = [m.value for m in parsed.members]
            if len(members) < 2 or set(parsed.relations) != {"="} or members[0] not in lx.W:
                return False
            values = [self._in_time(v) for v in members[1:]]
            if not all(isinstance(v, sp.Expr) and lx.t in _free(v) and v.has(*_JACOBI) for v in values):
                return False
            rows.append((piece, lx.W.index(members[0]), values))
        given = {i for _, i, _ in rows}
        why = self._solution_stop(rows, given)
        if why:
            for piece, _, _ in rows:
                self._add(line, piece, "solution", "unchecked", f"a solution in Jacobi's elliptic functions: {why}")
            return True
        verdict, why = self._solves_euler(rows)
        for piece, _, _ in rows:
            self._add(line, piece, "solution", verdict, why)
        self.settings_only = False
        return True

    def _modulus(self):
        """(the text's k, its value from the text's ``k^2 = …``), or None where the text gives none."""
        for key, value in self.ctx.defs.items():
            if isinstance(key, lx.Generic) and key.name == elliptic.MODULUS and isinstance(value, sp.Expr):
                return key, value
        return None

    def _solution_stop(self, rows, given):
        """What stops the check, in words; '' when nothing does."""
        if len(rows) != 3 or given != {0, 1, 2} or len({len(v) for _, _, v in rows}) != 1:
            return ("the display does not give all three body rates in one form, and a rate alone is no "
                    "definition of the model's")
        if self._modulus() is None:
            return f"the text gives no value of the modulus {elliptic.MODULUS}"
        k, value = self._modulus()
        allowed = set(_MOMENTS) | {lx.t, k} | {q for q in _free(value) | {a for _, _, vs in rows for v in vs for a in _free(v)}
                                                if isinstance(q, lx.Quantity) and q.name in _INTEGRALS}
        for _, _, values in rows:
            for v in values:
                loose = [s for s in _free(v) - allowed if not isinstance(s, lx.Generic) or s in self.ctx.defs]
                if loose:
                    return f"{self.tex(loose[0])} is not a free constant of the text's solution"
        loose = [s for s in _free(value) - allowed if not isinstance(s, lx.Generic) or s in self.ctx.defs]
        if loose:
            return f"the modulus holds {self.tex(loose[0])}, not a free constant of the text's"
        return ""

    def _solves_euler(self, rows):
        """(verdict, why) of the rows put into Euler's free equations, each chain position in turn."""
        k, value = self._modulus()
        order = sorted(rows, key=lambda r: r[1])
        for j in range(len(order[0][2])):
            w = [r[2][j].xreplace({k: value}) if k in _free(value) else r[2][j].subs(k, value) for r in order]
            exprs = [_MOMENTS[i] * sp.diff(w[i], lx.t) - (_MOMENTS[(i + 1) % 3] - _MOMENTS[(i + 2) % 3])
                     * w[(i + 1) % 3] * w[(i + 2) % 3] for i in range(3)]
            exprs += [integral - q ** power for q in sorted({q for x in w for q in _free(x) if isinstance(q, lx.Quantity)}, key=str)
                      for integral, power in [_INTEGRALS[q.name](w)]]
            if not _zero_in_region(exprs, f"jacobi/{j}"):
                return "unchecked", ("put into Euler's free equations with sn′ = cn dn, cn′ = −sn dn, dn′ = −k² sn cn "
                                     "and the text's k², the three rates are not shown to solve them and give back "
                                     "2T = Σ Iᵢωᵢ², L² = Σ Iᵢ²ωᵢ² where I₁ < I₂ < I₃ and the roots are real")
        return "holds", ("put into Euler's three free equations with sn′ = cn dn, cn′ = −sn dn, dn′ = −k² sn cn "
                         "and the text's k²: the three rates solve them and give back the integrals they hold (2T = Σ Iᵢωᵢ², "
                         "L² = Σ Iᵢ²ωᵢ²), at random points with I₁ < I₂ < I₃, 2I₁T < L² < 2I₃T and the roots real (50 digits)")


def _zero_in_region(exprs, seed, wanted=3) -> bool:
    """Whether every expression vanishes (to 40 of 50 digits) at ``wanted`` seeded points of the free
    body's region, I₁ < I₂ < I₃ and 2I₁T < L² < 2I₃T (other names positive), where every root's
    radicand is positive; False when they do not, or when too few such points turn up."""
    symbols = sorted(set().union(*(_free(e) for e in exprs)), key=str)
    bases = sorted({p.base for e in exprs for p in sp.sympify(e).atoms(sp.Pow) if not p.exp.is_Integer}, key=sp.default_sort_key)
    f, radicands = mp_values.evaluator(symbols, exprs), mp_values.evaluator(symbols, bases)
    rng, found = random.Random(seed), 0
    for _ in range(200):
        with mpmath.workdps(50):
            at = {x: mpmath.mpf(rng.randint(20, 200)) / 100 for x in symbols}
            moments = sorted(mpmath.mpf(rng.randint(50, 300)) / 100 for _ in range(3))
            at.update(zip(_MOMENTS, moments))
            energy = at.get(_quantity(symbols, "T"), mpmath.mpf(1))
            for q in symbols:
                if isinstance(q, lx.Quantity) and q.name == "|L|":
                    at[q] = mpmath.sqrt(2 * energy * (moments[0] + (moments[2] - moments[0]) * rng.randint(5, 95) / 100))
            point = [at[x] for x in symbols]
            vals = mp_values.real_values(f, radicands, point)
            if vals is None:
                continue
            if not all(mpmath.isfinite(v) and abs(v) < mpmath.mpf(10) ** -40 for v in vals):
                return False
            found += 1
            if found == wanted:
                return True
    return False


def _quantity(symbols, name):
    return next((q for q in symbols if isinstance(q, lx.Quantity) and q.name == name), None)
