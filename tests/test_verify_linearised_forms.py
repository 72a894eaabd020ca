"""Linearised equations of motion as texts write them: the prose taking components "as small",
a constant spin concluded after ⇒ in a display, and the linear system in matrix form read row by
row (`derive.lecture.notes`, `derive.lecture.notes_check`, `derive.lecture.matrix_rows`)."""
import kept_readings as kept
from derive.lecture import latex as lx

EULER = r"""# Spin about the third axis

Euler's equations of the free body:

\begin{align}
I_1 \dot{\omega}_1 - (I_2 - I_3) \omega_2 \omega_3 &= 0, \\
I_2 \dot{\omega}_2 - (I_3 - I_1) \omega_3 \omega_1 &= 0, \\
I_3 \dot{\omega}_3 - (I_1 - I_2) \omega_1 \omega_2 &= 0.
\end{align}

"""

CONCLUDED = EULER + r"""We take $\omega_1, \omega_2$ as small disturbances of a spin about the third axis, so

$$I_3 \dot{\omega}_3 =0\quad\Rightarrow\quad
\omega_3 = \Omega, \quad \text{(constant)}
$$

and to first order

\begin{align}
I_1 \dot{\omega}_1 &= (I_2 - I_3) \Omega \omega_2, \\
I_2 \dot{\omega}_2 &= (I_3 - I_1) \Omega \omega_1.
\end{align}
"""

MATRIX = CONCLUDED + r"""
As matrices:

$$
\begin{bmatrix} I_1 & 0 \\ 0 & I_2 \end{bmatrix}
\begin{bmatrix} \dot{\omega}_1 \\ \dot{\omega}_2 \end{bmatrix}
=
\begin{bmatrix} 0 & (I_2 - I_3) \Omega \\ (I_3 - I_1) \Omega & 0 \end{bmatrix}
\begin{bmatrix} \omega_1 \\ \omega_2 \end{bmatrix}.
$$

$$
\begin{bmatrix} \dot{\omega}_1 \\ \dot{\omega}_2 \end{bmatrix}
=
\begin{bmatrix} 0 & \frac{I_2 - I_3}{I_1} \Omega \\ \frac{I_1 - I_3}{I_2} \Omega & 0 \end{bmatrix}
\begin{bmatrix} \omega_1 \\ \omega_2 \end{bmatrix}.
$$
"""


def _verdicts(text, line):
    return [c.verdict for c in kept.by_line(text).get(line, [])]


def _line(text, start):
    return next(k for k, row in enumerate(text.split("\n"), 1) if row.startswith(start))


def test_components_taken_as_small_make_a_constant_spin_hold_to_first_order():
    at = _line(CONCLUDED, "$$I_3 \\dot{\\omega}_3 =0")
    assert "holds" in _verdicts(CONCLUDED, at)
    assert "fails" not in _verdicts(CONCLUDED, at)


def test_without_the_small_components_the_same_rate_is_not_a_consequence():
    text = CONCLUDED.replace("as small disturbances of", "as the components off")
    assert "fails" in _verdicts(text, _line(text, "$$I_3 \\dot{\\omega}_3 =0"))


def test_a_spin_concluded_after_an_implication_holds_for_the_equations_that_follow():
    at = _line(CONCLUDED, "I_1 \\dot{\\omega}_1 &= (I_2 - I_3) \\Omega") - 1       # its align line
    assert _verdicts(CONCLUDED, at) == ["holds", "holds"]


def test_a_linear_system_in_matrix_form_is_read_row_by_row():
    assert _verdicts(MATRIX, _line(MATRIX, "\\begin{bmatrix} I_1 & 0") - 1) == ["holds"]


def test_a_wrong_row_of_a_matrix_form_fails_naming_the_row():
    at = _line(MATRIX, "\\begin{bmatrix} 0 & \\frac{I_2 - I_3}{I_1}") - 3     # its opening $$
    claims = kept.by_line(MATRIX)[at]
    assert [c.verdict for c in claims] == ["fails"]
    assert "row 2" in claims[0].why


CHARACTERISTIC = r"""# Growth rates

For a rate $\lambda$ of the two components:

$$
\det \begin{bmatrix} -\lambda & a \\ b & -\lambda \end{bmatrix} = 0.
$$

Expanding the determinant:

$$
\lambda^2 - a b = 0.
$$
"""


def test_a_determinant_written_before_a_bracketed_matrix_is_read():
    vocab = lx.Vocabulary()
    vocab.open = True                    # every letter a name of the text's
    parsed = lx.parse(r"\det \begin{bmatrix} x & y \\ z & w \end{bmatrix}", vocab)
    value = parsed.members[0].value
    names = {str(s): s for s in value.free_symbols}
    assert (value - (names["x"] * names["w"] - names["y"] * names["z"])).expand() == 0


def test_an_equation_written_out_from_an_earlier_one_holds():
    at = _line(CHARACTERISTIC, "\\lambda^2 - a b") - 1
    assert _verdicts(CHARACTERISTIC, at) == ["holds"]


def test_an_equation_that_is_not_the_earlier_one_written_out_is_not_judged_by_it():
    text = CHARACTERISTIC.replace("\\lambda^2 - a b = 0", "\\lambda^2 + a b = 0")
    assert "holds" not in _verdicts(text, _line(text, "\\lambda^2 + a b") - 1)


ROOTS = CHARACTERISTIC + r"""
so

$$
\lambda = \pm \sqrt{a b}.
$$
"""


def test_two_roots_written_with_plus_minus_solve_the_earlier_equation():
    assert _verdicts(ROOTS, _line(ROOTS, "\\lambda = \\pm") - 1) == ["holds"]


def test_roots_that_do_not_solve_the_earlier_equation_are_not_judged_by_it():
    text = ROOTS.replace("\\pm \\sqrt{a b}", "\\pm \\sqrt{2 a b}")
    assert "holds" not in _verdicts(text, _line(text, "\\lambda = \\pm") - 1)
