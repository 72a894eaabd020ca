"""The notes reader on a case of the free body's constants at an extreme moment, set in the prose
("In the limit $L^2=2I_3T$") after the text orders its moments: written in the body rates the case
is Σ Iᵢ(Iᵢ − I₃)ω̃ᵢ² = 0, a sum of squares of one sign, so the rates with a coefficient that is not
zero vanish there, and the text's ``\\omega_1 = \\omega_2 = 0`` (the permanent rotation about the
third axis) holds in the case; at the middle moment (L² = 2I₂T) the squares take both signs and the
same statement stays the text's setting, unchecked."""
import kept_readings as kept

verdicts, line_of = kept.verdicts_by_line, kept.line_of
PROSE = ("# Free body\n\nThe moments are labelled so that\n\n$$\nI_3>I_2>I_1\n$$\n\n"
         "Conservation of the angular momentum and of the energy give\n\n"
         "$$\nI_1^2 \\omega_1^2+I_2^2 \\omega_2^2+I_3^2 \\omega_3^2 = L^2\n$$\n\n"
         "$$\nI_1 \\omega_1^2+I_2 \\omega_2^2+I_3 \\omega_3^2 = 2T\n$$\n\n")


def _verdict(case: str, statement: str) -> set:
    text = PROSE + f"In the limit ${case}$,\n\n$$\n{statement}\n$$\n\na uniform rotation.\n"
    return verdicts(text)[line_of(text, "$$\n" + statement)]


def test_the_other_rates_vanish_in_the_case_of_the_largest_moment():
    assert _verdict("L^2=2I_3T", "\\omega_1 = \\omega_2 = 0") == {"holds"}


def test_the_other_rates_vanish_in_the_case_of_the_least_moment():
    assert _verdict("L^2=2I_1T", "\\omega_2 = \\omega_3 = 0") == {"holds"}


def test_a_rate_the_case_leaves_free_stays_a_setting():
    assert _verdict("L^2=2I_3T", "\\omega_3 = 0") == {"unchecked"}
    assert _verdict("L^2=2I_2T", "\\omega_1 = 0") == {"unchecked"}
