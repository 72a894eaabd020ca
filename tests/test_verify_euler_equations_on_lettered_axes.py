"""Euler's equations written once for axes named by letters: the index form over (i, j, k), read in
its three cyclic orders of (1, 2, 3), and the body's axes x, y, z, read as 1, 2, 3; each instance
must be one of Euler's equations, and a form that is not is left unchecked, never flagged
(derive/lecture/index_euler.py)."""
import kept_readings as kept

_HEAD = ("A rigid body turns with angular velocity $\\vec{\\Omega}$, whose components on the body's principal "
         "axes are $\\Omega_i$, with moments of inertia $I_i$; an external torque has components $\\tau_i$ on the "
         "same axes. For each axis,\n\n")


def _one(formula):
    claims = [c for c in kept.check_text(_HEAD + f"$$\n{formula}\n$$\n") if "tau" in c.latex]
    assert len(claims) == 1
    return claims[0]


def test_the_index_form_holds_in_every_cyclic_order():
    c = _one("I_i \\dot{\\Omega}_i - (I_j - I_k) \\Omega_j \\Omega_k = \\tau_i")
    assert c.verdict == "holds" and "cyclic orders" in c.why


def test_the_index_form_in_the_other_order_is_left_unchecked():
    c = _one("I_i \\dot{\\Omega}_i - (I_k - I_j) \\Omega_j \\Omega_k = \\tau_i")
    assert c.verdict == "unchecked"


def test_axes_named_x_y_z_are_read_as_one_two_three():
    text = (_HEAD + "$$\nI_1 \\dot{\\Omega}_1 - (I_2 - I_3) \\Omega_2 \\Omega_3 = \\tau_1\n$$\n\n"
            "On axes $x, y, z$ fixed to the body,\n\n"
            "$$\nI_x \\dot{\\Omega}_x - (I_y - I_z) \\Omega_y \\Omega_z = \\tau_x\n$$\n")
    claims = [c for c in kept.check_text(text) if "tau_x" in c.latex]
    assert [c.verdict for c in claims] == ["holds"] and "for x, y, z" in claims[0].why


def test_the_index_form_with_its_rate_in_upright_differentials_holds():
    c = _one("I_i \\frac{\\mathrm{d} \\Omega_i}{\\mathrm{d} t} - (I_j - I_k) \\Omega_j \\Omega_k = \\tau_i")
    assert c.verdict == "holds" and "cyclic orders" in c.why
