"""The fast top's precession rate: the gyroscopic approximation as texts state it.

A heavy symmetric top precessing steadily (tilt β constant) obeys ∂L/∂β = 0 at β̇ = β̈ = 0, a
quadratic in the precession rate α̇. For a fast spin γ̇ its slow root is, to leading order in 1/γ̇,

    α̇ ≈ M g l / (I₃ γ̇)   (= M g l / p_γ, the same to that order),

which texts write as an equality ("φ̇ = mgd/(I_z ψ̇)", "Ω = Mgr/(Iω)") after saying the spin is fast.
Takes: the claim's value for the precession rate, resolved by the notes checker. Gives: the mixin
`FastTop` of `derive.lecture.notes_check.Checker`, whose `_fast_top` says why such a claim holds
(to leading order for a fast spin), or None; anything else — a wrong moment, a missing factor —
is judged as before.

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.comparing`,
:mod:`derive.lecture.zero_test`, SymPy.
"""
from __future__ import annotations

import functools

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.comparing import free
from derive.lecture.zero_test import surely_nonzero
from derive.symbolic.lagrangian import I3

_S = sp.Symbol("fast_spin", positive=True)
_C = sp.Symbol("fast_lead")
_UNBOUNDED = (sp.oo, -sp.oo, sp.zoo, sp.nan)


@functools.lru_cache(maxsize=None)
def slow_precession_lead(force, alpha_d, gamma_d):
    """c in α̇ = c/γ̇ + O(1/γ̇³), the slow root of the steady-precession condition ``force`` = 0
    (∂L/∂β at β̇ = 0) for a fast spin γ̇; None when the condition has no such root."""
    at = sp.expand(force.xreplace({gamma_d: _S, alpha_d: _C / _S}))
    lead = sp.limit(at, _S, sp.oo)
    if free(lead) & {_S} or not lead.has(_C):
        return None
    line = lead.as_poly(_C)
    if line is not None and line.degree() == 1:
        # A root that is a monomial in the parameters (M g l / I₃ in the proper Euler sequences) is
        # what `solve` would give: its `simplify`, which loads SymPy's units, has nothing to do.
        a, b = line.all_coeffs()
        root = sp.cancel(-b / a)
        if root != 0 and all(f.is_Number or f.is_Symbol or f.is_Pow and f.base.is_Symbol and f.exp.is_Integer
                             for f in sp.Mul.make_args(root)):
            return root
    roots = sp.solve(lead, _C)
    return roots[0] if len(roots) == 1 and roots[0] != 0 else None


def _lead(e):
    """lim e for a fast spin, or None where it has no finite value (e grows with the spin)."""
    spun = e.as_poly(_S)
    if spun is not None and spun.degree() > 0 and surely_nonzero(spun.coeff_monomial(_S**spun.degree())):
        return None     # a polynomial in the spin whose leading coefficient is not zero: no limit to take
    if _spun_only_by_its_phase(e):
        return None
    lead = sp.limit(e, _S, sp.oo)
    return None if lead.has(*_UNBOUNDED) else lead


def _spun_only_by_its_phase(e) -> bool:
    """Does e depend on the spin only through sines and cosines of a phase growing with it (a·γ̇ + b,
    a ≠ 0)? Such a function of γ̇ has a limit only where it does not vary with γ̇ at all, an identity
    the fast top's reading does not seek (SymPy's `limit` is costly there and finds none)."""
    phases = [f for f in e.atoms(sp.sin, sp.cos) if _S in f.free_symbols]
    if not phases or _S in e.xreplace({f: sp.Dummy() for f in phases}).free_symbols:
        return False
    return all(sp.diff(f.args[0], _S, 2) == 0 and surely_nonzero(sp.diff(f.args[0], _S)) for f in phases)


class FastTop:
    """Mixin of the checker; uses ``self.d`` (the derivation) and ``self.tex``."""

    def _fast_top(self, label, val) -> str | None:
        """Why ``label = val`` holds as the fast top's precession rate, or None."""
        rot = self.d.rot
        if label is not rot.alpha_d or isinstance(val, sp.MatrixBase):
            return None
        # |𝐋| is I₃γ̇ to leading order: the transverse part of 𝐋 is I₁α̇ sin β, of order 1/γ̇
        spin = {rot.gamma_d: _S, lx.p_gamma: I3 * _S, lx.W[self.vocab.axial]: _S, lx.LMAG: I3 * _S}
        if not free(val) & set(spin) or free(val) & {rot.alpha_d, rot.beta_d}:
            return None
        c = self.d.fast_precession
        if c is None:
            return None
        lead = _lead(sp.expand(val.xreplace(spin) * _S))
        if lead is None or lead == 0 or free(lead) & {_S} or sp.simplify(lead - c) != 0:
            return None
        spun, tilt = self.tex(rot.gamma_d), self.tex(rot.beta)
        return (f"the fast top's slow precession: to leading order in 1/{spun}, the steady-precession "
                f"condition ∂L/∂{tilt} = 0 gives {self.tex(rot.alpha_d)} = {self.tex(c / rot.gamma_d)} "
                f"(holds if the spin {spun} is fast)")
