"""A claim's value against the derived forms, in every case of its section, and the nearest
correct form by one edit.

Takes: the state of the notes checker (`derive.lecture.notes_check.Checker`: its context's
settings, solutions and sign cases, its resolution of the text's names). Gives: the mixin
`Judging` of the checker —

* ``_compare``: is the value the derived form in every sign case the section states (the zero
  test of `derive.lecture.comparing`, or a series to the claim's own order for an approximation)?
* ``_search``: one edit of the value (a sign, an index, sin ↔ cos, a factor, a power) or of the
  label that makes it hold, rendered as the statement with its left side;
* ``_render``: a statement as LaTeX in the text's relation.

* ``_unify``: the sides put in the same variables (rates of the angles, the body basis).

May import: :mod:`derive.lecture.comparing`, :mod:`derive.lecture.derivation`, :mod:`derive.lecture.latex`, SymPy.
"""
from __future__ import annotations

import contextlib
import functools

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.comparing import Mismatch, column, edits, free, has_rates, quick_equal, zero
from derive.lecture.derivation import families


class Judging:
    """Mixin of the notes checker: compare with the derivation, search for a one-edit correction."""

    def _unify(self, values: list, known=None) -> list:
        """With α̇ or γ̇ present, p_α, p_γ, ω̃ᵢ become functions of the angles; frame vectors go to the
        body basis. ``known`` keeps each value's form per the two flags its replacements depend on,
        for a search that unifies one target with each of its candidates."""
        rot = self.d.rot
        out = []
        rates = has_rates(values, rot)
        cyc = any(free(v) & {rot.alpha_d, rot.gamma_d} for v in values)
        for v in values:
            try:
                key = (v, rates, cyc) if known is not None and (v, rates, cyc) in known else None
            except TypeError:       # a mutable matrix: not hashable, unified as it stands
                key = None
            if key is not None:
                out.append(known[key])
                continue
            syms = free(v)      # only what v holds is derived: a sequence read again derives no heavy top for ω̃
            rep = dict(self.d.frames) if syms & (set(lx.PRIMED) | set(lx.INERTIAL)) else {}
            if rates and syms & set(lx.W):
                rep.update({w: self.d.omega[i] for i, w in enumerate(lx.W)})
            for p in (lx.p_alpha_sym(), lx.p_gamma_sym()) if cyc else ():
                if p in syms:
                    rep[p] = self.d.forms(p)[0]
            out.append(v.xreplace(rep) if rep else v)
            if known is not None:
                with contextlib.suppress(TypeError):
                    known[(v, rates, cyc)] = out[-1]
        return out

    def _case_subs(self, v, case, solutions=True):
        rep = dict(self.ctx.subs)
        if solutions:
            rep.update(self.ctx.solutions)
        if rep:
            v = self._resolve(v.xreplace(rep)).xreplace(rep)
        return v.xreplace(case) if case else v

    def _compare(self, claim_value, form, seed, small=None, order=None) -> tuple[bool, str]:
        """Is the claim's value the derived form, in every case of the section?"""
        a, b = self._unify([claim_value, form])
        try:
            A, B = column(a), column(b)
        except Mismatch as err:
            return False, str(err)
        why = []
        for k, case in enumerate(self.ctx.cases):
            Ac = A.applyfunc(lambda x: self._case_subs(x, case))
            Bc = B.applyfunc(lambda x: self._case_subs(x, case))
            if small is not None:
                ok, how = self._series_zero(Ac, Bc, small, order)
            else:
                ok, how = zero(Ac, Bc, f"{seed}/{k}")
            if not ok:
                where = f" (case {k + 1} of {len(self.ctx.cases)}: {self._case_text(case)})" if len(self.ctx.cases) > 1 else ""
                return False, how + where
            why.append(how)
        return True, why[0]

    def _case_text(self, case):
        return ", ".join(f"{self.tex(s)} {'> 0' if v.could_extract_minus_sign() is False else '< 0'}" for s, v in case.items())

    def _series_zero(self, A, B, x, order):
        # sin x and cos x by their Taylor polynomials first: the series of a rational function is
        # cheap, that of quotients of sines is not (a second each).
        n = order + 4
        taylor = {sp.sin(x): sum((-1) ** k * x ** (2 * k + 1) / sp.factorial(2 * k + 1) for k in range(n // 2 + 1)),
                  sp.cos(x): sum((-1) ** k * x ** (2 * k) / sp.factorial(2 * k) for k in range(n // 2 + 1))}
        for a, b in zip(A, B):
            d = _series_difference(a - b, x, order, tuple(taylor.items()))
            if sp.simplify(d) != 0:
                return False, f"series in {self.tex(x)} to order {order - 1}: claim − derived = {self.tex(sp.factor(d))}"
        return True, f"series in ${self.tex(x)}$ to order {order - 1}"

    def _search(self, value, targets, label, parsed, k, small, order, keep):
        """The nearest correct form by one edit of the member or of the label, or None."""
        tried = 0
        for f in targets:
            target = self._resolve(f)
            seen = {}      # the target in the first case, once per form `_unify` gives it (a few at most)
            unified = {}   # the target's forms by `_unify`, which does not change from candidate to candidate
            for cand, what in edits(value):
                tried += 1
                if tried > 400:
                    return None
                val = self._resolve(cand, keep=keep)
                a, b = self._unify([val, target], known=unified)
                if small is None:
                    ac = self._case_subs(a, self.ctx.cases[0])
                    try:
                        bc = seen[b] if b in seen else seen.setdefault(b, self._case_subs(b, self.ctx.cases[0]))
                    except TypeError:       # a mutable matrix: not hashable, substituted as it stands
                        bc = self._case_subs(b, self.ctx.cases[0])
                    if not quick_equal(ac, bc):
                        continue
                ok, _ = self._compare(val, target, f"edit/{tried}", small, order)
                if ok:
                    self._last_fix = cand
                    return self._render(parsed, k, cand), what
        # a swapped label
        if isinstance(label, sp.Symbol):
            for fam in families():
                if label in fam:
                    for other in fam:
                        if other == label:
                            continue
                        for f in self.d.forms(other):
                            ok, _ = self._compare(self._resolve(value), self._resolve(f), "label", small, order)
                            if ok:
                                return self._render(parsed, k, value, label=other), "a swapped label"
        return None

    def _render(self, parsed, k, value, label=None):
        left = label if label is not None else parsed.members[0].value
        rel = {"=": "=", "≡": r"\equiv", "≈": r"\approx", "≥": r"\ge", "≤": r"\le", ">": ">", "<": "<"}[parsed.relations[k - 1]]
        lhs = self.tex(left)
        if parsed.members[0].args and label is None:
            lhs += r"\left(" + ", ".join(self.tex(a) for a in parsed.members[0].args) + r"\right)"
        return f"{lhs} {rel} {self.tex(value)}"


@functools.lru_cache(maxsize=256)
def _series_difference(d, x, order, taylor):
    """d with sin x, cos x put as their Taylor polynomials ``taylor``, over one denominator, and its
    series in x to ``order``; kept per difference, which each reading of a text in another sequence
    of angles (or of a section's cases) expands again."""
    d = sp.cancel(sp.together(d.xreplace(dict(taylor))))
    return sp.series(d, x, 0, order).removeO()
