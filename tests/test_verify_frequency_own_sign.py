"""A frequency a text defines with the opposite sign to the derived one is the text's own name.

The free symmetric top's body frequency is written Ω = ω₃(I₃ − I₁)/I₁ by some texts and
Ω = ω₃(I₁ − I₃)/I₁ by others. A definition of either sign is read as the text's, and the
displays after it are judged with that Ω: with the text's sign they hold, with the other sign they
are flagged. A definition with another slip (a wrong moment) is still flagged.
"""
import kept_readings as kept

HEAD = """# Free symmetric top

Torque-free, with $I_1 = I_2$:

$$I_1\\dot{\\omega}_1 = (I_1 - I_3)\\omega_2\\omega_3$$

$$I_1\\dot{\\omega}_2 = (I_3 - I_1)\\omega_3\\omega_1$$

Define

$$%s$$

Then

$$%s$$
"""


def _verdicts(definition, use):
    claims = kept.check_text(HEAD % (definition, use))
    return {c.latex: c.verdict for c in claims}


OWN = r"\Omega \equiv \frac{I_1 - I_3}{I_1}\omega_3"


def test_the_text_s_sign_for_its_frequency_is_kept_and_its_uses_hold():
    got = _verdicts(OWN, r"\dot{\omega}_1 = \Omega\omega_2")
    assert got[OWN] == "holds"
    assert got[r"\dot{\omega}_1 = \Omega\omega_2"] == "holds"


def test_a_use_with_the_other_sign_is_flagged():
    got = _verdicts(OWN, r"\dot{\omega}_1 = -\Omega\omega_2")
    assert got[OWN] == "holds"
    assert got[r"\dot{\omega}_1 = -\Omega\omega_2"] in ("typo", "fails")


def test_the_derived_sign_is_read_as_before():
    usual = r"\Omega \equiv \frac{I_3 - I_1}{I_1}\omega_3"
    got = _verdicts(usual, r"\dot{\omega}_1 = -\Omega\omega_2")
    assert got[usual] == "holds" and got[r"\dot{\omega}_1 = -\Omega\omega_2"] == "holds"


def test_a_definition_with_a_wrong_moment_is_still_flagged():
    wrong = r"\Omega \equiv \frac{I_1 - I_3}{I_3}\omega_3"
    assert _verdicts(wrong, r"\dot{\omega}_1 = \Omega\omega_2")[wrong] in ("typo", "fails")
