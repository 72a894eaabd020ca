"""The notes reader on a function of a letter it would take for a quantity with a dimension: a sine
of an energy or a cosine of a mass says the text's letter is its own (Kepler's equation in the mean
and eccentric anomalies M and E), so the display is left unchecked, never judged in the derivation's
names; a function of an angle, or of a rate times the time, is read as before."""
import kept_readings as kept
from derive.lecture import latex as lx
from derive.lecture.dimensional_arguments import dimensional_argument

verdicts, line_of = kept.verdicts_by_line, kept.line_of


def test_keplers_equation_in_the_anomalies_is_unchecked_not_a_failed_definition():
    text = ("# Orbits\n\nThe mean anomaly $M$ relates to the eccentric anomaly $E$ through\n\n"
            "$$\nM = E - e \\sin E\n$$\n")
    assert verdicts(text)[line_of(text, "$$\nM = E")] == {"unchecked"}


def test_a_function_of_an_energy_a_mass_or_a_moment_names_what_the_letter_would_be():
    vocab = lx.Vocabulary(open=True)
    for latex, said in (("x = \\cos(M/2)", "a mass"), ("y = e^{-2 T}", "a kinetic energy"),
                        ("z = \\tan I_1", "a moment of inertia")):
        why = dimensional_argument(lx.parse(latex, vocab).members)
        assert why is not None and said in why, (latex, why)


def test_functions_of_angles_and_of_a_rate_times_the_time_are_read_as_before():
    vocab = lx.Vocabulary(open=True)
    for latex in ("T = \\frac{1}{2} I_1 \\dot\\theta^2 \\sin^2\\theta", "x = \\cos(\\omega t)", "E = e^{2}"):
        assert dimensional_argument(lx.parse(latex, vocab).members) is None, latex
    text = ("# Top\n\n$$\nT = \\frac{1}{2} I_1 (\\dot\\theta^2 + \\dot\\phi^2 \\sin^2\\theta) + "
            "\\frac{1}{2} I_3 (\\dot\\psi + \\dot\\phi \\cos\\theta)^2\n$$\n")
    assert verdicts(text)[line_of(text, "$$\nT =")] == {"holds"}
