"""Conventions of writing that real texts use: a fenced ``math`` block is a display, an inertia matrix
with −I_xy off its diagonal names the products of inertia +∫xy dm, and a chain of principal moments
with a numeric factor (I₁ = I₂ = 2I₃) is an assumption like I₁ = I₂ = I₃; Newton's law and Euler's equation written with frame
derivatives (d𝐕/dt_i, I_b d𝛚_b/dt_b) and a vector the prose calls the angular momentum (𝐇 = I𝛚)."""
import re

import pytest

import kept_readings as kept


def verdicts(text):
    return [(c.line, c.verdict) for c in kept.check_text(text)]


T = "T = \\frac{1}{2} I_1 \\omega_1^2 + \\frac{1}{2} I_2 \\omega_2^2 + \\frac{1}{2} I_3 \\omega_3^2"


def test_a_fenced_math_block_is_a_display_and_other_fences_are_not():
    text = f"# Notes\n\n```math\n{T}\n```\n\n```python\n$${T} + 1$$\n```\n"
    assert verdicts(text) == [(3, "holds")]


def test_a_slip_in_a_fenced_math_block_is_flagged():
    text = "# Notes\n\n```math\nT = \\frac{1}{2} I_1 \\omega_1^2 + \\frac{1}{2} I_2 \\omega_2^2 + I_3 \\omega_3^2\n```\n"
    assert {v for _, v in verdicts(text)} <= {"typo", "fails"} and verdicts(text)


_TENSOR = ("\\begin{{bmatrix}} I_{{xx}} & {s}I_{{xy}} & {s}I_{{xz}} \\\\ {s}I_{{xy}} & I_{{yy}} & {s}I_{{yz}} \\\\ "
           "{s}I_{{xz}} & {s}I_{{yz}} & I_{{zz}} \\end{{bmatrix}}")
_HEAD = "A body of point masses turns with $\\boldsymbol{\\omega}$; its inertia tensor:\n\n"


def test_an_inertia_matrix_with_minus_products_names_the_products_of_inertia():
    text = _HEAD + "$$\nI = " + _TENSOR.format(s="-") + "\n$$\n"
    assert [v for _, v in verdicts(text)] == ["holds"]


def test_an_inertia_matrix_with_minus_products_indexed_upright_names_the_products_of_inertia():
    for upright in ("I_\\text{{{0}}}", "I_{{\\mathrm{{{0}}}}}"):
        tensor = re.sub(r"I_\{\{(\w\w)\}\}", lambda m: upright.format(m[1]).replace("{", "{{").replace("}", "}}"), _TENSOR)
        assert tensor != _TENSOR
        assert [v for _, v in verdicts(_HEAD + "$$\nI = " + tensor.format(s="-") + "\n$$\n")] == ["holds"]


def test_an_inertia_matrix_with_plus_entries_keeps_the_tensors_own_entries():
    text = _HEAD + "$$\nI = " + _TENSOR.format(s="") + "\n$$\n"
    assert [v for _, v in verdicts(text)] == ["holds"]


def test_products_of_inertia_set_to_zero_are_an_assumption_never_a_failed_claim():
    text = (_HEAD + "$$\nI = " + _TENSOR.format(s="-") + "\n$$\n\nand the products of inertia, for example\n\n"
            "$$\nI_{xy} = \\int xy dm\n$$\n\nThe body is symmetric, so usually $I_{xy} = I_{yz} = 0$.\n")
    claims = kept.check_text(text)
    assert [(c.kind, c.verdict) for c in claims if c.line == 13] == [("assumption", "unchecked")]
    assert [c.verdict for c in claims if c.line != 13] == ["holds", "holds"]


def test_moments_in_a_ratio_are_an_assumption_for_the_equations_after_them():
    text = ("# Case\n\nThe principal moments satisfy $I_1 = I_2 = 2I_3$. Then\n\n"
            "$$\n2\\dot{\\omega}_1 - \\omega_2 \\omega_3 = 0\n$$\n")
    assert (5, "holds") in verdicts(text) and not [v for _, v in verdicts(text) if v in ("typo", "fails")]


