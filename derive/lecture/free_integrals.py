"""The free body's integrals as a text states them: ``L_x^2 + L_y^2 + L_z^2 = \\text{constant}``.

A text on the torque-free body states that the squared angular momentum and the kinetic energy
are constant, written in the body's principal components (``L_x^2 + L_y^2 + L_z^2``,
``\\frac{1}{I_{xx}}L_x^2 + …``, ``I_1\\omega_1^2 + …``). Such a statement F = const is read as a
claim about Euler's equations without a torque (the text's components L_x, M_2, its moments
I_{xx}, I_2 and rates ω_x read as the body's principal ones), I ω̇ = (I ω) × ω: it holds when F's rate
Σᵢ ∂F/∂ωᵢ ω̇ᵢ vanishes on them. A rate that does not vanish leaves it to the rest of the reader
(an assumption the text makes, never a verdict), since the text may mean a body with a torque.
A chain that names the quantity first and ends with the constant's value in an example
(``2T = I_1\\omega_1^2 + … = \\text{cte} = 172.80``) is judged the same way, its value left aside.
Takes the checker's context and vocabulary; gives claims; imports nothing of the checker.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.symbolic.lagrangian import I1, I2, I3


def free_rate(F, moments=(I1, I2, I3)):
    """dF/dt on the torque-free motion.

    Parameters
    ----------
    F : sympy expression
        In the body components ``lx.W`` of the angular velocity and the principal moments.
    moments : sequence of 3
        The principal moments, with the text's settings put in.

    Returns
    -------
    sympy expression
        Σᵢ ∂F/∂Wᵢ Ẇᵢ with Euler's equations without a torque, I Ẇ = (I W) × W.
    """
    W = sp.Matrix(lx.W)
    inertia = sp.diag(*moments)
    wdot = inertia.inv() * (inertia * W).cross(W)
    return sum(sp.diff(F, W[i]) * wdot[i] for i in range(3))


_AXIS = {"x": 0, "y": 1, "z": 2, "1": 0, "2": 1, "3": 2}
_MOMENTUM = re.compile(r"^[LMH]_\{?([xyz123])\}?$")
_MOMENT = re.compile(r"^I_\{?([xyz123])\1?\}?$")
_RATE = re.compile(r"^omega_\{?([xyz123])\}?$")


def principal_components(F):
    """F with the text's own principal components read as the body's: L_x, M_2 (the angular
    momentum's) as Iᵢωᵢ, I_x, I_{xx}, I_2 as the principal moments, ω_x as ωᵢ (axes x, y, z or 1,
    2, 3). None when F names components of both kinds of axes."""
    subs, kinds = {}, set()
    for s in F.free_symbols:
        name = getattr(s, "name", "")
        for pattern, value in ((_MOMENTUM, lambda k: (I1, I2, I3)[k] * lx.W[k]), (_MOMENT, lambda k: (I1, I2, I3)[k]),
                               (_RATE, lambda k: lx.W[k])):
            m = pattern.match(name) if isinstance(s, lx.Generic) else None
            if m:
                subs[s] = value(_AXIS[m.group(1)])
                kinds.add(m.group(1) in "xyz")
    return None if len(kinds) > 1 else F.xreplace(subs)


class FreeIntegrals:
    """Mixin of the checker: see the module docstring. Uses ``self.ctx`` (its substitutions),
    ``self._resolve``, ``self._compare``, ``self._add``, ``self._members_kept`` and
    ``self._centre_of_mass``."""

    def _constant_dropped(self, line, piece, parsed):
        """``A = F = \\text{const} = 172.80``: the numbers after the constant are its value in the
        text's example (not a claim: the state they come from is not given), dropped; F, the member
        written just before the constant after another, is judged as an integral of the free body
        when the text has set no centre of mass for a heavy body (a claim only when it is one). The
        rest is read on (`TextNames._constant_dropped`)."""
        members = [m.value for m in parsed.members]
        const = [k for k, m in enumerate(members) if isinstance(m, lx.Generic) and m.name == "const"]
        if len(const) == 1:
            k = const[0]
            tail = members[k + 1:]
            if tail and all(isinstance(v, sp.Expr) and v.is_number for v in tail):
                parsed = self._members_kept(parsed, list(range(k + 1)))
            # a heavy body's integrals are judged as such (`EulerPoisson`)
            if k >= 2 and k == len(parsed.members) - 1 and self._centre_of_mass() is None:
                self._conserved_free(line, piece, members[k - 1])
        return super()._constant_dropped(line, piece, parsed)

    def _conserved_free(self, line, piece, value) -> bool:
        """``F = const`` with F in the body's ω̃ᵢ and principal moments (not one ω̃ᵢ alone, which is a
        setting): holds when F is an integral of the free body's Euler equations. True when a claim
        was added."""
        F = self._resolve(value)
        if isinstance(F, sp.MatrixBase) or not hasattr(F, "free_symbols"):
            return False
        F = principal_components(sp.sympify(F).xreplace(self.ctx.subs))
        if F is None:
            return False
        moments = [sp.sympify(m).xreplace(self.ctx.subs) for m in (I1, I2, I3)]
        allowed = set(lx.W) | {I1, I2, I3}
        if F in set(lx.W) or not F.free_symbols & set(lx.W) or not F.free_symbols <= allowed:
            return False
        ok, how = self._compare(free_rate(F, moments), sp.S.Zero, f"{piece}/free integral")
        if not ok:
            return False
        self._add(line, piece, "integral", "holds",
                  f"conserved on Euler's equations of the free body (no torque; dF/dt: {how})")
        return True
