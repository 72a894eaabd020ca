"""The notes reader on an ``array`` used to align a chain (the display's body, as MathJax texts
write it), and on a body turning about a fixed axis (𝛚 = ω k̂, L_z = ω Σ mᵢ rᵢ²)."""
import kept_readings as kept
from derive.lecture import alignment_arrays
from derive.lecture.statements import statements


def verdicts(text):
    return [(c.line, c.verdict) for c in kept.check_text(text)]


_CHAIN = (r"\begin{equation}" "\n" r"\begin{array}{ll}" "\n"
          r"T & = \frac{1}{2} I_1 \omega_1^2 + \frac{1}{2} I_2 \omega_2^2 + \frac{1}{2} I_3 \omega_3^2 \\" "\n"
          r"\\" "\n"
          r"& = \frac{1}{2} (I_1 \omega_1^2 + I_2 \omega_2^2 + I_3 \omega_3^2)" "\n"
          r"\end{array}" "\n" r"\end{equation}")


def test_an_array_that_is_the_body_of_a_display_and_states_a_relation_is_cut_into_rows():
    rows = statements(_CHAIN)
    assert [r.split()[0] for r in rows] == ["T", "="]          # the rows, the chain's second going on with "="
    assert "&" not in "".join(rows) and "array" not in "".join(rows)
    assert set(verdicts(f"# Energy\n\n{_CHAIN}\n")) == {(3, "holds")}


def test_an_array_in_brackets_or_without_a_relation_stays_as_written():
    matrix = r"A = \left[\begin{array}{cc} 1 & 0 \\ 0 & 1 \end{array}\right]"
    names = r"\begin{array}{ll} xyz \quad xzy \\ zxz \quad zyz \end{array}"
    assert alignment_arrays.unwrapped(matrix) == matrix
    assert alignment_arrays.unwrapped(names) == names


_SETUP = "# Fixed axis\n\nThe body turns about the fixed $z$ axis.\n\n$$\\vec \\omega = \\omega \\hat k$$\n"


def test_an_angular_velocity_set_along_a_unit_vector_is_the_texts_set_up_not_a_claim():
    claims = kept.check_text(_SETUP)
    assert [(c.line, c.verdict) for c in claims] == [(5, "unchecked")]
    assert "fixed axis" in claims[0].why


def test_an_angular_velocity_set_along_a_unit_vector_with_a_centred_dot_is_the_same_set_up():
    # a scalar rate times a unit vector written with a product sign, as texts that write every product so do
    text = _SETUP.replace("\\omega \\hat k", "\\omega \\cdot \\hat k")
    claims = kept.check_text(text)
    assert [(c.line, c.verdict) for c in claims] == [(5, "unchecked")]
    assert "fixed axis" in claims[0].why
    both = "# Fixed axis\n\n$$\\vec \\omega = \\omega \\cdot \\hat k, \\; \\vec \\alpha = \\alpha \\cdot \\hat k$$\n"
    assert {c.verdict for c in kept.check_text(both)} == {"unchecked"}


def test_a_component_beside_a_plain_omega_reads_the_rotation_about_that_axis_and_r_from_it():
    text = "# Fixed axis\n\n$$L_z = \\omega \\sum_i m_i r_i^2$$\n\n$$L_z = \\omega \\sum_i m_i r_i^3$$\n"
    assert verdicts(text) == [(3, "holds"), (5, "fails")]


_TURNING = "# Fixed axis\n\n$$\\vec \\omega = \\omega \\hat k, \\; \\vec \\alpha = \\alpha \\hat k$$\n\n"


def test_a_chain_headed_by_the_texts_own_vector_checks_the_members_after_it():
    text = _TURNING + ("$$\\vec u_i^t = \\alpha \\hat k \\times \\vec r_i = \\alpha(x_i \\hat j - y_i \\hat i)$$\n\n"
                       "$$\\vec u_i^n = \\omega \\hat k \\times (\\omega \\hat k \\times \\vec r_i) = \\omega^2 (x_i \\hat i + y_i \\hat j)$$\n")
    got = verdicts(text)
    assert (5, "holds") in got and (5, "unchecked") in got      # the head is the text's name, left unchecked
    assert (7, "fails") in got or (7, "typo") in got             # the normal acceleration points to the axis


