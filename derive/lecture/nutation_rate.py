"""The fast top's nutation rate, as a text names it ("the nutation frequency $\\omega_n$ is …").

A heavy symmetric top precessing steadily at the tilt β₀ nods about it at the frequency
ω_n² = V_eff''(β₀)/I₁ (E′ = ½I₁β̇² + V_eff(β)). For a fast spin γ̇ (slow precession α̇ ≈ c/γ̇) its
leading order is ω_n ≈ I₃γ̇/I₁, the free symmetric top's turn of its axis about 𝐋 (L/I₁, L ≈ I₃γ̇);
seen from the body, which turns at the spin, the same motion has the rate (I₃ − I₁)γ̇/I₁.

Takes: a display ``ω = …`` whose head the prose names the nutation rate
(`derive.lecture.gyro_names`), its right side resolved by the checker. Gives: the mixin
`NutationRate` of `derive.lecture.notes_check.Checker`, whose `_nutation_rate` judges it against
that leading order, derived here in SymPy from the reader's V_eff and momenta: **holds** (if the spin
is fast) where the display's leading order in the spin is one of the two, **fails** where it is
another multiple of the spin in the moments, unchecked where it is a pure number times one (a half
rate, cycles per second: the text's own measure, perhaps); a display in symbols the text has not tied to the heavy top, or not
of the order of the spin, stays unchecked naming why.

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.comparing`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import functools

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.comparing import free
from derive.symbolic.lagrangian import I1, I3, Mass, g, l, p_alpha, p_gamma

_S = sp.Symbol("nutation_spin", positive=True)
_PARAMETERS = {I1, I3, Mass, g, l}


@functools.lru_cache(maxsize=None)
def fast_nutation_lead(veff, beta, momenta, rates, slow):
    """k in ω_n ≈ k γ̇ for a fast spin: V_eff''(β₀)/I₁ at the steady precession α̇ = slow/γ̇, β̇ = 0,
    to leading order in γ̇ (None where it depends on the angles: not a proper Euler sequence).
    ``momenta`` is (p_α, p_γ) in the rates, ``rates`` (α̇, β̇, γ̇)."""
    alpha_d, beta_d, gamma_d = rates
    at = {alpha_d: slow / _S, gamma_d: _S, beta_d: 0}
    curvature = sp.diff(veff, beta, 2).xreplace({p_alpha: momenta[0].xreplace(at), p_gamma: momenta[1].xreplace(at)})
    lead = sp.simplify(sp.limit(curvature / (I1 * _S**2), _S, sp.oo))
    if not free(lead) <= _PARAMETERS or lead.is_positive is not True:
        return None
    return sp.sqrt(lead)


class NutationRate:
    """Mixin of the checker; uses ``self.d``, ``self.notes``, ``self.vocab``, ``self._resolve``, ``self.tex``."""

    def _nutation_rate(self, line, piece, head, value) -> bool:
        """Judge ``head = value`` where the prose names ``head`` the nutation rate; False when it does not."""
        atom = self.vocab.generic.get(head) if isinstance(head, lx.Generic) else None
        if atom is None or self.notes.names.meaning(atom) != "nutation rate":
            return False
        val = self._resolve(value)
        if isinstance(val, sp.MatrixBase):
            return False
        rot = self.d.rot
        spin = {rot.gamma_d: _S, lx.p_gamma: I3 * _S, lx.W[self.vocab.axial]: _S, lx.LMAG: I3 * _S}
        loose = free(val) - set(spin) - _PARAMETERS
        if loose or not free(val) & set(spin):
            why = (f"involves {', '.join(sorted(self.tex(x) for x in loose))}, which the text has not tied to the heavy top"
                   if loose else "not in the spin: the reader derives the nutation rate of a fast top only")
            self._add(line, piece, "nutation rate", "unchecked", f"the nutation rate {self.tex(head)}: {why}")
            return True
        k = self._fast_nutation()
        if k is None:
            return False
        lead = sp.limit(val.xreplace(spin) / _S, _S, sp.oo)
        if lead.has(sp.oo, -sp.oo, sp.zoo, sp.nan) or lead == 0 or free(lead) - _PARAMETERS:
            self._add(line, piece, "nutation rate", "unchecked", f"the nutation rate {self.tex(head)}: it does not "
                      "grow as the spin does, where the reader's fast-top expansion holds")
            return True
        spun = self.tex(rot.gamma_d)
        derived = (f"expanding V_eff''({self.tex(rot.beta)}₀)/I₁ about steady precession to leading order in the spin "
                   f"{spun} gives the nutation rate {self.tex(k * rot.gamma_d)} ({self.tex((k - 1) * rot.gamma_d)} "
                   "as seen from the body, turning at the spin)")
        if sp.simplify(lead - k) == 0 or sp.simplify(lead - (k - 1)) == 0:
            self.ctx.defs[head] = value
            self._add(line, piece, "nutation rate", "holds", f"the fast top's nutation: {derived} (holds if the spin {spun} is fast)")
            return True
        if sp.simplify(lead / k).is_number:
            # a number times the derived rate may be another measure of the same motion (a half rate, cycles per second)
            self._add(line, piece, "nutation rate", "unchecked", f"the nutation rate {self.tex(head)}: a number times "
                      f"the fast top's, {self.tex(k * rot.gamma_d)}; it may measure the motion otherwise: not judged")
            return True
        self._add(line, piece, "nutation rate", "fails", f"the fast top's nutation: {derived}; the display's leads "
                  f"with {self.tex(lead * rot.gamma_d)}")
        return True

    def _fast_nutation(self):
        """k in ω_n ≈ k γ̇, or None (a Tait–Bryan sequence: its first angle is no precession about the vertical)."""
        d = self.d
        if d.conv.axes[0] != d.conv.axes[2] or d.fast_precession is None:
            return None
        rot = d.rot
        return fast_nutation_lead(d.reduction.effective_potential, rot.beta, (d.momenta[rot.alpha], d.momenta[rot.gamma]),
                                  (rot.alpha_d, rot.beta_d, rot.gamma_d), d.fast_precession)
