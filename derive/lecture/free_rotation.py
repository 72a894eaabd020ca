"""The free body's Euler equations in the vector reader's model of mass points.

Takes: a difference of two sides read in `derive.lecture.vector_algebra_model` (its ω, ω̇, masses
μₖ and positions 𝐫ₖ). Gives: `vanishes_for_free_body`, whether it is zero once ω̇ is taken from
Euler's equations of a body with no torque, 𝐈ω̇ = −ω × 𝐈ω, with 𝐈 = Σₖ μₖ (|𝐫ₖ|² 𝟙 − 𝐫ₖ𝐫ₖᵀ) the
points' tensor. The model reads a torque as d𝐋/dt, so a statement without one (``I\\dot\\omega =
-\\omega \\times I\\omega``) is no identity of it: it is the law of motion of a free body, which a
text writes as the scalar path reads Iᵢω̃̇ᵢ = (Iⱼ − Iₖ)ω̃ⱼω̃ₖ.
May import: SymPy, :mod:`derive.lecture.vector_algebra_model`.
"""
from __future__ import annotations

import random

import sympy as sp

from derive.lecture.vector_algebra_model import E, MU, RK, W, WD

_SAMPLES = 3
_MODEL = frozenset({*W, *WD, *MU, *(x for r in RK for x in r)})


def vanishes_for_free_body(d) -> bool:
    """Is ``d`` (a scalar or a matrix in the model's symbols, with ω̇ in it) zero once ω̇ is the
    free body's, at three exact rational points (masses, positions and ω drawn from a fixed seed)?

    The free body's law of motion, in the body's principal or any axes:
    𝐈ω̇ + ω × (𝐈ω) = 0, 𝐈 = Σₖ μₖ (𝐫ₖ·𝐫ₖ 𝟙 − 𝐫ₖ𝐫ₖᵀ).
    """
    entries = [sp.sympify(e) for e in (d if isinstance(d, sp.MatrixBase) else [d])]
    free = set().union(*(e.free_symbols for e in entries))
    if not free & set(WD) or not free <= _MODEL:
        return False
    rng = random.Random(20261202)
    for _ in range(_SAMPLES):
        at = {s: sp.Rational(rng.randint(1, 9), rng.randint(1, 4)) * rng.choice((1, -1))
              for s in (*W, *(x for r in RK for x in r))}
        at.update({m: sp.Rational(rng.randint(1, 9), rng.randint(1, 4)) for m in MU})
        tensor = sum((m * (r.dot(r) * E - r * r.T) for m, r in zip(MU, RK)), sp.zeros(3)).xreplace(at)
        if tensor.det() == 0:
            continue
        w = W.xreplace(at)
        at.update(zip(WD, tensor.LUsolve(-w.cross(tensor * w))))
        if any(e.xreplace(at) != 0 for e in entries):
            return False
    return True
