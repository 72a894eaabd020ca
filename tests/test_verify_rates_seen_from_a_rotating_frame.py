"""A rate seen from a frame written as a bracket with the frame's label, ``\\Bigg(\\frac{d\\vec v}{dt}
\\Bigg)_{I}`` and ``_{R}`` (inertial, rotating; `derive.lecture.vector_models.FRAMES`): the transport
theorem for a vector of the text's holds, and with its cross product's sign slipped it does not."""
import pytest

from derive.lecture import notes_check as nc

THEOREM = (r"\Bigg(\frac{\mathrm{d}\vec{v}}{\mathrm{d}t} \Bigg)_{I}= \Bigg(\frac{\mathrm{d}\vec{v}}{\mathrm{d}t} \Bigg)_{R}"
           r"{sign} \vec{\omega} \times \vec{v}")


def _verdicts(statement):
    return [c.verdict for c in nc.check_text("# Frames that turn\n\n$$" + statement + "$$\n") if c.line == 3]


def test_the_transport_theorem_with_the_rotating_frame_labelled_r_holds():
    assert _verdicts(THEOREM.replace("{sign}", "+")) == ["holds"]


@pytest.mark.parametrize("label", ["R", "rot"])
def test_the_transport_theorem_with_its_sign_slipped_is_flagged(label):
    statement = THEOREM.replace("{sign}", "-").replace("_{R}", "_{" + label + "}")
    assert set(_verdicts(statement)) & {"typo", "fails"}
