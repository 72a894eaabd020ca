"""The notes reader on what a text states in its running prose and its chains: cases it lists
in one sentence, a chain whose first member it names only in words, and an angle it gives in
its constants, at which later relations of the angles are judged."""
from kept_readings import by_line
from derive.lecture.statements import statements

ZXZ = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Notes\n\n"


def test_contradictory_settings_listed_in_one_sentence_are_cases_not_assumptions():
    text = ZXZ + ("Figures show the cases $I_1=I_2>I_3$, $I_1=I_2=I_3$ and $I_1=I_2<I_3$.\n\n"
                  "$$T = \\frac12 (I_1 \\omega_1^2 + I_2 \\omega_2^2 + I_3 \\omega_3^2)$$\n\n"
                  "$$T = \\frac12 I_1 (\\omega_1^2 + \\omega_2^2 + \\omega_3^2)$$\n")
    got = by_line(text)
    assert all("one of the cases" in c.why for c in got[7] if c.kind == "setting")
    assert {c.verdict for c in got[9]} == {"holds"}
    assert {c.verdict for c in got[11]} & {"typo", "fails"}        # I₁ = I₃ was never assumed


def test_settings_in_one_sentence_that_agree_are_both_kept():
    text = ZXZ + ("For a symmetric body $I_1 = I_2$ and we take $I_3 = 2 I_1$.\n\n"
                  "$$T = \\frac12 I_1 (\\omega_1^2 + \\omega_2^2 + 2\\omega_3^2)$$\n")
    assert {c.verdict for c in by_line(text)[9]} == {"holds"}


def test_a_chain_opening_with_a_name_given_only_in_words_is_checked_from_its_second_member():
    row = "\\tan\\beta = \\tan(\\phi-\\theta) = \\frac{\\tan\\phi-\\tan\\theta}{1+\\tan\\phi\\tan\\theta}"
    got = by_line(ZXZ + "Let $\\beta$ be the half-angle of the cone. Then\n\n$$" + row + "$$\n")[9]
    assert [c.verdict for c in got] == ["holds"]


def test_a_relation_of_the_angles_is_judged_at_the_angle_the_text_gives():
    text = ZXZ + ("The nutation angle is fixed:\n\n$$\\tan\\theta = \\frac{2 I_1}{I_3}$$\n\n"
                  "Write $\\gamma = \\dfrac{I_3}{I_1}$. Then\n\n"
                  "$$\\gamma \\tan\\theta = 2$$\n\n"
                  "$$\\tan(2\\theta) = \\frac{2 \\tan\\theta}{1 - \\tan^2\\theta}"
                  " = \\frac{4 \\gamma}{\\gamma^2 + 4}$$\n")
    got = by_line(text)
    assert {c.verdict for c in got[9]} == {"unchecked"}             # the angle given, not a claim
    assert [c.verdict for c in got[13]] == ["holds"] and "at the angle the text gives" in got[13][0].why
    assert [c.verdict for c in got[15]] == ["holds", "typo"]          # γ² − 4, not γ² + 4
    assert got[15][1].correction.endswith("{\\gamma^2 - 4}")


def test_a_relation_of_an_angle_the_text_never_gave_stays_a_condition():
    text = ZXZ + "$$\\frac{\\tan\\theta}{a} = \\frac{1}{b}$$\n"
    assert {c.verdict for c in by_line(text)[7]} == {"unchecked"}


def test_the_column_count_of_alignat_is_not_read_as_part_of_the_first_statement():
    pieces = statements("\\begin{alignat}{2}\nT &= 0, \\quad E &&= 1\n\\end{alignat}")
    assert pieces and not any("{2}" in p for p in pieces)
