"""The notes reader on three theorems of a rigid body as a text states them: the parallel-axis
theorem (I_P = I_G + m d²) and König's theorem (T = ½ m v_G² + ½ I_G ω², or ½ 𝛚·𝐇_G), the centre of
mass named by a subscript (and T = ½ 𝛚·𝐇_P, holding if P is at rest), and the projection theorem
(v_B cos θ_B = v_A cos θ_A). Each holds as written, a name it sets is still the text's own, and
another form is not judged by the rule (never flagged by it)."""
import kept_readings as kept

HEAD = "# Moments\n\nThe moment about a parallel axis at a distance $d$ from the centre of mass:\n\n"


def _claims(display, after=""):
    text = HEAD + "$$" + display + "$$\n\n" + after
    return kept.by_line(text)


def _kinds(display):
    return [(c.verdict, c.kind) for cs in _claims(display).values() for c in cs]


def test_the_parallel_axis_theorem_holds_as_written():
    for display in ("J_{z^\\prime} = J_C + m d^2", "I_O = I_G + M a^2", "I_{cm} = I_P - m h^2"):
        assert _kinds(display) == [("holds", "parallel axes")], display


def test_the_name_the_parallel_axis_theorem_sets_is_used_after_it():
    claims = _claims("J_{z^\\prime} = J_C + m d^2", "$$J_C = J_{z^\\prime} - m d^2$$\n")
    assert [c.verdict for c in claims[max(claims)]] == ["holds"]


def test_koenigs_theorem_holds_as_written_in_scalars_and_in_vectors():
    for display in ("T = \\frac{1}{2} m v_c^2 + \\frac{1}{2} J_C \\omega^2",
                    "T=\\frac{1}{2}m\\mathbf{v}_G^2+\\frac{1}{2}\\mathbf{\\omega H_G}",
                    "T = \\frac12 \\boldsymbol\\omega \\cdot \\mathbf{H}_G + \\frac12 M \\mathbf{v}_G^2"):
        assert _kinds(display) == [("holds", "König")], display


def test_koenigs_theorem_holds_in_every_bold_and_another_form_in_it_is_not_taken_for_it():
    written = "T=\\frac{1}{2}m\\mathbf{v}_G^2+\\frac{1}{2}\\mathbf{\\omega H_G}"
    for bold in ("\\bm", "\\pmb", "\\boldsymbol"):
        assert _kinds(written.replace("\\mathbf", bold)) == [("holds", "König")], bold
        assert "holds" not in {v for v, _ in _kinds(written.replace("\\mathbf", bold).replace("_G^2", "_B^2"))}, bold


def test_the_energy_about_a_point_holds_if_the_point_is_at_rest():
    for display in ("T=\\frac{1}{2}\\mathbf{\\omega H_B}", "T = \\frac{1}{2} \\boldsymbol{\\omega} \\cdot \\mathbf{H}_O"):
        [claim] = [c for cs in _claims(display).values() for c in cs]
        assert (claim.verdict, claim.kind) == ("holds", "fixed point"), display
        assert claim.why.startswith("holds if")


def test_the_projection_theorem_holds_as_written():
    for display in ("v_B \\cos \\theta_B = v_a \\cos \\theta_A", "v_B \\cos(\\alpha_B) = v_A \\cos(\\alpha_A)",
                    "v_B \\cos{\\theta_B} = v_A \\cos{\\theta_A}"):
        assert _kinds(display) == [("holds", "projection")], display


def test_other_forms_are_not_taken_for_the_theorems():
    for display in ("I_O = I_G - M a^2", "I_O = I_G + M a", "I_G = I_O + M a^2", "I_O = J_G + M a^2",
                    "T = \\frac{1}{2} m v_c^2 + J_C \\omega^2", "T=\\frac{1}{2}m\\mathbf{v}_B^2+\\frac{1}{2}\\mathbf{\\omega H_B}", "T = \\boldsymbol{\\omega} \\cdot \\mathbf{H}_O",
                    "T = \\frac{1}{2} m v_c + \\frac{1}{2} J_C \\omega^2", "v_B \\cos\\theta_B = v_A \\sin\\theta_A",
                    "v_B \\cos\\theta_B = v_A \\cos\\theta_B", "v_x \\cos\\alpha_x = v_y \\cos\\alpha_y"):
        assert "holds" not in {v for v, _ in _kinds(display)}, display


def _prose_kinds(prose, display):
    return [(c.verdict, c.kind) for cs in kept.by_line("# Moments\n\n" + prose + "\n$$" + display + "$$\n").values()
            for c in cs]


def test_the_parallel_axis_theorem_holds_where_the_prose_names_the_centre_of_mass_axis():
    prose = "For an axis $A'$ parallel to an axis $A$ through the centre of mass, a distance $d$ from it,"
    assert _prose_kinds(prose, "I_{A'} = I_A + Md^2") == [("holds", "parallel axes")]
    # the axis through the centre of mass is the primed one here: the same display is not the theorem
    swapped = "For an axis $A'$ through the centre of mass, parallel to an axis $A$ a distance $d$ from it,"
    assert not {v for v, _ in _prose_kinds(swapped, "I_{A'} = I_A + Md^2")} & {"holds", "fails", "typo"}


def test_primed_moments_about_a_point_a_distance_from_the_centre_of_mass_hold():
    prose = ("When $O'$ lies a distance $l$ from the centre of mass along the $3$-axis, the principal moments "
             "about it are")
    assert ("holds", "parallel axes") in _prose_kinds(prose, "I_1' = I_1 + Ml^2")
    # another distance than the one the prose sets is not the theorem it states
    assert not {v for v, _ in _prose_kinds(prose, "I_1' = I_1 + Mh^2")} & {"holds", "fails", "typo"}


def test_moments_moved_to_the_centre_of_mass_a_distance_away_hold():
    prose = "The moments about the apex are then moved to the centre of mass at distance $R$, giving $I_x$:"
    assert _prose_kinds(prose, "I_x = I_1 - M R^2") == [("holds", "parallel axes")]
    # moved to the centre of mass, the moments drop: a plus sign is left to the rest of the reader
    assert not {v for v, _ in _prose_kinds(prose, "I_x = I_1 + M R^2")} & {"holds", "fails", "typo"}
