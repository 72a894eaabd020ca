"""The notes reader on a linearisation set up in a sentence: "we assume that $\\omega_1 = \\Omega$, and
$\\omega_2, \\omega_3 \\ll \\Omega$" sets ω₁ (the words before "that" make it an assumption) and makes
ω₂, ω₃ small, so the equations that follow are judged to first order in them: the linearised
equations and their time derivatives hold, a derivative the linearisation makes zero is never
flagged for the second-order terms it drops, and a slip in a linearised step is still flagged."""
import kept_readings as kept

verdicts, line_of = kept.verdicts_by_line, kept.line_of

EULER = ("# Stability\n\nEuler's equations in principal axes:\n\n$$\n\\begin{align*}\n"
         "I_1 \\dot\\omega_1 &= (I_2 - I_3) \\omega_2 \\omega_3 \\\\\nI_2 \\dot\\omega_2 &= (I_3 - I_1) \\omega_3 \\omega_1 \\\\\n"
         "I_3 \\dot\\omega_3 &= (I_1 - I_2) \\omega_1 \\omega_2\n\\end{align*}\n$$\n\n"
         "Here we assume that $\\omega_1 = \\Omega$, and $\\omega_2, \\omega_3 \\ll \\Omega$.\n\n$$\n\\begin{align*}\n"
         "I_2 \\dot\\omega_2 &= (I_3 - I_1) \\Omega \\omega_3 \\\\\nI_3 \\dot\\omega_3 &= (I_1 - I_2) \\Omega \\omega_2\n"
         "\\end{align*}\n$$\n\nTaking the time derivatives,\n\n$$\n\\begin{align*}\nI_1 \\ddot\\omega_1 &= 0 \\\\\n")


def test_a_linearisation_set_up_in_a_sentence_is_judged_to_first_order():
    text = EULER + "I_2 \\ddot\\omega_2 &= \\frac{(I_3 - I_1)(I_1 - I_2)}{I_3} \\Omega^2 \\omega_2\n\\end{align*}\n$$\n"
    got = verdicts(text)
    assert got[line_of(text, "$$\n\\begin{align*}\nI_2 \\dot")] == {"holds"}
    derivatives = got[line_of(text, "$$\n\\begin{align*}\nI_1 \\ddot")]
    assert "holds" in derivatives and not derivatives & {"typo", "fails"}


def test_a_slip_in_the_linearised_derivative_is_still_flagged():
    text = EULER + "I_2 \\ddot\\omega_2 &= \\frac{(I_3 - I_1)(I_1 - I_2)}{I_2} \\Omega^2 \\omega_2\n\\end{align*}\n$$\n"
    assert verdicts(text)[line_of(text, "$$\n\\begin{align*}\nI_1 \\ddot")] & {"typo", "fails"}
