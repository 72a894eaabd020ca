"""Equations of motion in a text, and their solutions: the part of the notes checker that checks a formula with
ω̃̇ᵢ, ω̃̈ᵢ or an angle's acceleration, a solution ω̃ᵢ(t) = f(t), a steady precession, a stability inequality, a repeated row.

Takes: statements parsed by `derive.lecture.latex` and the checker's context (the section's settings, the text's
definitions, the equations it has written). Gives: the mixin `Motion` of `derive.lecture.notes_check.Checker`:

* an equation with ω̃̇ᵢ is a non-zero constant multiple of one of Euler's equations
  Iᵢω̃̇ᵢ − ((Iω̃)×ω̃)ᵢ under the section's settings (ω̃₁ = Ω, a constant spin, linearises them), or
  a combination of them;
* an equation with ω̃̈ᵢ follows from the text's latest first-order equations (or Euler's under the
  settings) by one more derivative, ω̃̈ᵢ = Σⱼ ∂ω̃̇ᵢ/∂ω̃ⱼ ω̃̇ⱼ;
* a group of consecutive solutions ω̃ᵢ(t) = f(t) (or Lᵢ = Iᵢω̃ᵢ = f(t)) is substituted into the
  latest equations the text wrote for those components under the same settings, or Euler's
  under them; the text's undefined symbols in a solution are its integration constants.

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.comparing`, :mod:`derive.lecture.matrix_rows`, :mod:`derive.lecture.sparse_forms`, :mod:`derive.lecture.zero_test`,
:mod:`derive.lecture.spin_threshold`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import functools

import sympy as sp

from derive.lecture import latex as lx, spin_threshold
from derive.lecture.comparing import edits, flow_of, free, not_a_consequence, positive_multiple, quick_equal, zero
from derive.lecture.context import is_ordering, sign_under_orderings
from derive.lecture.matrix_rows import rows_verdict
from derive.lecture.sparse_forms import rational_zero
from derive.lecture.zero_test import differs_somewhere, expanded, surely_depends, surely_nonzero
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3, Mass, g, l


class Motion:
    """Mixin of the checker: see the module docstring. Uses ``self.ctx`` (subs, defs, eoms, cases,
    solutions), ``self.d`` (the derivation), ``self.pending``, ``self._resolve``, ``self._unify``,
    ``self._compare``, ``self._add`` and ``self.tex``."""

    def _eom(self, line, piece, parsed):
        members = [m.value for m in parsed.members]
        if len(members) != 2 or isinstance(members[0], sp.MatrixBase):
            rows = rows_verdict(members, self._eom_check)
            self._add(line, piece, "equation of motion", *(rows or ("unchecked", "not a single scalar equation")))
            return
        raw = members[0] - members[1]
        used = [x for x in free(raw) if x in self.ctx.defs]
        if used and not surely_nonzero(e := self._resolve(raw).xreplace(self.ctx.subs)) and not differs_somewhere(e, sp.S.Zero, "eom") and expanded(e) == 0:
            names = ", ".join(sorted(self.tex(x) for x in used))
            self._add(line, piece, "equation of motion", "holds", f"the text's own definition of {names}, restated")
            return
        branch = self._rate_in_angles(members) or (None if self.ctx.first_order else self._on_a_branch(members))
        if branch:
            self._add(line, piece, "equation of motion", "holds", branch)
            return
        ok, why, residual = self._eom_check(raw)
        if ok:
            self._eom_noted(raw, line)
            self._add(line, piece, "equation of motion", "holds", why)
            return
        for cand, what in ([] if self.judging_only else edits(raw)):
            if self._eom_check(cand, candidate=True)[0]:
                fixed = sp.Eq(cand, 0) if members[1] == 0 else None
                corr = self.tex(cand) + " = 0" if fixed is not None else self._render_eq(cand, parsed)
                self._add(line, piece, "equation of motion", "typo", f"as written: {why}; one edit ({what}) makes it hold", corr)
                self._eom_noted(cand, line)   # the solutions that follow meet the corrected equation
                return
        self._add(line, piece, "equation of motion", "fails", f"as written: {why}")
        found = [i for i in range(3) if lx.WD[i] in free(raw)]
        if len(found) == 1:   # … or, past correcting, the derived one for that component
            self._eom_noted(self.d.euler(self.ctx.subs)[found[0]], line)

    def _angle_eom(self, line, piece, parsed):
        """An equation of motion in the angles (I₁θ̈ = …): solved for the one acceleration it has,
        against the heavy symmetric top's Lagrange equations — in the rates, or with the cyclic
        momenta for the rates (Routh's reduction)."""
        raw = self._resolve(parsed.members[0].value - parsed.members[1].value)
        accels = [a for a in ACCELS if a in free(raw)]
        rot = self.d.rot
        if len(accels) != 1 or sp.diff(raw, accels[0], 2) != 0 or accels[0] != ACCELS[1]:
            self._add(line, piece, "equation of motion", "unchecked", "an equation of motion the derivation does not write")
            return
        a = accels[0]
        claim = sp.cancel(sp.together(-raw.xreplace({a: 0}) / sp.diff(raw, a)))
        # one equation once `_unify` writes the momenta in the rates: a claim in the rates is held against
        # Lagrange's form, one in the momenta against Routh's (a sequence probed derives only that one)
        rated, held = free(claim) & {rot.alpha_d, rot.gamma_d, *lx.W}, free(claim) & {lx.p_alpha_sym(), lx.p_gamma_sym()}
        why = ""
        for k in ["top"] if rated else ["routh"] + ([] if held else ["top"]):
            f = self.d.top.accelerations[1] if k == "top" else self.d.reduction.beta_acceleration
            ok, why = self._compare(claim, f, piece + "/angle")
            if ok:
                self._add(line, piece, "equation of motion", "holds", f"Lagrange's equation for ${self.tex(rot.beta)}$: {why}")
                return
        if self._learned(piece) or free(claim) & {lx.Generic}:
            self._add(line, piece, "equation of motion", "unchecked", f"does not match the heavy top's equation ({why})")
            return
        self._add(line, piece, "equation of motion", "fails",
                  f"as written: not Lagrange's equation for ${self.tex(rot.beta)}$ of the heavy symmetric top ({why})")

    # -- steady precession
    def _steady_section(self) -> bool:
        """The text has set β̇ = 0 (a steady precession at a fixed tilt)."""
        return self.ctx.subs.get(self.d.rot.beta_d, None) == 0

    def _steady(self, line, piece, parsed):
        """A condition for steady precession: with β̇ = β̈ = 0 the β equation of motion reduces to
        ∂L/∂β = 0; the claim's lhs − rhs (rates and momenta in terms of the angles) must be a
        non-zero multiple of it by a factor free of the rates."""
        raw = parsed.members[0].value - parsed.members[1].value
        ok, why = self._steady_check(raw)
        if ok:
            self._add(line, piece, "steady precession", "holds", why)
            return
        for cand, what in ([] if self.judging_only else edits(raw)):
            if self._steady_check(cand)[0]:
                self._add(line, piece, "steady precession", "typo",
                          f"as written: {why}; one edit ({what}) makes it hold", self.tex(cand) + " = 0")
                return
        self._add(line, piece, "steady precession", "fails", f"as written: {why}")

    def _steady_check(self, raw):
        rot = self.d.rot
        (r,) = self._unify([self._resolve(raw).xreplace(self.ctx.subs)])
        r = expanded(r)
        if r == 0:
            return False, "the condition is empty (0 = 0)"
        force = self.d.steady_force
        q = sp.cancel(sp.together(r / force))
        if q != 0 and not free(q) & (set(rot.RATES) | {rot.alpha, rot.gamma}):
            return True, f"a multiple ({self.tex(q)}) of the β equation at β̇ = β̈ = 0: ∂L/∂β = 0"
        return False, "not a multiple of the β equation at β̇ = β̈ = 0 (derived: ∂L/∂β = 0)"

    def _render_eq(self, residual, parsed):
        return self.tex(residual) + " = 0"

    def _on_a_branch(self, members):
        """An equation of motion with a square root of the ω̃ᵢ (``ds/dτ = √((1 − s²)(1 − k²s²))`` of a
        text's s ∝ ω̃₂): its sides compared once ω̃̇ is taken from Euler's equations, a root being the
        branch the text takes (`derive.lecture.comparing.zero`); the why when that holds, else None
        (it is then read as any other, and left unjudged for its roots)."""
        sides = [self._resolve(m).xreplace(self.ctx.subs) for m in members]
        dyn = set(lx.W) | set(lx.WD)
        if not any(not p.exp.is_integer and free(p.base) & dyn for e in sides for p in e.atoms(sp.Pow)) \
                or any(free(e) & set(lx.TAU) for e in sides):
            return None
        flow = flow_of(tuple(expanded(R.xreplace(self.ctx.subs)) for R in self.d.euler(self.ctx.subs)))
        a, b = (e.xreplace(flow) for e in sides)
        if (free(a) | free(b)) & set(lx.WD):
            return None
        ok, why = zero(sp.Matrix([a]), sp.Matrix([b]), "branch")
        return f"once ω̃̇ is taken from Euler's equations, {why}" if ok else None

    def _eom_check(self, raw, candidate=False):
        """(holds, why, the residual) of an equation of motion; a ``candidate`` correction that
        cannot hold is refused before its residual is expanded (only whether it holds counts)."""
        # in Euler's equations the axial momentum p_γ is the body component I₃ω̃₃ it equals
        axial = {lx.p_gamma: (I1, I2, I3)[self.vocab.axial] * lx.W[self.vocab.axial]}
        r = self._resolve(raw).xreplace(axial).xreplace(self.ctx.subs)
        dyn = set(lx.W) | set(lx.WD)
        if any(not p.exp.is_integer and free(p.base) & dyn for p in r.atoms(sp.Pow)):
            # √ of the ω̃ᵢ (a text's u ∝ Π₂ under a root): not Euler's form, and its expansion is unbounded
            raise lx.NotRead("roots of the angular velocity's components: not an equation of motion the reader checks")
        # the section's settings (ω̃₃ = Ω, a constant spin) hold in Euler's equations too
        euler = [expanded(R.xreplace(self.ctx.subs)) for R in self.d.euler(self.ctx.subs)]
        if candidate and not self.ctx.first_order and not free(r) & set(lx.TAU) and not any(
                isinstance(x, lx.Generic) and x not in self.ctx.defs for x in free(r)) and not_a_consequence(r, euler):
            return False, "", None        # the residual below is this one expanded: the same screen
        # a torque the text wrote in an earlier equation of motion is that component's torque here too
        r = expanded(r.xreplace(self.ctx.torques))
        if r == 0:
            return False, "the equation is empty (0 = 0)", r
        loose = [x for x in free(r) if isinstance(x, lx.Generic) and x not in self.ctx.defs]
        own_torque = None
        if len(loose) == 1 and sp.diff(r, loose[0], 2) == 0 and not free(sp.diff(r, loose[0])) & set(lx.W):
            # one symbol of the text's, entering linearly: its term is the torque's component (N₃,
            # τ_z, αγ₃), scaled as the rest of the equation is (q, from the coefficients of ω̃̇ᵢ)
            for i in range(3):
                if free(r) & {lx.WD[i]}:
                    slope, scale = sp.diff(r, loose[0]), sp.diff(euler[i], lx.WD[i])
                    q = sp.cancel(sp.diff(r, lx.WD[i]) / scale) if scale != 0 else 0
                    own_torque = {loose[0]: -q * lx.TAU[i] / slope if q != 0 else lx.TAU[i]}
                    r = expanded(r.xreplace(own_torque))
                    break
        if free(r) & set(lx.TAU):          # with the text's torque: Iᵢω̃̇ᵢ − ((Iω̃)×ω̃)ᵢ = τᵢ
            # (none about an axis whose equation the text wrote without one, once it wrote one elsewhere)
            euler = [R - (0 if self.ctx.torques and i in self.ctx.untorqued else tau)
                     for i, (R, tau) in enumerate(zip(euler, lx.TAU))]
        if self.ctx.first_order:           # the prose made some ω̃ᵢ small: to first order in them
            r, euler = self._to_first_order(r), [self._to_first_order(R) for R in euler]
        failed = False, "not a consequence of Euler's equations (derived: I ω̃̇ = (I ω̃) × ω̃)", r
        # both ways of holding below leave r = 0 once ω̃̇ is taken from the equations (a multiple
        # q Rᵢ of one, Rᵢ linear in ω̃̇ᵢ, too): an exact point where it is not spares the search
        # for a correction its symbolic steps on every candidate
        if not_a_consequence(r, euler):
            return failed
        for i, R in enumerate(euler):
            if R == 0 or surely_depends(r, R, dyn):
                continue
            q = sp.cancel(sp.together(r / R))
            if not (free(q) & dyn) and q != 0:
                if not candidate and own_torque:
                    self.ctx.torques.update(own_torque)
                    self.ctx.untorqued.discard(i)
                elif not candidate and not free(r) & set(lx.TAU):
                    self.ctx.untorqued.add(i)
                return True, f"a multiple ({self.tex(q)}) of Euler's equation {i + 1}{self._order_note()}", r
        # a combination of them (Σ Iᵢω̃ᵢ × equation i, …): zero once ω̃̇ is taken from them
        flow = flow_of(tuple(euler))
        if free(r) & set(lx.WD) and rational_zero(expanded(r.xreplace(flow))):
            return True, "a consequence of Euler's equations (zero once ω̃̇ is taken from them)", r
        return failed

    def _duplicate(self, line, piece, parsed, pieces):
        """A row repeated within one block: a transcription slip; the missing equation is named."""
        have = set()
        for p in pieces:  # the rows that are one component's equation (not the vector sum)
            found = [i for i, w in enumerate(lx.WD) if lx.latex_atoms(p, self.vocab) & {w}]
            if len(found) == 1:
                have.add(found[0])
        gaps = [i for i in range(3) if i not in have]
        missing = self.tex(self.d.euler(self.ctx.subs)[gaps[0]]) + " = 0" if gaps else None
        kind = "equation of motion" if any(free(m.value) & set(lx.WD) for m in parsed.members) else "identity"
        if gaps:  # a typo: the row that should stand here is the missing component's equation
            self._add(line, piece, kind, "typo", "repeats an earlier row of the same block; the "
                      f"equation for component {gaps[0] + 1} is missing", missing)
        else:  # nothing is missing: a repeat is no wrong formula (a typo would need a correction)
            self._add(line, piece, kind, "unchecked", "repeats an earlier row of the same block")

    def _inequality(self, line, piece, parsed):
        if self._ordered(line, piece, [m.value for m in parsed.members], parsed.relations):
            return
        if len(parsed.members) != 2:
            self._add(line, piece, "inequality", "unchecked", "a chain of inequalities")
            return
        rel = parsed.relations[0]
        a, b = (self._resolve(m.value) for m in parsed.members)
        syms = free(a) | free(b)
        spin = {lx.p_gamma_sym(), lx.W[2], self.d.rot.gamma_d, self.d.rot.alpha_d}
        if not (syms & {Mass, g, l} and syms & spin):
            self._add(line, piece, "inequality", "unchecked",
                      "an inequality the derivation does not decide (it knows the sleeping top's condition)")
            return
        claim = (a - b) if rel in ("≥", ">") else (b - a)
        strict = rel in (">", "<")
        cond = self.d.sleeping.condition
        d = (cond.lhs - cond.rhs) if isinstance(cond, (sp.GreaterThan, sp.StrictGreaterThan)) else (cond.rhs - cond.lhs)
        d_strict = isinstance(cond, (sp.StrictGreaterThan, sp.StrictLessThan))
        ok, why = zero(sp.Matrix([claim, int(strict)]), sp.Matrix([d, int(d_strict)]), piece)
        if ok:
            self._add(line, piece, "inequality", "holds", "the stability condition of the sleeping top (k₂ ≥ 0): " + why)
            return
        if (bound := spin_threshold.judged(claim, d, self.tex)) is not None:    # the same bound solved for the spin
            return self._add(line, piece, "inequality", *bound)
        k2 = self.d.sleeping.coefficient(2)
        # the condition squared or scaled: k₂ ≥ 0 itself (p_γ² ≥ 4 M g l I₁), up to a positive factor
        if not strict and positive_multiple(claim, k2):
            self._add(line, piece, "inequality", "holds",
                      "a positive multiple of the sleeping top's k₂ ≥ 0 (the β² coefficient of V_eff)")
            return

        def derived(c) -> bool:
            return (not strict and positive_multiple(c, k2)) or \
                zero(sp.Matrix([c, int(strict)]), sp.Matrix([d, int(d_strict)]), piece)[0]

        if derived(-claim):
            flip = r"\le" if rel in ("≥", ">") else r"\ge"
            corr = f"{self.tex(parsed.members[0].value)} {flip} {self.tex(parsed.members[1].value)}"
            self._add(line, piece, "inequality", "typo", "the relation is reversed", corr)
            return
        for side in (1, 0):
            for cand, what in ([] if self.judging_only else edits(parsed.members[side].value)):
                c2 = self._resolve(cand) - b if side == 0 else a - self._resolve(cand)
                c2 = c2 if rel in ("≥", ">") else -c2
                if (quick_equal(c2, d) or positive_multiple(c2, k2)) and derived(c2):
                    fixed = [m.value for m in parsed.members]
                    fixed[side] = cand
                    rel_tex = {"≥": r"\ge", "≤": r"\le", ">": ">", "<": "<"}[rel]
                    self._add(line, piece, "inequality", "typo", f"one edit ({what}) makes it the derived condition",
                              f"{self.tex(fixed[0])} {rel_tex} {self.tex(fixed[1])}")
                    return
        self._add(line, piece, "inequality", "fails", f"not the derived stability condition {self.tex(cond)}: {why}")

    def _order_note(self) -> str:
        if not self.ctx.first_order:
            return ""
        return f" (to first order in {', '.join(self.tex(w) for w in lx.W if w in self.ctx.first_order)}, small as the text says)"

    def _to_first_order(self, e):
        """e without its terms of second or higher order in the small ω̃ᵢ (and their rates)."""
        small = [w for w in lx.W if w in self.ctx.first_order] + \
            [lx.WD[i] for i, w in enumerate(lx.W) if w in self.ctx.first_order]
        keep = []
        for term in sp.Add.make_args(sp.expand(e)):
            powers = term.as_powers_dict()
            if sum(powers.get(s, 0) for s in small) < 2:
                keep.append(term)
        return sp.Add(*keep)

    # -- inequalities under the orderings the text states
    def _ordered(self, line, piece, written, rels) -> bool:
        """A chain of symbols (``a > b > c``, ``I_1 < I_2 < I_3``) is an ordering the text states;
        an inequality in the symbols it ordered (and others, with the section's settings) holds
        when it follows from the orderings, and is a typo (the relation reversed) when its
        opposite does. False when the statement is neither."""
        values = [sp.sympify(v) for v in written]
        if not set(rels) <= {"<", ">", "≤", "≥"} or any(isinstance(v, sp.MatrixBase) for v in values):
            return False
        if is_ordering(values):
            chain = values if rels[0] in ("<", "≤") else values[::-1]
            self.ctx.orderings.append(chain)
            self._add(line, piece, "assumption", "unchecked", "an ordering the text states (used for the inequalities that follow)")
            return True
        ordered = set().union(*map(set, self.ctx.orderings)) if self.ctx.orderings else set()
        # three moments ordered: an asymmetric body, whose energy here is the free body's ½ Σ Iᵢω̃ᵢ²
        free_body = {I1, I2, I3} <= ordered and any(free(v) & {lx.ENERGY, lx.T_, lx.LMAG} for v in values)
        if free_body:       # E and T the body's ½ Σ Iᵢω̃ᵢ², |L| its √(Σ Iᵢ²ω̃ᵢ²): the constants in the rates
            half = self.d.forms(lx.T_)[0]
            values = [v.xreplace({lx.ENERGY: half, lx.T_: half, lx.LMAG: self.d.forms(lx.LMAG)[0]}) for v in values]
        values = [self._own_defs(self._resolve(v)).xreplace(self.ctx.subs) for v in values]
        syms = set().union(*(free(v) for v in values))
        if not ordered or not syms & ordered or not syms <= ordered | set(lx.W) | {s for s in syms if isinstance(s, lx.Generic)}:
            return False
        verdicts, names = [], sorted(syms, key=lambda x: x.name)
        for k, rel in enumerate(rels):
            a, b = (values[k], values[k + 1]) if rel in ("<", "≤") else (values[k + 1], values[k])
            verdict = self._sign(b - a, names)
            if verdict == "mixed" and all(self._sign(x, names) == "positive" for x in (a, b)):
                verdict = self._sign(sp.expand(b ** 2 - a ** 2), names)   # √x ≤ y as x ≤ y²
            verdicts.append(verdict)
        if all(v == "positive" for v in verdicts):
            energy = " (E, T the free body's ½ Σ Iᵢω̃ᵢ², |L| its √(Σ Iᵢ²ω̃ᵢ²))" if free_body else ""
            self._add(line, piece, "inequality", "holds", f"follows from {self._orderings_text()}{energy}")
        elif all(v == "negative" for v in verdicts) and len(rels) == 1:
            flip = {"<": ">", ">": "<", "≤": r"\ge", "≥": r"\le"}[rels[0]]
            self._add(line, piece, "inequality", "typo", f"the relation is reversed: its opposite follows from "
                      f"{self._orderings_text()}", f"{self.tex(written[0])} {flip} {self.tex(written[1])}")
        else:
            self._add(line, piece, "inequality", "unchecked", f"not decided by {self._orderings_text()}")
        return True

    def _orderings_text(self) -> str:
        return "; ".join(" < ".join(self.tex(x) for x in chain) for chain in self.ctx.orderings)

    def _sign(self, d, syms) -> str:
        return sign_under_orderings(d, tuple(syms), tuple(map(tuple, self.ctx.orderings)))

    # -- second-order equations ω̃̈ᵢ = …
    def _second_order(self, line, piece, parsed) -> bool:
        """An equation with ω̃̈ᵢ (the text eliminating one component): ω̃̈ᵢ = Σⱼ ∂ω̃̇ᵢ/∂ω̃ⱼ ω̃̇ⱼ with ω̃̇
        from the latest first-order equations the text wrote under the same settings (or Euler's
        under them). False when the statement has no ω̃̈ᵢ."""
        dd = {}
        for m in parsed.members:
            for s in free(m.value):
                i = self._second_rate(s)
                if i is not None:
                    dd[s] = i
        if not dd or len(parsed.members) != 2 or set(parsed.relations) != {"="}:
            return False
        self._flush()
        flows = self._flows()
        accel = {}
        for s, i in dd.items():
            f = flows.get(lx.WD[i])
            if f is None or any(w in free(f) and lx.WD[j] not in flows for j, w in enumerate(lx.W)):
                self._add(line, piece, "equation of motion", "unchecked",
                          f"no first-order equation for {self.tex(lx.WD[i])} in the text to differentiate")
                return True
            accel[s] = sum((sp.diff(f, w) * flows[lx.WD[j]] for j, w in enumerate(lx.W) if w in free(f)), sp.S.Zero)
        raw = parsed.members[0].value - parsed.members[1].value

        def residual(r):
            r = self._own_defs(self._resolve(r)).xreplace(accel).xreplace(self.ctx.subs).xreplace(flows)
            r = expanded(r.xreplace(self.ctx.subs))
            return self._to_first_order(r) if self.ctx.first_order else r

        r = residual(raw)
        known = set(dd) | self._constants() | set(self.ctx.defs)
        loose = sorted(self.tex(x) for x in free(r) if isinstance(x, lx.Generic) and x not in known)
        why = "one more derivative of the first-order equations (ω̃̈ᵢ = Σⱼ ∂ω̃̇ᵢ/∂ω̃ⱼ ω̃̇ⱼ, under the section's settings)"
        ok, how = zero(sp.Matrix([r]), sp.Matrix([0]), piece + "/second")
        if ok:
            self._add(line, piece, "equation of motion", "holds", f"{why}: {how}{self._order_note()}")
            self._second_noted(raw, dd)
            return True
        if loose:
            self._add(line, piece, "equation of motion", "unchecked", f"involves {', '.join(loose)}, which the text has not defined")
            return True
        for cand, what in ([] if self.judging_only else edits(raw)):
            if zero(sp.Matrix([residual(cand)]), sp.Matrix([0]), piece + "/second-edit")[0]:
                self._second_noted(cand, dd)
                self._add(line, piece, "equation of motion", "typo", f"as written: {how}; one edit ({what}) makes it "
                          f"{why}", self.tex(cand) + " = 0")
                return True
        self._add(line, piece, "equation of motion", "fails", f"as written: not {why}: {how}")
        return True

    def _second_rate(self, s):
        """The component i of a symbol of the text's that is ω̃̈ᵢ (``\\ddot{\\omega}_1``, or ``_y`` where
        the text calls the axes x, y, z), or None."""
        atom = self.vocab.generic.get(s) if isinstance(s, lx.Generic) else None
        if atom is None or atom.dots != 2 or atom.bold:
            return None
        try:
            plain = self.vocab.resolve(atom.with_(dots=0))
        except lx.NotRead:
            return None
        return lx.W.index(plain) if plain in lx.W else None

    def _second_noted(self, raw, dd):
        """Keep a second-order equation: the solutions after it are substituted into it."""
        self.ctx.eoms2.append((raw, dd, self._regime()))

    def _flows(self) -> dict:
        """ω̃̇ⱼ → its value, from the equation for it that applies now (`_eom_for`)."""
        flows = {}
        for j in range(3):
            eq = self._eom_for(j, self.ctx.subs, set(lx.W))
            if eq is None:
                continue
            eq = expanded(self._own_defs(eq).xreplace(self.ctx.subs))
            eq = self._to_first_order(eq) if self.ctx.first_order else eq
            c = sp.diff(eq, lx.WD[j])
            if c == 0 or free(c) & set(lx.WD) or (free(eq) & set(lx.WD)) - {lx.WD[j]}:
                continue
            flows[lx.WD[j]] = sp.cancel(-eq.xreplace({lx.WD[j]: 0}) / c)
        return flows

    # -- solutions ω̃ᵢ(t) = f(t)
    def _solution_row(self, parsed):
        """``ω̃ᵢ = f(t)`` or the angular momentum's component ``Lᵢ = Iᵢω̃ᵢ = f(t)``: (ω̃ᵢ, f, the factor
        Iᵢ or 1), or None. The right side depends on t and not on ω̃ (else it is an equation); ``≈``
        is a solution of the linearised equations the text wrote before it, checked as ``=``."""
        if len(parsed.members) != 2 or parsed.relations[0] not in ("=", "≈"):
            return None
        m0, value = parsed.members[0], parsed.members[1].value
        if isinstance(value, sp.MatrixBase) or isinstance(m0.value, sp.MatrixBase):
            return None
        lhs = m0.value
        if m0.args and lhs in lx.W:
            return lhs, value, sp.S.One
        if lx.t not in free(value) or free(value) & (set(lx.W) | set(lx.WD)):
            return None
        if lhs in lx.W:
            return lhs, value, sp.S.One
        moments = (I1, I2, I3)
        if lhs == lx.p_gamma_sym():
            lhs = moments[self.vocab.axial] * lx.W[self.vocab.axial]
        for i in range(3):
            if lhs == moments[i] * lx.W[i]:
                return lx.W[i], value / moments[i], moments[i]
        return None

    def _own_defs(self, v):
        """The text's own symbols replaced by their definitions (ω₀ ≡ …, n ≡ …)."""
        for _ in range(4):
            rep = {s: self.ctx.defs[s] for s in free(v) if isinstance(s, lx.Generic) and s in self.ctx.defs}
            if not rep:
                break
            v = v.xreplace(rep)
        return v

    def _eom_for(self, i, subs, allowed):
        """The latest equation the text wrote for ω̃̇ᵢ under the same settings of ω̃ (ω̃₁ = Ω): its
        residual, or, when it wrote none that applies, Euler's equation i under the settings. None
        when that equation involves a component outside ``allowed``."""
        wset = {k: v for k, v in subs.items() if k in lx.W}
        regime = self._regime(subs)
        for raw, _, settings in reversed(self.ctx.eoms):
            if free(raw) & {lx.WD[i]} and settings == regime and \
                    (free(raw) & set(lx.W)) - {lx.W[2]} - set(wset) <= set(allowed):
                return raw
        if lx.W[i] in wset:
            return None
        R = expanded(self.d.euler(subs)[i].xreplace(subs))
        if R == 0 or (free(R) & set(lx.W)) - set(allowed):
            return None
        return R

    def _regime(self, subs=None) -> dict:
        """The settings of ω̃ (ω̃₁ = Ω) and the components taken as small: an equation the text wrote
        under other ones (another axis, another linearisation) no longer applies."""
        subs = self.ctx.subs if subs is None else subs
        return {**{k: v for k, v in subs.items() if k in lx.W}, "small": frozenset(self.ctx.first_order)}

    def _eom_noted(self, raw, line):
        """Keep an equation of motion the text wrote, with the regime it was written under."""
        self.ctx.eoms.append((raw, line, self._regime()))

    def _flush(self):
        """Check the pending group of solutions against the latest equations, under the settings of
        the display that wrote them (a row ``ω̃₃ = Ω`` beside them)."""
        if not self.pending:
            return
        group, self.pending = self.pending, []
        subs = self.pending_subs if self.pending_subs is not None else dict(self.ctx.subs)
        self.pending_subs = None
        saved, self.ctx.subs = self.ctx.subs, subs
        start = len(self.claims)
        try:
            self._solutions(group)
        finally:
            self.ctx.subs = saved
            self.flushed.extend(self.claims[start:])
            del self.claims[start:]

    def _solutions(self, group):
        sol = {w: self._own_defs(f) for _, _, w, f, _ in group}
        t = lx.t
        chosen = []
        regime = self._regime()
        # a spin whose two other components the text calls small is constant to first order
        steady = {w for w in lx.W if set(lx.W) - {w} <= self.ctx.first_order}
        for w in sol:
            second = next((r.xreplace({d: sp.Derivative(lx.W[i], lx.t, 2) for d, i in dd.items()})
                           for r, dd, settings in reversed(self.ctx.eoms2)
                           if settings == regime and lx.W.index(w) in dd.values()
                           and free(r) & set(lx.W) <= set(sol) | {lx.W[lx.W.index(w)]} | steady), None)
            raw = second if second is not None else self._eom_for(lx.W.index(w), self.ctx.subs, sol)
            raw = raw if raw is None else self._own_defs(raw)
            if raw is not None and raw not in chosen:
                chosen.append(raw)
        for w, f in sol.items():
            self.ctx.solutions[w] = f
        if not chosen:
            for line, piece, *_ in group:
                self._add(line, piece, "solution", "unchecked", "no earlier equation of motion for these components to substitute into")
            return
        subs = {k: v for k, v in self.ctx.subs.items() if k not in sol}

        def holds(sol_, screen=False):
            """(holds, why); with ``screen``, a residual shown non-zero at a point ends it (no why)."""
            for k, case in enumerate(self.ctx.cases):
                for raw in chosen:
                    # only the derivatives the equation holds are taken (a candidate's second
                    # derivative is of no use to a first-order equation)
                    r = raw.xreplace({sp.Derivative(w, t, 2): _dt(f, 2) for w, f in sol_.items()
                                      if raw.has(sp.Derivative(w, t, 2))})
                    rates_ = {lx.WD[lx.W.index(w)]: _dt(f) for w, f in sol_.items() if r.has(lx.WD[lx.W.index(w)])}
                    r = r.xreplace({**sol_, **rates_}).xreplace(subs)
                    r = r.xreplace(case) if case else r
                    if screen and surely_nonzero(r):
                        return False, ""
                    ok, how = zero(sp.Matrix([r]), sp.Matrix([0]), f"solution/{k}")
                    if not ok:
                        where = f" in case {k + 1} of {len(self.ctx.cases)} ({self._case_text(case)})" if len(self.ctx.cases) > 1 else ""
                        return False, f"substituted into the earlier equations: {how}{where}"
            return True, f"substituted into the earlier equations of motion ({len(chosen)}), in {len(self.ctx.cases)} case(s)"

        ok, why = holds(sol)
        if ok:
            for line, piece, *_ in group:
                self._add(line, piece, "solution", "holds", why)
            return
        loose = self._loose_frequencies(sol)
        if loose:
            for line, piece, *_ in group:
                self._add(line, piece, "solution", "unchecked",
                          f"the frequency or rate {loose} is not defined in the text, so the solution cannot be substituted")
            return
        # one edit of which member restores the group? When several can (a phase's sign flipped in
        # one of a pair: either line may be the slip), each is named with its own correction.
        fixes = {}
        for j, (line, piece, w, f, scale) in enumerate(group):
            for cand, what in edits(f):
                if holds({**sol, w: self._own_defs(cand)}, screen=True)[0]:
                    fixes[j] = (cand, what)
                    break
        if not fixes:
            for line, piece, *_ in group:
                self._add(line, piece, "solution", "fails", why)
            return
        either = " (or, instead, the companion named with it)" if len(fixes) > 1 else ""
        for j, (line, piece, w, _, scale) in enumerate(group):
            if j in fixes:
                cand, what = fixes[j]
                left = piece.split("=")[0].strip() if scale != 1 else f"{self.tex(w)}(t)"
                self._add(line, piece, "solution", "typo", f"as written: {why}; one edit ({what}) makes it hold{either}",
                          f"{left} = {self.tex(sp.expand(scale * cand) if scale != 1 else cand)}")
            else:
                self._add(line, piece, "solution", "holds", "with the corrected companion")

    def _loose_frequencies(self, sol) -> str:
        """The text's undefined symbols that multiply t inside a function of a solution (a frequency
        it never gave): the LaTeX names, or ''. Amplitudes and phases are integration constants."""
        out = set()
        for f in sol.values():
            for fn in sp.sympify(f).atoms(sp.Function, sp.Pow):
                arg = fn.args[0] if isinstance(fn, sp.Function) else fn.exp
                if lx.t in free(arg):
                    out |= {s for s in free(sp.diff(arg, lx.t)) if isinstance(s, lx.Generic) and s not in self.ctx.defs
                            and s not in set(free(sp.Matrix(list(self.ctx.subs.values()))))}
        return ", ".join(sorted(self.tex(s) for s in out))


@functools.lru_cache(maxsize=4096)
def _dt(f, n=1):
    """dⁿf/dtⁿ, memoised: the search for a correction of one solution differentiates the
    unchanged members of its group again with every candidate."""
    return sp.diff(f, lx.t, n)