_PRECESSION = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Top\n\n"
               "The top precesses regularly: the nutation angle stays $\\theta = \\theta_0$, and the precession "
               "rate $\\dot\\phi = \\omega_p$ and the spin rate $\\dot\\psi = \\omega_s$ are constant. Then\n\n$$\n{}\n$$\n")


def test_what_the_angles_and_rates_the_text_set_give_holds():
    for claim in ("\\omega_1=\\omega_p\\sin\\theta_0\\sin\\psi", "\\omega_3=\\omega_p\\cos\\theta_0+\\omega_s"):
        assert verdicts(_PRECESSION.format(claim))[-1] == (9, "holds")


def test_a_component_the_settings_do_not_give_is_never_judged_from_them():
    out = verdicts(_PRECESSION.format("\\omega_1=\\omega_p\\sin\\theta_0\\cos\\psi"))
    assert out[-1][0] == 9 and out[-1][1] == "unchecked"


def test_a_torque_term_of_the_texts_own_symbol_with_a_coefficient_is_the_torque():
    head = "# Case\n\nThe principal moments satisfy $I_1 = I_2 = 2I_3$. Then\n\n$$\n{}\n$$\n"
    assert verdicts(head.format("2\\dot{\\omega}_2 + \\omega_3 \\omega_1 = \\kappa\\cos\\beta"))[-1] == (5, "holds")
    assert verdicts(head.format("2\\dot{\\omega}_2 - \\omega_3 \\omega_1 = \\kappa\\cos\\beta"))[-1][1] in ("typo", "fails")


_AIRCRAFT = ("---\nconvention: z-y-x\nangles: [\\psi, \\theta, \\phi]\n---\n# Rates\n\n"
             "The velocities are body-frame; $p, q, r$ are the roll, pitch and yaw rates. The result:\n\n$$\n"
             "\\begin{{bmatrix}} \\dot{{\\phi}} \\\\ \\dot{{\\theta}} \\\\ \\dot{{\\psi}} \\end{{bmatrix}} = "
             "\\begin{{bmatrix}} 1 & \\sin\\phi\\tan\\theta & \\cos\\phi\\tan\\theta \\\\ 0 & \\cos\\phi & {s}\\sin\\phi \\\\ "
             "0 & \\sin\\phi/\\cos\\theta & \\cos\\phi/\\cos\\theta \\end{{bmatrix}} "
             "\\begin{{bmatrix}} p \\\\ q \\\\ r \\end{{bmatrix}}\n$$\n")


def test_the_roll_pitch_and_yaw_rates_p_q_r_are_the_body_angular_velocity():
    assert verdicts(_AIRCRAFT.format(s="-")) == [(9, "holds")]


def test_a_slip_read_only_through_the_rates_names_is_never_called_correct():
    assert verdicts(_AIRCRAFT.format(s=""))[-1][1] != "holds"


_FRAMES = "---\nconvention: z-y-x\nangles: [\\psi, \\theta, \\phi]\n---\n# Frames\n\nFor any vector:\n\n$$\nBODY\n$$\n"
_TRANSPORT = ("\\left.\\frac{d \\vec{v}}{dt}\\right|_i = \\left.\\frac{d \\vec{v}}{dt}\\right|_b "
              "SIGN \\vec{\\omega}_{b/i} \\times \\vec{v}")


def test_the_transport_theorem_for_a_vector_of_the_texts_holds_in_its_frame_notation():
    assert verdicts(_FRAMES.replace("BODY", _TRANSPORT.replace("SIGN", "+"))) == [(9, "holds")]


def test_frame_derivatives_with_an_upright_d_read_as_with_an_italic_one():
    upright = _TRANSPORT.replace("{d \\vec{v}}{dt}", "{\\mathrm{d}\\, \\vec{v}}{\\mathrm{d}t}")
    assert upright != _TRANSPORT
    assert verdicts(_FRAMES.replace("BODY", upright.replace("SIGN", "+"))) == [(9, "holds")]
    assert verdicts(_FRAMES.replace("BODY", upright.replace("SIGN", "-")))[-1][1] in ("typo", "fails")
    law = "\\vec{F} = m \\frac{\\mathrm{d} \\vec{V}}{\\mathrm{d}t_i}"
    assert verdicts(_FRAMES.replace("BODY", law)) == [(9, "holds")]


