"""Kane's notation (derive/lecture/kane_notation.py): positions labelled by their two points, unit
vectors named by a letter, dyadics with a breve, and the names a text defines with := in it."""
import kept_readings as kept
from derive.lecture import kane_notation

HEAD = "Particles $P_i$ of masses $m_i$, at positions relative to a point $O$.\n\n"
INERTIA_VECTOR = ("$$\\bar{I}_a := \\sum_{i=1}^\\nu m_i \\bar{r}^{P_i/O} \\times \\left( \\hat{n}_a \\times "
                  "\\bar{r}^{P_i/O} \\right)$$\n\n")


def at(body: str, line: int) -> set:
    return {c.verdict for c in kept.check_text(HEAD + body) if c.line == line}


def test_a_labelled_position_is_the_particles_and_a_breve_dyadic_about_the_same_point_the_inertia_tensor():
    assert kane_notation.rewrite("\\bar{r}^{P_i/O} \\otimes \\bar{r}^{P_i/O}") == "\\mathbf{r}_{i} \\otimes \\mathbf{r}_{i}"
    assert kane_notation.rewrite("\\breve{I}^{S/O} + \\breve{U}") == "\\mathbf{I}_{system} + \\mathrm{I}"   # the set's
    two_points = "\\breve{I}^{B/O} = \\breve{I}^{B/B_o} + \\breve{I}^{B_o/O}"
    assert kane_notation.rewrite(two_points) == two_points


def test_a_labelled_position_with_its_points_index_braced_is_kanes_notation():
    assert kane_notation.kane("\\bar{r}^{S_{o}/O} = \\frac{a}{m}")
    assert kane_notation.rewrite("\\bar{r}^{P_{i}/O} \\otimes \\bar{r}^{P_{i}/O}") == "\\mathbf{r}_{i} \\otimes \\mathbf{r}_{i}"


def test_a_vector_defined_with_a_colon_equals_stands_for_its_sum_in_later_statements():
    body = INERTIA_VECTOR + ("$$\\bar{I}_a = \\sum_{i=1}^\\nu m_i \\left[\\hat{n}_a \\left( \\bar{r}^{P_i/O} \\cdot "
                             "\\bar{r}^{P_i/O} \\right) - \\bar{r}^{P_i/O} \\left( \\bar{r}^{P_i/O} \\cdot \\hat{n}_a "
                             "\\right) \\right]$$\n")
    assert at(body, 5) == {"holds"}
    slip = INERTIA_VECTOR + ("$$\\bar{I}_a = \\sum_{i=1}^\\nu m_i \\left[\\bar{r}^{P_i/O} \\left( \\bar{r}^{P_i/O} \\cdot "
                             "\\bar{r}^{P_i/O} \\right) - \\hat{n}_a \\left( \\bar{r}^{P_i/O} \\cdot \\hat{n}_a "
                             "\\right) \\right]$$\n")
    assert at(slip, 5) & {"typo", "fails"}


def test_the_definition_itself_is_not_checked_against_itself():
    assert at(INERTIA_VECTOR, 3) <= {"unchecked"}


def test_an_inertia_scalar_defined_from_the_inertia_vector_is_read_through_it():
    body = INERTIA_VECTOR + "$$I_{ab} := \\bar{I}_{a} \\cdot \\hat{n}_b$$\n\n" + (
        "$$I_{ab} = \\sum_{i=1}^\\nu m_i \\left( \\bar{r}^{P_i/O} \\times \\hat{n}_a \\right) \\cdot "
        "\\left( \\bar{r}^{P_i/O} \\times \\hat{n}_b \\right)$$\n")
    assert at(body, 7) == {"holds"}


def test_a_definition_of_a_known_name_that_disagrees_with_the_readers_meaning_is_left_unchecked():
    assert at("$$m := \\sum_{i=1}^\\nu m_i$$\n", 3) == {"unchecked"}


SCALAR = INERTIA_VECTOR + "$$I_{ab} := \\bar{I}_{a} \\cdot \\hat{n}_b$$\n\n"


def test_a_name_defined_over_letter_indices_is_read_at_other_letters():
    assert at(SCALAR + "$$I_{ab} = I_{ba}$$\n", 7) == {"holds"}
    moment = ("$$I_{aa} = \\sum_{i=1}^\\nu m_i \\left( \\bar{r}^{P_i/O} \\times \\hat{n}_a \\right) \\cdot "
              "\\left( \\bar{r}^{P_i/O} \\times \\hat{n}_a \\right)$$\n")
    assert at(SCALAR + moment, 7) == {"holds"}
    assert at(SCALAR + moment.replace("I_{aa} = ", "I_{aa} = -"), 7) & {"typo", "fails"}


