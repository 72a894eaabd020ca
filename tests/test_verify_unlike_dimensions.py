"""A sum of unlike quantities is a slip wherever it stands: a free top's solution written in its
angular momentum with h = ‖Π‖ where the derivation has h² (h − 2E I₃ adds an angular momentum to
its square) is flagged, the same formula with h² is not, and a letter whose dimension the text has
not tied (by an equation setting it equal to members of known dimensions) is never compared."""
import kept_readings as kept

HEAD = ("---\nconvention: z-x-z\n---\n# The free asymmetric top\n\n"
        "The body angular momentum $\\Pi$ has components $\\Pi_1, \\Pi_2, \\Pi_3$ along the principal axes, "
        "with principal moments $I_1 > I_2 > I_3$.\n\n")
ENERGY = "$$\nE = \\frac{1}{2}\\left(\\frac{\\Pi_1^2}{I_1} + \\frac{\\Pi_2^2}{I_2} + \\frac{\\Pi_3^2}{I_3}\\right)\n$$\n\n"
NORM = "$$\nh^2 = \\Pi_1^2 + \\Pi_2^2 + \\Pi_3^2\n$$\n\n"
SLIP = "$$\n\\Pi_2(t) = \\sqrt{\\frac{I_2 (h - 2 E I_3)}{I_2 - I_3}} \\, \\mathrm{sn}(\\lambda t)\n$$\n\n"
RIGHT = "$$\n\\Pi_2(t) = \\sqrt{\\frac{I_2 (h^2 - 2 E I_3)}{I_2 - I_3}} \\, \\mathrm{sn}(\\lambda t)\n$$\n\n"
MODULUS = "$$\nk^2 = \\frac{(I_1 - I_2)(h^2 - 2 E I_3)}{(I_2 - I_3)(2 E I_1 - h)}\n$$\n\n"


def _claims(text, start):
    return [c for c in kept.check_text(text) if c.latex.startswith(start)]


def _flagged(text, start):
    return [c for c in _claims(text, start) if c.verdict in ("typo", "fails")]


def test_h_for_h_squared_in_the_amplitude_is_flagged_and_h_squared_holds():
    flagged = _flagged(HEAD + ENERGY + NORM + SLIP, "\\Pi_2(t)")
    assert [c.verdict for c in flagged] == ["fails"]
    assert "unlike dimensions" in flagged[0].why and "2 E I_3" in flagged[0].why and "h (M L^2 T^-1)" in flagged[0].why
    assert _flagged(HEAD + ENERGY + NORM + RIGHT, "\\Pi_2(t)") == []


def test_the_modulus_with_h_in_one_factor_is_flagged():
    assert [c.verdict for c in _flagged(HEAD + ENERGY + NORM + MODULUS, "k^2")] == ["fails"]
    right = MODULUS.replace("2 E I_1 - h)", "2 E I_1 - h^2)")
    assert _flagged(HEAD + ENERGY + NORM + right, "k^2") == []


def test_a_letter_the_text_has_not_tied_is_never_compared():
    # no equation gives h its dimension: h − 2E I₃ may be anything the text means by h
    assert _flagged(HEAD + ENERGY + SLIP, "\\Pi_2(t)") == []
    # nor E, whose dimension only the energy's equation gives
    assert _flagged(HEAD + NORM + SLIP, "\\Pi_2(t)") == []


def test_a_letter_two_equations_give_unlike_dimensions_is_unknown():
    twice = NORM + "$$\nh = I_1 \\Pi_1^2\n$$\n\n"
    assert _flagged(HEAD + ENERGY + twice + SLIP, "\\Pi_2(t)") == []


def test_a_name_set_to_a_number_is_not_compared():
    # a worked example in scaled units: I₃ = 1 makes h − 2E I₃ a sum the text may mean
    scaled = HEAD.replace("$I_1 > I_2 > I_3$", "$I_1 > I_2 > I_3$ and, in scaled units, $I_3 = 1$")
    assert _flagged(scaled + ENERGY + NORM + SLIP, "\\Pi_2(t)") == []


def test_a_display_the_reader_flags_already_is_not_flagged_twice():
    # the energy with ω₃ unsquared: its reading finds the one edit, the sum of unlike terms adds nothing
    text = HEAD + "$$\nT = \\frac{1}{2}\\left(I_1 \\omega_1^2 + I_2 \\omega_2^2 + I_3 \\omega_3\\right)\n$$\n"
    claims = _claims(text, "T =")
    assert [c.verdict for c in claims if c.verdict in ("typo", "fails")] == ["typo"]
    assert not any(c.kind == "dimensions" for c in claims)


SHIFT = ("A body's centre of mass sits at $\\mathbf{a} = (a_1, a_2, a_3)$ from the point $O$.\n\n"
         "$$\nJ_{11} = I_{11} + M((a_1^2 + a_2^2 + a_3^%s) \\delta_{11} - a_1^2)\n$$\n\n")


