"""The notes reader on relations among a rotation matrix and the text's matrices and vectors: an
identity for every rotation (``R R^T = I``, the rate of ``R R^T``, a product regrouped, a point
carried by ``R(t)``) holds, a wrong one is left unjudged (its letters may be particular matrices),
and an inertia tensor set equal to a rotation times the tensor in other axes fails."""
import kept_readings as kept
from derive.lecture.rotation_products import prepared, rotation_letters

verdicts, line_of = kept.verdicts_by_line, kept.line_of
HEAD = "# Notes\n\nA rotation matrix $R$ (orthogonal, $R^T$ its inverse) turns the body.\n\n"


def _note(*displays):
    return HEAD + "".join(f"Then\n\n$${d}$$\n\n" for d in displays)


def test_the_orthogonality_of_a_rotation_and_the_rate_of_it_hold():
    text = _note("R R^T = I", "\\dot R R^T = -R\\dot R^T = -(\\dot R R^T)^T")
    assert verdicts(text)[line_of(text, "$$R R^T")] == {"holds"}
    assert verdicts(text)[line_of(text, "$$\\dot R R^T")] == {"holds"}


def test_a_rate_of_a_rotation_with_its_sign_turned_is_not_held():
    text = _note("\\dot R R^t = R\\dot R^t")
    assert "holds" not in verdicts(text).get(line_of(text, "$$\\dot R"), set())


def test_a_point_carried_by_the_rotation_and_its_velocity():
    text = _note("\\mathbf x(t) = R(t)\\mathbf x(0)", "\\dot{\\mathbf x}(t) = \\dot R(t)\\mathbf x(0) = \\dot R(t)R^t(t)\\mathbf x(t)")
    assert verdicts(text)[line_of(text, "$$\\dot{\\mathbf x}")] == {"holds"}
    slip = _note("\\mathbf x(t) = R(t)\\mathbf x(0)", "\\dot{\\mathbf x}(t) = \\dot R(t)\\mathbf x(0) = R^t(t)\\dot R(t)\\mathbf x(t)")
    assert "holds" not in verdicts(slip).get(line_of(slip, "$$\\dot{\\mathbf x}"), set())


def test_a_point_carried_by_the_rotation_with_its_time_in_sized_brackets():
    sized = "\\dot{\\mathbf x}\\left(t\\right) = \\dot R\\left(t\\right)\\mathbf x\\left(0\\right) = \\dot R\\left(t\\right)R^t\\left(t\\right)\\mathbf x\\left(t\\right)"
    text = _note("\\mathbf x(t) = R(t)\\mathbf x(0)", sized)
    assert verdicts(text)[line_of(text, "$$\\dot{\\mathbf x}")] == {"holds"}


def test_a_relation_premultiplied_and_regrouped_with_times_between_matrices():
    text = _note("\\vec L = I \\vec\\omega", "R\\times L = R \\times I\\times (R^T\\times R) \\times \\omega")
    assert verdicts(text)[line_of(text, "$$R\\times")] == {"holds"}
    slip = _note("\\vec L = I \\vec\\omega", "R\\times L = R \\times I\\times (R\\times R^T) \\times R \\times \\omega")
    assert "holds" not in verdicts(slip).get(line_of(slip, "$$R\\times"), set())


def test_an_inertia_tensor_set_to_a_rotation_times_the_body_tensor_fails():
    head = ("# Notes\n\nThe rotation matrix $\\mathbf R$ carries body components into inertial ones, "
            "$\\mathbf R^T$ back; $\\mathbf I_B$ is the inertia tensor in body components.\n\n")
    slip = head + "$$\\mathbf J = \\mathbf R\\,\\mathbf I_B$$\n"
    assert verdicts(slip)[line_of(slip, "$$\\mathbf J")] == {"fails"}
    right = head + "$$\\mathbf J = \\mathbf R\\,\\mathbf I_B\\,\\mathbf R^T$$\n"
    assert "fails" not in verdicts(right).get(line_of(right, "$$\\mathbf J"), set())


