"""The notes reader on vector statements written in one frame's components (every vector and tensor
labelled by the frame, 𝛚_B, 𝐈_B, 𝛕_B), on an equation's number written in letters after the
statement (``\\quad~Eq. (1)``), as texts without ``\\tag`` number their rows, and on a dot over a
bold letter written without braces (``\\dot{\\boldsymbol\\omega}``)."""
import kept_readings as kept
from derive.lecture.frame_labels import dropped
from derive.lecture.statements import statements

verdicts, line_of = kept.verdicts_by_line, kept.line_of
HEAD = "# Notes\n\nThe body's angular velocity $\\mathbf\\omega$, its inertia tensor $\\mathbf I$, the torque $\\mathbf\\tau$.\n\n"
BODY = "In the body's components:\n\n"


def test_eulers_equation_in_body_components_labelled_b_holds():
    text = HEAD + BODY + ("$$\\mathbf I_B\\,\\mathbf{\\dot{\\omega}}_B + \\mathbf\\omega_B \\times \\mathbf I_B"
                          "\\,\\mathbf\\omega_B = \\mathbf\\tau_B$$\n")
    assert verdicts(text)[line_of(text, "$$\\mathbf I_B")] == {"holds"}


def test_the_same_equation_with_its_gyroscopic_sign_turned_fails():
    text = HEAD + BODY + ("$$\\mathbf I_b\\,\\mathbf{\\dot{\\omega}}_b - \\mathbf\\omega_b \\times \\mathbf I_b"
                          "\\,\\mathbf\\omega_b = \\mathbf\\tau_b$$\n")
    assert verdicts(text)[line_of(text, "$$\\mathbf I_b")] == {"fails"}


def test_a_rate_of_a_labelled_vector_other_than_the_angular_velocity_keeps_the_label():
    # the rate of L's body components is not the body components of dL/dt: no verdict from dropping B
    assert dropped("\\dot{\\mathbf L}_B = \\boldsymbol\\tau_B + 0\\,\\boldsymbol\\omega_B") is None
    assert dropped("\\frac{d\\mathbf L_B}{dt} = \\boldsymbol\\tau_B + 0\\,\\boldsymbol\\omega_B") is None


def test_mixed_labels_an_unlabelled_vector_or_a_component_index_are_not_a_frame():
    assert dropped("\\mathbf L_B = \\mathbf I_B \\boldsymbol\\omega") is None
    assert dropped("\\mathbf L_B = \\mathbf I_S \\boldsymbol\\omega_B") is None
    assert dropped("\\boldsymbol\\omega_x = \\mathbf r_x") is None
    assert dropped("\\mathbf L_B = \\mathbf R^T \\boldsymbol\\omega_B") is None
    assert dropped("\\mathbf L_B = \\mathbf I_B \\mathbf v_B") is None      # no angular velocity in it


def test_an_equation_number_in_letters_after_a_quad_is_dropped():
    assert statements("\\boxed{\\quad a = b\\quad~Eq. (1)}") == ["\\boxed{\\quad a = b}"]
    assert statements("a = b \\qquad \\text{Eq. (2)}") == ["a = b"]
    assert statements("\\boxed{\\quad a = b\\quad~Eq. \\left(2\\right)}") == ["\\boxed{\\quad a = b}"]


def test_words_that_mention_an_equation_and_a_bracket_after_a_formula_stay():
    assert statements("E = q (1)") == ["E = q (1)"]
    assert [" ".join(s.split()) for s in statements("a = b \\quad,\\text{you obtain Eq. (1)}")] == ["a = b"]


def test_a_boxed_result_numbered_in_letters_is_judged():
    text = HEAD + ("$$\\boxed{\\quad\\mathbf I\\,\\mathbf{\\dot{\\omega}}+\\mathbf\\omega\\times\\,\\mathbf I"
                   "\\,\\mathbf\\omega=\\mathbf\\tau\\quad~Eq. (1)}$$\n")
    assert verdicts(text)[line_of(text, "$$\\boxed")] == {"holds"}


def test_a_dot_over_a_bold_letter_written_without_braces_is_the_rate_of_the_vector():
    text = HEAD + ("$$\\mathbf I\\,\\dot{\\boldsymbol\\omega}+\\boldsymbol\\omega\\times\\,\\mathbf I\\,"
                   "\\boldsymbol\\omega=\\boldsymbol\\tau$$\n")
    assert verdicts(text)[line_of(text, "$$\\mathbf I")] == {"holds"}


def test_that_rate_with_the_gyroscopic_term_dropped_fails():
    text = HEAD + "$$\\mathbf I\\,\\dot{\\mathbf\\omega}=\\boldsymbol\\tau$$\n"
    assert verdicts(text)[line_of(text, "$$\\mathbf I")] == {"fails"}
