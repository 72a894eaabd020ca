"""The notes reader on sums whose range the text writes 1 to 3 over an index of any letter (Σ_{a=1}^3): read once
per body axis, the text's components under them given the index's value (r_a → r₁, r₂, r₃; r_a^{(i)}, particle
i's, never a power i), Kronecker's δ_{ak} its 0 or 1, and the components one sum adds given one dimension, so a
square of a sum of squared rates beside the square of a sum of single rates adds unlike quantities."""
import kept_readings as kept
from derive.lecture.axis_sums import range_letters

PROSE = "# Notes\n\nThe particles $m_i$ at $r_a^{(i)}$ turn at the rate $\\omega_k$; their rotational energy is\n\n"


def _claims(text, start):
    return [c for c in kept.check_text(text) if c.latex.startswith(start)]


def test_a_sum_over_any_letter_with_its_range_written_is_read_with_kroneckers_delta():
    text = PROSE + ("$$\nK = \\frac{1}{2} m \\left(\\sum_{k=1}^3 \\omega_k^2\\right) \\left(\\sum_{a=1}^3 r_a^2\\right) "
                    "= \\frac{1}{2} m \\sum_{a=1}^3 \\sum_{k=1}^3 \\omega_a \\omega_k \\delta_{ak} \\sum_{b=1}^3 r_b^2\n$$\n")
    assert "holds" in {c.verdict for c in _claims(text, "K =")}


def test_the_components_a_sum_adds_share_a_dimension():
    text = PROSE + ("$$\nK = \\frac{1}{2} \\sum_i m_i \\left[\\left(\\sum_{k=1}^3 \\omega_k^2\\right)^2 "
                    "\\left(\\sum_{a=1}^3 {r_a^{(i)}}^2\\right) - \\left(\\sum_{a=1}^3 r_a^{(i)}\\omega_a\\right)^2\\right]\n$$\n")
    claims = _claims(text, "K =")
    assert {c.verdict for c in claims if c.kind == "dimensions"} == {"fails"}
    assert "T^-2" in next(c.why for c in claims if c.kind == "dimensions")


def test_a_sum_whose_range_is_not_written_1_to_3_keeps_its_letter_unread():
    assert range_letters("a", 3, "{a=1}", 0) == ["a"]
    assert range_letters("a", 3, "{a=0}", 0) == []          # from 0: not the three body axes
    assert range_letters("a", 4, "{a=1}", 0) == []
    assert range_letters("ab", 3, "{ab=1}", 0) == []
