"""A square array between bars, ``\\begin{vmatrix} … \\end{vmatrix}``, of scalar entries is its
determinant: a determinant the text states is checked (a quadratic form's singular matrix, a turn's
unit determinant), a wrong one is not called true, and one that is not square is not read."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n# Determinants\n\n"


def _verdicts(text):
    return [c.verdict for c in kept.check_text(text)]


def test_a_determinant_of_scalars_the_text_states_is_checked():
    singular = "$$\n\\begin{vmatrix} I_1 & 0 & 0 \\\\ 0 & 1 & 1 \\\\ 0 & 1 & 1 \\end{vmatrix} = 0\n$$\n"
    assert set(_verdicts(HEAD + singular)) == {"holds"}
    turn = "$$\n\\begin{vmatrix} \\cos\\theta & -\\sin\\theta \\\\ \\sin\\theta & \\cos\\theta \\end{vmatrix} = 1\n$$\n"
    assert set(_verdicts(HEAD + turn)) == {"holds"}


def test_a_wrong_determinant_does_not_hold():
    wrong = "$$\n\\begin{vmatrix} 2 & 1 \\\\ 1 & 1 \\end{vmatrix} = 3\n$$\n"
    claims = kept.check_text(HEAD + wrong)
    assert "holds" not in [c.verdict for c in claims]
    assert not any("cannot parse" in c.why for c in claims)     # read (1 against 3), never taken as true
    # one that holds only for a value of the text's parameter is that value set, never a claim that holds
    setting = "$$\n\\begin{vmatrix} I_1 & 0 & 0 \\\\ 0 & 1 & 1 \\\\ 0 & 1 & 2 \\end{vmatrix} = 0\n$$\n"
    assert "holds" not in _verdicts(HEAD + setting)


def test_a_determinant_that_is_not_square_is_not_read():
    text = HEAD + "$$\n\\begin{vmatrix} a & b & c \\\\ d & e & f \\end{vmatrix} = 0\n$$\n"
    assert set(_verdicts(text)) <= {"unchecked"}