def test_a_row_that_goes_on_with_equals_continues_its_own_display_not_an_earlier_statement():
    text = _TURNING + ("$$\\vec a_i^t = \\alpha \\hat k \\times \\vec r_i = \\alpha(x_i \\hat j - y_i \\hat i)$$\n\n"
                       "$$\\begin{aligned}\\vec Q_i &= \\vec r_i \\times \\vec P_i \\\\ &= \\alpha x_i \\hat k\\end{aligned}$$\n")
    assert [v for line, v in verdicts(text) if line == 7] == ["unchecked", "unchecked"]


_RX = r"\begin{bmatrix} 1 & 0 & 0 \\ 0 & \cos\alpha & -\sin\alpha \\ 0 & \sin\alpha & \cos\alpha \end{bmatrix}"
_RZ = r"\begin{bmatrix} \cos\gamma & -\sin\gamma & 0 \\ \sin\gamma & \cos\gamma & 0 \\ 0 & 0 & 1 \end{bmatrix}"
_PRODUCT = (r"\begin{bmatrix} \cos\gamma & -\sin\gamma\,\cos\alpha & \sin\gamma\,\sin\alpha \\ \sin\gamma & \cos\gamma\,\cos\alpha & "
            r"-\cos\gamma\,\sin\alpha \\ 0 & \sin\alpha & \cos\alpha \end{bmatrix}")


def _chain(product):
    return (f"# Turns\n\n$$\n\\begin{{aligned}}\n\\mathbf{{Q}} &= \\mathbf{{A}} \\mathbf{{B}} \\\\\n"
            f"&= {_RZ} {_RX} \\\\\n&= {product}\n\\end{{aligned}}\n$$\n")


def test_a_chain_row_the_reader_cannot_compare_with_its_new_name_is_checked_against_the_member_before_it():
    assert (3, "holds") in verdicts(_chain(_PRODUCT))
    slipped = _PRODUCT.replace(r"\sin\gamma\,\sin\alpha \\", r"-\sin\gamma\,\sin\alpha \\", 1)
    assert slipped != _PRODUCT
    assert any(v in ("typo", "fails") for line, v in verdicts(_chain(slipped)))


def test_a_link_between_vectors_that_would_flag_stays_unchecked():
    text = ("# Sums\n\n$$\n\\begin{aligned}\n\\vec L_z &= \\sum_i \\vec r_i \\times m_i \\vec v_i \\\\\n"
            "&= \\sum_i m_i \\vec\\omega (\\vec r_i \\cdot \\vec r_i) - \\sum_i m_i \\vec r_i (\\vec r_i \\cdot \\vec\\omega) \\\\\n"
            "&= \\vec\\omega \\sum_i m_i r_i^2\n\\end{aligned}\n$$\n")
    assert not any(v in ("typo", "fails") for line, v in verdicts(text))


_TANGENTIAL = "$$\\vec u_i^t = \\alpha \\hat k \\times \\vec r_i = \\alpha(x_i \\hat j - y_i \\hat i)$$\n\n"
_NORMAL = "$$\\vec u_i^t = \\omega \\hat k \\times (\\omega \\hat k \\times \\vec r_i) = -\\omega^2 (x_i \\hat i + y_i \\hat j)$$\n"


def test_a_name_a_holding_chain_gave_heading_another_chain_in_its_section_is_compared_with_that_value():
    got = verdicts(_TURNING + _TANGENTIAL + _NORMAL)
    assert (7, "fails") in got and (7, "holds") in got        # the label slipped; the chain itself holds
    assert [v for line, v in verdicts(_TURNING + _TANGENTIAL + _TANGENTIAL.replace("t =", "t = 1 \\cdot", 1))
            if line == 7 and v in ("typo", "fails")] == []


def test_a_name_heading_a_chain_in_another_section_is_not_compared_with_an_earlier_sections_value():
    text = _TURNING + _TANGENTIAL + "## Another example\n\n" + _NORMAL
    assert not any(v in ("typo", "fails") for line, v in verdicts(text))


_FORCE_ROW = r"m_i (\alpha y_i + \omega^2 x_i) & m_i (-\alpha x_i + \omega^2 y_i) & 0"
_DET = r"\det \begin{bmatrix} \hat i & \hat j & \hat k \\ x_i & y_i & z_i \\ " + _FORCE_ROW + r" \end{bmatrix}"
_MOMENT = (r"m_i [(\alpha x_i z_i - \omega^2 y_i z_i) \hat i + (\alpha y_i z_i + \omega^2 x_i z_i) \hat j "
           r"- \alpha (x_i^2 + y_i^2) \hat k ]")


