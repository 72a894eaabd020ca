"""A free symmetric rotor written as textbooks write it: the text's I₁ = I₂ holds in its vector
statements as in its scalar ones (and fixes 𝐋 = (I₁ω̃₁, I₂ω̃₂, I₃ω̃₃) beside frame derivatives, L₃ its
third body component), a bold 𝛚₃ in a scalar formula is the component ω̃₃, and the bare argument of
cos Ωt runs over the time."""
import kept_readings as kept

HEAD = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n"
        "## Free symmetric rotor\n\nNo torque acts, and the body is symmetric, $I_1 = I_2 \\neq I_3$.\n\n")


def verdicts(text: str, start: str) -> list:
    return [c.verdict for c in kept.check_text(text) if c.latex.lstrip().startswith(start)]


def test_the_texts_equal_moments_hold_in_a_vector_identity():
    text = HEAD + ("$$\n\\mathbf{L} \\cdot \\boldsymbol{\\omega} \\times \\hat{\\mathbf{e}}_3 = "
                   "I_1\\omega_1\\omega_2 - I_2\\omega_1\\omega_2 = 0\n$$\n")
    assert set(verdicts(text, "\\mathbf{L} \\cdot")) == {"holds"}


def test_without_the_equal_moments_the_vector_identity_is_not_held():
    text = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n## Free rotor\n\n"
            "No torque acts on the body, $I_1 \\neq I_2 \\neq I_3$.\n\n") + (
        "$$\n\\mathbf{L} \\cdot \\boldsymbol{\\omega} \\times \\hat{\\mathbf{e}}_3 = "
        "I_1\\omega_1\\omega_2 - I_2\\omega_1\\omega_2 = 0\n$$\n")
    assert set(verdicts(text, "\\mathbf{L} \\cdot")) != {"holds"}


AXIS_RATE = "\\left(\\frac{d\\hat{\\mathbf{e}}_3}{dt}\\right)_{space}"


def test_the_axis_rate_of_a_symmetric_body_in_its_angular_momentum_holds():
    text = HEAD + f"$$\n{AXIS_RATE} = \\frac{{\\mathbf{{L}}}}{{I_1}} \\times \\hat{{\\mathbf{{e}}}}_3\n$$\n"
    assert verdicts(text, "\\left(\\frac{d") == ["holds"]


def test_the_axis_rate_with_the_wrong_moment_is_flagged():
    text = HEAD + f"$$\n{AXIS_RATE} = \\frac{{\\mathbf{{L}}}}{{I_3}} \\times \\hat{{\\mathbf{{e}}}}_3\n$$\n"
    assert verdicts(text, "\\left(\\frac{d") in (["fails"], ["typo"])


def test_the_angular_momentum_rebuilt_from_the_axis_rate_holds():
    text = HEAD + (f"$$\n\\mathbf{{L}} = I_1\\hat{{\\mathbf{{e}}}}_3 \\times {AXIS_RATE} + "
                   "I_3\\omega_3\\hat{\\mathbf{e}}_3\n$$\n")
    assert verdicts(text, "\\mathbf{L} =") == ["holds"]


def test_a_component_of_the_angular_momentum_beside_a_frame_derivative_is_its_body_component():
    text = HEAD + ("$$\n\\begin{align} L_3 &= \\hat{\\mathbf{e}}_3 \\cdot \\mathbf{L} \\\\ "
                   f"&= I_1\\hat{{\\mathbf{{e}}}}_3 \\cdot \\hat{{\\mathbf{{e}}}}_3 \\times {AXIS_RATE} + "
                   "I_3\\omega_3\\hat{\\mathbf{e}}_3 \\cdot \\hat{\\mathbf{e}}_3 \\end{align}\n$$\n")
    kinds = [c for c in kept.check_text(text) if "I_1\\hat" in c.latex]
    assert kinds and {c.verdict for c in kinds} == {"holds"}


RATE = "$$\n\\Omega \\equiv \\frac{(I_3 - I_1)}{I_1} \\boldsymbol{\\omega}_3\n$$\n\n"


def test_a_bold_indexed_omega_in_a_scalar_formula_is_the_component():
    text = HEAD + RATE + "$$\n\\ddot{\\omega}_1 + \\Omega^2 \\omega_1 = 0\n$$\n"
    assert verdicts(text, "\\ddot{\\omega}_1") == ["holds"]


def test_a_wrong_frequency_with_the_bold_component_is_not_held():
    text = HEAD + RATE + "$$\n\\ddot{\\omega}_1 + 4\\Omega^2 \\omega_1 = 0\n$$\n"
    assert verdicts(text, "\\ddot{\\omega}_1") != ["holds"]


def test_cos_of_a_rate_times_the_time_takes_the_time_into_its_argument():
    text = HEAD + RATE + ("$$\n\\ddot{\\omega}_1 + \\Omega^2 \\omega_1 = 0\n$$\n\n"
                          "$$\n\\omega_1 = A \\cos \\Omega t\n$$\n")
    assert verdicts(text, "\\omega_1 = A") == ["holds"]


def test_a_solution_at_the_wrong_frequency_is_flagged():
    text = HEAD + RATE + ("$$\n\\ddot{\\omega}_1 + \\Omega^2 \\omega_1 = 0\n$$\n\n"
                          "$$\n\\omega_1 = A \\cos 2 \\Omega t\n$$\n")
    assert verdicts(text, "\\omega_1 = A") != ["holds"]


INSTANT = ("$$\n\\omega_1 = 0 \\quad \\omega_2 = \\omega \\sin \\alpha \\quad \\omega_3 = \\omega \\cos \\alpha\n$$\n\n")


def test_the_angles_rates_tied_to_the_values_of_a_case_are_not_judged():
    text = HEAD + INSTANT + "$$\n\\dot{\\phi} \\sin \\theta = \\omega \\sin \\alpha\n$$\n"
    assert verdicts(text, "\\dot{\\phi} \\sin") == ["unchecked"]


def test_the_values_of_a_case_still_meet_in_a_relation_without_rates():
    text = HEAD + INSTANT + "$$\n\\omega_2^2 + \\omega_3^2 = \\omega^2\n$$\n"
    assert verdicts(text, "\\omega_2^2") == ["holds"]
