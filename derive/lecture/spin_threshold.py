"""A spin threshold as texts write it: "the spin must exceed …" (ω_s > 2√(I₁ M g l)/I₃, I₃²ω₃² > 4 I₁ M g l).

The derived stability condition of the sleeping top is written in p_γ (p_γ ≥ 2√(I₁ M g l)); a text
writes the same bound on the spin ω̃₃ (or ψ̇), scaled, squared or solved for the spin, which the
checker's exact comparison of lhs − rhs does not see. A careful reader compares what such a bound
says instead: the spin at which it turns (its one positive root in the spin) and its side (a fast
spin satisfies it). Takes: the claim as ``c ≥ 0`` (or > 0) and the derived condition the same way,
both resolved by the checker. Gives: `judged`, ("holds", why) where the claim is the sleeping
top's bound, else None: the checker then seeks a reversed relation or one edit, or calls it not
the condition, as before (so too where the claim is not a bound on the spin alone in the heavy
top's parameters: a tilt, a rate of precession, a symbol of the text's own).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.comparing`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.comparing import free
from derive.symbolic.lagrangian import I1, I3, Mass, g, l
from derive.symbolic.rotations import RATES

_S = sp.Symbol("threshold_spin", positive=True)
_PARAMETERS = {I1, I3, Mass, g, l}


def _in_spin(e):
    """``e`` with the spin (ω̃₃, ψ̇ of a sleeping top, p_γ = I₃ω̃₃) as one positive symbol, or None
    where it holds anything else than the spin and the heavy top's parameters."""
    e = sp.sympify(e).xreplace({lx.W[2]: _S, RATES[2]: _S, lx.p_gamma: I3 * _S, lx.p_gamma_sym(): I3 * _S})
    if not free(e) - {_S} <= _PARAMETERS or _S not in free(e):
        return None
    return e


def _threshold(e):
    """The one positive spin at which ``e`` turns, or None."""
    positive = {s: sp.Symbol(s.name, positive=True) for s in free(e) - {_S}}
    try:
        roots = [r for r in sp.solve(e.xreplace(positive), _S) if r.is_positive is not False]
    except (NotImplementedError, TypeError, ValueError):
        return None
    back = {v: k for k, v in positive.items()}
    return roots[0].xreplace(back) if len(roots) == 1 else None


def _fast_side(e) -> bool | None:
    """Does a fast spin satisfy ``e ≥ 0``?"""
    lead = sp.limit(e.xreplace({s: sp.Symbol(s.name, positive=True) for s in free(e) - {_S}}), _S, sp.oo)
    return True if lead == sp.oo or lead.is_positive else False if lead == -sp.oo or lead.is_negative else None


def judged(claim, derived, tex):
    """("holds", why) for ``claim ≥ 0`` as the bound on the spin ``derived ≥ 0`` sets, or None."""
    c, d = _in_spin(claim), _in_spin(derived)
    if c is None or d is None:
        return None
    mine, theirs = _threshold(c), _threshold(d)
    if mine is None or theirs is None or _fast_side(d) is not True:
        return None
    if _fast_side(c) is True and sp.simplify(mine - theirs) == 0:
        return "holds", (f"the sleeping top's threshold: the bound turns at {tex(lx.W[2])} = {tex(theirs)}, "
                         "as the derived stability condition does, and a fast spin satisfies it")
    return None     # any other bound is the checker's: a reversed relation, one edit, or not the condition