def test_the_angular_momentum_seen_in_a_frame_is_the_inertia_dyadic_on_the_bodys_angular_velocity():
    holds = "$${}^A \\bar{H}^{B/B_o} = \\breve{I}^{B/B_o} \\cdot {}^A\\bar{\\omega}^B$$\n"
    assert at(holds, 3) == {"holds"}
    halved = "$${}^A \\bar{H}^{B/B_o} = \\frac{1}{2} \\breve{I}^{B/B_o} \\cdot {}^A\\bar{\\omega}^B$$\n"
    assert at(halved, 3) & {"typo", "fails"}
    two_frames = "$${}^A \\bar{H}^{B/B_o} = \\breve{I}^{B/B_o} \\cdot {}^N\\bar{\\omega}^B$$\n"
    assert not at(two_frames, 3) & {"typo", "fails", "holds"}


PRINCIPAL = ("$$\\breve{I}^{S/O} := \\sum_{i=1}^\\nu m_i \\left( \\left|\\bar{r}^{P_i/O}\\right|^2 \\breve{U} - "
             "\\bar{r}^{P_i/O} \\otimes \\bar{r}^{P_i/O} \\right)$$\n\n")


def test_a_frames_hatted_unit_vectors_one_to_three_are_the_axes_so_the_principal_dyadic_holds_on_principal_axes():
    dyadic = ("$$\\breve{I}^{S/O} = I_{11} \\hat{b}_1 \\otimes \\hat{b}_1 + I_{22} \\hat{b}_2 \\otimes \\hat{b}_2 + "
              "I_{33} \\hat{b}_3 \\otimes \\hat{b}_3$$\n")
    assert at(PRINCIPAL + dyadic, 5) == {"holds"}
    assert at(PRINCIPAL + dyadic.replace("I_{22} \\hat{b}_2 \\otimes \\hat{b}_2", "I_{22} \\hat{b}_1 \\otimes \\hat{b}_1"),
              5) & {"typo", "fails"}


def test_unit_vectors_of_two_frames_in_one_statement_are_not_both_the_axes():
    mixed = ("$$\\breve{I}^{S/O} = I_{11} \\hat{b}_1 \\otimes \\hat{b}_1 + I_{22} \\hat{n}_2 \\otimes \\hat{n}_2 + "
             "I_{33} \\hat{b}_3 \\otimes \\hat{b}_3$$\n")
    assert at(PRINCIPAL + mixed, 5) == {"unchecked"}


def test_a_frames_unit_vector_under_a_rate_is_not_taken_for_a_fixed_axis():
    # the body's b̂₁ turns with it (db̂₁/dt = 𝛚 × b̂₁): a constant axis would call that wrong
    text = ("A rigid body of particles $m_i$ at $\\mathbf{r}_i$ turns with $\\boldsymbol{\\omega}$.\n\n"
            "$$\\frac{d\\hat{b}_1}{dt} = \\boldsymbol{\\omega} \\times \\hat{b}_1$$\n")
    assert {c.verdict for c in kept.check_text(text) if c.line == 3} == {"unchecked"}


def test_a_dyadic_about_a_point_whose_position_is_written_beside_it_is_that_one_particles():
    one = ("$$\\breve{I}^{B_o/O} = m \\left( \\left|\\bar{r}^{B_o/O}\\right|^2 \\breve{U} - "
           "\\bar{r}^{B_o/O} \\otimes \\bar{r}^{B_o/O} \\right)$$\n\n")
    assert at(PRINCIPAL + one, 5) == {"holds"}
    assert at(PRINCIPAL + one.replace("\\right|^2 \\breve{U} -", "\\right|^2 \\breve{U} +"), 5) & {"typo", "fails"}
    # after it, the body's dyadic about O is the body's again, not that particle's
    dyadic = ("$$\\breve{I}^{B/O} = I_{11} \\hat{b}_1 \\otimes \\hat{b}_1 + I_{22} \\hat{b}_2 \\otimes \\hat{b}_2 + "
              "I_{33} \\hat{b}_3 \\otimes \\hat{b}_3$$\n")
    assert at(PRINCIPAL + one + dyadic, 7) == {"holds"}
