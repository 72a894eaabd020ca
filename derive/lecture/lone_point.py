"""One point's motion set beside the sum over a body's points, in the vector model.

`derive.lecture.vector_algebra_model` reads a statement that sums over particles (Σᵢ 𝐅ᵢ, ∫ dm) as
speaking of a body: three generic mass points turning about a fixed origin. A bare 𝐩, 𝐯 or 𝐚
outside the sum it reads as one point mass m at 𝐫 = (x, y, z) turning with them. Beside the sum
such a letter is the body's own total (𝐩̇ = Σᵢ 𝐅ᵢ: 𝐩 is the body's momentum, m𝐯 of its centre of
mass), which a model of points turning about a fixed origin does not hold: a pair of members, one
in the lone point's symbols and the other in the summed points' symbols, is left unchecked
instead of failed (`derive.lecture.algebra_claims`).

May import: :mod:`derive.lecture.vector_algebra_model`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import vector_algebra_model as va

_LONE = frozenset(va.R0) | {va.M0}
_SUMMED = frozenset(va.MU) | frozenset(s for point in va.RK for s in point)

WHY = ("sets one point's motion (a bare 𝐩, 𝐯 or 𝐚 outside the sum: the reader's lone point mass m at "
       "𝐫 = (x, y, z)) beside a sum over the body's points; there the letter is the body's own total, "
       "m𝐯 of its centre of mass, which a model of points turning about a fixed origin does not give")


def _symbols(value) -> frozenset:
    return frozenset(value.free_symbols) if isinstance(value, (sp.Basic, sp.MatrixBase)) else frozenset()


def mixed(reading, ref: int, k: int) -> bool:
    """Whether members ``ref`` and ``k`` of a statement about a body are one in the lone point's
    symbols only and the other in the summed points' symbols only."""
    if reading.model != "body":
        return False
    kinds = []
    for member in (reading.members[0][ref], reading.members[0][k]):
        found = _symbols(member.value)
        kinds.append("lone" if found & _LONE and not found & _SUMMED else
                     "summed" if found & _SUMMED and not found & _LONE else None)
    return set(kinds) == {"lone", "summed"}
