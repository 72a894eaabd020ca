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
