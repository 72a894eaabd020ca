"""A chain whose head the reader cannot tie to the body, with links between two integrals over the
body or two sums over its particles: each such link read alone, held when it is an identity, never
flagged when it is not (`derive/lecture/body_links.py`)."""
from kept_readings import by_line

NOTES = "# Power\n\nThe power of the external forces on the body.\n\n$$\nCHAIN\n$$\n"
POWER = (r"\frac{\mathrm{d} T}{\mathrm{d} t} = \int_V \mathbf{f}^{(e)} \cdot \dot{\mathbf{r}} \mathrm{d} V "
         r"= \int_V \mathbf{f}^{(e)} \cdot (\boldsymbol{\omega} \times \mathbf{r}) \mathrm{d} V "
         r"= \int_V \boldsymbol{\omega} \cdot (\mathbf{r} \times \mathbf{f}^{(e)}) \mathrm{d} V")


def _verdicts(chain):
    return [c.verdict for c in by_line(NOTES.replace("CHAIN", chain))[5]]


def test_a_link_between_two_integrals_over_the_body_holds_under_an_unread_head():
    assert "holds" in _verdicts(POWER)


def test_a_link_between_two_integrals_that_is_no_identity_is_left_unchecked_not_flagged():
    slip = POWER.replace(r"(\mathbf{r} \times \mathbf{f}^{(e)})", r"(\mathbf{f}^{(e)} \times \mathbf{r})")
    assert _verdicts(slip) == ["holds"]                  # the first link alone
    second = r"\frac{\mathrm{d} T}{\mathrm{d} t} = " + slip.split("= ", 2)[2]
    assert set(_verdicts(second)) == {"unchecked"}


def test_a_volume_element_beside_the_mass_is_not_read_as_the_mass_element():
    massive = (r"\frac{\mathrm{d} T}{\mathrm{d} t} = \int_V m \mathbf{f} \cdot (\boldsymbol{\omega} \times \mathbf{r}) "
               r"\mathrm{d} V = \int_V \boldsymbol{\omega} \cdot (\mathbf{r} \times \mathbf{f}) \mathrm{d} V")
    assert set(_verdicts(massive)) == {"unchecked"}


def test_a_link_from_the_bodys_momentum_to_its_integral_holds_and_one_resting_on_the_set_up_is_not_flagged():
    chain = (r"L_n = \mathbf{n} \cdot \mathbf{L} = \int_V \rho \mathbf{r} \times (\boldsymbol{\omega} \times \mathbf{r}) "
             r"\cdot \mathbf{n} \mathrm{d} V = \int_V \rho (\mathbf{n} \times \mathbf{r}) \cdot (\mathbf{n} \times \mathbf{r}) "
             r"\omega \mathrm{d} V")
    assert _verdicts(chain) == ["holds"]        # the last link holds only for omega along n


def test_a_position_from_a_reference_point_beside_a_velocity_is_not_read_from_the_origin():
    chain = (r"\mathbf{J} = \sum_{i=1}^n m_i \Delta\mathbf{r}_i \times \mathbf{v}_i "
             r"= \sum_{i=1}^n m_i \Delta\mathbf{r}_i \times (\boldsymbol{\omega} \times \Delta\mathbf{r}_i)")
    assert set(_verdicts(chain)) == {"unchecked"}
