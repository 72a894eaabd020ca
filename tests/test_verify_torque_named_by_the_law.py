"""The notes reader on a text that names its torque by Euler's second law: a display setting the rate
of the angular momentum equal to a letter (``\\dot{\\vec{H}} = \\vec{L}``, Schaub's notation) makes that
letter the text's torque, so Euler's equations written with its components (= L₁) are judged with a
torque, not as a free body whose angular momentum is L."""
from kept_readings import by_line, line_of

from derive.lecture import names as nm
from derive.lecture.vocabulary import Atom

LAW = ("# Rotational equations of motion\n\nThe rate of change of the angular momentum is the external "
       "torque:\n\n$$\nRATE = \\vec{\\mathbf{L}}\n$$\n\n## Principal axes\n\nIn principal axes:\n\n$$\n"
       "EULER\n$$\n")
EULER = r"I_1 \dot{\omega}_1 + (I_3 - I_2) \omega_2 \omega_3 = L_1"
SLIP = r"I_1 \dot{\omega}_1 + (I_2 - I_3) \omega_2 \omega_3 = L_1"


def _euler(rate=r"\dot{\vec{\mathbf{H}}}", row=EULER, prose=""):
    text = LAW.replace("RATE", rate).replace("EULER", row).replace("In principal axes:", prose + "In principal axes:")
    return [c.verdict for c in by_line(text)[line_of(text, "$$\n" + row)]]


def test_euler_s_equations_with_the_components_of_the_torque_the_law_names_hold():
    assert _euler() == ["holds"]


def test_the_law_written_as_a_derivative_in_the_inertial_frame_names_the_torque_too():
    assert _euler(r"^N\frac{\text{d}\vec{\mathbf{H}}}{\text{d}t}") == ["holds"]


def test_a_sign_slip_in_euler_s_equations_with_the_named_torque_is_still_flagged():
    assert _euler(row=SLIP) in (["fails"], ["typo"])


def test_without_the_law_a_component_l1_is_the_angular_momentum_as_before():
    text = "# Euler\n\nIn principal axes:\n\n$$\n" + EULER + "\n$$\n"
    assert [c.verdict for c in by_line(text)[line_of(text, "$$\n" + EULER)]] == ["fails"]


def test_the_law_binds_only_a_letter_the_prose_has_not_named():
    learned = nm.learn("Here $\\mathbf{L}$ is the angular momentum.\n\n$$\n\\dot{\\mathbf{H}} = \\mathbf{L}\n$$\n")
    assert learned.meaning(Atom("L", bold=True)) == "angular momentum"
    learned = nm.learn("The law:\n\n$$\n\\dot{\\mathbf{H}} = \\mathbf{L}\n$$\n")
    assert learned.meaning(Atom("L", sub="1")) == "torque"


def test_a_rate_equal_to_a_sum_or_a_rate_of_a_letter_that_is_no_angular_momentum_binds_nothing():
    for display in (r"\dot{\mathbf{H}} = \mathbf{L} + \mathbf{N}", r"\dot{\mathbf{p}} = \mathbf{L}",
                    r"\dot{\mathbf{H}} = \dot{\mathbf{L}}"):
        learned = nm.learn("The law:\n\n$$\n" + display + "\n$$\n")
        assert learned.meaning(Atom("L", sub="1")) is None


GYRO = ("# Gyroscope\n\nA gyroscope of mass $m$ spins at $\\omega$ about its axis, whose moment of inertia is $I$; its "
        "centre of mass is at distance $r$ from the pivot.\n\n$$\n\\Omega = \\frac{m g r}{I \\omega}\n$$\n\n"
        "PROSE\n\n$$\nM = I \\omega \\Omega\n$$\n")


def test_a_plain_letter_the_prose_calls_the_gyroscopic_moment_is_never_the_mass():
    for prose in ("The gyroscopic moment $M$ is", "The gyroscopic moment is", "The applied couple $M$ is"):
        text = GYRO.replace("PROSE", prose)
        assert [c.verdict for c in by_line(text)[line_of(text, "$$\nM = ")]] == ["unchecked"]
