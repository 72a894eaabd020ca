"""The notes reader on a moment about an axis written I_x (I_y, I_z) beside the body's own integral
or sum: it is the inertia tensor's diagonal entry I_xx, so the integral of the squared distance from
that axis holds and one about another axis fails; a relation of such moments alone (a lamina's
I_x + I_y = I_z) is a case of the text's body and is left unflagged."""
import kept_readings as kept

HEAD = "# The inertia tensor\n\nFor a body of density $\\rho$,\n\n"


def _verdicts(body):
    text = HEAD + body
    return [c.verdict for c in kept.check_text(text)]


def test_a_moment_named_by_its_axis_holds_with_its_integral():
    assert _verdicts("$$I_x = \\int (y^2 + z^2) \\rho \\, dV$$\n") == ["holds"]
    assert set(_verdicts("$$I_{33} = I_z = \\int (x^2 + y^2) \\rho \\, dV$$\n")) == {"holds"}


def test_a_moment_with_the_distance_from_another_axis_fails():
    assert _verdicts("$$I_x = \\int (x^2 + z^2) \\rho \\, dV$$\n") == ["fails"]


def test_a_relation_of_moments_alone_is_not_flagged():
    body = "$$I_x = \\int (y^2 + z^2) \\rho \\, dV$$\n\nFor a thin lamina in the plane $z = 0$,\n\n$$I_x + I_y = I_z$$\n"
    assert not set(_verdicts(body)[1:]) & {"fails", "typo"}
