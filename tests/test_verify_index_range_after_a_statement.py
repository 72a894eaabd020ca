"""A statement with a free index and the index's range written after it (``L_i = I_i \\omega_i,\\quad
i = 1,2,3``, ``(i = 1, 2, 3)``) is its three statements, each checked (a wrong one never holds); an
index that also sits in a longer subscript (``I_{ij}``) or under a sum is left alone."""
import kept_readings as kept
from derive.lecture.statements import statements

HEAD = "---\nconvention: z-x-z\n---\n# Principal axes\n\n"


def test_the_range_makes_three_statements():
    assert statements(r"L_i = I_i \omega_i,\quad i = 1,2,3") == \
        [r"L_{1} = I_{1} \omega_{1}", r"L_{2} = I_{2} \omega_{2}", r"L_{3} = I_{3} \omega_{3}"]
    assert len(statements(r"T_i = \frac{1}{2} I_i \omega_i^2 \quad (i = 1, 2, 3)")) == 3


def test_each_statement_is_checked_and_a_wrong_one_never_holds():
    good = kept.check_text(HEAD + "$$\nL_i = I_i \\omega_i,\\quad i = 1,2,3\n$$\n")
    assert [c.verdict for c in good] == ["holds"] * 3
    bad = kept.check_text(HEAD + "$$\nL_i = I_i \\omega_i^2,\\quad i = 1,2,3\n$$\n")
    assert len(bad) == 3 and "holds" not in [c.verdict for c in bad]     # each read, none taken as true


def test_an_index_in_a_longer_subscript_or_under_a_sum_is_left_alone():
    assert statements(r"L_i = I_{ij} \omega_j, \quad i = 1,2,3")[0] == r"L_i = I_{ij} \omega_j"
    assert statements(r"L_i = \sum_j I_{ij} \omega_j, \quad i = 1,2,3")[0] == r"L_i = \sum_j I_{ij} \omega_j"


def test_a_statement_in_brackets_plain_or_sized_is_read_without_them():
    for open_, close in (("(", ")"), ("\\left(", "\\right)"), ("\\bigl(", "\\bigr)")):
        assert statements(f"k^2 = a \\quad {open_}0 \\le k^2 \\le 1{close}")[-1].strip() == "0 \\le k^2 \\le 1"
    assert statements("\\left(a\\right) = \\left(b\\right)") == ["\\left(a\\right) = \\left(b\\right)"]