def test_one_component_of_a_vector_raised_to_another_power_in_its_sum_is_flagged():
    # the components of one vector share a dimension: a_1² + a_2² + a_3³ adds unlike quantities
    flagged = _flagged(HEAD + SHIFT % "3", "J_{11}")
    assert [c.verdict for c in flagged] == ["fails"] and "a_{3}^{3}" in flagged[0].why
    assert _flagged(HEAD + SHIFT % "2", "J_{11}") == []


def test_powers_of_two_components_or_of_several_alike_are_not_compared():
    # two terms give no majority to call the other odd; a polynomial's powers 1, 2, 3 are all unlike
    two = "$$\nJ_{11} = I_{11} + M(a_1^2 + a_2^3)\n$$\n\n"
    series = "$$\nJ_{11} = I_{11} + M(a_1 + a_2^2 + a_3^3)\n$$\n\n"
    assert _flagged(HEAD + two, "J_{11}") == [] and _flagged(HEAD + series, "J_{11}") == []


TOP = ("---\nconvention: z-x-z\n---\n# The symmetric top\n\n"
       "For the symmetric top $I_1 = I_2$ and Euler's equations read\n\n"
       "$$\nI_1\\dot{\\omega}_1 = (I_1 - I_3)\\omega_2\\omega_3\n$$\n\n")
SQUARE = ("The angular momentum's square is constant, with $A$ the radius of the circle:\n\n"
          "$$\nL^2 = I_1^2 A^2 + I_3^2 \\omega_3^2\n$$\n\n")
ANGLE = "so\n\n$$\n\\cos\\tau = \\frac{I_3\\omega_3}{\\sqrt{I_1^2 A^2 + I_3^2\\omega_3%s}}\n$$\n"


def test_a_letter_in_one_term_of_a_sum_of_known_terms_takes_their_dimension():
    # L² = I₁²A² + I₃²ω₃² makes A a rate: I₁²A² + I₃²ω₃ (ω₃ unsquared) adds unlike quantities
    flagged = _flagged(TOP + SQUARE + ANGLE % "", "\\cos\\tau")
    assert [c.verdict for c in flagged] == ["fails"] and "A^{2} I_1^{2}" in flagged[0].why
    assert _flagged(TOP + SQUARE + ANGLE % "^2", "\\cos\\tau") == []
    # without the sum that ties it, A may be anything the text means by it
    assert _flagged(TOP + ANGLE % "", "\\cos\\tau") == []


def test_a_sum_with_a_pure_number_or_two_untied_letters_ties_no_letter():
    scaled = SQUARE.replace("I_3^2 \\omega_3^2", "I_3^2 \\omega_3^2 + 1")
    two = SQUARE.replace("I_1^2 A^2", "I_1^2 A^2 B")
    assert _flagged(TOP + scaled + ANGLE % "", "\\cos\\tau") == []
    assert _flagged(TOP + two + ANGLE % "", "\\cos\\tau") == []


AXES = ("---\nconvention: z-x-z\n---\n# A disk on an elbow\n\n"
        "The disk has moments $I_x$ and $I_z$ about its body axes and mass $M$ a distance $s$ from the pivot.\n\n")
SPIN_UNSQUARED = ("$$ T = \\frac{1}{2}I_{z}\\left(\\dot{\\phi} + \\cos\\theta\\,\\dot{\\psi}\\right) + "
                  "\\frac{1}{2}I_{x}\\sin^2\\theta\\,\\dot{\\psi}^2 + \\frac{1}{2}M s^2 \\sin^2\\theta\\,\\dot{\\psi}^2 $$\n\n")


def test_two_terms_alike_but_for_two_axis_components_of_one_letter_are_compared():
    # I_z and I_x share a dimension, whatever it is: I_z times a rate beside I_x times a rate squared is unlike
    flagged = _flagged(AXES + SPIN_UNSQUARED, "T =")
    assert [c.verdict for c in flagged] == ["fails"]
    assert "[I] T^-1" in flagged[0].why and "[I] T^-2" in flagged[0].why
    squared = SPIN_UNSQUARED.replace("\\dot{\\psi}\\right)", "\\dot{\\psi}\\right)^2")
    assert _flagged(AXES + squared, "T =") == []


def test_numbered_components_or_unlike_letters_are_not_compared():
    # C_1 + C_2 t: a solution's constants are numbered, not components along axes
    assert _flagged(AXES + "$$ x = C_1 + C_2 t $$\n\n", "x =") == []
    # two letters' components: I_z and J_x need not share a dimension
    other = SPIN_UNSQUARED.replace("I_{x}", "J_{x}")
    assert _flagged(AXES + other, "T =") == []
