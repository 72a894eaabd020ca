"""A worked example's own body: its written values set against the reader's general body.

Takes: a member the text writes and the member the reader derives for its general body of mass
points. Gives: `particular` and `one_body`, whether the written member is one body's values (which
the general body's points cannot decide), and the why of each.
May import: SymPy, :mod:`derive.lecture.vector_algebra_model`.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import vector_algebra_model as va


def _zero(d) -> bool:
    return all(x == 0 for x in d) if isinstance(d, sp.MatrixBase) else d == 0


PARTICULAR = ("the value of a particular body (numbers and its mass, no position of its points): the reader's "
              "body is a general one, whose value is in its points' positions, so the two are not compared")
_POSITIONS = frozenset(va.R0) | frozenset(c for point in va.RK for c in point)
_RATES = frozenset(va.W) | frozenset(va.WD)


def particular(written, derived) -> bool:
    """``\\mathbf{I} = m\\,\\mathrm{diag}(0.0016, 0.0049, 0.0016)``, ``I_{zz} = 0.3\\,m``: a member in no position
    of the body's points and no rate, not zero, beside one in positions: a worked example's body, not the general one
    (a member in the rates, 𝛚 where 𝛚 × 𝐫 belongs, is a slip the points decide)."""
    free = lambda x: sp.sympify(x).free_symbols if not isinstance(x, sp.MatrixBase) else x.free_symbols  # noqa: E731
    return not _zero(written) and not free(written) & (_POSITIONS | _RATES) and bool(free(derived) & _POSITIONS)


ONE_BODY = ("one body's values: the written side names none of the coordinates the generic mass points' "
            "expression is quadratic in, so it describes the text's own body, which those points cannot decide")


def one_body(derived, written) -> bool:
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
