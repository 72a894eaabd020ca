"""A square ``array`` (or ``matrix``) between bars is a determinant, as a ``vmatrix`` is
(derive/lecture/bar_determinants.py); a column between bars stays a length."""
import kept_readings as kept

from derive.lecture.bar_determinants import vertical

HEAD = "---\nconvention: z-x-z\n---\n# Determinants\n\n"


def test_a_square_array_between_sized_bars_is_read_as_its_determinant():
    turn = ("$$\n\\left|\\begin{array}{cc} \\cos\\theta & -\\sin\\theta \\\\ \\sin\\theta & \\cos\\theta "
            "\\end{array}\\right| = 1\n$$\n")
    assert [c.verdict for c in kept.check_text(HEAD + turn)] == ["holds"]
    assert "holds" not in [c.verdict for c in kept.check_text(HEAD + turn.replace("= 1", "= 2"))]


def test_only_a_square_environment_between_bars_becomes_a_determinant():
    assert vertical(r"|\begin{matrix} a & b \\ c & d \end{matrix}| = ad - bc") == \
        r"\begin{vmatrix} a & b \\ c & d \end{vmatrix} = ad - bc"
    column = r"\left| \begin{array}{c} x \\ y \end{array} \right|"
    assert vertical(column) == column
    assert vertical(r"\left\vert \begin{array}{cc} a & b \end{array} \right\vert") == \
        r"\left\vert \begin{array}{cc} a & b \end{array} \right\vert"
