"""Two components joined into one complex quantity, and a torque the text writes in its own names:
a lone i multiplying something is √−1 (derive/lecture/imaginary_unit.py), and the torque a text
writes in one component's equation of motion is that component's torque in its later equations
(derive/lecture/motion.py)."""
import kept_readings as kept

from derive.lecture import imaginary_unit

_FORCED = ("A symmetric body, $I_1 = I_2 = I$, carries a weight whose torque $mgd$ acts about its second "
           "axis:\n\n"
           "$$ \\dot{\\omega}_{1}I - (I-I_{3}) \\omega_{2}\\omega_{3} = 0 $$\n\n"
           "$$ \\dot{\\omega}_{2}I + (I-I_{3}) \\omega_{3}\\omega_{1} = mgd $$\n\n"
           "$$ \\dot{\\omega}_{3}I_3 = 0 $$\n\n"
           "With $\\Omega = \\frac{I-I_3}{I}\\omega_3$ and $\\alpha = mgd/I$ the first two join:\n\n")


def _verdicts(claims, line):
    return [c.verdict for c in claims if c.line == line]


def test_a_lone_i_beside_a_factor_is_the_imaginary_unit():
    assert imaginary_unit.read(r"\dot{u} - \Omega i u = \alpha") == r"\dot{u} - \Omega \sqrt{-1} u = \alpha"
    assert imaginary_unit.read(r"u = \omega_2 + i\omega_1") == r"u = \omega_2 + \sqrt{-1}\omega_1"


def test_an_index_a_unit_vector_and_a_word_keep_their_i():
    for kept_i in (r"\omega_i = \sum_{i=1}^3 x_i", r"i = 1, 2, 3", r"\hat{i} \omega", r"\mathbf i \times \mathbf j",
                   r"x i + y j + z k", r"v_x\bm{\hat{\imath}} i", r"(i)", r"\text{if } x > 0", r"\quad i = 2"):
        assert imaginary_unit.read(kept_i) == kept_i


def test_two_components_joined_by_i_are_judged_against_eulers_equations():
    claims = kept.check_text(_FORCED + "$$ (\\dot{\\omega_2} + i\\dot{\\omega_1}) - \\Omega i (\\omega_2 + i "
                                       "\\omega_1) = \\alpha $$\n")
    assert _verdicts(claims, 11) == ["holds"]
    slip = kept.check_text(_FORCED + "$$ (\\dot{\\omega_2} + i\\dot{\\omega_1}) + \\Omega i (\\omega_2 + i "
                                     "\\omega_1) = \\alpha $$\n")
    assert _verdicts(slip, 11) and set(_verdicts(slip, 11)) <= {"typo", "fails"}


def test_the_torque_a_text_wrote_for_one_component_holds_in_its_later_equations():
    same = kept.check_text(_FORCED + "$$ \\dot\\omega_2 = -\\Omega\\omega_1 + \\alpha $$\n")
    assert _verdicts(same, 11) == ["holds"]
    doubled = kept.check_text(_FORCED + "$$ \\dot\\omega_2 + \\Omega\\omega_1 = 2\\alpha $$\n")
    assert _verdicts(doubled, 11) and set(_verdicts(doubled, 11)) <= {"typo", "fails"}


def test_a_torque_in_the_texts_names_is_still_read_afresh_in_a_new_section():
    claims = kept.check_text(_FORCED + "## A heavier weight\n\n"
                             "Again $I_1 = I_2 = I$, the weight doubled:\n\n"
                             "$$ \\dot{\\omega}_{2}I + (I-I_{3}) \\omega_{3}\\omega_{1} = 2mgd $$\n")
    assert _verdicts(claims, 15) == ["holds"]
