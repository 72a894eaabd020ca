"""A perturbation the text names (ω_i = c_i + η_i in its prose) and the equations it writes in the
η_i: Euler's equations with the perturbation put in, to the order a remainder O(η²) keeps."""
import kept_readings as kept

HEAD = ("---\nconvention: z-x-z\n---\n# Spin about the middle axis\n\n"
        "Euler's equations of a free body:\n\n"
        "$$I_1\\dot\\omega_1 = (I_2 - I_3)\\omega_2\\omega_3$$\n\n"
        "Put $\\omega_1 = \\eta_1$, $\\omega_3 = \\eta_3$ and $\\omega_2 = \\Omega + \\eta_2$ with $\\eta$ small. "
        "The equations become\n\n")


def _verdicts(body):
    found = kept.by_line(HEAD + body)
    first = HEAD.count("\n") + 1
    return [sorted({c.verdict for c in found.get(first + 2 * k, [])}) for k in range(body.count("$$") // 2)]


def test_the_linearised_equations_hold_to_the_order_their_remainder_keeps():
    body = ("$$I_1\\dot\\eta_1 = (I_2 - I_3)\\Omega\\eta_3 + O(\\eta^2)$$\n\n"
            "$$I_2\\dot\\eta_2 = O(\\eta^2)$$\n\n"
            "$$I_3\\dot\\eta_3 = (I_1 - I_2)\\Omega\\eta_1 + O(\\eta^2)$$\n\n"
            "$$\\ddot\\eta_1 = \\frac{(I_2 - I_3)(I_1 - I_2)\\Omega^2}{I_3I_1}\\eta_1$$")
    assert _verdicts(body) == [["holds"]] * 4


def test_a_remainder_written_in_sized_brackets_is_the_same_remainder():
    body = ("$$I_1\\dot\\eta_1 = (I_2 - I_3)\\Omega\\eta_3 + O\\left(\\eta^2\\right)$$\n\n"
            "$$I_3\\dot\\eta_3 = (I_1 - I_3)\\Omega\\eta_1 + O\\bigl(\\eta^2\\bigr)$$")
    assert _verdicts(body) == [["holds"], ["fails"]]


def test_a_slip_in_a_linearised_equation_fails_at_its_order():
    body = ("$$I_1\\dot\\eta_1 = (I_3 - I_2)\\Omega\\eta_3 + O(\\eta^2)$$\n\n"
            "$$\\ddot\\eta_1 = \\frac{(I_2 - I_3)(I_1 - I_3)\\Omega^2}{I_3I_1}\\eta_1$$")
    assert _verdicts(body) == [["fails"], ["fails"]]


def test_without_a_remainder_in_the_section_an_equation_is_held_exactly():
    body = "$$\\ddot\\eta_1 = \\frac{(I_2 - I_3)(I_1 - I_2)\\Omega^2}{I_3I_1}\\eta_1$$"
    assert _verdicts(body) == [["unchecked"]]


def test_a_name_the_perturbation_does_not_tie_leaves_the_equation_to_the_rest_of_the_reader():
    body = "$$I_1\\dot\\eta_1 = (I_2 - I_3)\\Omega\\eta_3 + N_1 + O(\\eta^2)$$"
    assert all("perturbation" not in c.why for c in kept.check_text(HEAD + body))


def test_a_symbol_added_to_a_moving_value_is_no_perturbation_of_a_steady_spin():
    head = HEAD.replace("$\\omega_2 = \\Omega + \\eta_2$", "$\\omega_2 = A\\cos(\\Omega t) + \\eta_2$")
    body = "$$I_1\\dot\\eta_1 = (I_2 - I_3)A\\eta_3 + O(\\eta^2)$$"
    assert all("perturbation" not in c.why for c in kept.check_text(head + body))
