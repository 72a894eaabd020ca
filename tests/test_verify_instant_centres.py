"""The notes reader on relations between points of a body named by letters that hold only when one
of the points is at rest, or has no acceleration, at that instant (an instantaneous centre, as
plane-motion texts take one): ``holds if`` that, naming the point; any other slip stays unchecked."""
import kept_readings as kept

HEAD = ("# Notes\n\nThe body moves in its plane with angular velocity $\\vec\\omega$.\n\n"
        "$$\\vec v_B = \\vec v_A + \\vec\\omega \\times \\vec r_{AB}$$\n\n")


def _claims(display, before=""):
    text = HEAD + before + "Taking it as the point:\n\n$$" + display + "$$\n"
    return kept.by_line(text)[kept.line_of(text, "$$" + display)]


def test_a_velocity_as_a_turn_about_a_point_at_rest_holds_if_that_point_is_at_rest():
    [claim] = _claims("\\vec v_B = \\vec\\omega \\times \\vec r_{AB}")
    assert claim.verdict == "holds"
    assert "velocity of A is zero" in claim.why


def test_an_acceleration_about_a_point_without_acceleration_holds_if_that_point_has_none():
    composed = "$$\\vec a_B = \\vec a_A + \\vec a_{BA}^t + \\vec a_{BA}^n$$\n\n"
    [claim] = _claims("\\vec a_B = \\vec a_{BA}^t + \\vec a_{BA}^n", composed)
    assert claim.verdict == "holds"
    assert "acceleration of A is zero" in claim.why


def test_a_turn_about_a_point_at_rest_the_wrong_way_round_is_not_held():
    assert {c.verdict for c in _claims("\\vec v_B = \\vec\\omega \\times \\vec r_{BA}")} == {"unchecked"}


def test_a_point_said_at_rest_is_not_held_by_its_own_rest():
    assert "holds" not in {c.verdict for c in _claims("\\vec v_B = \\vec\\omega \\times \\vec r_{BB}")}
    assert "holds" not in {c.verdict for c in _claims("\\vec a_B = \\vec\\alpha \\times \\vec r_{B}")}