def test_the_transport_theorem_with_a_wrong_sign_is_flagged():
    assert verdicts(_FRAMES.replace("BODY", _TRANSPORT.replace("SIGN", "-")))[-1][1] in ("typo", "fails")


def test_a_vector_the_text_defines_is_read_with_its_definition_later():
    law = "\\vec{F} = m \\frac{d \\vec{V}}{dt_i}"
    body = "\\vec{F_b} = m \\left( \\frac{d\\vec{V_b}}{dt_b} SIGN \\vec{\\omega_b} \\times \\vec{V_b} \\right)"
    text = _FRAMES.replace("BODY", law) + "\nand in the body frame\n\n$$\nLATER\n$$\n"
    assert verdicts(text.replace("LATER", body.replace("SIGN", "+"))) == [(9, "holds"), (15, "holds")]
    assert verdicts(text.replace("LATER", body.replace("SIGN", "-")))[-1][1] in ("typo", "fails")


def test_newtons_law_with_the_inertial_derivative_is_a_law_the_reader_recognises():
    assert verdicts(_FRAMES.replace("BODY", "\\vec{F} = m \\frac{d \\vec{V}}{dt_i}")) == [(9, "holds")]


def test_newtons_law_with_a_body_frame_derivative_or_another_factor_is_flagged():
    for slip in ("\\vec{F} = m \\frac{d \\vec{V}}{dt_b}", "\\vec{F} = 2 m \\frac{d \\vec{V}}{dt_i}"):
        assert verdicts(_FRAMES.replace("BODY", slip)) == [(9, "fails")]


def test_vectors_of_the_text_that_nothing_ties_are_never_judged():
    text = _FRAMES.replace("BODY", "\\vec{M} = \\frac{d\\vec{H}}{dt_b} + \\vec{\\omega} \\times \\vec{G}")
    assert [v for _, v in verdicts(text)] == ["unchecked"]


_POISSON = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Heavy body\n\n"
            "Let $\\gamma_1, \\gamma_2, \\gamma_3$ be the body-frame components of the unit vector $\\mathbf{n}$ "
            "of the vertical. Then\n\n$$\n\\gamma_1=\\sin\\theta\\sin\\psi,\\quad \\gamma_2=\\sin\\theta\\cos\\psi,"
            "\\quad \\gamma_3=\\cos\\theta\n$$\n")


def test_the_components_of_the_vertical_unit_vector_are_poissons_gamma():
    assert verdicts(_POISSON) == [(9, "holds")] * 3


def test_a_wrong_component_of_the_vertical_is_never_called_correct():
    assert verdicts(_POISSON.replace("\\gamma_2=\\sin\\theta\\cos\\psi", "\\gamma_2=\\sin\\theta\\sin\\psi"))[1][1] != "holds"


def test_poissons_equation_with_the_relative_derivative_holds_and_a_wrong_sign_is_flagged():
    poisson = ("\\frac{\\tilde{\\mathrm{d}} \\mathbf{n}}{\\mathrm{d} t} SIGN \\boldsymbol{\\omega}\\times \\mathbf{n}"
               "=\\mathbf{0}")
    text = _POISSON.split("Then")[0] + "Then\n\n$$\nBODY\n$$\n"
    assert verdicts(text.replace("BODY", poisson.replace("SIGN", "+"))) == [(9, "holds")]
    assert verdicts(text.replace("BODY", poisson.replace("SIGN", "-")))[-1][1] in ("typo", "fails")


def test_poissons_equation_with_a_thin_space_after_its_differentials_holds_and_a_wrong_sign_is_flagged():
    poisson = ("\\frac{\\tilde{\\mathrm{d}} \\, \\mathbf{n}}{\\mathrm{d} \\, t} SIGN \\boldsymbol{\\omega}\\times \\mathbf{n}"
               "=\\mathbf{0}")
    text = _POISSON.split("Then")[0] + "Then\n\n$$\nBODY\n$$\n"
    assert verdicts(text.replace("BODY", poisson.replace("SIGN", "+"))) == [(9, "holds")]
    assert verdicts(text.replace("BODY", poisson.replace("SIGN", "-")))[-1][1] in ("typo", "fails")


