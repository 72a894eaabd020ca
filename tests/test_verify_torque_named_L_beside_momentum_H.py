"""The notes reader on a text that names the angular momentum 𝐇 and the torque 𝐋, as spacecraft
and engineering courses do: the prose's torque is the torque, never the angular momentum."""
import kept_readings as kept

_TEXT = ("# Motion\n\nThe angular momentum of the body about its centre of mass,\n\n"
         "$$\n\\mathbf{H} = \\int \\mathbf{r} \\times \\dot{\\mathbf{r}} \\, dm = [\\mathbf{I}] \\boldsymbol{\\omega}\n$$\n\n"
         "Its rate of change equals $\\mathbf{L}$, the external torque:\n\n"
         "$$\n\\dot{\\mathbf{H}} = {side}\n$$\n")


def _verdicts(side):
    return {c.verdict for c in kept.check_text(_TEXT.replace("{side}", side)) if c.line == 11}


def test_a_letter_L_the_prose_names_the_torque_is_the_rate_of_the_angular_momentum_H():
    assert _verdicts(r"\mathbf{L}") == {"holds"}


def test_a_sign_slipped_on_the_torque_named_L_is_flagged():
    assert _verdicts(r"-\mathbf{L}") == {"fails"}
