"""An aligned display whose row opens with ``+`` or ``-`` and states no relation of its own carries
the right side of the row before it on (``T &= \\frac{1}{2}I_1\\omega_1^2 \\\\ &+ \\frac{1}{2}I_2 …``):
the rows are one member, judged whole, so a correct sum holds and a slip in a carried row is
flagged; a row that opens with a sign and states a relation is a statement of its own."""
import kept_readings as kept
from derive.lecture.statements import statements

SUM = ("\\begin{align}\nT &= \\frac{1}{2}I_1\\omega_1^2\\\\\n&+ \\frac{1}{2}I_2\\omega_2^2\\\\\n"
       "&+ \\frac{1}{2}I_3\\omega_3%s.\n\\end{align}")


def test_rows_opening_with_a_sign_continue_the_member_before():
    spaced = lambda rows: [" ".join(r.split()) for r in rows]  # noqa: E731
    assert spaced(statements(SUM % "^2")) == [r"T = \frac{1}{2}I_1\omega_1^2 + \frac{1}{2}I_2\omega_2^2 + \frac{1}{2}I_3\omega_3^2"]
    assert spaced(statements("\\begin{align}\na &= b\\\\\n-c &= d\n\\end{align}")) == ["a = b", "-c = d"]


def test_the_carried_sum_holds_and_a_slip_in_it_is_flagged():
    right = kept.check_text("# Free body\n\n" + SUM % "^2" + "\n")
    assert [c.verdict for c in right] == ["holds"]
    wrong = kept.check_text("# Free body\n\n" + SUM % "" + "\n")
    assert [c.verdict for c in wrong] in (["typo"], ["fails"])


BRACKETED = ("\\begin{align}\nT &= \\frac{1}{2}\\left(I_1\\omega_1^2 + I_2\\omega_2^2\\right)\\\\\n"
             "&+ \\frac{1}{2}I_3\\left(\\omega_3\\right)%s.\n\\end{align}")


def test_a_carried_row_in_left_right_brackets_is_carried_not_a_relation():
    """``\\left(`` opens a bracket: its ``\\le`` is no ``\\leq``, so the row states no relation."""
    assert len(statements(BRACKETED % "^2")) == 1
    assert [c.verdict for c in kept.check_text("# Free body\n\n" + BRACKETED % "^2" + "\n")] == ["holds"]
    assert [c.verdict for c in kept.check_text("# Free body\n\n" + BRACKETED % "" + "\n")] in (["typo"], ["fails"])
