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
