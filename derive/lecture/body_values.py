"""A worked example's own body: its written values set against the reader's general body.

Takes: a member the text writes and the member the reader derives for its general body of mass
points. Gives: `own_body`, whether either member is one body's values set against the other (which
the general body's points cannot decide), and `WHY`, the reason the pair is then left unjudged.
May import: SymPy, :mod:`derive.lecture.vector_algebra_model`.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import vector_algebra_model as va


def _zero(d) -> bool:
    return all(x == 0 for x in d) if isinstance(d, sp.MatrixBase) else d == 0


WHY = ("one body's values: the written side is a particular body's (numbers and its mass, or a tensor free of the "
       "coordinates the generic mass points' expression is quadratic in), which the reader's general body of points "
       "cannot decide, so the two are not compared")
_POSITIONS = frozenset(va.R0) | frozenset(c for point in va.RK for c in point)
_RATES = frozenset(va.W) | frozenset(va.WD)


def _particular(written, derived) -> bool:
    """``\\mathbf{I} = m\\,\\mathrm{diag}(0.0016, 0.0049, 0.0016)``, ``I_{zz} = 0.3\\,m``: a member in no position
    of the body's points and no rate, not zero, beside one in positions: a worked example's body, not the general one
    (a member in the rates, 𝛚 where 𝛚 × 𝐫 belongs, is a slip the points decide)."""
    free = lambda x: sp.sympify(x).free_symbols if not isinstance(x, sp.MatrixBase) else x.free_symbols  # noqa: E731
    return not _zero(written) and not free(written) & (_POSITIONS | _RATES) and bool(free(derived) & _POSITIONS)


def _one_body(derived, written) -> bool:
    """Whether ``written`` (4m on the diagonal) is free of every coordinate ``derived`` is quadratic in
    (m(y² + z²)): the text's own body's values, set against the reader's generic mass points. Only a
    tensor set against a tensor: a vector's slip (ω² r for α k × r) is judged as before."""
    if not all(isinstance(e, sp.MatrixBase) and e.shape == (3, 3) for e in (derived, written)):
        return False
    try:
        coords = {x for e in derived for x in e.free_symbols if sp.Poly(e, x).degree() >= 2}
    except (sp.PolynomialError, sp.GeneratorsNeeded, AttributeError, TypeError):
        return False
    return bool(coords) and not coords & getattr(written, "free_symbols", set())


def own_body(a, b) -> bool:
    """Whether either member is a particular body's values set against the general body's (a member in
    no position of the points and no rate beside one in positions, or a tensor free of every coordinate
    the other tensor is quadratic in)."""
    return _particular(a, b) or _particular(b, a) or _one_body(a, b) or _one_body(b, a)
