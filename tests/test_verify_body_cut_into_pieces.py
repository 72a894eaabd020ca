"""A body cut into pieces, summed over them: the mass of piece i written Δmᵢ, or its density times its
volume ρᵢ ΔVᵢ, is the particle's mass mᵢ, so the angular momentum of the pieces is checked and a
slip in it flagged; a ΔVᵢ without its ρᵢ is not a mass."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n# Pieces\n\n"
L = "\\boldsymbol{L} = \\sum_{i=1}^n \\boldsymbol{r}_i \\times "


def _verdicts(text):
    return [c.verdict for c in kept.check_text(text)]


def test_the_pieces_masses_are_the_particles_masses():
    text = HEAD + "$$\n" + L + "\\Delta m_i \\dot{\\boldsymbol{r}}_i = \\sum_{i=1}^n \\boldsymbol{r}_i \\times " \
        "\\rho_i \\dot{\\boldsymbol{r}}_i \\Delta V_i\n$$\n"
    assert set(_verdicts(text)) == {"holds"}


def test_a_slip_in_the_pieces_sum_is_flagged():
    text = HEAD + "$$\n" + L + "\\Delta m_i \\dot{\\boldsymbol{r}}_i = \\sum_{i=1}^n \\dot{\\boldsymbol{r}}_i \\times " \
        "\\rho_i \\boldsymbol{r}_i \\Delta V_i\n$$\n"
    assert set(_verdicts(text)) & {"typo", "fails"}


def test_a_volume_without_its_density_is_not_a_mass():
    text = HEAD + "$$\n" + L + "\\dot{\\boldsymbol{r}}_i \\Delta V_i\n$$\n"
    assert "holds" not in _verdicts(text)
