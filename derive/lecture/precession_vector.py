"""The precession vector of a steady precession, as a text defines it ("precesses at the angular
velocity $\\boldsymbol{\\Omega}_p = \\mathbf{L} \\times \\boldsymbol{\\tau} / L^2$").

A vector 𝐋 turning at the angular velocity 𝛀 changes at d𝐋/dt = 𝛀 × 𝐋; under a torque d𝐋/dt = 𝛕.
A steady precession (|𝐋| constant, so 𝛕 ⟂ 𝐋) turns 𝐋 at the 𝛀 that solves 𝛀 × 𝐋 = 𝛕 with 𝛀 ⟂ 𝐋;
solved here in SymPy for general vectors: 𝛀 = 𝐋 × 𝛕 / L².

Takes: a definition ``𝛀 = …`` read by `derive.lecture.named_vectors` (each vector a general
3-vector of components), its head a bold Ω or ω that the prose before it ties to the precession
("precess", "precession"), its right side in one torque (𝛕, 𝐍, 𝐌 …) and one angular momentum
(𝐋, 𝐇, 𝐉) only. Gives: `judged`, (verdict, why) — **holds** where the side is that solution for
every 𝐋 and every torque across it, **typo** where it is its negative (the order of the cross
product: `_named_vectors` seeks the edit), **fails** otherwise — or None where the display is not
such a definition (then it is recorded as before).

May import: SymPy.
"""
from __future__ import annotations

import functools
import re

import sympy as sp


_PRECESS = re.compile(r"\bprecess", re.I)
_TORQUES = ("tau", "N", "T", "M", "G", "Gamma", "K")
_MOMENTA = ("L", "H", "J")
_WHY = ("a steady precession turns 𝐋 at the 𝛀 with d𝐋/dt = 𝛀 × 𝐋 = 𝛕 and 𝛀 ⟂ 𝐋; solved for general vectors "
        "(𝛕 across 𝐋) it is 𝛀 = 𝐋 × 𝛕 / L²")


def _vector_names(value) -> set:
    """The named vectors (the part of a component's name before its axis) a side is written in."""
    return {s.name.rsplit(".", 1)[0] for s in value.free_symbols if "." in s.name}


@functools.lru_cache(maxsize=None)
def _solved():
    """(𝐋, 𝐮, 𝛀) with 𝛕 = 𝐋 × 𝐮 (any torque across 𝐋) and 𝛀 the solution of 𝛀 × 𝐋 = 𝛕, 𝛀·𝐋 = 0."""
    L = sp.Matrix(sp.symbols("Lp1:4", real=True))
    u = sp.Matrix(sp.symbols("up1:4", real=True))
    w = sp.Matrix(sp.symbols("wp1:4"))
    tau = L.cross(u)
    eqs = list(w.cross(L) - tau) + [w.dot(L)]
    sol = sp.solve(eqs, list(w), dict=True)
    return L, u, sp.simplify(w.xreplace(sol[0])) if len(sol) == 1 else None


def ties(head, lead: str) -> bool:
    """Does the prose before the display tie this bold head to the precession?"""
    return head is not None and head.bold and head.base in ("Omega", "omega") and not head.dots \
        and not head.hat and bool(_PRECESS.search(lead or ""))


def judged(value):
    """(verdict, why) for a precession vector written ``value``, or None (not in one torque and one
    angular momentum alone)."""
    if not isinstance(value, sp.MatrixBase) or value.shape != (3, 1):
        return None
    names = _vector_names(value)
    torque = [n for n in names if n.split("_")[0] in _TORQUES]
    momentum = [n for n in names if n.split("_")[0] in _MOMENTA]
    if len(names) != 2 or len(torque) != 1 or len(momentum) != 1 or any("." not in s.name for s in value.free_symbols):
        return None
    L, u, omega = _solved()
    if omega is None:
        return None
    tau = L.cross(u)
    by_name = {f"{momentum[0]}.{x}": L[i] for i, x in enumerate("xyz")}
    by_name.update({f"{torque[0]}.{x}": tau[i] for i, x in enumerate("xyz")})
    if {s.name for s in value.free_symbols} - set(by_name):
        return None
    side = value.xreplace({s: by_name[s.name] for s in value.free_symbols})
    if all(sp.cancel(d) == 0 for d in side - omega):
        return "holds", _WHY
    if all(sp.cancel(d) == 0 for d in side + omega):
        return "typo", _WHY + ": the display's side is its negative"
    return "fails", _WHY + ": the display's side is another vector"
