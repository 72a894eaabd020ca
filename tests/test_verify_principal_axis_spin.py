"""A spin about a principal axis and its small disturbance, as stability sections write them: the
angular velocity along the body's principal axes names its components, prose that calls them "very
small" linearises, and the rate of a body component of the angular momentum is Iᵢω̃̇ᵢ
(derive/lecture/vector_claims.py, derive/lecture/notes.py, derive/lecture/vocabulary.py)."""
import kept_readings as kept

_HEAD = ("A rigid body with principal moments $I_1$, $I_2$, $I_3$ turns freely. Let it spin about the first "
         "principal axis:\n\n"
         "$$\n\\boldsymbol{\\omega} = \\omega_1 \\widehat{\\mathbf{e}}_1\n$$\n\n"
         "A disturbance gives it components along the other two axes:\n\n"
         "$$\n\\boldsymbol{\\omega} = \\omega_1 \\widehat{\\mathbf{e}}_1 + \\lambda \\widehat{\\mathbf{e}}_2 + "
         "\\mu \\widehat{\\mathbf{e}}_3\n$$\n\n")


def _at(claims, line):
    return [c for c in claims if c.line == line]


def test_the_angular_velocity_along_the_principal_axes_sets_its_components_and_is_no_claim():
    claims = kept.check_text(_HEAD + "Then\n\n$$\n\\dot{\\lambda} = \\frac{I_3 - I_1}{I_2} \\omega_1 \\mu\n$$\n")
    spin, disturbed = _at(claims, 3), _at(claims, 9)
    assert [c.verdict for c in spin] == ["unchecked"] and "_{2} = 0" in spin[0].why
    assert [c.verdict for c in disturbed] == ["unchecked"] and "_{2} = \\lambda" in disturbed[0].why
    assert [c.verdict for c in _at(claims, 15)] == ["holds"]          # Euler's second equation in λ, μ


def test_a_hatted_unit_vector_written_with_an_arrow_is_a_principal_axis_too():
    # \widehat{\vec{e}}_1 is the unit vector ê₁ as \widehat{\mathbf{e}}_1 is: the spin and its disturbance set
    # the components as before, and Euler's second equation in λ, μ holds
    text = _HEAD.replace("\\mathbf{e}", "\\vec{e}") + "Then\n\n$$\n\\dot{\\lambda} = \\frac{I_3 - I_1}{I_2} \\omega_1 \\mu\n$$\n"
    claims = kept.check_text(text)
    assert [c.verdict for c in _at(claims, 3)] == ["unchecked"] and "_{2} = 0" in _at(claims, 3)[0].why
    assert [c.verdict for c in _at(claims, 9)] == ["unchecked"] and "_{2} = \\lambda" in _at(claims, 9)[0].why
    assert [c.verdict for c in _at(claims, 15)] == ["holds"]


def test_a_slip_in_the_named_components_is_flagged():
    claims = kept.check_text(_HEAD + "Then\n\n$$\n\\dot{\\lambda} = \\frac{I_1 - I_3}{I_2} \\omega_1 \\mu\n$$\n")
    assert any(c.verdict in ("typo", "fails") for c in _at(claims, 15))


def test_a_vector_with_an_expression_along_an_axis_is_not_read_as_its_components():
    text = "$$\n\\boldsymbol{\\omega} = \\omega \\cos\\theta \\widehat{\\mathbf{e}}_1\n$$\n"
    assert not any("principal axes" in c.why for c in kept.check_text(text))


def test_prose_that_calls_components_very_small_linearises_the_equations_after_it():
    head = "A body spins about its first principal axis, $\\omega_1 = \\Omega$.\n\n"
    eq = "$$\nI_1\\dot{\\omega}_1 = 0\n$$\n"
    small = kept.check_text(head + "Here $\\omega_2$ and $\\omega_3$ are very small, so\n\n" + eq)
    assert [c.verdict for c in _at(small, 5)] == ["holds"] and "first order" in _at(small, 5)[0].why
    exact = kept.check_text(head + "Here $\\omega_2$ and $\\omega_3$ are the other components, so\n\n" + eq)
    assert [c.verdict for c in _at(exact, 5)] != ["holds"]


def test_the_rate_of_a_body_component_of_the_angular_momentum_is_its_moment_times_the_rate():
    text = "With $L_i = I_i\\omega_i$ in principal axes, the free body's equations read\n\n"
    good = kept.check_text(text + "$$\nI_2I_3\\dot{L}_1 = (I_2 - I_3)L_2L_3\n$$\n")
    assert [c.verdict for c in _at(good, 3)] == ["holds"]
    bad = kept.check_text(text + "$$\nI_2I_3\\dot{L}_1 = (I_3 - I_2)L_2L_3\n$$\n")
    assert any(c.verdict in ("typo", "fails") for c in _at(bad, 3))


_OSCILLATOR = (_HEAD + "where $\\lambda$ and $\\mu$ are very small. Eliminating $\\mu$:\n\n"
               "$$\n\\ddot{\\lambda} + \\left(\\frac{(I_1 - I_3) (I_1 - I_2)}{ I_2I_3} \\omega^2_1 \\right) \\lambda = 0\n$$\n\n"
               "Its solution is\n\n$$\n\\lambda (t) = Ae^{i\\Omega t} + Be^{-i\\Omega t}\n$$\n\nwith\n\n")


def test_a_disturbance_in_complex_exponentials_solves_the_oscillator_about_a_steady_spin():
    good = kept.check_text(_OSCILLATOR + "$$\n\\Omega = \\omega_1 \\sqrt{\\frac{(I_1 - I_3) (I_1 - I_2)}{I_2I_3}}\n$$\n")
    assert [c.verdict for c in _at(good, 21)] == ["holds"]
    wrong = kept.check_text(_OSCILLATOR + "$$\n\\Omega = \\omega_1 \\sqrt{\\frac{(I_1 - I_3) (I_1 - I_2)}{I_1I_3}}\n$$\n")
    assert any(c.verdict in ("typo", "fails") for c in _at(wrong, 21))


def test_the_angular_momentum_as_its_own_component_along_one_axis_is_a_setting_not_a_claim():
    # after L_i = I_i ω_i names the components, 𝐋 = L₂ ê₂ chooses the axes by 𝐋 in an example (L₁ = L₃ = 0
    # there); compared with the body's general 𝐋 it would be flagged, though the text states no slip
    text = ("With the body axes chosen as principal axes, with principal moments $I_i$,\n\n"
            "$$\nL_i = I_i \\omega_i\n$$\n\n"
            "In an example the angular momentum is perpendicular to a shaft; the 2 axis is chosen along it:\n\n"
            "$$\n\\mathbf{L} = L_2 \\widehat{\\mathbf{e}_2}\n$$\n")
    setting = _at(kept.check_text(text), 9)
    assert [c.verdict for c in setting] == ["unchecked"] and "L_1 = L_3 = 0" in setting[0].why
