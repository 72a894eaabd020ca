"""The vector-algebra reader on the inertia tensor derived as integrals over the volume with a
uniform density (ρ ∫ … dV), the momentum element d𝐩, the integration point 𝐫ᵢ, the unit tensor
𝐞 beside a dyadic, and a text that fixes its sign convention by writing I_ij in index form."""
import sympy as sp
from kept_readings import by_line

from derive.lecture import latex as lx
from derive.lecture import source
from derive.lecture import vector_algebra_model as va


def _holds(latex):
    reading = va.read(source.normalize(latex), va.State())
    a, b = (m.value for m in reading.members[0])
    return sp.simplify(a - b) == sp.zeros(*a.shape)


def test_a_uniform_density_over_the_volume_is_the_integral_over_the_mass():
    assert _holds(r"\boldsymbol L = \rho \int \boldsymbol r \times (\boldsymbol \omega \times \boldsymbol r) \mathrm dV")
    assert _holds(r"\boldsymbol L = \int \boldsymbol r \times \rho \boldsymbol v \mathrm dV")
    assert not _holds(r"\boldsymbol L = \rho \int \boldsymbol r \times (\boldsymbol r \times \boldsymbol \omega) \mathrm dV")


def test_the_momentum_element_in_an_integral_is_the_velocity_times_dm():
    assert _holds(r"\boldsymbol L = \int \boldsymbol r \times \mathrm d \boldsymbol p")


def test_r_with_an_index_in_an_integral_is_its_element_and_e_beside_a_dyadic_the_unit_tensor():
    assert _holds(r"\boldsymbol I = \rho \int (r_i^2 \mathbf e - \boldsymbol r_i \otimes \boldsymbol r_i) \mathrm dV")
    assert not _holds(r"\boldsymbol I = \rho \int (r_i^2 \mathbf e + \boldsymbol r_i \otimes \boldsymbol r_i) \mathrm dV")


def test_a_one_beside_a_dyadic_is_the_unit_tensor():
    assert _holds(r"\boldsymbol L = \int \rho(\mathbf r) (\one r^2 - \mathbf r \mathbf r) \mathrm d^3 r \cdot \boldsymbol \omega")
    assert _holds(r"\boldsymbol L = \int (\mathbb{1} r^2 - {\bf r} {\bf r}) dm \cdot \boldsymbol \omega")
    assert not _holds(r"\boldsymbol L = \int (\one r^2 + \mathbf r \mathbf r) dm \cdot \boldsymbol \omega")


def test_a_density_that_does_not_pair_with_the_volume_element_is_not_read_as_the_mass():
    try:
        ok = _holds(r"\boldsymbol L = \rho \rho \int \boldsymbol r \times \boldsymbol v \mathrm dV")
    except lx.NotRead:
        ok = False
    assert not ok


ENTRIES = ("# Inertia\n\nThe tensor of a body of density $\\rho$:\n\n$$\nINDEX\n$$\n\n$$\n"
           "I_{xy} = \\rho \\int xy \\mathrm dV\n$$\n")
INDEX = r"I_{ij} = \rho \int \left[ (x^2 + y^2 + z^2) \delta_{ij} - x_ix_j \right]\mathrm dV"


def test_a_product_written_with_the_other_sign_is_a_slip_once_the_text_wrote_the_entries_in_index_form():
    with_index = by_line(ENTRIES.replace("INDEX", INDEX))
    assert [c.verdict for c in with_index[5]] == ["holds"]
    assert [c.verdict for c in with_index[9]] == ["typo"]
    assert "-\\int xy" in with_index[9][0].correction
    without = by_line(ENTRIES.replace("INDEX", r"I_{xx} = \rho \int (y^2 + z^2) \mathrm dV"))
    assert [c.verdict for c in without[9]] == ["holds"]        # the products-of-inertia convention


def test_a_rate_seen_from_the_turning_frame_is_the_inertial_rate_less_omega_cross():
    assert _holds(r"\left[ \frac{\mathrm d (\mathbf I \boldsymbol \omega)}{\mathrm dt}\right]_r + "
                  r"\boldsymbol \omega \times (\mathbf I \boldsymbol \omega) = \boldsymbol \tau")
    assert not _holds(r"\left[ \frac{\mathrm d (\mathbf I \boldsymbol \omega)}{\mathrm dt}\right]_r - "
                      r"\boldsymbol \omega \times (\mathbf I \boldsymbol \omega) = \boldsymbol \tau")


LAWS = ("# Euler's equations\n\nBy the angular momentum theorem, $\\boldsymbol M$ being the external torque,\n\n"
        "$$\n\\frac{\\mathrm d \\boldsymbol L}{\\mathrm dt} = \\boldsymbol M\n$$\n\nand in the body\n\n$$\n"
        "\\mathbf I \\left( \\frac{\\mathrm d \\boldsymbol \\omega}{\\mathrm dt} \\right)_r + \\begin{vmatrix} \\hat i & "
        "\\hat j & \\hat k \\\\ \\omega_1 & \\omega_2 & \\omega_3 \\\\ ROW \\end{vmatrix} = \\boldsymbol M\n$$\n")
ROW = r"\mathrm I_{11} \omega_1 & \mathrm I_{22} \omega_2 & \mathrm I_{33} \omega_3"


def test_the_torque_the_prose_names_and_a_law_in_the_principal_moments_hold_and_a_slip_does_not():
    good = by_line(LAWS.replace("ROW", ROW))
    bad = by_line(LAWS.replace("ROW", ROW.replace("I_{11} \\omega_1", "I_{22} \\omega_1")))
    assert [c.verdict for c in good[5]] == ["holds"]
    assert [c.verdict for c in good[11]] == ["holds"] and "principal axes" in good[11][0].why
    assert [c.verdict for c in bad[11]] in (["fails"], ["typo"])


def test_the_identity_of_size_three_beside_a_dyadic_is_the_unit_tensor():
    assert _holds(r"I = \int_{V} \rho \left( (\mathbf{r} \cdot \mathbf{r}) I_{3} - \mathbf{r} \mathbf{r}^{T} \right) dV")
    assert _holds(r"\mathbf I = \int \left( r^2 I_{3 \times 3} - \mathbf{r} \mathbf{r}^{T} \right) dm")
    assert not _holds(r"I = \int_{V} \rho \left( (\mathbf{r} \cdot \mathbf{r}) I_{3} + \mathbf{r} \mathbf{r}^{T} \right) dV")


def test_a_density_that_multiplies_only_part_of_the_integrand_is_read_as_written():
    # the integral runs to dV and the density stops at the minus: the dyadic's term has no ρ
    assert not _holds(r"I = \int_{V} \rho (\mathbf{r} \cdot \mathbf{r}) I_{3} - \mathbf{r} \mathbf{r}^{T} \, dV")
    assert _holds(r"I = \int_{V} \rho (\mathbf{r} \cdot \mathbf{r}) I_{3} - \rho \mathbf{r} \mathbf{r}^{T} \, dV")
