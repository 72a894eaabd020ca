"""The notes reader on an inequality between a free body's constants of the motion after the text
orders its moments: ``I_3 > I_2 > I_1`` written either way round is the ordering I₁ < I₂ < I₃, and
``2I_1T \\le L^2 \\le 2I_3T`` is read with T = ½ Σ Iᵢω̃ᵢ² and L² = Σ Iᵢ²ω̃ᵢ² (the body's kinetic energy
and its angular momentum's magnitude, in the rates): each link holds when its difference keeps one
sign for every rate under that ordering, is a typo when its opposite does, and is left unchecked
otherwise (2I₂T against L² takes either sign)."""
import kept_readings as kept

verdicts, line_of = kept.verdicts_by_line, kept.line_of
PROSE = ("# Free body\n\nThe moments are labelled so that\n\n$$\nI_3>I_2>I_1\n$$\n\n"
         "Conservation of the angular momentum and of the energy give\n\n"
         "$$\nI_1^2 \\omega_1^2+I_2^2 \\omega_2^2+I_3^2 \\omega_3^2 = L^2\n$$\n\n"
         "$$\nI_1 \\omega_1^2+I_2 \\omega_2^2+I_3 \\omega_3^2 = 2T\n$$\n\nso that\n\n")


def _verdict(statement: str) -> set:
    text = PROSE + "$$\n" + statement + "\n$$\n"
    return verdicts(text)[line_of(text, "$$\n" + statement)]


def test_the_range_of_the_angular_momentum_between_the_extreme_moments_holds():
    assert _verdict("2I_1T\\leqslant L^2\\leqslant 2I_3T") == {"holds"}


def test_the_angular_momentum_below_the_least_moment_bound_is_a_reversed_relation():
    assert _verdict("L^2\\leqslant 2I_1T") == {"typo"}


def test_the_middle_moment_bound_is_left_unchecked():
    assert _verdict("2I_2T\\leqslant L^2") == {"unchecked"}
