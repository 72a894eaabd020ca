"""A vector written as the tuple of its components, ``\\mathbf{L} = (I_1\\omega_1, I_2\\omega_2, I_3\\omega_3)``,
is its column (the reader of three entries in round brackets, `derive.lecture.written_matrices`): the
body's angular momentum so written holds and a slip in a component is flagged. A pair and three numbers
alone are left as written (tests/test_verify_vector_components_in_brackets.py)."""
from __future__ import annotations

import kept_readings as kept

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

