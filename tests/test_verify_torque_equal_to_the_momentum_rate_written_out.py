"""The notes reader on a text in Schaub's notation (𝐇 the angular momentum, 𝐋 the torque, named by the
law ``^N\\frac{d\\vec{H}}{dt} = \\vec{L}``): the torque set equal to a sum that writes out the angular
momentum's inertial rate — its rate seen from the body frame plus 𝛚 × 𝐇, about the centre of mass
too — is the law with the transport theorem, and is checked against that inertial rate; a sum that
does not hold is left unchecked, the law being where the derivation starts."""
from kept_readings import by_line, line_of

from derive.lecture import names as nm
from derive.lecture.vocabulary import Atom

LAW = r"^N\frac{\text{d}\vec{\mathbf{H}}}{\text{d}t} = \vec{\mathbf{L}}"
TEXT = "# Equations of motion\n\nThe law in the inertial frame N:\n\n$$\n" + LAW + "\n$$\n\nIn the body frame B:\n\n$$\nROW\n$$\n"
ABOUT_C = (r"\vec{\mathbf{L}}_C = ^B\frac{\text{d}\vec{\mathbf{H}}_C}{\text{d}t} SIGN \vec{\boldsymbol{\omega}}_{B/N} "
           r"\times ^B\vec{\mathbf{H}}_C")
PLAIN = r"\vec{\mathbf{L}} = \left(\frac{d\vec{\mathbf{H}}}{dt}\right)_B SIGN \vec{\boldsymbol{\omega}} \times \vec{\mathbf{H}}"


def _verdicts(row: str) -> list[str]:
    text = TEXT.replace("ROW", row)
    return [c.verdict for c in by_line(text)[line_of(text, "$$\n" + row)]]


def test_the_torque_about_the_centre_of_mass_equal_to_the_transported_rate_holds():
    assert _verdicts(ABOUT_C.replace("SIGN", "+")) == ["holds"]


def test_the_torque_equal_to_the_body_frame_rate_plus_omega_cross_h_holds():
    assert _verdicts(PLAIN.replace("SIGN", "+")) == ["holds"]


def test_a_sum_with_its_sign_slipped_is_left_unchecked_not_flagged():
    assert _verdicts(ABOUT_C.replace("SIGN", "-")) == ["unchecked"]
    assert _verdicts(PLAIN.replace("SIGN", "-")) == ["unchecked"]


def test_the_law_itself_stays_where_the_derivation_starts():
    text = TEXT.replace("ROW", PLAIN.replace("SIGN", "+"))
    assert [c.verdict for c in by_line(text)[line_of(text, "$$\n" + LAW)]] == ["unchecked"]


def test_the_law_names_the_bold_letter_under_its_rate_the_angular_momentum():
    learned = nm.learn("The law:\n\n$$\n" + LAW + "\n$$\n")
    assert learned.meaning(Atom("H", bold=True)) == "angular momentum"
    learned = nm.learn("Here $\\mathbf{H}$ is the energy flux.\n\n$$\n" + LAW + "\n$$\n")
    assert learned.meaning(Atom("L", bold=True)) == "torque"
