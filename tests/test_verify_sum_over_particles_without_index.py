"""Σ m(y² + z²), Σ mxy: a sum written with no index whose summand is the mass m and the coordinates
x, y, z, none subscripted, is a sum over the body's particles, as ∫(y² + z²) dm is over its mass:
the inertia tensor's entries written so are judged; a wrong entry is flagged, and a bare sum over
anything else stays unread."""
import kept_readings as kept

HEAD = "# Inertia tensor\n\nIts elements, summed over the particles of the body:\n\n$$%s$$\n"


def _verdicts(formula):
    return [c.verdict for c in kept.check_text(HEAD % formula)]


def test_the_moments_and_products_of_inertia_summed_without_an_index_hold():
    assert _verdicts(r"I_{xx} = \sum m(y^2 + z^2), \quad I_{yy} = \sum m(x^2 + z^2), \quad I_{zz} = \sum m(x^2 + y^2)") \
        == ["holds"] * 3
    assert _verdicts(r"I_{xy} = -\sum mxy") == ["holds"]


def test_a_wrong_moment_summed_without_an_index_is_flagged():
    assert _verdicts(r"I_{xx} = \sum m(x^2 + z^2)") in (["typo"], ["fails"])


def test_a_bare_sum_over_other_quantities_stays_unread():
    claims = kept.check_text(HEAD % r"F = \sum F_{i,x} + G")
    assert all(c.verdict == "unchecked" for c in claims)
    assert any("a sum without its index" in c.why for c in claims)
