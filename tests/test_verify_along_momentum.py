"""The prose choosing the fixed z axis along the angular momentum (derive/lecture/notes.py, the
checker's orientation): a free symmetric top's rates in M_z hold in that frame, for that section."""
import kept_readings as kept

FREE_TOP = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n"
            "## Free symmetric top\n\nFree symmetric top ($I_1 = I_2$, no torque); $\\mathbf{M}$ is the angular momentum. "
            "The fixed $z$ axis is taken along the conserved angular momentum, so $M_z$ is its magnitude.\n\n")


def verdicts(text: str, start: str) -> list:
    return [c.verdict for c in kept.check_text(text) if c.latex.startswith(start)]


def test_a_rate_in_the_frame_the_prose_chooses_holds():
    assert verdicts(FREE_TOP + "$$\\dot{\\phi} = \\frac{M_z}{I_1}$$\n", "\\dot{\\phi}") == ["holds"]


def test_a_wrong_rate_in_that_frame_is_not_taken_as_holding():
    assert "holds" not in verdicts(FREE_TOP + "$$\\dot{\\phi} = \\frac{M_z}{I_3}$$\n", "\\dot{\\phi}")


def test_without_the_prose_the_rate_stays_unchecked():
    text = FREE_TOP.replace("The fixed $z$ axis is taken along the conserved angular momentum, so $M_z$ is its "
                            "magnitude.", "")
    assert verdicts(text + "$$\\dot{\\phi} = \\frac{M_z}{I_1}$$\n", "\\dot{\\phi}") == ["unchecked"]


def test_the_frame_ends_with_its_section():
    text = FREE_TOP + "## Another section\n\nA symmetric top, $I_1 = I_2$.\n\n$$\\dot{\\phi} = \\frac{M_z}{I_1}$$\n"
    assert verdicts(text, "\\dot{\\phi}") == ["unchecked"]


FREE_TOP_SYMBOL = ("## Torque-free symmetric top\n\nA free symmetric body with $I_1 = I_2$ has no torque on it, so its "
                   "angular momentum $\\mathbf{L}$ is constant. PROSE, and the body is described by the Euler angles "
                   "$\\phi$, $\\theta$, $\\psi$.\n\n$$\n\\dot{\\psi} = \\frac{I_1 - I_3}{I_1}\\,\\omega_3\n$$\n")


def test_the_z_axis_taken_along_the_bold_momentum_in_symbols_chooses_the_frame():
    for prose in ("Take the space $z$-axis along $\\mathbf{L}$", "Let $\\vec{L}$ point along the $z$ axis",
                  "With $\\mathbf{L}$ along the fixed $z$-axis"):
        assert verdicts(FREE_TOP_SYMBOL.replace("PROSE", prose), "\\dot{\\psi}") == ["holds"]


def test_a_body_axis_along_the_momentum_chooses_no_frame():
    text = FREE_TOP_SYMBOL.replace("PROSE", "Take the body $z$-axis along $\\mathbf{L}$")
    assert "holds" not in verdicts(text, "\\dot{\\psi}")


STATED_MOTION = (
    "## Free symmetric top\n\nA free top with $I_1 = I_2$; its angular momentum is conserved and $M_z$ is its "
    "component along the fixed axis.\n\n"
    "$$\n\\dot\\phi = \\frac{M_z}{I_1}, \\qquad \\dot\\psi = M_z\\cos\\theta\\left(\\frac{1}{I_3}-\\frac{1}{I_1}\\right)\n$$\n\n"
    "$$\n\\begin{aligned}\n\\frac{\\partial L}{\\partial \\dot\\psi} &= I_3(\\dot\\phi\\cos\\theta + \\dot\\psi) = M_3 = M_z\\cos\\theta \\\\\n"
    "\\frac{\\partial L}{\\partial \\dot\\phi} &= I_1\\dot\\phi\\sin^2\\theta + I_3(\\dot\\phi\\cos\\theta+\\dot\\psi)\\cos\\theta = M_z\n"
    "\\end{aligned}\n$$\n\n"
    "$$\nE = \\frac{M_z^2 \\sin^2\\theta}{2 I_1} + \\frac{I_1 \\dot\\theta^2}{2} + \\frac{M_z^2\\cos^2\\theta}{2 I_3}\n$$\n")


def test_the_energy_holds_in_the_motion_the_text_states_and_is_not_flagged_through_its_own_chain():
    # the energy holds once the stated rates are put in (cos² θ + sin² θ = 1 removes θ̇'s partner);
    # M₃ = M_z cos θ holds only on those rates, so that chain confirms no reading of M_z as p_φ
    claims = kept.check_text(STATED_MOTION)
    assert not [c for c in claims if c.verdict in ("typo", "fails")]
    assert [c.verdict for c in claims if c.latex.startswith("E =")] == ["holds"]
    assert "in the motion the text describes" in next(c.why for c in claims if c.latex.startswith("E ="))


def test_an_energy_with_the_wrong_moment_does_not_hold_in_that_motion():
    slipped = STATED_MOTION.replace("{2 I_3}\n$$", "{2 I_1}\n$$")
    assert "holds" not in verdicts(slipped, "E =")
