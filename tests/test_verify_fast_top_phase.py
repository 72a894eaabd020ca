"""The fast top's limit for a fast spin is not sought for a value that depends on the spin only
through the phase of a sine or cosine (it oscillates with the spin: no slow precession)."""
import sympy as sp

from derive.lecture import fast_top
from derive.symbolic.lagrangian import I1, I3, Mass, g, l

S = fast_top._S
t = sp.Symbol("t")


def test_a_value_oscillating_with_the_spins_phase_has_no_lead():
    assert fast_top._lead(sp.sqrt(1 - sp.cos(S * t - I3 * S * t / I1)) * Mass * g * l / (I1 - I3)) is None


def test_a_phase_beside_the_spin_itself_is_still_taken_to_its_limit():
    assert fast_top._lead(Mass * g * l / I3 + sp.sin(S) / S) == Mass * g * l / I3
