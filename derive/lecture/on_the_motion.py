"""Statements that hold on the motion the text describes, not as identities: the rates it solved
for, and Lagrange's equations themselves.

Takes: a claim the notes checker (`derive.lecture.notes_check.Checker`) found not to hold as an
identity. Gives: the mixin `OnTheMotion`, which tries two readings a careful reader gives before
calling such a claim wrong —

1. **in this motion**: the text has stated the rates of the motion it studies (``\\dot\\phi =
   M_z/I_1``, kept in ``ctx.motion``); with those put in, the claim holds (``∂L/∂θ = … = 0`` of a
   steady precession);
2. **Lagrange's equation**: claim − derived is ±(d/dt ∂L/∂q̇ − ∂L/∂q) for one coordinate q, with
   the Lagrangian the text uses (``∂L/∂θ = d/dt(∂L/∂θ̇)``): the law of motion, true on every motion.

Either only makes a claim hold; it never flags one. May import: :mod:`derive.lecture.latex`,
:mod:`derive.lecture.verify` (its exact screen), :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.verify import surely_nonzero
from derive.symbolic.lagrangian import ACCELS
from derive.symbolic.rotations import ANGLES, RATES, time_derivative, trig_reduce


_RATE_FIRST = re.compile(r"\s*&?\s*\\dot\s*\{?\s*\\?[A-Za-z]+[^=]*=")


def _free(obj) -> set:
    return set(obj.free_symbols) if hasattr(obj, "free_symbols") else set()


class OnTheMotion:
    """Mixin of the checker: see the module docstring. Uses ``self.ctx`` (``motion``, ``forms_held``),
    ``self.d``, ``self._resolve``, ``self._unify``, ``self._compare`` and ``self.tex``."""

    def _note_motion(self, line, piece):
        """``\\dot\\phi = M_z/I_1``, a rate given by constants and the angles: the rate of the
        motion the text studies, kept as written (read with the names in force where it is used)."""
        if not _RATE_FIRST.match(piece):
            return
        try:
            parsed = lx.parse(piece, self.vocab)
        except (lx.NotRead, lx.Words):
            return
        members = [m.value for m in parsed.members]
        if len(members) < 2 or members[0] not in RATES or set(parsed.relations) - {"="}:
            return
        value = members[-1]
        try:
            resolved = self._resolve(value)
        except (TypeError, ValueError, AttributeError):
            return
        if any(isinstance(x, lx.Generic) and x.name == "const" for x in _free(value)):
            return                  # "= const" says it is constant, not what it is
        if not _free(resolved) & (set(RATES) | set(ACCELS) | set(lx.W)) and not isinstance(resolved, sp.MatrixBase):
            self.ctx.motion[members[0]] = (value, line)

    def _on_the_motion(self, val, targets, seed) -> str | None:
        """Why the claim holds on the text's motion (its stated rates, or Lagrange's equation), or None."""
        if isinstance(val, sp.MatrixBase):
            return None
        for f in targets:
            target = self._resolve(f)
            if isinstance(target, sp.MatrixBase):
                continue
            q = self._lagrange_equation(val, target)
            if q is not None:
                return f"Lagrange's equation for {self.tex(q)}: d/dt ∂L/∂{self.tex(q)}̇ = ∂L/∂{self.tex(q)} (true on every motion)"
            if target in RATES or val in RATES:
                continue            # a rate against the motion's rates would check the text against itself
            motion = {r: self._resolve(v) for r, (v, _) in self.ctx.motion.items()}
            if not motion or not (_free(val) | _free(target)) & (set(motion) | set(lx.W)):
                continue
            a, b = (x.xreplace(self.ctx.subs) for x in self._unify([val, target]))
            a, b = sp.expand(a.xreplace(motion)), sp.expand(b.xreplace(motion))
            if _free(a - b) & set(RATES) - set(motion):
                continue
            ok, how = self._compare(a, b, seed + "/motion")
            if ok:
                where = ", ".join(f"{self.tex(r)} = {self.tex(v)} (line {n})" for r, (v, n) in self.ctx.motion.items())
                return f"{how}, in the motion the text describes ({where})"
        return None

    def _lagrange_equation(self, val, target):
        """The coordinate q when val − target = ±(d/dt ∂L/∂q̇ − ∂L/∂q), else None."""
        if not (_free(val) | _free(target)) & set(ACCELS):
            return None
        lag = self.ctx.forms_held.get(lx.LAGRANGIAN)
        lag = self._resolve(lag) if lag is not None else self.d.top.lagrangian
        a, b = (x.xreplace(self.ctx.subs) for x in self._unify([val, target]))
        diff = sp.expand(a - b)
        for q, qd in zip(ANGLES, RATES):
            el = time_derivative(sp.diff(lag, qd), accels=ACCELS) - sp.diff(lag, q)
            el = el.xreplace(self.ctx.subs)
            for sign in (1, -1):
                d = sp.expand(diff - sign * el)
                if not surely_nonzero(d) and trig_reduce(d) == 0:
                    return q
        return None
