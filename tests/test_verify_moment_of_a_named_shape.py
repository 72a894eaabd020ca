"""The notes reader on the moment of inertia of a uniform body the prose names just before the
display (a ball, a shell, a hoop, a disk, a cylinder, a rod, a cube) about the axis it names: the
standard moment holds, another number for a body of one length about a stated axis fails, and a
paragraph that names an axis away from the centre, or no body, leaves the display unchecked."""
import kept_readings as kept

HEAD = "# Moments of inertia\n\n"


def _verdicts(prose, display):
    text = HEAD + prose + "\n\n$$" + display + "$$\n"
    return {c.verdict for c in kept.check_text(text) if c.latex.strip().startswith("I")}


def test_a_ball_about_its_centre_holds_and_a_wrong_number_fails():
    prose = "A solid sphere of radius $R$ and mass $M$, about an axis through its centre:"
    assert _verdicts(prose, "I = \\frac{2}{5} M R^2") == {"holds"}
    assert _verdicts(prose, "I = \\frac{2}{3} M R^2") == {"fails"}


def test_a_rod_written_with_l_and_a_hoop_in_its_plane_hold():
    assert _verdicts("A thin rod of length $L$ and mass $M$, about an axis through its centre:",
                     "I = \\frac{1}{12} M L^2") == {"holds"}
    assert _verdicts("A hoop of radius $R$, about an axis through its centre lying in its plane, has",
                     "I = \\frac{1}{2} M R^2") == {"holds"}


def test_a_cylinder_across_its_axis_holds_in_its_two_lengths():
    prose = "A cylinder of radius $R$ and height $H$, about an axis through its centre perpendicular to its symmetry axis:"
    assert _verdicts(prose, "I = \\frac{1}{4} M R^2 + \\frac{1}{12} M H^2") == {"holds"}


def test_an_axis_away_from_the_centre_is_not_judged():
    prose = "A solid sphere of radius $R$ rolls; about its point of contact, a distance $R$ from its centre,"
    assert not _verdicts(prose, "I = \\frac{7}{5} M R^2") & {"holds", "fails", "typo"}


def test_a_hoop_through_its_centre_with_an_unlisted_number_is_not_flagged():
    # through its centre a hoop has two axes: a number that is neither is not decided by the prose
    prose = "A hoop of radius $R$ and mass $M$, about an axis through its centre:"
    assert not _verdicts(prose, "I = \\frac{1}{3} M R^2") & {"fails", "typo"}


def test_a_cone_about_its_axis_and_across_it_through_its_centre_of_mass_holds():
    prose = ("In the frame $(x,y,z)$ attached to the cone, $z$ its axis of symmetry and the base parallel to the "
             "$xy$ plane, with $a$ the radius of the base and $h$ the height:")
    assert _verdicts(prose, "I_x = I_y = \\frac{3M}{20} \\bigg(a^2 + \\frac{h^2}{4} \\bigg)") == {"holds"}
    assert _verdicts(prose, "I_z = \\frac{3M}{10} a^2") == {"holds"}


def test_a_cone_with_another_number_or_the_axes_exchanged_is_not_judged():
    # a cone has two lengths: a number that is none of its moments is not decided by the prose, never flagged
    prose = "A solid cone of base radius $a$ and height $h$, with $z$ its axis of symmetry, about its apex:"
    assert not _verdicts(prose, "I_x = \\frac{3M}{20} \\left(a^2 + \\frac{h^2}{4}\\right)") & {"holds", "fails", "typo"}
    assert not _verdicts(prose, "I_z = \\frac{3M}{5} a^2") & {"holds", "fails", "typo"}
    assert _verdicts(prose, "I_x = \\frac{3M}{20} a^2 + \\frac{3M}{5} h^2") == {"holds"}


def test_the_cone_a_rate_vector_sweeps_is_not_a_body():
    prose = "Seen from the body, $\\omega$ sweeps a cone about the symmetry axis $z$ (the body cone), with $a$ and $h$:"
    assert not _verdicts(prose, "I_z = \\frac{3M}{10} a^2") & {"holds", "fails", "typo"}


def test_a_cones_centre_of_mass_from_its_apex_holds_in_the_section_that_names_the_cone():
    text = ("# The cone\n\nIn the frame $(x,y,z)$ attached to the cone, $z$ its axis of symmetry, with $a$ the radius "
            "of the base and $h$ the height:\n\n$$I_z = \\frac{3M}{10} a^2$$\n\n"
            "The centre of mass lies at a distance $R$ from the apex $O$:\n\n$$R = \\frac{3h}{4}$$\n")
    assert {c.verdict for c in kept.check_text(text) if c.latex.strip().startswith("R")} == {"holds"}
    # another fraction may be a hollow cone's or another length's: left as the other rules leave it
    wrong = text.replace("\\frac{3h}{4}", "\\frac{2h}{3}")
    assert not {c.verdict for c in kept.check_text(wrong) if c.latex.strip().startswith("R")} & {"holds", "fails", "typo"}
    # with no cone in its section the distance is not judged
    other = text.replace("# The cone\n\nIn the frame $(x,y,z)$ attached to the cone,", "# A top\n\nIn the frame $(x,y,z)$,")
    assert not {c.verdict for c in kept.check_text(other) if c.latex.strip().startswith("R")} & {"holds", "fails", "typo"}


def test_a_named_solids_volume_and_its_density_hold():
    text = ("# Cylinder\n\nA solid cylinder with radius $R$, height $h$ and mass $m$: its volume\n\n$$V = \\pi R^2 h$$\n\n"
            "and its density\n\n$$\\rho = \\frac{m}{\\pi R^2 h}$$\n")
    assert {c.verdict for c in kept.check_text(text) if c.latex.strip()[:2] in ("V ", "\\r")} == {"holds"}
    cone = ("# The cone\n\nThe body is a solid cone of height $h$ whose base has radius $d$. Its volume is "
            "$\\pi d^2 h/3$, and from it the density $\\rho$ in terms of the mass $M$:\n\n$$\\rho = \\frac{3M}{\\pi d^2 h}$$\n")
    assert {c.verdict for c in kept.check_text(cone) if c.latex.strip().startswith("\\rho")} == {"holds"}
    # another volume is left as the other rules leave it, never flagged
    wrong = text.replace("V = \\pi R^2 h", "V = 2 \\pi R h")
    assert not {c.verdict for c in kept.check_text(wrong) if c.latex.strip().startswith("V")} & {"holds", "fails", "typo"}
