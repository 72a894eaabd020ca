"""The notes reader on the body rates named as "the body angular velocity $[p, q, r]^\\top$" (a
bracketed list right after the phrase, as aircraft and drone texts write it), and on a sibling row
that holds by restating the text's own earlier equation, which confirms no reading of the prose's
names (it holds whatever they mean)."""
from kept_readings import verdicts_by_line

verdicts = verdicts_by_line

PLAIN = "# Notes\n\n"
ZYX = "---\nconvention: z-y-x\nangles: [\\psi, \\theta, \\phi]\n---\n\n# Notes\n\n"

RATES = (ZYX + "The attitude is built from three successive rotations in the Z-Y-X (yaw-pitch-roll) order: "
         "first the yaw $\\psi$ about the Z axis, then the pitch $\\theta$ about the Y axis, then the roll "
         "$\\phi$ about the X axis.\n\n"
         "From the body angular velocity $[p, q, r]^\\top$ to the rates of the Euler angles:\n\n"
         "$$\n\\begin{bmatrix} \\dot{\\phi} \\\\ \\dot{\\theta} \\\\ \\dot{\\psi} \\end{bmatrix} =\n"
         "\\begin{bmatrix}\n1 & \\sin\\phi\\tan\\theta & \\cos\\phi\\tan\\theta \\\\\n"
         "0 & \\cos\\phi & -\\sin\\phi \\\\\n0 & \\sin\\phi/\\cos\\theta & \\cos\\phi/\\cos\\theta\n\\end{bmatrix}\n"
         "\\begin{bmatrix} p \\\\ q \\\\ r \\end{bmatrix}\n$$\n")


def _row(text, start):
    return next(k for k, r in enumerate(text.split("\n"), start=1) if r.startswith(start))


def test_the_body_angular_velocity_listed_in_brackets_names_the_body_rates():
    got = verdicts(RATES)
    assert any(v == {"holds"} for k, v in got.items() if k >= _row(RATES, "$$"))


def test_a_wrong_sign_in_the_rates_after_the_listed_body_angular_velocity_is_not_passed():
    wrong = RATES.replace("0 & \\cos\\phi & -\\sin\\phi", "0 & \\cos\\phi & \\sin\\phi")
    got = verdicts(wrong)
    assert not any("holds" in v for k, v in got.items() if k >= _row(wrong, "$$"))


def test_a_list_before_the_phrase_binds_no_body_rate():
    # only a formula right after "the body angular velocity" names its components
    text = RATES.replace("From the body angular velocity $[p, q, r]^\\top$ to",
                         "With $[p, q, r]^\\top$ the body angular velocity, from it to")
    got = verdicts(text)
    assert not any("holds" in v for k, v in got.items() if k >= _row(text, "$$"))


EULER = (PLAIN + "The body angular velocity $[p, q, r]^\\top$ and the moment $[L, M, N]^\\top$ in body "
         "components; the inertia tensor is taken diagonal. In components:\n\n"
         "$$\n\\begin{align}\nI_{xx}\\dot{p} + (I_{zz} - I_{yy})qr &= L \\\\\n"
         "I_{yy}\\dot{q} + (I_{xx} - I_{zz})pr &= M \\\\\nI_{zz}\\dot{r} + (I_{yy} - I_{xx})pq &= N\n\\end{align}\n$$\n\n"
         "Solved for the angular accelerations:\n\n"
         "$$\n\\begin{align}\n\\dot{p} &= \\frac{L - (I_{zz} - I_{yy})qr}{I_{xx}} \\\\\n"
         "\\dot{q} &= \\frac{M - (I_{xx} - I_{zz})pr}{I_{yy}} \\\\\n"
         "\\dot{r} &= \\frac{N - (I_{yy} - I_{xx})pq}{I_{zz}}\n\\end{align}\n$$\n")


def test_a_row_restating_the_texts_own_equation_confirms_no_reading_of_its_names():
    # Euler's equations with the text's own moments I_xx and torque L, M, N: the solved rows are not flagged
    got = verdicts(EULER)
    assert not any(v & {"fails", "typo"} for v in got.values())
