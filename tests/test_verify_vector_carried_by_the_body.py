"""The notes reader on a vector of the text's own that turns with the body: d𝐀/dt = 𝛚 × 𝐀, for an
𝐀 the derivation knows nothing of, holds exactly when 𝐀's body components are constant, so the
statement is the text's set-up of 𝐀 (left unchecked), not a slip; a statement that fails for a
body-fixed 𝐀 as well is still flagged, and the transport theorem, true of any vector, still holds."""
import kept_readings as kept

verdicts, line_of = kept.verdicts_by_line, kept.line_of
PROSE = "# Notes\n\nA vector $\\boldsymbol{A}$ turns with the body, whose angular velocity is $\\boldsymbol{\\omega}$:\n\n"


def _read(display):
    text = PROSE + "$$" + display + "$$\n"
    return verdicts(text)[line_of(text, "$$")]


def test_the_rate_of_a_vector_of_the_texts_set_to_omega_cross_it_is_its_set_up_not_a_slip():
    assert _read("\\frac{d\\boldsymbol{A}}{dt} = \\boldsymbol{\\omega}\\times\\boldsymbol{A}") == {"unchecked"}


def test_a_rate_wrong_for_a_body_fixed_vector_too_is_still_flagged():
    assert _read("\\frac{d\\boldsymbol{A}}{dt} = -\\boldsymbol{\\omega}\\times\\boldsymbol{A}") & {"fails", "typo"}


def test_the_transport_theorem_for_the_same_vector_still_holds():
    assert _read("\\frac{d\\boldsymbol{A}}{dt} = \\left(\\frac{d\\boldsymbol{A}}{dt}\\right)_{body} + "
                 "\\boldsymbol{\\omega}\\times\\boldsymbol{A}") == {"holds"}
