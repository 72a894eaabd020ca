"""A text's own letters in vector statements (derive/lecture/vector_parser.py, vector_models.py,
vector_claims.py): Landau's 𝛀 and 𝐌 for the angular velocity and momentum, a particle index of
its own (m_α, 𝐫_α under Σ_α), Euler's equations written as columns."""
import kept_readings as kept

LANDAU = ("## Inertia\n\nThe body-frame components $\\Omega_1, \\Omega_2, \\Omega_3$ of the angular velocity "
          "$\\boldsymbol{\\Omega}$, and the angular momentum $\\mathbf{M}$, of point masses $m_\\alpha$.\n\n")


def verdicts(text: str) -> list:
    return [c.verdict for c in kept.check_text(text)]


def test_a_sum_over_the_texts_own_particle_index_is_a_sum_over_particles():
    text = LANDAU + ("$$T = \\sum_{\\alpha} \\frac{1}{2} m_{\\alpha} (\\boldsymbol{\\Omega} \\times \\mathbf{r}_{\\alpha})"
                     " \\cdot (\\boldsymbol{\\Omega} \\times \\mathbf{r}_{\\alpha})"
                     " = \\sum_{\\alpha} \\frac{1}{2} m_{\\alpha} [\\Omega^2 r_{\\alpha}^2 - "
                     "(\\boldsymbol{\\Omega}\\cdot\\mathbf{r}_{\\alpha})^2]$$\n")
    assert verdicts(text) == ["holds", "holds"]


def test_the_texts_angular_momentum_letter_is_the_vector_and_its_components():
    text = LANDAU + ("$$\\mathbf{M} = \\sum_{\\alpha} m_{\\alpha} \\mathbf{r}_{\\alpha} \\times (\\boldsymbol{\\Omega}"
                     " \\times \\mathbf{r}_{\\alpha})$$\n\n"
                     "$$M_i = \\sum_j \\sum_{\\alpha} m_{\\alpha} (\\delta_{ij} r_{\\alpha}^2 - r_{\\alpha ,i} "
                     "r_{\\alpha ,j}) \\Omega_j$$\n")
    assert verdicts(text) == ["holds", "holds"]


def test_a_wrong_particle_sum_in_the_texts_letters_is_not_taken_as_holding():
    text = LANDAU + ("$$\\mathbf{M} = \\sum_{\\alpha} m_{\\alpha} (\\boldsymbol{\\Omega} \\times \\mathbf{r}_{\\alpha})"
                     " \\times \\mathbf{r}_{\\alpha}$$\n")
    assert "holds" not in verdicts(text)


COLUMNS = ("## Euler\n\nThe body-frame components $\\Omega_1, \\Omega_2, \\Omega_3$ of the angular velocity. "
           "Euler's equations, with $N_1, N_2, N_3$ the body-frame components of the external torque $\\mathbf{N}$.\n\n"
           "$$\\begin{bmatrix} I_1 \\dot{\\Omega}_1 \\\\ I_2 \\dot{\\Omega}_2 \\\\ I_3 \\dot{\\Omega}_3 \\end{bmatrix} + "
           "\\begin{bmatrix} \\Omega_1 \\\\ \\Omega_2 \\\\ \\Omega_3 \\end{bmatrix} \\times "
           "\\begin{bmatrix} I_1 \\Omega_1 \\\\ I_2 \\Omega_2 \\\\ I_3 \\Omega_3 \\end{bmatrix} = "
           "\\begin{bmatrix} N_1 \\\\ N_2 \\\\ N_3 \\end{bmatrix}$$\n")


def test_eulers_equations_written_as_columns_hold_row_by_row():
    assert verdicts(COLUMNS) == ["holds"]


def test_eulers_equations_as_columns_with_the_cross_product_reversed_do_not_hold():
    left, right = "\\Omega_1 \\\\ \\Omega_2 \\\\ \\Omega_3", "I_1 \\Omega_1 \\\\ I_2 \\Omega_2 \\\\ I_3 \\Omega_3"
    assert COLUMNS.count(left) == 1 and COLUMNS.count(right) == 1
    reversed_ = COLUMNS.replace(right, "@").replace(left, right).replace("@", left)
    assert "holds" not in verdicts(reversed_)


BODY_RATE = ("## Free body\n\nHere $\\Omega$ is the body angular velocity; no moment acts.\n\n"
             "$$\\begin{{align}}\n"
             "I_1 \\dot{{\\Omega}}_1 &= (I_2 - I_3) \\Omega_2 \\Omega_3, \\\\\n"
             "I_2 \\dot{{\\Omega}}_2 &= (I_3 - I_1) \\Omega_3 \\Omega_1, \\\\\n"
             "I_3 \\dot{{\\Omega}}_3 &= ({first} - {second}) \\Omega_1 \\Omega_2\n"
             "\\end{{align}}$$\n")


def test_a_bare_letter_named_the_body_angular_velocity_names_its_components():
    assert verdicts(BODY_RATE.format(first="I_1", second="I_2")) == ["holds"] * 3
    slipped = verdicts(BODY_RATE.format(first="I_2", second="I_1"))
    assert slipped[:2] == ["holds", "holds"] and slipped[2] in ("typo", "fails")


PI_EQUATIONS = ("## Free body\n\nThe free equations are written in the body angular momentum $\\Pi$.\n\n"
                "$$\\begin{{align}}\n"
                "\\dot{{\\Pi}}_1 & = \\frac{{(I_2-I_3)}}{{I_2 I_3}}\\Pi_2 \\Pi_3, \\\\\n"
                "\\dot{{\\Pi}}_2 & = \\frac{{(I_3-I_1)}}{{I_3 I_1}}\\Pi_3 \\Pi_1, \\\\\n"
                "\\dot{{\\Pi}}_3 & = \\frac{{({first}-{second})}}{{I_1 I_2}}\\Pi_1 \\Pi_2.\n"
                "\\end{{align}}$$\n")


def test_the_body_angular_momentum_pi_and_its_rates_are_read_in_eulers_equations():
    assert verdicts(PI_EQUATIONS.format(first="I_1", second="I_2")) == ["holds"] * 3


def test_a_slip_in_eulers_equations_written_in_pi_is_flagged_in_the_texts_letters():
    claims = kept.check_text(PI_EQUATIONS.format(first="I_2", second="I_1"))
    assert [c.verdict for c in claims][:2] == ["holds", "holds"] and claims[2].verdict in ("typo", "fails")
    assert claims[2].verdict != "typo" or "\\Pi" in claims[2].correction
