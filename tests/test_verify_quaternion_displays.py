"""The notes reader on displays in quaternions, as attitude texts write them: a Hamilton product
written out in components, the exponential of a rotation vector and its series, and a quaternion's
successive rates. Each is judged in the four components at exact values of the text's names, a
product of two quaternions by the rule the text names (Hamilton's or the JPL one); a slip planted
in each is flagged, its correct form holds, and what the text leaves open stays unchecked."""
import kept_readings as kept
from derive.lecture.quaternion_algebra import Names, Quat, hamilton
from derive.lecture.quaternion_reader import read

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
        assert [c.verdict for c in claims] == ["holds", "holds", verdict]


def test_a_third_rate_that_holds_only_with_a_rate_the_text_never_sets_to_zero_is_not_flagged():
    rows = ("$$\n\\begin{array}{rcl}\n\\dot{\\mathbf{q}} &=& \\frac{1}{2}\\mathbf{q}\\boldsymbol\\omega \\\\\n"
            "\\ddot{\\mathbf{q}} &=& \\frac{1}{4}\\mathbf{q}\\boldsymbol\\omega^2 + \\frac{1}{2}\\mathbf{q}\\dot{\\boldsymbol\\omega} \\\\\n"
            "\\dddot{\\mathbf{q}} &=& \\frac{1}{8}\\mathbf{q}\\boldsymbol\\omega^3 + \\frac{1}{4}\\mathbf{q}\\dot{\\boldsymbol\\omega}"
            "\\boldsymbol\\omega + \\frac{1}{2}\\mathbf{q}\\boldsymbol\\omega\\dot{\\boldsymbol\\omega}\n\\end{array}\n$$\n")
    text = HEAD + NO_RULE + rows
    claims = kept.by_line(text)[_display(text, "\\begin{array}")]
    assert [c.verdict for c in claims][:2] == ["holds", "holds"]
    assert claims[2].verdict == "unchecked" and "rates of omega" in claims[2].why    # 1/2 q omega'' left out


def test_a_limit_set_under_its_operator_is_taken_in_its_variable():
    chain = ("$$\n\\begin{array}{rcl}\n\\dot{\\mathbf{q}} &=& \\underset{\\Delta t\\to 0}{\\mathrm{lim}} \\frac{1}{\\Delta t}"
             "\\sin\\big(\\frac{\\|\\boldsymbol\\omega\\|\\Delta t}{2}\\big)\\frac{\\boldsymbol\\omega}{\\|\\boldsymbol\\omega\\|}"
             "\\mathbf{q} \\\\\n&=& \\frac{1}{%s}\\boldsymbol\\omega\\mathbf{q}\n\\end{array}\n$$\n")
    for half, verdict in (("2", "holds"), ("4", "fails")):
        text = HEAD + HAMILTON + chain % half
        claims = kept.by_line(text)[_display(text, "\\begin{array}")]
        assert [c.verdict for c in claims] == ["holds", verdict]


OMEGA_OPERATOR = ("$$\n\\boldsymbol\\Omega(\\boldsymbol\\omega) = \\begin{bmatrix} 0 & -\\omega_x & -\\omega_y & -\\omega_z \\\\ "
                  "\\omega_x & 0 & \\omega_z & -\\omega_y \\\\ \\omega_y & -\\omega_z & 0 & \\omega_x \\\\ "
                  "\\omega_z & \\omega_y & %s & 0 \\end{bmatrix}\n$$\n\n")
RATE = "$$\n\\dot{\\mathbf{q}} = \\frac{1}{2}\\boldsymbol\\Omega(\\boldsymbol\\omega)\\mathbf{q}\n$$\n\n"


def test_a_quaternions_rate_in_the_texts_omega_operator_is_one_of_the_four_forms_or_flagged():
    for entry, verdict in (("-\\omega_x", "holds"), ("\\omega_x", "fails")):
        text = HEAD + NO_RULE + "The omega operator:\n\n" + OMEGA_OPERATOR % entry + "so that\n\n" + RATE
        (rate,) = _lines(text, "\\dot{\\mathbf{q}} = ")
        assert rate == {verdict}


def test_the_texts_omega_operator_with_its_argument_in_sized_brackets_is_the_same_operator():
    def sized(tex):
        return tex.replace("\\Omega(\\boldsymbol\\omega)", "\\Omega\\left(\\boldsymbol\\omega\\right)")

    for entry, verdict in (("-\\omega_x", "holds"), ("\\omega_x", "fails")):
        text = HEAD + NO_RULE + "The omega operator:\n\n" + sized(OMEGA_OPERATOR) % entry + "so that\n\n" + sized(RATE)
        (rate,) = _lines(text, "\\dot{\\mathbf{q}} = ")
        assert rate == {verdict}