def test_a_relation_typed_as_a_plus_sign_is_a_typo_corrected_in_the_texts_latex():
    out = kept.check_text(_FRAMES.replace("BODY", _TRANSPORT.replace("SIGN", "+").replace(" = ", " + ", 1)))
    assert [(c.line, c.verdict) for c in out] == [(9, "typo")]
    assert out[0].correction.startswith("\\left.\\frac{d \\vec{v}}{dt}\\right|_i = \\left.\\frac")


def test_a_sum_of_vectors_that_no_single_relation_makes_hold_is_no_claim():
    text = _FRAMES.replace("BODY", "\\left.\\frac{d \\vec{v}}{dt}\\right|_i + \\vec{\\omega} \\times \\vec{v}")
    assert verdicts(text) == [(9, "unchecked")]


_MOMENT = ("---\nconvention: z-y-x\nangles: [\\psi, \\theta, \\phi]\n---\n# Rotation\n\nThe moment is the inertial "
           "rate of change of the angular momentum:\n\n$$\n\\vec{M} = \\frac{d\\vec{H}}{dt_i}\n$$\n\nThe angular momentum is "
           "the inertia tensor times the angular velocity, in body components:\n\n$$\n\\vec{H_b} = I_b \\vec{\\omega_b}\n$$\n"
           "\nwith the inertia tensor constant in the body frame, so\n\n$$\nLATER\n$$\n")
_EULER = "\\vec{M_b} = I_b \\frac{d\\vec{\\omega_b}}{dt_b} SIGN \\vec{\\omega_b} \\times I_b \\vec{\\omega_b}"
_SOLVED = "\\frac{d\\vec{\\omega_b}}{dt_b} = I_b^{-1} \\left(\\vec{M_b} SIGN \\vec{\\omega_b} \\times I_b \\vec{\\omega_b} \\right)"


def test_eulers_equation_with_the_inertia_tensor_and_frame_derivatives_holds():
    assert verdicts(_MOMENT.replace("LATER", _EULER.replace("SIGN", "+")))[-1] == (21, "holds")


def test_eulers_equation_in_tensor_form_with_a_slip_is_flagged():
    for slip in (_EULER.replace("SIGN", "-"), "\\vec{M_b} = I_b \\frac{d\\vec{\\omega_b}}{dt_b}"):
        assert verdicts(_MOMENT.replace("LATER", slip))[-1][1] in ("typo", "fails")


@pytest.mark.slow
def test_eulers_equation_solved_with_the_inverse_tensor_holds_and_a_slip_is_flagged():
    assert verdicts(_MOMENT.replace("LATER", _SOLVED.replace("SIGN", "-")))[-1] == (21, "holds")
    assert verdicts(_MOMENT.replace("LATER", _SOLVED.replace("SIGN", "+")))[-1][1] in ("typo", "fails")


def test_eulers_equation_for_a_vector_the_text_never_names_the_angular_momentum_is_not_judged():
    text = _MOMENT.replace("The angular momentum is the inertia tensor times", "Also, take")
    assert verdicts(text.replace("LATER", _EULER.replace("SIGN", "+")))[-1][1] == "unchecked"


_NAMED = (_HEAD + "$$\nI = " + _TENSOR.format(s="-") + "\n$$\n\nThe angular momentum is the inertia tensor times the "
          "angular velocity:\n\n$$\n\\vec{H} = RIGHT\n$$\n")


def test_a_display_the_prose_calls_the_angular_momentum_names_its_letter_so_h_equals_i_omega_holds():
    assert verdicts(_NAMED.replace("RIGHT", "I \\vec{\\omega}")) == [(3, "holds"), (9, "holds")]
    assert verdicts(_NAMED.replace("RIGHT", "I_b \\vec{\\omega_b}").replace("\\vec{H}", "\\vec{H_b}"))[-1] == (9, "holds")


def test_h_equal_to_a_wrong_product_is_flagged():
    for slip in ("2 I \\vec{\\omega}", "\\vec{\\omega} \\times I \\vec{\\omega}"):
        assert verdicts(_NAMED.replace("RIGHT", slip))[-1][1] in ("typo", "fails")


