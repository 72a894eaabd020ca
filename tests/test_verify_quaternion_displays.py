"""The notes reader on displays in quaternions, as attitude texts write them: a Hamilton product
written out in components, the exponential of a rotation vector and its series, and a quaternion's
successive rates. Each is judged in the four components at exact values of the text's names, a
product of two quaternions by the rule the text names (Hamilton's or the JPL one); a slip planted
in each is flagged, its correct form holds, and what the text leaves open stays unchecked."""
import kept_readings as kept
from derive.lecture.quaternion_reader import Names, Quat, hamilton, read

HEAD = "---\ntitle: Attitude quaternion\n---\n# Attitude\n\n"
HAMILTON = ("The attitude is a unit quaternion $\\mathbf{q}$ with components $q_w, q_x, q_y, q_z$; "
            "products of quaternions are Hamilton's, and $\\boldsymbol\\omega$ is a pure quaternion.\n\n")
NO_RULE = ("The attitude is a unit quaternion $\\mathbf{q}$ with components $q_w, q_x, q_y, q_z$, "
           "and $\\boldsymbol\\omega$ is a pure quaternion.\n\n")

Q_OMEGA = ("\\begin{bmatrix} -\\omega_x q_x - \\omega_y q_y - \\omega_z q_z \\\\ "
           "\\omega_x q_w + \\omega_z q_y - \\omega_y q_z \\\\ "
           "\\omega_y q_w - \\omega_z q_x + \\omega_x q_z \\\\ "
           "\\omega_z q_w + \\omega_y q_x - \\omega_x q_y \\end{bmatrix}")


def _display(text, marker):
    """The line of the display (its opening ``$$``) in which ``marker`` stands."""
    return text[:text.rindex("$$", 0, text.index(marker))].count("\n") + 1


def _lines(text, *markers):
    v = kept.verdicts_by_line(text)
    return [v.get(_display(text, m), set()) for m in markers]


def test_hamiltons_rule_is_i_j_equals_k_and_a_pure_quaternion_squares_to_minus_its_norm_squared():
    i, j, k = Quat((0, 1, 0, 0)), Quat((0, 0, 1, 0)), Quat((0, 0, 0, 1))
    assert hamilton(i, j) == k and hamilton(j, i) == -k
    square = read("\\boldsymbol\\omega\\boldsymbol\\omega", Names(), {})
    assert square.c[1:] == (0, 0, 0) and square.c[0] == read("-\\|\\boldsymbol\\omega\\|^2", Names(), {})


def test_a_hamilton_product_written_out_in_components_holds_and_the_factors_swapped_fail():
    text = HEAD + HAMILTON + (
        "$$\n\\frac{1}{2}\\mathbf{q}\\boldsymbol\\omega = \\frac{1}{2}" + Q_OMEGA + "\n$$\n\n"
        "and, the factors the other way round,\n\n"
        "$$\n\\frac{1}{2}\\boldsymbol\\omega\\mathbf{q} = \\frac{1}{2}" + Q_OMEGA + "\n$$\n")
    right, swapped = _lines(text, "\\frac{1}{2}\\mathbf{q}\\boldsymbol", "\\frac{1}{2}\\boldsymbol\\omega\\mathbf{q}")
    assert right == {"holds"}
    assert swapped == {"fails"}


def test_a_product_whose_order_decides_is_unchecked_when_the_text_names_no_rule():
    text = HEAD + NO_RULE + "$$\n\\frac{1}{2}\\boldsymbol\\omega\\mathbf{q} = \\frac{1}{2}" + Q_OMEGA + "\n$$\n"
    (verdicts,) = _lines(text, "\\frac{1}{2}\\boldsymbol\\omega\\mathbf{q}")
    assert "fails" not in verdicts and "holds" not in verdicts


def test_the_exponential_of_a_rotation_vector_is_the_half_angle_quaternion_only_with_half_the_vector():
    text = HEAD + HAMILTON + (
        "A turn by $\\theta$ about a unit axis $\\mathbf{u}$ is\n\n"
        "$$\n\\mathbf{q} = e^{\\frac{\\theta}{2}\\mathbf{u}} = "
        "\\begin{bmatrix}\\cos\\frac{\\theta}{2} \\\\ \\mathbf{u}\\sin\\frac{\\theta}{2}\\end{bmatrix}\n$$\n\n"
        "and with the whole angle in the exponent\n\n"
        "$$\n\\mathbf{q} = e^{\\mathbf{u}\\theta} = "
        "\\begin{bmatrix}\\cos\\frac{\\theta}{2} \\\\ \\mathbf{u}\\sin\\frac{\\theta}{2}\\end{bmatrix}\n$$\n")
    half, whole = _lines(text, "e^{\\frac{\\theta}{2}", "e^{\\mathbf{u}\\theta}")
    assert half == {"holds"}
    assert "fails" in whole


