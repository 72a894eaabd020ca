"""The free body's Euler equations in the vector reader's model of mass points.

Takes: a difference of two sides read in `derive.lecture.vector_algebra_model` (its ω, ω̇, masses
μₖ and positions 𝐫ₖ). Gives: `vanishes_for_free_body`, whether it is zero once ω̇ is taken from
Euler's equations of a body with no torque, 𝐈ω̇ = −ω × 𝐈ω, read off the model's own
torque d𝐋/dt of the reading's system. The model reads a torque as d𝐋/dt, so a statement without one (``I\\dot\\omega =
-\\omega \\times I\\omega``) is no identity of it: it is the law of motion of a free body, which a
text writes as the scalar path reads Iᵢω̃̇ᵢ = (Iⱼ − Iₖ)ω̃ⱼω̃ₖ.
May import: the standard library (`random`), SymPy, :mod:`derive.lecture.vector_algebra_model`.
"""
from __future__ import annotations

import random

import sympy as sp

from derive.lecture.vector_algebra_model import WD

_SAMPLES = 3


def vanishes_for_free_body(d, torque) -> bool:
    """Is ``d`` (a scalar or a matrix in the model's symbols, with ω̇ in it) zero once ω̇ is the
    free body's, at three exact rational points of the other symbols (drawn from a fixed seed)?
    ``torque`` is the model's d𝐋/dt (`vector_algebra_model.torque` of the reading's system),
    linear in ω̇: the free body's law of motion is that it vanishes,
    𝐈ω̇ + ω × (𝐈ω) = 0, ω̇ = −𝐉⁻¹ τ|_{ω̇=0} with 𝐉 = ∂τ/∂ω̇ (the inertia tensor).
    """
    entries = [sp.sympify(e) for e in (d if isinstance(d, sp.MatrixBase) else [d])]
    free = set().union(*(e.free_symbols for e in entries))
    others = sorted(set(torque.free_symbols) - set(WD), key=str)
    if not free & set(WD) or not free <= set(others) | set(WD):
        return False
    slope, rest = sp.Matrix(torque).jacobian(WD), sp.Matrix(torque).xreplace(dict.fromkeys(WD, 0))
    rng, checked = random.Random(20261202), 0
    for _ in range(_SAMPLES):
        at = {s: sp.Rational(rng.randint(1, 9), rng.randint(1, 4)) * (1 if s.is_positive else rng.choice((1, -1)))
              for s in others}
        tensor = slope.xreplace(at)
        if tensor.det() == 0:
            continue
        at.update(zip(WD, tensor.LUsolve(-rest.xreplace(at))))
        if any(e.xreplace(at) != 0 for e in entries):
            return False
        checked += 1
    return checked > 0          # a singular tensor at every point (one point mass) decides nothing