def test_a_text_that_does_not_speak_of_rotations_has_no_rotation_letters():
    assert rotation_letters("a matrix $R^T R$ of the data") == frozenset()
    assert rotation_letters("the rotation $\\mathbf R_1^T$ and $Q^{-1}$") == {("R", "1", True), ("Q", "", False)}


def test_functions_of_time_and_transposes_as_written():
    assert prepared("\\dot R(t)R^t(t)\\mathbf x(0)") == "\\dot RR^T\\mathbf x_{0}"
    assert prepared("R^{\\top} R") == "R^T R"


def test_a_matrix_written_as_a_function_of_an_angle_is_left_to_the_other_readers():
    text = _note("R(\\theta)^T R(\\theta) = I")
    assert verdicts(text).get(line_of(text, "$$R(\\theta)"), set()) <= {"unchecked"}


def test_determinants_of_the_rotation_and_of_its_products_are_read():
    text = _note("\\det(R R^T) = \\det(R)\\det(R^T) = [\\det R]^2 = 1", "\\det(R - I) = \\det((R - I)^T)")
    assert verdicts(text)[line_of(text, "$$\\det(R R^T)")] == {"holds"}
    assert verdicts(text)[line_of(text, "$$\\det(R - I)")] == {"holds"}
    slip = _note("\\det(R R^T) = \\det(R)\\det(R^T) = 2")
    assert "holds" not in verdicts(slip).get(line_of(slip, "$$\\det"), set())


def test_a_lone_zero_beside_matrices_is_the_zero_matrix():
    text = _note("0 = \\frac{d[R(t)R^T(t)]}{dt} = \\dot{R}R^T(t)+(\\dot{R}R^T(t))^T",
                 "\\dot R R^T + R \\dot R^T = 0")
    assert verdicts(text)[line_of(text, "$$0 =")] == {"holds"}
    assert verdicts(text)[line_of(text, "$$\\dot R R^T +")] == {"holds"}
    slip = _note("0 = \\dot{R}R^T(t)-(\\dot{R}R^T(t))^T")
    assert "holds" not in verdicts(slip).get(line_of(slip, "$$0 ="), set())


def test_the_identity_written_first_and_set_to_products_of_rotations():
    text = _note("I = R(t)R^T(t).", "I = R^T R")
    assert verdicts(text)[line_of(text, "$$I = R(t)")] == {"holds"}
    assert verdicts(text)[line_of(text, "$$I = R^T")] == {"holds"}
    slip = _note("I = R R")
    assert "holds" not in verdicts(slip).get(line_of(slip, "$$I = R R"), set())


def test_a_relation_of_the_rotation_alone_that_no_rotation_satisfies_fails():
    # multiplied by A^-1 on the left and (A^T)^-1 on the right, with an A too many on the left: A = I
    text = _note("R^{-1}RR^{T} (R^{T})^{-1} = R^{-1}I(R^{T})^{-1}", "R^{-1}RR^{T} R(R^{T})^{-1} = R^{-1}I(R^{T})^{-1}")
    assert verdicts(text)[line_of(text, "$$R^{-1}RR^{T} (")] == {"holds"}
    (flag,) = [c for c in kept.check_text(text) if c.line == line_of(text, "$$R^{-1}RR^{T} R(")]
    assert flag.verdict == "fails" and "not an identity of the rotation R" in flag.why


def test_a_relation_with_the_rotation_on_one_side_only_or_a_rotation_the_text_sets_is_left_alone():
    one_side = _note("R^{T} R R = I")                 # a particular turn (a half-turn's square) may be meant
    assert "fails" not in verdicts(one_side).get(line_of(one_side, "$$R^{T}"), set())
    set_before = _note("R = R_0", "R^{T} R R = R^{T}")   # the text fixed R: a particular matrix
    assert "fails" not in verdicts(set_before).get(line_of(set_before, "$$R^{T} R R"), set())