_R_TO_BODY = ("\\begin{bmatrix} \\cos\\theta\\cos\\psi & \\cos\\theta\\sin\\psi & -\\sin\\theta \\\\ \\sin\\phi\\sin\\theta"
              "\\cos\\psi - \\cos\\phi\\sin\\psi & \\sin\\phi\\sin\\theta\\sin\\psi + \\cos\\phi\\cos\\psi & \\sin\\phi\\cos\\theta"
              " \\\\ \\cos\\phi\\sin\\theta\\cos\\psi + \\sin\\phi\\sin\\psi & \\cos\\phi\\sin\\theta\\sin\\psi - \\sin\\phi"
              "\\cos\\psi & \\cos\\phi\\cos\\theta \\end{bmatrix}")
_GRAVITY = ("---\nconvention: z-y-x\nangles: [\\psi, \\theta, \\phi]\n---\n# Gravity\n\nThe inertial frame is FRAME. "
            "From inertial to body coordinates:\n\n$$\nR_{i \\rightarrow b} = " + _R_TO_BODY + "\n$$\n\nand back, "
            "$R_{b \\rightarrow i} = R_{i \\rightarrow b}^T$. Gravity in body components:\n\n$$\nF_g = WEIGHT\n$$\n")


def test_the_weight_rotated_into_body_axes_holds_with_the_down_axis_the_prose_gives():
    ned = _GRAVITY.replace("FRAME", "north-east-down")
    assert verdicts(ned.replace("WEIGHT", "R_{i \\rightarrow b} [0, 0, mg]^T"))[-1] == (15, "holds")
    up = _GRAVITY.replace("FRAME", "fixed to the ground with $z$ up")
    assert verdicts(up.replace("WEIGHT", "R_{i \\rightarrow b} [0, 0, -mg]^T"))[-1] == (15, "holds")


def test_the_weight_with_the_wrong_sign_or_rotated_the_wrong_way_fails():
    ned = _GRAVITY.replace("FRAME", "north-east-down")
    for slip in ("R_{i \\rightarrow b} [0, 0, -mg]^T", "R_{b \\rightarrow i} [0, 0, mg]^T"):
        assert verdicts(ned.replace("WEIGHT", slip))[-1] == (15, "fails")


def test_the_weight_in_a_frame_whose_vertical_the_text_never_gives_is_not_judged():
    text = _GRAVITY.replace("FRAME", "fixed to the ground").replace("WEIGHT", "R_{i \\rightarrow b} [0, 0, mg]^T")
    assert verdicts(text)[-1] == (15, "unchecked")


_POSITION = _GRAVITY.replace("FRAME", "north-east-down").replace(
    "Gravity in body components:\n\n$$\nF_g = WEIGHT\n$$\n",
    "The position changes with the velocity $\\vec{V_b}$, given in the body frame:\n\n$$\n"
    "\\frac{d \\vec{r_i}}{dt} = MATRIX \\vec{V_b}\n$$\n")


def test_the_position_rate_is_the_body_velocity_turned_into_inertial_components():
    assert verdicts(_POSITION.replace("MATRIX", "R_{b \\rightarrow i}"))[-1] == (15, "holds")


def test_the_position_rate_with_the_velocity_turned_the_wrong_way_fails():
    assert verdicts(_POSITION.replace("MATRIX", "R_{i \\rightarrow b}"))[-1] == (15, "fails")


def test_the_position_rate_with_an_upright_d_reads_as_with_an_italic_one():
    upright = _POSITION.replace("\\frac{d \\vec{r_i}}{dt}", "\\frac{\\mathrm{d} \\vec{r_i}}{\\mathrm{d}t}")
    assert upright != _POSITION
    assert verdicts(upright.replace("MATRIX", "R_{b \\rightarrow i}"))[-1] == (15, "holds")
    assert verdicts(upright.replace("MATRIX", "R_{i \\rightarrow b}"))[-1] == (15, "fails")


def test_the_position_rate_with_spacing_between_the_matrix_and_the_velocity_reads_the_same():
    spaced = _POSITION.replace("MATRIX \\vec{V_b}", "MATRIX \\, \\vec{V_b}")
    assert spaced != _POSITION
    assert verdicts(spaced.replace("MATRIX", "R_{b \\rightarrow \\, i}"))[-1] == (15, "holds")
    assert verdicts(spaced.replace("MATRIX", "R_{i \\rightarrow b}"))[-1] == (15, "fails")


