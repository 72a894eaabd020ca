"""The notes reader on the exponential of a matrix (``\\exp([\\boldsymbol{\\omega}]_\\times dt)``): a skew
matrix's exponential is the turn about its vector by its length (Rodrigues' formula, the matrix
SymPy's general exponential gives), and an exponential that may become a matrix stays apart from
SymPy's scalar exp until its argument is known."""
import random

import sympy as sp

import kept_readings as kept
from derive.lecture.matrix_exp import MatrixExp, skew_exponential
from derive.lecture.vocabulary import CrossMatrix

HEAD = "---\nconvention: z-y-z\n---\n# Notes\n\n"


def _skew(a, b, c):
    return sp.ImmutableMatrix([[0, -c, b], [c, 0, -a], [-b, a, 0]])


def test_a_skew_matrix_exponential_is_the_matrix_sympys_general_exponential_gives():
    k = _skew(1, 2, 2)
    assert (skew_exponential(k) - k.exp()).evalf(30).norm() < 1e-25
    theta = sp.Symbol("theta", real=True)
    turn = skew_exponential(_skew(0, 0, theta))
    assert turn == sp.ImmutableMatrix([[sp.cos(theta), -sp.sin(theta), 0], [sp.sin(theta), sp.cos(theta), 0], [0, 0, 1]])
    assert skew_exponential(_skew(0, 0, 0)) == sp.eye(3)
    assert skew_exponential(sp.ImmutableMatrix([[0, 1, 0], [0, 0, 0], [0, 0, 0]])) is None    # not skew


def test_a_symbolic_skew_exponential_is_a_turn_that_keeps_its_vector():
    a, b, c, t = sp.symbols("a b c t", real=True)
    k = _skew(a, b, c) * t
    r = MatrixExp(k)
    assert isinstance(r, sp.MatrixBase)
    rng = random.Random(3)
    for _ in range(3):
        at = {s: sp.Rational(rng.randint(-20, 20), 7) for s in (a, b, c, t)}
        n = r.xreplace(at).evalf(30)
        assert (n.T * n - sp.eye(3)).norm() < 1e-25
        assert (n * sp.Matrix([a, b, c]).xreplace(at) - sp.Matrix([a, b, c]).xreplace(at)).evalf(30).norm() < 1e-25


def test_an_exponential_that_may_become_a_matrix_is_not_merged_and_a_scalar_one_is_sympys():
    u, v = sp.symbols("u v", real=True)
    p = MatrixExp(CrossMatrix(u)) * MatrixExp(CrossMatrix(v))
    assert len([f for f in p.args if isinstance(f, MatrixExp)]) == 2      # e^A e^B is not e^(A+B)
    assert MatrixExp(CrossMatrix(u)).xreplace({CrossMatrix(u): u}) == sp.exp(u)
    assert sp.sstr(MatrixExp(CrossMatrix(u))) == "exp(CrossMatrix(u))"


_verdicts = kept.verdicts_by_line


def test_the_exponential_of_the_cross_product_matrix_of_an_angle_about_an_axis_is_that_turn():
    text = HEAD + (
        "A turn about the body's third axis:\n\n"
        "$$\n\\mathbf{R} = \\exp\\left(\\left[\\theta \\hat{\\mathbf{e}}_3\\right]_\\times\\right)\n$$\n\n"
        "$$\n\\mathbf{R} = \\begin{bmatrix} \\cos\\theta & -\\sin\\theta & 0 \\\\ \\sin\\theta & \\cos\\theta & 0 "
        "\\\\ 0 & 0 & 1 \\end{bmatrix}\n$$\n\n"
        "$$\n\\mathbf{R} = \\begin{bmatrix} \\cos\\theta & \\sin\\theta & 0 \\\\ \\sin\\theta & \\cos\\theta & 0 "
        "\\\\ 0 & 0 & 1 \\end{bmatrix}\n$$\n")
    assert _verdicts(text) == {8: {"holds"}, 12: {"holds"}, 16: {"typo"}}


def test_a_step_of_the_exponential_of_the_angular_velocitys_cross_matrix_defines_the_new_orientation():
    text = HEAD + ("One step of the integration:\n\n$$\n\\mathbf{R}_{new} = \\exp\\left(\\left[\\boldsymbol{\\omega}"
                   "\\right]_\\times dt\\right) \\mathbf{R}_{old}\n$$\n")
    claims = kept.check_text(text)
    assert [(c.kind, c.verdict) for c in claims] == [("new symbol", "unchecked")]