def test_a_step_of_the_texts_rate_is_exact_in_closed_form_and_a_series_to_its_order():
    steps = ("$$\n\\mathbf{q}_{t+1} = e^{\\frac{1}{2}\\boldsymbol\\Omega(\\boldsymbol\\omega)\\Delta t}\\mathbf{q}_t\n$$\n\n"
             "in closed form\n\n"
             "$$\n\\mathbf{q}_{t+1} = \\Bigg[\\cos\\Big(\\frac{\\|\\boldsymbol\\omega\\|\\Delta t}{2}\\Big)\\mathbf{I}_4 + "
             "\\frac{1}{\\|\\boldsymbol\\omega\\|}\\sin\\Big(\\frac{\\|\\boldsymbol\\omega\\|\\Delta t}{2}\\Big)"
             "\\boldsymbol\\Omega(\\boldsymbol\\omega)\\Bigg]\\mathbf{q}_t\n$$\n\n"
             "to first order, the update the package keeps,\n\n"
             "$$\n\\mathbf{q}_{t+1} = \\Bigg[\\mathbf{I}_4 + \\frac{1}{2}\\boldsymbol\\Omega(\\boldsymbol\\omega)\\Delta t\\Bigg]\\mathbf{q}_t\n$$\n\n"
             "and as a series\n\n"
             "$$\n\\mathbf{q}_{t+1} = \\Bigg[\\mathbf{I}_4 + \\frac{1}{2}\\boldsymbol\\Omega(\\boldsymbol\\omega)\\Delta t + "
             "\\frac{1}{%s}\\Big(\\frac{1}{2}\\boldsymbol\\Omega(\\boldsymbol\\omega)\\Delta t\\Big)^2 + \\cdots\\Bigg]\\mathbf{q}_t\n$$\n")
    for factorial, verdict in (("2!", "holds"), ("3!", "fails")):
        text = HEAD + NO_RULE + OMEGA_OPERATOR % "-\\omega_x" + RATE + \
            "With the rate constant over the step, $\\dot{\\boldsymbol\\omega}=0$,\n\n" + steps % factorial
        closed, trig, first, series = _lines(text, "e^{\\frac{1}{2}", "\\cos\\Big(", "\\Delta t\\Bigg]", "\\cdots\\Bigg]")
        assert closed == {"holds"} and trig == {"holds"}
        assert not first & {"holds", "typo", "fails"}         # an approximation the text chooses, never flagged
        assert series == {verdict}


def test_a_series_step_that_holds_only_with_omega_constant_is_not_flagged_where_the_text_lets_it_vary():
    text = HEAD + NO_RULE + OMEGA_OPERATOR % "-\\omega_x" + RATE + (
        "$$\n\\mathbf{q}_{t+1} = \\Bigg[\\mathbf{I}_4 + \\frac{1}{2}\\boldsymbol\\Omega(\\boldsymbol\\omega)\\Delta t + "
        "\\frac{1}{2!}\\Big(\\frac{1}{2}\\boldsymbol\\Omega(\\boldsymbol\\omega)\\Delta t\\Big)^2 + \\cdots\\Bigg]\\mathbf{q}_t\n$$\n")
    (series,) = _lines(text, "\\cdots\\Bigg]")
    assert not series & {"typo", "fails"}


def test_a_plain_q_with_named_components_and_a_labelled_body_rate_is_the_attitude_quaternion():
    lead = ("The unit quaternion $q(t) = [q_w, q_x, q_y, q_z]^T$ moves with the body's angular velocity "
            "$\\vec{\\omega}_b$:\n\n")
    for half, verdict in (("2", "holds"), ("4", "fails")):
        text = HEAD + lead + ("$$\\frac{dq}{dt} = \\frac{1}{%s} q \\otimes \\begin{pmatrix} 0 \\\\ \\vec{\\omega}_b "
                              "\\end{pmatrix}$$\n" % half)
        (rate,) = _lines(text, "\\frac{dq}{dt}")
        assert rate == {verdict}


def test_a_rate_in_an_operator_is_not_judged_where_the_text_never_names_which_component_is_the_scalar():
    text = ("---\ntitle: Attitude quaternion\n---\n# Attitude\n\nThe attitude is a unit quaternion "
            "$\\mathbf{q}$.\n\n" + OMEGA_OPERATOR % "\\omega_x" + RATE)
    (rate,) = _lines(text, "\\dot{\\mathbf{q}} = ")
    assert not rate & {"holds", "typo", "fails"}


def test_a_norm_of_one_holds_for_a_unit_quaternion_and_is_not_flagged_where_the_text_never_says_unit():
    chain = ("$$\n\\|\\mathbf{q}\\| = \\sqrt{q_w^2 + q_x^2 + q_y^2 + q_z^2} = 1\n$$\n\n"
             "$$\n\\|\\mathbf{q}\\| = \\sqrt{q_w^2 + q_x^2 + q_y^2 + q_z^2} = 2\n$$\n")
    unit = HEAD + "The attitude is a unit quaternion $\\mathbf{q}$ with components $q_w, q_x, q_y, q_z$.\n\n" + chain
    one, two = _lines(unit, "= 1\n"), _lines(unit, "= 2\n")
    assert one == [{"holds"}] and two == [{"fails"}]
    plain = HEAD + "The attitude is a quaternion $\\mathbf{q}$ with components $q_w, q_x, q_y, q_z$.\n\n" + chain
    assert not _lines(plain, "= 1\n")[0] & {"typo", "fails"}


def test_a_body_rate_q_under_d_dt_after_a_moment_is_no_quaternion_rate():
    # p, q, r the body rates beside the attitude quaternion q_0 … q_3: I_yy dq/dt in Euler's equations is the
    # pitch rate's rate, as I_yy \dot{q} is, never a quaternion's (whose component check would flag it)
    text = HEAD + ("The attitude is a unit quaternion with components $q_0, q_1, q_2, q_3$; the body rates are "
                   "$p$, $q$, $r$ about the body axes and the moments about them are $L$, $M$, $N$.\n\n"
                   "$$\n\\mathbf{q} = q_0 + q_1 i + q_2 j + q_3 k = [q_0, q_1, q_2, q_3]^\\top\n$$\n\n"
                   "$$\n\\begin{align}\nI_{xx}\\frac{d p}{d t} + (I_{zz} - I_{yy})qr &= L \\\\\n"
                   "I_{yy}\\frac{d q}{d t} + (I_{xx} - I_{zz})pr &= M \\\\\n"
                   "I_{zz}\\frac{d r}{d t} + (I_{yy} - I_{xx})pq &= N\n\\end{align}\n$$\n")
    (euler,) = _lines(text, "I_{yy}\\frac{d q}")
    assert not euler & {"typo", "fails"}
