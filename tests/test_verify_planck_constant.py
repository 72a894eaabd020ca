"""``\\hbar`` is read as a letter of the text's own: the algebra written in it is checked, and a
quantum claim about a quantity the derivation knows (an energy level E = ħω) is never judged as
the rigid body's classical energy."""
import sympy as sp

import kept_readings as kept
from derive.lecture.matrix_exp import MatrixExp

HEAD = "---\nconvention: z-y-z\n---\n# Planck's constant\n\n"


def _verdicts(tex):
    return [c.verdict for c in kept.check_text(HEAD + "$$\n" + tex + "\n$$\n")]


def test_algebra_in_planck_constant_is_checked():
    assert set(_verdicts(r"x = \frac{\hbar}{2} + \frac{\hbar}{2} = \hbar")) == {"holds"}


def test_a_slip_in_planck_constant_is_never_called_true():
    assert "holds" not in _verdicts(r"x = \frac{\hbar}{2} + \frac{\hbar}{2} = 2\hbar")


def test_an_energy_level_in_planck_constant_is_not_judged_as_the_classical_energy():
    assert set(_verdicts(r"E = \frac{\hbar}{2} + \frac{\hbar}{2} = \hbar")) == {"unchecked"}
    assert set(_verdicts(r"E = \hbar \omega")) == {"unchecked"}



def test_exponential_of_a_matrix_with_a_cubic_characteristic_polynomial_is_left_unread():
    # a spin-one operator with a letter among its entries: its Jordan form needs the roots of a
    # symbolic cubic, which take SymPy minutes, so the exponential stays unevaluated (unread)
    beta, o = sp.symbols("beta o", real=True)
    cubic = sp.ImmutableMatrix([[0, -sp.I, 0], [sp.I, 0, -sp.I], [0, sp.I, o]]) * (-sp.I * beta)
    assert not isinstance(MatrixExp(cubic), sp.MatrixBase)
    half = sp.ImmutableMatrix([[0, -sp.I], [sp.I, 0]]) * (-sp.I * beta / 2)
    assert sp.simplify(MatrixExp(half) - sp.Matrix([[sp.cos(beta / 2), -sp.sin(beta / 2)],
                                                    [sp.sin(beta / 2), sp.cos(beta / 2)]])) == sp.zeros(2, 2)