def test_an_exponential_of_an_axis_the_text_never_calls_unit_is_not_flagged():
    text = HEAD + HAMILTON + (
        "$$\n\\mathbf{q} = e^{\\mathbf{a}\\theta} = \\cos\\theta + \\mathbf{a}\\sin\\theta\n$$\n")
    (verdicts,) = _lines(text, "e^{\\mathbf{a}")
    assert "fails" not in verdicts and "typo" not in verdicts


def test_a_truncated_series_of_the_exponential_is_compared_to_the_order_of_its_shortest_sum():
    text = HEAD + HAMILTON + (
        "For a unit axis $\\mathbf{u}$:\n\n"
        "$$\ne^{\\mathbf{u}\\theta} = \\Big(1 - \\frac{\\theta^2}{2!} + \\frac{\\theta^4}{4!} + \\cdots\\Big) + "
        "\\Big(\\mathbf{u}\\theta - \\frac{\\mathbf{u}\\theta^3}{3!} + \\cdots\\Big)\n$$\n\n"
        "and with a sign slipped\n\n"
        "$$\ne^{\\mathbf{u}\\theta} = \\Big(1 + \\frac{\\theta^2}{2!} + \\cdots\\Big) + "
        "\\Big(\\mathbf{u}\\theta - \\frac{\\mathbf{u}\\theta^3}{3!} + \\cdots\\Big)\n$$\n")
    right, slipped = _lines(text, "\\Big(1 - ", "\\Big(1 + ")
    assert right == {"holds"}
    assert slipped == {"fails"}


def test_a_quaternions_successive_rates_are_each_the_rate_of_the_row_before():
    rows = ("$$\n\\begin{array}{rcl}\n\\dot{\\mathbf{q}} &=& \\frac{1}{2}\\mathbf{q}\\boldsymbol\\omega \\\\\n"
            "\\ddot{\\mathbf{q}} &=& \\frac{1}{4}\\mathbf{q}\\boldsymbol\\omega^2 + \\frac{1}{2}\\mathbf{q}\\dot{\\boldsymbol\\omega} \\\\\n"
            "\\dddot{\\mathbf{q}} &=& \\frac{1}{%s}\\mathbf{q}\\boldsymbol\\omega^3 + \\frac{1}{4}\\mathbf{q}\\dot{\\boldsymbol\\omega}"
            "\\boldsymbol\\omega + \\frac{1}{2}\\mathbf{q}\\boldsymbol\\omega\\dot{\\boldsymbol\\omega}\n\\end{array}\n$$\n")
    for third, verdict in (("8", "holds"), ("6", "fails")):
        text = HEAD + NO_RULE + "Differentiating again, with $\\ddot{\\boldsymbol\\omega}=0$:\n\n" + rows % third
        claims = kept.by_line(text)[_display(text, "\\begin{array}")]
        assert [c.verdict for c in claims] == ["unchecked", "holds", verdict]


def test_a_third_rate_that_holds_only_with_a_rate_the_text_never_sets_to_zero_is_not_flagged():
    rows = ("$$\n\\begin{array}{rcl}\n\\dot{\\mathbf{q}} &=& \\frac{1}{2}\\mathbf{q}\\boldsymbol\\omega \\\\\n"
            "\\ddot{\\mathbf{q}} &=& \\frac{1}{4}\\mathbf{q}\\boldsymbol\\omega^2 + \\frac{1}{2}\\mathbf{q}\\dot{\\boldsymbol\\omega} \\\\\n"
            "\\dddot{\\mathbf{q}} &=& \\frac{1}{8}\\mathbf{q}\\boldsymbol\\omega^3 + \\frac{1}{4}\\mathbf{q}\\dot{\\boldsymbol\\omega}"
            "\\boldsymbol\\omega + \\frac{1}{2}\\mathbf{q}\\boldsymbol\\omega\\dot{\\boldsymbol\\omega}\n\\end{array}\n$$\n")
    text = HEAD + NO_RULE + rows
    claims = kept.by_line(text)[_display(text, "\\begin{array}")]
    assert [c.verdict for c in claims][:2] == ["unchecked", "holds"]
    assert claims[2].verdict == "unchecked" and "rates of omega" in claims[2].why    # 1/2 q omega'' left out


def test_a_limit_set_under_its_operator_is_taken_in_its_variable():
    chain = ("$$\n\\begin{array}{rcl}\n\\dot{\\mathbf{q}} &=& \\underset{\\Delta t\\to 0}{\\mathrm{lim}} \\frac{1}{\\Delta t}"
             "\\sin\\big(\\frac{\\|\\boldsymbol\\omega\\|\\Delta t}{2}\\big)\\frac{\\boldsymbol\\omega}{\\|\\boldsymbol\\omega\\|}"
             "\\mathbf{q} \\\\\n&=& \\frac{1}{%s}\\boldsymbol\\omega\\mathbf{q}\n\\end{array}\n$$\n")
    for half, verdict in (("2", "holds"), ("4", "fails")):
        text = HEAD + HAMILTON + chain % half
        claims = kept.by_line(text)[_display(text, "\\begin{array}")]
        assert [c.verdict for c in claims] == ["unchecked", verdict]
