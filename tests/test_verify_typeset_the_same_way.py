"""The same formula typeset another way is read the same: a small space after the upright
differential d (``\\mathrm{d}\\,t``), a derivative whose numerator sets the italic d over an upright
``\\mathrm{d}t``, brackets sized by hand (``\\bigl(
… \\bigr)`` as ``\\left( … \\right)``, the cross-product matrix's ``\\bigl[\\mathbf{b}\\bigr]`` too) and a
spaced full stop after a row's words before ``\\end{equation}``."""
from __future__ import annotations

import pytest

import kept_readings as kept
from derive.lecture import source

def _verdicts(text: str, first: int) -> list[str]:
    return [c.verdict for c in kept.check_text(text) if c.line >= first]


EULER = r"""# Euler's equations of a free body

The body turns freely about its centre of mass with principal moments $I_1, I_2, I_3$:

$$
\frac{\mathrm{d}\omega_1}{\mathrm{d}t} = \frac{I_2 - I_3}{I_1} \omega_2 \omega_3
$$
"""


@pytest.mark.parametrize("written", [r"\frac{\mathrm{d}\,\omega_1}{\mathrm{d}\,t}", r"\frac{\mathrm{d}\;\omega_1}{\mathrm{d}~t}",
                                     r"\frac{d\omega_1}{\mathrm{d}\,t}", r"\frac{d\omega_1}{\mathrm{d}t}"])
def test_a_small_space_after_the_upright_d_or_an_italic_d_over_it_is_the_same_derivative(written):
    text = EULER.replace(r"\frac{\mathrm{d}\omega_1}{\mathrm{d}t}", written)
    assert _verdicts(text, 5) == _verdicts(EULER, 5) == ["holds"]
    slipped = text.replace("I_2 - I_3", "I_3 - I_2")
    assert all(v in ("typo", "fails") for v in _verdicts(slipped, 5))


def test_the_small_space_goes_only_after_the_upright_d():
    assert source.normalize(r"\frac{\mathrm{d}\,q}{\mathrm{d}\,t}") == r"\frac{\mathrm{d} q}{\mathrm{d} t}"
    assert source.normalize(r"\frac{dq}{\mathrm{d}\,t}") == r"\frac{dq}{dt}"
    assert source.normalize(r"a \, b") == r"a \, b"


def test_brackets_sized_by_hand_are_the_pair_left_right_sets():
    assert source.normalize(r"\bigl( a + b \bigr)^2 + \Biggl[ c \Biggr]") == r"\left( a + b \right)^2 + \left[ c \right]"
    assert source.normalize(r"\bigl. x \bigr|_0") == r"x \right|_0"


CROSS = r"""# The cross-product matrix

The text writes the matrix that takes the cross product with $\mathbf{b}$ as $\mathbf{b}$ in brackets:

$$
\mathbf{b} \times \mathbf{y} \equiv \left[\mathbf{b}\right] \mathbf{y}
$$

$$
\left[\mathbf{b}\right] \equiv \begin{bmatrix} 0 & -b_z & b_y \\ b_z & 0 & -b_x \\ -b_y & b_x & 0 \end{bmatrix}
$$
"""


def test_a_cross_product_matrix_in_brackets_sized_by_hand_is_read_as_one_in_left_right():
    sized = CROSS.replace(r"\left[", r"\bigl[").replace(r"\right]", r"\bigr]")
    assert _verdicts(sized, 5) == _verdicts(CROSS, 5) == ["holds", "holds"]


ENERGY = r"""# The kinetic energy of a free body

Multiplying Euler's equations of the free body by $\omega_1$, $\omega_2$, $\omega_3$ and adding shows the
kinetic energy constant:

\begin{equation}
	\frac12 \sum_{i=1}^3 I_i \omega_i^2 = T \quad\text{(constant)}
	\label{energy}END
\end{equation}
"""


@pytest.mark.parametrize("end", ["", ".", r" \, .", r" \; ,"])
def test_a_spaced_full_stop_after_a_rows_words_leaves_the_words_read(end):
    assert _verdicts(ENERGY.replace("END", end), 7) == _verdicts(ENERGY.replace("END", ""), 7)
    assert source.normalize("a = b \\, , \\\\ c = d").startswith("a = b \\\\")
