"""A perturbation written as a column of variations about a steady spin the text sets as a column,
``\\vec\\omega = [0, 0, \\Omega]^T`` then ``\\delta\\vec\\omega = [\\delta\\omega_1, \\delta\\omega_2, 0]``: each
δωᵢ is ω̃ᵢ − cᵢ, so the linearised equations with a remainder ``O(\\delta\\omega^2)`` are Euler's equations to
first order (derive/lecture/perturbations.py); an accented δ alone (``\\hat{\\delta}``, a unit tensor) is a symbol
of its own and leaves δω a variation (derive/lecture/variations.py)."""
import kept_readings as kept
from derive.lecture.variations import delta_a_quantity

_HEAD = ("A free rigid body with principal moments $I_1$, $I_2$, $I_3$ obeys Euler's equations. A spin about one "
         "principal axis, $\\vec{\\omega} = [ 0 , 0 , \\Omega ]^T$ with $\\Omega$ constant, solves them. A small "
         "transverse kick $\\delta \\vec{\\omega} = [ \\delta\\omega_1 , \\delta\\omega_2 , 0 ]$ is added and the first "
         "order kept; the equations become\n\n")


def _rows(first):
    text = _HEAD + ("$$\n\\delta\\dot{\\omega}_1 = " + first + " + O( \\delta\\omega^2 )\n$$\n\nand\n\n"
                    "$$\n\\delta\\dot{\\omega}_3 = O( \\delta\\omega^2 )\n$$\n")
    return [c for c in kept.check_text(text) if "O(" in c.latex]


def test_linearised_equations_about_a_steady_column_hold_to_first_order():
    rows = _rows("\\frac{( I_2 - I_3 )}{I_1}\\Omega \\delta\\omega_2")
    assert [c.verdict for c in rows] == ["holds", "holds"]
    assert all("to order 1" in c.why for c in rows)


def test_a_wrong_sign_in_the_linearised_equation_fails():
    rows = _rows("\\frac{( I_3 - I_2 )}{I_1}\\Omega \\delta\\omega_2")
    assert [c.verdict for c in rows] == ["fails", "holds"]


def test_a_steady_column_alone_names_no_perturbation():
    text = _HEAD.split(" A small")[0] + "\n\n$$\n\\dot{\\Omega} = 0\n$$\n"
    assert all(c.verdict != "fails" for c in kept.check_text(text))


def test_an_accented_delta_alone_is_no_quantity_delta():
    names = {"omega", "delta", "hat"}
    assert not delta_a_quantity("\\hat{ \\delta } |r|^2 and \\delta\\omega_1", names)
    assert delta_a_quantity("\\cos(\\Omega t + \\delta)", names)