def test_det_before_a_bracketed_matrix_is_its_determinant_along_the_row_of_unit_vectors():
    text = _TURNING + f"$$\\vec M_i = {_DET} = {_MOMENT}$$\n"
    assert (5, "holds") in verdicts(text)
    slipped = _MOMENT.replace(r"- \omega^2 y_i z_i", r"+ \omega^2 y_i z_i", 1)
    assert any(v in ("typo", "fails") for line, v in verdicts(_TURNING + f"$$\\vec M_i = {_DET} = {slipped}$$\n"))


def test_a_member_in_the_texts_own_vectors_stays_with_the_head_and_the_members_after_it_are_checked():
    text = _TURNING + f"$$\\vec M_i = \\vec r_i \\times \\vec F_i = {_DET} = {_MOMENT}$$\n"
    got = verdicts(text)
    assert (5, "holds") in got and (5, "unchecked") in got
    slipped = _MOMENT.replace(r"- \alpha (x_i^2", r"+ \alpha (x_i^2", 1)
    got = verdicts(_TURNING + f"$$\\vec M_i = \\vec r_i \\times \\vec F_i = {_DET} = {slipped}$$\n")
    assert any(v in ("typo", "fails") for line, v in got)


def test_a_row_after_a_chain_headed_by_the_texts_own_name_is_checked_against_the_row_before_it():
    text = _TURNING + ("$$\\begin{aligned}\\vec M_{O,i} &= \\vec r_i \\times \\vec F_i = " + _DET +
                       " \\\\\n&= " + _MOMENT + "\\end{aligned}$$\n")
    assert (5, "holds") in verdicts(text)
    slipped = text.replace(r"- \alpha (x_i^2", r"+ \alpha (x_i^2", 1)
    assert not any(v in ("typo", "fails") for line, v in verdicts(slipped))    # a link between vectors never flags


def flagged(text, at):
    """Whether the reader flags (typo or fails) a statement on line ``at`` of ``text``."""
    return any(v in ("typo", "fails") for line, v in verdicts(text) if line == at)


_NAMED_AT_END = "# Fixed axis\n\nA body turns about the fixed $z$ axis.\n\n$$L_z = \\omega \\sum_i m_i r_i^2 = J_z \\omega$$\n\n"
_RATE = r"\frac{\mathrm d \omega}{\mathrm d t}"


def test_a_name_defined_at_a_chains_end_is_read_as_that_definition_in_a_later_statement_in_sums():
    holds = _NAMED_AT_END + f"$$\\frac{{\\mathrm d L_z}}{{\\mathrm d t}} = J_z {_RATE}$$\n"
    assert (7, "holds") in verdicts(holds)
    doubled = _NAMED_AT_END + f"$$\\frac{{\\mathrm d L_z}}{{\\mathrm d t}} = 2 J_z {_RATE}$$\n"
    assert flagged(doubled, 7)
    same_line = verdicts(_NAMED_AT_END)
    assert not any(v in ("typo", "fails") for line, v in same_line)        # its own display is its definition


def test_the_rate_of_a_plain_omega_implies_the_fixed_axis_as_a_plain_omega_does():
    text = _NAMED_AT_END + f"$$\\frac{{\\mathrm d L_z}}{{\\mathrm d t}} = \\sum_i m_i r_i^2 {_RATE}$$\n"
    assert (7, "holds") in verdicts(text)
    assert flagged(text.replace("r_i^2 \\frac", "r_i^3 \\frac"), 7)


def test_a_points_acceleration_and_its_tangential_and_normal_parts_are_read_by_their_labels():
    sum_of_parts = _TURNING + "$$\\vec a_i = \\vec a_i^t + \\vec a_i^n$$\n"
    assert (5, "holds") in verdicts(sum_of_parts)
    tangential = _TURNING + "$$\\vec a_i^t = \\alpha \\hat k \\times \\vec r_i = \\alpha(x_i \\hat j - y_i \\hat i)$$\n"
    assert [v for line, v in verdicts(tangential) if line == 5] == ["holds", "holds"]
    normal_for_tangential = _TURNING + "$$\\vec a_i^t = \\omega \\hat k \\times (\\omega \\hat k \\times \\vec r_i)$$\n"
    assert flagged(normal_for_tangential, 5)
    assert (5, "holds") in verdicts(normal_for_tangential.replace("a_i^t", "a_i^n"))


_PRODUCTS = ("$$\\begin{aligned} J_{yz} = J_{zy} &= \\sum_i m_i y_i z_i \\\\ J_{zx} = J_{xz} &= \\sum_i m_i z_i x_i "
             "\\end{aligned}$$\n\n")
