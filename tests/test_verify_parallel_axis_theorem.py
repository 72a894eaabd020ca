"""The notes reader on the parallel-axis theorem as a text states it (I_P = I_G + m d²: a moment of
inertia is the centre of mass's, of the same letter, plus the mass times the squared distance):
it holds, and the name it sets is still the text's own; other forms are not judged by it."""
import kept_readings as kept

HEAD = "# Moments\n\nThe moment about a parallel axis at a distance $d$ from the centre of mass:\n\n"


def _claims(display, after=""):
    text = HEAD + "$$" + display + "$$\n\n" + after
    return kept.by_line(text)


def test_the_theorem_holds_as_written_with_the_centre_of_mass_subscript():
    for display in ("J_{z^\\prime} = J_C + m d^2", "I_O = I_G + M a^2", "I_{cm} = I_P - m h^2"):
        [claim] = next(iter(_claims(display).values()))
        assert (claim.verdict, claim.kind) == ("holds", "parallel axes"), display


def test_the_name_the_theorem_sets_is_used_after_it():
    after = "$$J_C = J_{z^\\prime} - m d^2$$\n"
    claims = _claims("J_{z^\\prime} = J_C + m d^2", after)
    assert [c.verdict for c in claims[max(claims)]] == ["holds"]


def test_a_wrong_sign_or_power_is_not_taken_for_the_theorem():
    for display in ("I_O = I_G - M a^2", "I_O = I_G + M a", "I_G = I_O + M a^2", "I_O = J_G + M a^2"):
        verdicts = {c.verdict for cs in _claims(display).values() for c in cs}
        assert "holds" not in verdicts, display
