"""A display that sets the inertia matrix equal to a diagonal matrix of one letter numbered 1, 2, 3
(``\\boldsymbol{J} = [J_1, 0, 0; 0, J_2, 0; 0, 0, J_3]``), after prose that calls it the moment of
inertia, names those letters the principal moments, so Euler's equations written in them are judged;
without the words, or with a moment the text gives a formula of its own, they stay unnamed."""
import kept_readings as kept

PROSE = "When the moment of inertia is diagonal (principal axes),\n"
MATRIX = r"""
$$
\boldsymbol{J} = \left[ \begin{array}{ccc} J_{1} & 0 & 0 \\ 0 & J_{2} & 0 \\ 0 & 0 & J_{3} \end{array} \right]
$$

its components give Euler's equations:

$$
\frac{d\omega_1}{dt} + \frac{J_3 - J_2}{J_1} \omega_2 \omega_3 = 0
$$
"""


def _verdicts(prose=PROSE, matrix=MATRIX, extra=""):
    text = "# Euler's equations\n\n" + extra + prose + matrix
    by_line = kept.verdicts_by_line(text)
    return by_line.get(kept.line_of(text, r"\frac{d\omega_1}{dt}") - 1, set())


def test_a_diagonal_inertia_matrix_names_its_entries_the_principal_moments():
    assert _verdicts() == {"holds"}


def test_a_slip_in_euler_equations_in_those_moments_is_never_a_hold():
    assert "holds" not in _verdicts(matrix=MATRIX.replace(r"\frac{J_3 - J_2}", r"\frac{J_2 - J_3}"))


def test_a_diagonal_matrix_the_prose_does_not_call_the_inertia_is_no_name():
    assert _verdicts(prose="When the matrix is diagonal,\n") == {"unchecked"}


def test_a_moment_the_text_gives_a_formula_of_its_own_is_no_name():
    assert _verdicts(extra="The disk has $J_1 = m a^2$.\n\n") == {"unchecked"}


def test_the_matrix_in_brackets_sized_by_hand_or_plain_names_them_too():
    for opening, closing in ((r"\bigl[", r"\bigr]"), (r"\Bigl(", r"\Bigr)"), ("[", "]")):
        sized = MATRIX.replace(r"\left[", opening).replace(r"\right]", closing)
        assert _verdicts(matrix=sized) == {"holds"}, opening
