"""A letter the prose sets equal to a numbered principal moment ("$I_3 = C$", "($A = I_1 = I_2$, $C
= I_3$)") or calls the equal moments ("the equal moments called $A$") is that moment; a letter in use
before, or set equal to moments of two kinds, is bound to nothing."""
import kept_readings as kept

HEAD = "---\nconvention: z-y-z\n---\n# Heavy top\n\nThe top has mass $M$ and a distance $l$ from the pivot to its centre of mass.\n"
LAGRANGIAN = r"""

$$
\mathcal{L} = \frac{1}{2}A(\dot\beta^2 + \dot\alpha^2\sin^2\beta) + \frac{1}{2}C(\dot\gamma + \dot\alpha\cos\beta)^2 - Mgl\cos\beta
$$

$$
p_\gamma = C(\dot\gamma + \dot\alpha\cos\beta)
$$
"""
SLIP = LAGRANGIAN.replace(r"\cos\beta)^2 - Mgl", r"\cos\beta) - Mgl")


def _verdicts(prose, displays=LAGRANGIAN):
    text = HEAD + prose + displays
    by_line = kept.verdicts_by_line(text)
    # a display's claims stand on the line of its opening $$
    return [by_line.get(kept.line_of(text, marker) - 1, set()) for marker in (r"\mathcal{L} =", r"p_\gamma =")]


def test_the_equal_moments_called_a_letter_and_a_moment_set_equal_to_a_new_letter():
    prose = "Its third axis is a symmetry axis, with the equal moments called $A$ and $I_3 = C$, so"
    assert _verdicts(prose) == [{"holds"}, {"holds"}]


def test_letters_set_equal_to_the_moments_in_brackets():
    assert _verdicts("Its moments are written ($A = I_1 = I_2$, $C = I_3$), so") == [{"holds"}, {"holds"}]


def test_a_letter_the_text_used_before_is_not_taken_for_a_moment():
    prose = "The point $C$ is the tip of the top. Its moments are written ($A = I_1 = I_2$, $C = I_3$), so"
    assert _verdicts(prose) == [{"unchecked"}, {"unchecked"}]


def test_a_letter_set_equal_to_moments_of_two_kinds_is_bound_to_nothing():
    prose = "Its moments are written ($A = I_1 = I_3$, $C = I_3$), so"
    assert _verdicts(prose) == [{"unchecked"}, {"holds"}]


def test_a_slip_in_letters_the_prose_named_is_never_a_hold():
    prose = "Its moments are written ($A = I_1 = I_2$, $C = I_3$), so"
    lagrangian, momentum = _verdicts(prose, SLIP)
    assert "holds" not in lagrangian and momentum == {"holds"}


def test_a_letter_defined_as_the_equal_moments_with_a_sign_of_definition():
    assert _verdicts(r"Its moments are written $A \equiv I_1 = I_2$ and $C := I_3$, so") == [{"holds"}, {"holds"}]


def test_letters_set_equal_to_moments_about_principal_axes_named_x_y_z():
    prose = "The body axes are principal axes, with $I_x = I_y = A$ and $I_z = C$, so"
    assert _verdicts(prose) == [{"holds"}, {"holds"}]
    assert _verdicts(prose.replace("The body axes are principal axes, with", "With")) == [{"unchecked"}, {"unchecked"}]


def test_two_equal_moments_make_the_body_symmetric_and_no_two_equal_moments_do_not():
    def why(prose):
        text = HEAD + prose + " We write ($A = I_1$, $C = I_3$).\n\n$$\nT = \\frac{1}{2}[A(\\omega_1^2 + \\omega_2^2) + C\\omega_3^2]\n$$\n"
        return [c.why for c in kept.check_text(text) if c.latex.strip().startswith("T =")]
    symmetric, asymmetric = why("The body has two equal moments."), why("The body has no two equal moments.")
    assert symmetric and all("under I₁ = I₂" in w for w in symmetric)
    assert asymmetric and all("the text does not say so" in w for w in asymmetric)
