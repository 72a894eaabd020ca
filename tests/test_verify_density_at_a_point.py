"""The notes reader on integrals over a body written with its density at the point and the volume
element, ``\\int \\rho(\\mathbf{r}) … \\mathrm{d}^3 r``: the mass element dm, so the integral is one
over the body's mass and is read as such."""
from kept_readings import verdicts_by_line as verdicts

L = ("# Angular momentum\n\nWith the density $\\rho(\\mathbf{r})$ of the body:\n\n$$\n\\mathbf{L} = \\int \\rho(\\mathbf{r})\\, "
     "\\mathbf{r} \\times (\\boldsymbol\\omega \\times \\mathbf{r})\\, \\mathrm{d}^3 r = \\int \\rho(\\mathbf{r}) "
     "\\left(\\boldsymbol\\omega r^2 - \\mathbf{r}(\\mathbf{r}\\cdot\\boldsymbol\\omega)\\right) \\mathrm{d}^3 r\n$$\n")


def test_the_density_at_the_point_with_the_volume_element_is_the_mass_element():
    assert verdicts(L)[5] == {"holds"}


def test_a_sign_slipped_in_such_an_integral_is_flagged():
    assert "typo" in verdicts(L.replace("r^2 - \\mathbf{r}", "r^2 + \\mathbf{r}"))[5]


def test_the_density_at_the_point_in_sized_brackets_is_the_same_mass_element():
    sized = L.replace("\\rho(\\mathbf{r})", "\\rho\\left(\\mathbf{r}\\right)")
    assert sized != L and verdicts(sized)[5] == {"holds"}
    assert "typo" in verdicts(sized.replace("r^2 - \\mathbf{r}", "r^2 + \\mathbf{r}"))[5]
