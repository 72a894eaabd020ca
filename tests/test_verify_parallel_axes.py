"""A text that writes I₁ + M a² gives its moments about the centre of mass: the second reading
(derive/lecture/rereading.py) that makes its heavy-top formulas hold, and only those."""
import kept_readings as kept

TOP = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n## Heavy symmetric top\n\n"
       "Here $M$ is the top's mass, $a$ is the distance from the fixed point to the centre of mass and "
       "$I_1$, $I_3$ are the principal moments about the centre of mass.\n\n")


def verdicts(text: str) -> list:
    return [c.verdict for c in kept.check_text(text)]


def test_a_lagrangian_with_moments_about_the_centre_of_mass_holds_by_the_parallel_axes():
    text = TOP + ("$$L = \\frac{1}{2} (I_1 + Ma^2) (\\dot{\\phi}^2 \\sin^2 \\theta + \\dot{\\theta}^2) + "
                  "\\frac{1}{2} I_3 (\\dot{\\phi} \\cos \\theta + \\dot{\\psi})^2 - Mga \\cos \\theta$$\n")
    claims = kept.check_text(text)
    assert [c.verdict for c in claims] == ["holds"]
    assert "centre of mass" in claims[0].why


def test_a_rate_with_moments_about_the_centre_of_mass_holds_by_the_parallel_axes():
    text = TOP + ("$$\\dot{\\phi} = \\frac{M_z - M_3 \\cos \\theta}{(I_1 + Ma^2) \\sin^2 \\theta}$$\n")
    text = text.replace("centre of mass.", "centre of mass. $\\mathbf{M}$ is the angular momentum, "
                        "$M_z$ and $M_3$ its components along the fixed vertical and the symmetry axis.")
    assert verdicts(text) == ["holds"]


def test_a_parallel_axes_term_with_the_wrong_sign_does_not_hold():
    text = TOP + ("$$L = \\frac{1}{2} (I_1 + Ma^2) (\\dot{\\phi}^2 \\sin^2 \\theta + \\dot{\\theta}^2) + "
                  "\\frac{1}{2} I_3 (\\dot{\\phi} \\cos \\theta + \\dot{\\psi})^2 + Mga \\cos \\theta$$\n")
    assert "holds" not in verdicts(text)
