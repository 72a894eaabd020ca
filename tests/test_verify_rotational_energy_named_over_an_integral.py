"""The notes reader on an integral over the body's mass under a name labelled as the rotational part
of the kinetic energy (T_rot = ½ ∫_B ṙ·ṙ dm = ½ ∫_B (𝛚 × 𝐫)·(𝛚 × 𝐫) dm)."""
import kept_readings as kept

_TEXT = ("# Energy\n\nEvery point of the body moves about the centre of mass with omega cross r, so\n\n"
         "$$\nT_{rot} = \\frac{1}{2} \\int_B \\dot{\\mathbf{r}} \\cdot \\dot{\\mathbf{r}} \\, dm = "
         "\\frac{1}{2} \\int_B {last} \\, dm\n$$\n")


def _verdicts(last):
    return {c.verdict for c in kept.check_text(_TEXT.replace("{last}", last)) if c.line == 5}


def test_an_integral_over_the_mass_under_a_rotational_energy_name_is_checked():
    assert _verdicts(r"(\boldsymbol{\omega} \times \mathbf{r}) \cdot (\boldsymbol{\omega} \times \mathbf{r})") == {"holds"}


def test_a_slipped_integrand_under_a_rotational_energy_name_is_flagged():
    assert "fails" in _verdicts(r"(\boldsymbol{\omega} \cdot \mathbf{r}) (\boldsymbol{\omega} \cdot \mathbf{r})")
