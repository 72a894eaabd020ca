"""The notes reader on Euler's equation in vectors taken about one point the text labels (the inertia
tensor and the torque both labelled c, cm, G, O …: ``\\bm{\\tau}_{\\bm{c}} = \\bm{\\omega} \\times
(\\mathbf{I}^{\\bm{c}} \\bm{\\omega}) + \\mathbf{I}^{\\bm{c}} \\frac{d\\bm{\\omega}}{dt}``), and on a tensor
written before the vector on the left of a cross product (``\\mathbf I \\boldsymbol\\omega \\times
\\boldsymbol\\omega``, the tensor acting on 𝛚 before the cross product)."""
import kept_readings as kept
from derive.lecture.point_moments import dropped

verdicts, line_of = kept.verdicts_by_line, kept.line_of
HEAD = ("# Notes\n\nThe body turns with angular velocity $\\bm{\\omega}$; $\\mathbf{I}^{\\bm{c}}$ is its inertia "
        "tensor about the centre of mass $\\bm{c}$ and $\\bm{\\tau}_{\\bm{c}}$ the torque about it.\n\n")


def test_eulers_equation_with_tensor_and_torque_labelled_by_the_centre_of_mass_holds():
    text = HEAD + ("$$\\bm{\\tau}_{\\bm{c}} = \\bm{\\omega} \\times (\\mathbf{I}^{\\bm{c}} \\bm{\\omega}) + "
                   "\\mathbf{I}^{\\bm{c}} \\frac{d\\bm{\\omega}}{dt}.$$\n")
    assert verdicts(text)[line_of(text, "$$\\bm{\\tau}_{\\bm{c}} = ")] == {"holds"}


def test_the_same_equation_with_its_gyroscopic_sign_turned_about_the_labelled_point_is_flagged():
    text = HEAD + ("$$\\boldsymbol\\tau_{cm} = \\mathbf I_{cm} \\dot{\\boldsymbol\\omega} - \\boldsymbol\\omega "
                   "\\times \\mathbf I_{cm} \\boldsymbol\\omega$$\n")
    assert verdicts(text)[line_of(text, "$$\\boldsymbol\\tau_{cm} = ")] == {"typo"}


def test_a_tensor_before_the_vector_on_the_left_of_a_cross_product_acts_on_it_first():
    text = HEAD + "$$\\mathbf{I}\\dot{\\bm{\\omega}} = \\mathbf{I} \\bm{\\omega} \\times \\bm{\\omega} + \\bm{\\tau}$$\n"
    assert verdicts(text)[line_of(text, "$$\\mathbf{I}\\dot")] == {"holds"}


def test_the_label_is_dropped_from_the_tensor_and_the_torque_only():
    assert dropped("\\bm{\\tau}_{\\bm{c}} = \\bm{\\omega} \\times (\\mathbf{I}^{\\bm{c}} \\bm{\\omega}) + "
                   "\\mathbf{I}^{\\bm{c}} \\dot{\\bm{\\omega}}") == \
        ("\\bm{\\tau} = \\bm{\\omega} \\times (\\mathbf{I} \\bm{\\omega}) + \\mathbf{I} \\dot{\\bm{\\omega}}", "c")
    assert dropped("\\tau_{\\mathrm{cm}} = I_{\\mathrm{cm}} \\dot\\omega + \\omega \\times I_{\\mathrm{cm}} \\omega")[1] == "cm"


def test_two_points_an_unlabelled_tensor_or_the_points_own_position_keep_the_labels():
    assert dropped("\\boldsymbol\\tau_O = \\mathbf I_C \\dot{\\boldsymbol\\omega} + \\boldsymbol\\omega \\times "
                   "\\mathbf I_C \\boldsymbol\\omega") is None
    assert dropped("\\boldsymbol\\tau = \\mathbf I_C \\dot{\\boldsymbol\\omega} + \\boldsymbol\\omega \\times "
                   "\\mathbf I \\boldsymbol\\omega") is None
    assert dropped("\\boldsymbol\\tau_c = \\mathbf I_c \\dot{\\boldsymbol\\omega} + \\boldsymbol\\omega \\times "
                   "\\mathbf I_c \\boldsymbol\\omega + \\mathbf r_c \\times \\mathbf F") is None
    assert dropped("\\mathbf I_c = \\mathbf I_O - m \\mathbf r \\times \\mathbf r") is None      # no rate of 𝛚
    assert dropped("\\mathbf I_P \\dot{\\boldsymbol\\omega} + \\boldsymbol\\omega \\times \\mathbf I_P "
                   "\\boldsymbol\\omega = \\boldsymbol\\tau_P") is None                    # a point of no such name
    assert dropped("I_{xx} \\dot\\omega_x + (\\omega \\times I \\omega)_x = \\tau_x") is None