def test_a_myst_math_directive_is_a_display_its_options_dropped():
    text = f"# Notes\n\n```{{math}}\n:label: eq-energy\n{T}\n```\n"
    assert verdicts(text) == [(3, "holds")]


def test_a_myst_math_directive_indented_in_a_list_item_is_a_display():
    text = f"# Notes\n\n- The energy:\n\n    ```{{math}}\n    {T}\n    ```\n"
    assert verdicts(text) == [(5, "holds")]


_SIX = ("\\begin{align*}\n\\dot{\\mathbf{p}}^N &= \\mathbf{R}_{BN}^T(\\mathbf{q}) \\mathbf{v}^B \\\\\n"
        "\\dot{\\mathbf{v}}^B &= \\frac{1}{m}\\mathbf{F}^B - \\boldsymbol{\\omega}^B \\times \\mathbf{v}^B\n\\end{align*}")
_MASS_RATE = ("\\frac{d}{dt}(m \\mathbf{v}^B) = \\mathbf{F}^B\n"
              "\\implies m \\dot{\\mathbf{v}}^B + \\dot{m} \\mathbf{v}^B = \\mathbf{F}^B")


def test_a_bold_p_the_prose_calls_a_position_is_not_taken_for_a_momentum():
    text = ("# Motion\n\nThe equations of motion are\n\n$$\n" + _SIX + "\n$$\n\nThe mass rate enters through the rate "
            "of the linear momentum,\n\n$$\n" + _MASS_RATE + "\n$$\n\nThe body's state is its position $\\mathbf{p}^E$ "
            "and its velocity $\\mathbf{v}^E$ in the frame E. Then\n\n$$\n\\dot{\\mathbf{p}}^E = \\mathbf{v}^E\n$$\n")
    assert ("holds" in [v for line, v in verdicts(text) if line == 14]
            and [v for line, v in verdicts(text) if line == 21] == ["unchecked"])


_Z = "\\begin{bmatrix} \\cos\\psi & -\\sin\\psi & 0 \\\\ \\sin\\psi & \\cos\\psi & 0 \\\\ 0 & 0 & 1 \\end{bmatrix}"
_Y = "\\begin{bmatrix} \\cos\\theta & 0 & \\sin\\theta \\\\ 0 & 1 & 0 \\\\ -\\sin\\theta & 0 & \\cos\\theta \\end{bmatrix}"
_X = "\\begin{bmatrix} 1 \\\\ 0 \\\\ 0 \\end{bmatrix}"


def _turned_x(last):
    return ("# Axes\n\nThe turned x axis in the frame I:\n\n$$\n{}_I \\mathbf{e}^x = \\mathbf{C}(\\psi) \\cdot \\mathbf{C}(\\theta) "
            "\\cdot " + _X + " = " + _Z + _Y + _X + " = \\begin{bmatrix} \\cos\\theta\\cos\\psi \\\\ \\cos\\theta\\sin\\psi "
            "\\\\ " + last + " \\end{bmatrix}\n$$\n")


def test_a_frame_index_written_on_the_left_of_a_symbol_in_one_frame_only_is_read_past():
    assert "holds" in {v for _, v in verdicts(_turned_x("-\\sin\\theta"))}
    assert "holds" not in {v for _, v in verdicts(_turned_x("-\\sin\\psi"))}


def test_a_small_space_between_a_left_frame_index_and_its_symbol_changes_nothing():
    spaced = _turned_x("-\\sin\\theta").replace("{}_I \\mathbf", "{}_I \\, \\mathbf")
    assert "holds" in {v for _, v in verdicts(spaced)}


def test_a_symbol_written_in_two_frames_keeps_its_left_indices_and_is_not_read_as_one():
    text = ("# Rates\n\n$$\n{}_I \\mathbf{e}^y = \\begin{bmatrix} 0 \\\\ 1 \\\\ 0 \\end{bmatrix}\n$$\n\n"
            "$$\n{}_B \\mathbf{e}^y = \\begin{bmatrix} 1 \\\\ 0 \\\\ 0 \\end{bmatrix}\n$$\n")
    assert not {v for _, v in verdicts(text)} & {"typo", "fails"}