_SUMMED = ("$$\\vec M_{I} = \\sum_i m_i[(\\alpha x_i z_i - \\omega^2 y_i z_i) \\hat i + "
           "(\\alpha y_i z_i + \\omega^2 x_i z_i) \\hat j]$$\n\n")
_IN_PRODUCTS = "$$\\vec M_{I} = (J_{xz} \\alpha - J_{yz} \\omega^2) \\hat i + (J_{yz} \\alpha + J_{xz} \\omega^2) \\hat j$$\n"


def test_the_texts_vector_set_again_holds_when_both_expressions_agree_with_its_names_put_in():
    got = verdicts(_TURNING + _PRODUCTS + _SUMMED + _IN_PRODUCTS)
    assert (7, "unchecked") in got and (9, "holds") in got       # J_zx = J_xz named together; M_O recorded, then met
    slipped = _IN_PRODUCTS.replace("J_{yz} \\alpha + J_{xz}", "J_{yz} \\alpha - J_{xz}", 1)
    got = verdicts(_TURNING + _PRODUCTS + _SUMMED + slipped)
    assert [v for line, v in got if line == 9] == ["unchecked"]    # either expression may be the one meant


def test_an_equivalence_between_two_statements_is_cut_into_each_statement():
    assert [r.strip() for r in statements(r"a = b \iff c = d")] == ["a = b", "c = d"]
    assert [r.strip() for r in statements(r"a = b \Leftrightarrow c = d")] == ["a = b", "c = d"]


_TORQUES = r"\sum_{i=1}^n M_z (\vec F_i)"


def test_the_moment_of_a_force_about_an_axis_is_the_component_of_r_cross_f_and_a_plain_alpha_implies_the_axis():
    holds = _NAMED_AT_END + f"$$J_z \\alpha = {_TORQUES}$$\n"
    assert (7, "holds") in verdicts(holds)
    doubled = _NAMED_AT_END + f"$$2 J_z \\alpha = {_TORQUES}$$\n"
    assert flagged(doubled, 7)
    rate = _NAMED_AT_END + f"$$\\frac{{\\mathrm d L_z}}{{\\mathrm d t}} = {_TORQUES}$$\n"
    assert (7, "holds") in verdicts(rate)


def test_the_moment_of_a_force_in_sized_brackets_is_the_moment_applied_to_the_force_not_a_product():
    for opened, closed in (("\\left(", "\\right)"), ("\\bigl(", "\\bigr)")):
        torques = _TORQUES.replace("(", opened).replace(")", closed)
        assert (7, "holds") in verdicts(_NAMED_AT_END + f"$$J_z \\alpha = {torques}$$\n")
        assert flagged(_NAMED_AT_END + f"$$2 J_z \\alpha = {torques}$$\n", 7)


_PLANE = "# Plane motion\n\n"


def test_points_named_by_letters_move_with_the_body_and_a_relation_for_every_motion_of_them_holds():
    velocities = _PLANE + "$$\\vec v_B = \\vec v_A + \\vec v_{BA} = \\vec v_A + \\vec \\omega \\times \\vec r_{AB}$$\n"
    assert [v for line, v in verdicts(velocities) if line == 3] == ["holds", "holds"]
    parts = _PLANE + ("$$\\vec a_{BA}^t = \\vec \\alpha \\times \\vec r_{AB}, \\; "
                      "\\vec a_{BA}^n = \\vec \\omega \\times (\\vec \\omega \\times \\vec r_{AB})$$\n")
    assert [v for line, v in verdicts(parts) if line == 3] == ["holds", "holds"]
    swapped = velocities.replace("\\vec \\omega \\times \\vec r_{AB}", "\\vec r_{AB} \\times \\vec \\omega")
    assert [v for line, v in verdicts(swapped) if line == 3] == ["holds", "unchecked"]


def test_a_relation_of_lettered_points_that_rests_on_the_texts_choice_of_them_is_never_flagged():
    centre = _PLANE + "$$\\vec v_B = \\vec \\omega \\times \\vec r_{AB}$$\n"       # A an instantaneous centre
    at_rest = _PLANE + "$$\\vec v_P = 0$$\n"                                     # a rolling contact
    same = _PLANE + "$$\\vec v_A = \\vec v_B$$\n"                                # a translation
    for text in (centre, at_rest, same):
        assert not any(v in ("typo", "fails") for line, v in verdicts(text)), text
