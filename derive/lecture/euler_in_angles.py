"""Euler's equations written out in the angles: I₁(θ̈₁ sin θ₂ sin θ₃ + …) = (I₂ − I₃)(…)(…) + T₁.

Takes: one statement of the checker with the angles' accelerations in it. Gives: the mixin
`EulerInAngles` of `derive.lecture.notes_check.Checker`, whose `_euler_in_angles` says it holds
when its lhs − rhs is a constant non-zero multiple k of one of Euler's residuals
Iᵢ ω̃̇ᵢ − ((Iω̃)×ω̃)ᵢ with ω̃ and ω̃̇ in the convention's angles, their rates and accelerations
(ω̃ from Rᵀ Ṙ, ω̃̇ its time derivative by the chain rule). One symbol of the text's own that enters
linearly is the torque's component: its term is dropped before the comparison (τᵢ, written T₁ᵉ).
It only ever says *holds*: a statement it cannot match goes on to the other readings (the heavy
top's Lagrange equation), so it adds no flag of its own. Its `_rate_in_angles` says why a statement
with ω̃̇ᵢ and the angles' accelerations holds as the rate of ω̃'s components in the angles (kinematics,
which Euler's equations do not decide).

May import: SymPy and :mod:`derive.lecture.latex`, :mod:`derive.lecture.comparing`, :mod:`derive.symbolic`.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.comparing import free
from derive.symbolic.lagrangian import ACCELS
from derive.symbolic.rotations import ANGLES, RATES


class EulerInAngles:
    """Mixin of the checker (see the module docstring)."""

    def _euler_in_angles(self, line, piece, members) -> bool:
        """True (and the claim added) when ``members`` (lhs, rhs) is one of Euler's equations in the angles."""
        if len(members) != 2:
            return False
        raw = self._resolve(members[0] - members[1])
        if isinstance(raw, sp.MatrixBase) or not free(raw) & set(ACCELS) or free(raw) & (set(lx.W) | set(lx.WD)):
            return False
        raw = sp.expand(raw)
        loose = [x for x in free(raw) if isinstance(x, lx.Generic) and x not in self.ctx.defs]
        torque = ""
        if len(loose) > 1:
            return False
        if loose:
            (t,) = loose
            if sp.diff(raw, t, 2) != 0 or free(sp.diff(raw, t)) & (set(ANGLES) | set(RATES) | set(ACCELS)):
                return False
            raw, torque = sp.expand(raw - t * sp.diff(raw, t)), f", with {self.tex(t)} the torque's component"
        for i, target in enumerate(self._euler_targets()):
            lead = next((a for a in ACCELS if sp.diff(target, a) != 0 and sp.diff(raw, a) != 0), None)
            if lead is None:
                continue
            k = sp.cancel(sp.diff(raw, lead) / sp.diff(target, lead))
            if k == 0 or free(k) & (set(ANGLES) | set(RATES) | set(ACCELS)):
                continue
            ok, how = self._compare(raw, k * target, f"{piece}/euler-in-angles/{i}")
            if ok:
                self._add(line, piece, "equation of motion", "holds",
                          f"a multiple ({self.tex(k)}) of Euler's equation {i + 1} in the angles{torque}: {how}")
                return True
        return False

    def _rate_in_angles(self, members) -> str | None:
        """The why when ``members`` (lhs, rhs), with ω̃̇ᵢ and the angles' accelerations, agree once ω̃ and
        ω̃̇ are put in the angles (ω̃̇₃ = φ̈ cos θ − φ̇ θ̇ sin θ + ψ̈ in z-x-z): the rate of ω̃'s components,
        true of every motion, so no equation of motion; else None."""
        raw = self._resolve(members[0] - members[1])
        if isinstance(raw, sp.MatrixBase) or not free(raw) & set(ACCELS) or not free(raw) & set(lx.WD):
            return None
        in_angles = {**dict(zip(lx.W, self.d.omega)), **dict(zip(lx.WD, self._body_rate()))}
        ok, how = self._compare(raw.xreplace(in_angles), sp.S.Zero, "rate-in-angles")
        return f"the rate of the angular velocity's components in the angles: {how}" if ok else None

    def _euler_targets(self) -> list:
        """Euler's residuals in the angles under the section's settings, kept per derivation and settings."""
        kept = self.__dict__.setdefault("_euler_in_angles_kept", {})
        key = (id(self.d), tuple(sorted(self.ctx.subs.items(), key=str)))
        if key not in kept:
            in_angles = {**dict(zip(lx.W, self.d.omega)), **dict(zip(lx.WD, self._body_rate()))}
            kept[key] = [sp.expand(r.xreplace(in_angles)) for r in self.d.euler(self.ctx.subs)]
        return kept[key]
