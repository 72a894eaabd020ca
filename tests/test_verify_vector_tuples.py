"""A vector written as the tuple of its components, ``\\mathbf{L} = (I_1\\omega_1, I_2\\omega_2, I_3\\omega_3)``,
is its column: the body's angular momentum so written holds, a slip in a component is flagged, and a
tuple named by a plain letter (a point, not a vector), or of numbers alone (a unit vector in its own
frame), is left as written."""
from __future__ import annotations

import kept_readings as kept

from derive.lecture import vector_tuples

TEXT = r"""# The angular momentum in principal axes

The body's angular velocity $\boldsymbol{\omega}$ and angular momentum $\mathbf{L}$, principal moments
$I_1, I_2, I_3$.

$$
\mathbf{L} = (I_1\omega_1, I_2\omega_2, THIRD)
$$
"""


def _verdicts(third: str) -> list[str]:
    return [c.verdict for c in kept.check_text(TEXT.replace("THIRD", third)) if c.line == 6]


def test_the_angular_momentum_as_a_tuple_holds():
    assert _verdicts(r"I_3\omega_3") == ["holds"]


def test_a_wrong_moment_in_the_tuple_is_flagged():
    verdicts = _verdicts(r"I_2\omega_3")
    assert verdicts and all(v in ("typo", "fails") for v in verdicts)


def test_a_tuple_beside_a_plain_letter_or_an_interval_is_left_as_written():
    assert vector_tuples.as_columns(r"P = (x, y, z)") == r"P = (x, y, z)"
    assert vector_tuples.as_columns(r"\mathbf{r} = (x, y, z) \in (0, 1)") == r"\mathbf{r} = (x, y, z) \in (0, 1)"
    assert vector_tuples.as_columns(r"\mathbf{r} = (x, y)") == r"\mathbf{r} = (x, y)"


def test_a_unit_vector_in_its_own_frame_numbers_alone_is_left_as_written():
    assert vector_tuples.as_columns(r"\mathbf{e}_Z = (0, 0, 1)") == r"\mathbf{e}_Z = (0, 0, 1)"
    assert vector_tuples.as_columns(r"\mathbf{e} = (\mathbf{e}_X\, \mathbf{e}_Y\, \mathbf{e}_Z)") == \
        r"\mathbf{e} = (\mathbf{e}_X\, \mathbf{e}_Y\, \mathbf{e}_Z)"
