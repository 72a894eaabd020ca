"""A whole display in one pair of parentheses is what they hold, cut into its rows as any display is
(derive/lecture/statements.py)."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n# Euler's equations\n\n"


def test_a_whole_display_in_one_pair_of_parentheses_is_read_row_by_row():
    """A sheet's aligned rows wrapped in ``\\left( … \\right)`` are its statements (derive/lecture/statements.py)."""
    rows = (r"\left(\begin{aligned} I_{1} \dot{\omega}_{1} + (I_{3} - I_{2}) \omega_{2} \omega_{3} &= 0 \\ "
            r"I_{2} \dot{\omega}_{2} + (I_{1} - I_{3}) \omega_{3} \omega_{1} &= 0 \\ "
            r"I_{3} \dot{\omega}_{3} + (I_{2} - I_{1}) \omega_{1} \omega_{2} &= 0 \end{aligned}\right)")
    assert [c.verdict for c in kept.check_text(HEAD + "$$" + rows + "$$\n")] == ["holds"] * 3
