"""A worked example's own body and its rounded numbers: one body's inertia matrix is not judged against
generic mass points (derive/lecture/algebra_claims.py), the principal moments A, B, C of one body set
to a value are the text's own (derive/lecture/notes_check.py), and a rotation written to four
decimals is not flagged for its rounding (derive/lecture/worked_values.py)."""
import sympy as sp

import kept_readings as kept

from derive.lecture.worked_values import rounded

ROTATION = ("The rotation that diagonalizes the inertia matrix, to four decimals:\n\n"
            "$$ R = \\left[\\begin{array}{ccc} 0.3404 & 0 & -0.9403\\\\ 0 & 1 & 0\\\\ 0.9403 & 0 & 0.3404 "
            "\\end{array}\\right] $$\n\nIt is a rotation:\n\n"
            "$$ R^T\\ R = \\left[\\begin{array}{ccc} 1 & 0 & 0\\\\ 0 & 1 & 0\\\\ 0 & 0 & 1 \\end{array}\\right] $$\n")


def _flagged(claims):
    return [c for c in claims if c.verdict in ("typo", "fails")]


def test_a_rotation_written_to_four_decimals_is_not_flagged_for_its_rounding():
    assert not _flagged(kept.check_text(ROTATION))
    # a wrong entry is off by far more than the rounding: still flagged
    assert _flagged(kept.check_text(ROTATION.replace("0.3404", "0.4404")))


def test_sides_apart_by_their_decimals_rounding_only_are_told_apart_from_a_slip():
    r = sp.Matrix([[sp.Rational("0.3404"), sp.Rational("-0.9403")], [sp.Rational("0.9403"), sp.Rational("0.3404")]])
    assert rounded(r.T * r, [sp.eye(2)])
    assert rounded(2 * r.T * r, [sp.eye(2)]) is None
    # fractions the text means exactly (1/8 against 1000/7999) are no rounded decimals, however close
    assert rounded(sp.Rational(1, 8), [sp.Rational(1000, 7999)]) is None


def test_one_bodys_inertia_matrix_is_not_judged_against_generic_mass_points():
    text = ("Four masses $m$ sit at $(\\pm 1, 0, -\\frac{1}{\\sqrt{2}})$ and $(0, \\pm 1, \\frac{1}{\\sqrt{2}})$. "
            "The moments of inertia are\n\n$$\nI_{00} = \\sum_i m_i \\left(y_i^2 + z_i^2 \\right) = 4m\n$$\n\n"
            "so the inertia matrix is\n\n$$\nI = \\begin{bmatrix}4m & 0 & 0\\\\ 0 & 4m & 0\\\\ 0 & 0 & 4m"
            "\\end{bmatrix}\n$$\n")
    claims = kept.check_text(text)
    assert not _flagged(claims)
    # either of derive.lecture.body_values' two reasons: the text's own body, not the reader's general one
    assert any("one body's values" in c.why or "a particular body" in c.why for c in claims)


def test_one_bodys_principal_moments_set_equal_are_the_texts_own_names():
    text = ("For a tetrahedron of four masses the principal moments are\n\n$$\nA = B = C = 4m\n$$\n\n"
            "For a uniform cube of side $L$ and mass $M$ about its centre the principal moments are\n\n"
            "$$\nA = B = C = \\frac{M L^2}{6}\n$$\n")
    assert not _flagged(kept.check_text(text))
