"""The notes reader on a text whose own angular momentum in principal axes names its angular velocity:
``\\dot{L}_i \\equiv I_i \\dot{\\Omega}_i`` (or ``L_1 = I_1\\Omega_1``) says the letter beside the moment
(Landau's Ω) is the body angular velocity, so Euler's equations and their consequences written in Ω
are judged; a chain that restates the momentum first (``\\dot{L}_1 \\equiv
I_1\\dot{\\Omega}_1 = …``) is read as its equation of motion. Without the tie, Ω stays unread. As with
a letter the prose names, a statement in Ω that does not hold is left unchecked, not flagged: the text
may mean something else by the letter there."""
from kept_readings import by_line, line_of

from derive.lecture import names as nm
from derive.lecture import source
from derive.lecture.vocabulary import Atom

TIE = r"\dot{L}_1~\equiv~ I_1 \dot{\Omega}_1~=~\Omega_{2}(I_{2}-I_{3}) \Omega_{3}"
SECOND = r"I_1I_2 I_3 \ddot{\Omega}_1 = (I_{2}-I_{3}) \Omega_1\left\{(I_1 -I_{2}) I_{2}\Omega_{2}^2- (I_1 -I_{3}) I_{3}\Omega_{3}^2\right\}"
SECOND_SLIP = SECOND.replace(r"(I_1 -I_{2}) I_{2}", r"(I_1 -I_{2}) I_{3}")


def _text(*rows):
    return "# Free body\n\nThe equations of the free body:\n\n" + "".join("$$" + r + "$$\n\n" for r in rows)


def _verdicts(text, row):
    return [c.verdict for c in by_line(text)[line_of(text, "$$" + row)]]


def test_the_momentum_in_principal_axes_names_omega_the_body_angular_velocity():
    assert nm.learn(_text(TIE)).meaning(Atom("Omega", sub="2")) == "angular velocity"
    assert nm.learn(_text(r"L_1 = I_1 \Omega_1")).meaning(Atom("Omega", sub="3")) == "angular velocity"


def test_euler_s_equation_and_its_second_derivative_in_omega_hold_and_a_slip_is_no_false_holds():
    text = _text(TIE, SECOND)
    assert _verdicts(text, TIE) == ["holds"]
    assert _verdicts(text, SECOND) == ["holds"]
    assert _verdicts(_text(TIE, SECOND_SLIP), SECOND_SLIP) == ["unchecked"]


def test_without_the_tie_omega_is_not_read():
    text = _text(SECOND)
    assert _verdicts(text, SECOND) == ["unchecked"]


def test_the_momentum_names_omega_with_the_rates_dots_over_unbraced_letters():
    for row in (r"\dot L_1~\equiv~ I_1 \dot\Omega_1", r"\dot{L}_1 \equiv I_1 \dot \Omega_1"):
        assert nm.learn(_text(row)).meaning(Atom("Omega", sub="1")) == "angular velocity", row
    unbraced = TIE.replace(r"\dot{\Omega}_1", r"\dot\Omega_1")
    assert _verdicts(_text(unbraced, SECOND), unbraced) == ["holds"]


def test_a_momentum_with_another_index_or_an_unlike_rate_names_nothing():
    for row in (r"\dot{L}_1 \equiv I_2 \dot{\Omega}_2", r"\dot{L}_1 \equiv I_1 \Omega_1", r"L_1 = I_1 x_1"):
        learned = nm.learn(_text(row))
        assert learned.meaning(Atom("Omega", sub="1")) is None


def test_a_chain_restating_the_momentum_is_read_as_its_equation_of_motion_and_a_slip_there_is_flagged():
    chain = r"\dot{L}_1 = I_1 \dot{\omega}_1 = (I_2 - I_3)\omega_2\omega_3"
    assert _verdicts(_text(chain), chain) == ["holds"]
    slip = r"\dot{L}_1 = I_1 \dot{\omega}_1 = (I_3 - I_2)\omega_2\omega_3"
    assert _verdicts(_text(slip), slip)[0] in ("typo", "fails")


def test_the_momentum_names_omega_with_the_rates_written_in_differentials():
    for row in (r"\frac{\mathrm{d} L_1}{\mathrm{d} t} \equiv I_1 \frac{\mathrm{d} \Omega_1}{\mathrm{d} t}",
                r"\frac{dL_1}{dt} = I_1\frac{d\Omega_1}{dt}"):
        assert nm.learn(_text(row)).meaning(Atom("Omega", sub="1")) == "angular velocity", row
    upright = TIE.replace(r"\dot{L}_1", r"\frac{\mathrm{d} L_1}{\mathrm{d} t}").replace(
        r"\dot{\Omega}_1", r"\frac{\mathrm{d} \Omega_1}{\mathrm{d} t}")
    assert _verdicts(_text(upright, SECOND), upright) == ["holds"]


# Euler's equations on axes x, y, z, in a display environment, the rates in the text's own macro for d
_XYZ = "\n".join([
    r"$\newcommand{\D}{\mathop{}\!\mathrm{d}}$", "", "When the tensor $I$ is diagonal this reads", r"\begin{align*}",
    r"\dot{L}_x &= I_x \frac{\D \Omega_x}{\D t} + (I_z-I_y)\Omega_y \Omega_z \\",
    r"\dot{L}_y &= I_y \frac{\D \Omega_y}{\D t} + (I_x-I_z)\Omega_x \Omega_z \\",
    r"\dot{L}_z &= I_z \frac{\D \Omega_z}{\D t} + (I_y-I_x)\Omega_x \Omega_y", r"\end{align*}", ""])


def _xyz_verdicts(text):
    return [c.verdict for c in by_line(text)[line_of(text, r"\begin{align*}")]]


def test_euler_s_shape_on_axes_x_y_z_names_its_letter_and_the_principal_axes_so_a_slip_is_flagged():
    text = "# Free body\n\n" + _XYZ
    assert nm.learn(text, macros=source.macros(text)).meaning(Atom("Omega", sub="y")) == "angular velocity"
    assert _xyz_verdicts(text) == ["holds"] * 3
    slip = text.replace(r"(I_z-I_y)\Omega_y", r"(I_y-I_z)\Omega_y")
    assert sorted(_xyz_verdicts(slip)) == ["holds", "holds", "typo"]


def test_the_moment_times_a_rate_with_another_term_names_nothing():
    for row in (r"\dot{L}_x = I_x \dot\Omega_x + (I_z-I_y)\Omega_y \beta_z",
                r"\dot{L}_x = I_x \dot\Omega_x + (I_z-I_y)\Omega_y \Omega_z + \Omega_x",
                r"L_x = I_x \Omega_x + (I_z-I_y)\Omega_y \Omega_z"):
        assert nm.learn(_text(row)).meaning(Atom("Omega", sub="x")) is None, row
