"""The angular momentum's body components written together, ``L_1^2+L_2^2+L_3^2 = L^2``,
``\\frac{L_1^2}{I_1}+\\frac{L_2^2}{I_2}+\\frac{L_3^2}{I_3} = 2T``, in a text whose prose names the Lᵢ
the body components of 𝐋 and whose convention makes L₃ also the momentum of the third angle: read
with every Lᵢ = Iᵢω̃ᵢ (the third angle's momentum is I₃ω̃₃ as a function, but the reader keeps it
a conserved symbol of its own), such statements hold; a slip in one of them is flagged where the
reading is confirmed by a sibling statement of its display."""
from __future__ import annotations

import kept_readings as kept

HEAD = r"""---
convention: z-x-z
angles: [\phi, \theta, \psi]
---

A free body, principal moments $I_1, I_2, I_3$, $\omega_i$ and $L_i$ the body components of the
angular velocity and of the angular momentum $\mathbf{L}$, $L$ its constant magnitude and $T$ the
constant kinetic energy.

"""

INTEGRALS = HEAD + r"""$$
I_1^2 \omega_1^2+I_2^2 \omega_2^2+I_3^2 \omega_3^2 = L^2
$$

$$
L_1^2+L_2^2+L_3^2 = L^2
$$

$$
\frac{L_1^2}{I_1}+\frac{L_2^2}{I_2}+\frac{L_3^2}{I_3} = 2T
$$
"""

PAIR = HEAD + r"""\begin{align}
\frac{L_1^2}{I_1}+\frac{L_2^2}{I_2}+\frac{L_3^2}{I_3} &= 2T \\
\frac{L_1^2}{2I_1}+\frac{L_2^2}{2I_2}+\frac{L_3^2}{2I_LAST} &= T
\end{align}
"""


def _verdicts(text: str, line: int) -> list[str]:
    return [c.verdict for c in kept.check_text(text) if c.line == line]


def test_the_two_integrals_in_the_components_of_the_angular_momentum_hold():
    assert _verdicts(INTEGRALS, 14) == ["holds"]
    assert _verdicts(INTEGRALS, 18) == ["holds"]


def test_the_pair_read_as_body_components_holds():
    assert _verdicts(PAIR.replace("LAST", "3"), 10) == ["holds", "holds"]


def test_a_wrong_moment_under_the_axial_component_is_flagged():
    verdicts = _verdicts(PAIR.replace("LAST", "2"), 10)
    assert verdicts[0] == "holds" and verdicts[1] in ("typo", "fails")
