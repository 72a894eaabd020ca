"""The heavy top's equation for the tilt β, written in the rates (Lagrange's form) or in the conserved
momenta (Routh's): each is judged against the form it is written in (`derive.lecture.motion`), which is
the same equation once the momenta are written in the rates."""
import pytest

from derive.lecture import notes_check as nc

RATES = (r"I_1\ddot\beta = I_1\dot\alpha^2\sin\beta\cos\beta - I_3(\dot\gamma + \dot\alpha\cos\beta)\dot\alpha\sin\beta"
         r" {sign} Mgl\sin\beta")
MOMENTA = (r"I_1\ddot\beta = \frac{(p_\alpha - p_\gamma\cos\beta)^2\cos\beta}{I_1\sin^3\beta}"
           r" - \frac{(p_\alpha - p_\gamma\cos\beta)p_\gamma}{I_1\sin\beta} {sign} Mgl\sin\beta")


def _verdicts(statement):
    text = "# The heavy symmetric top\n\nIts equation for the tilt:\n\n$$" + statement + "$$\n"
    return {c.verdict for c in nc.check_text(text) if c.line == 5}


@pytest.mark.parametrize("equation", [RATES, MOMENTA], ids=["rates", "momenta"])
def test_the_tilts_equation_holds_in_the_form_it_is_written_in(equation):
    assert _verdicts(equation.replace("{sign}", "+")) == {"holds"}


@pytest.mark.parametrize("equation", [RATES, MOMENTA], ids=["rates", "momenta"])
def test_the_tilts_equation_with_the_weights_sign_slipped_does_not_hold(equation):
    assert "holds" not in _verdicts(equation.replace("{sign}", "-"))
