"""A bold letter set to its three components in round brackets, numbers too (``{\\bf n} = (0, 0, 1)``,
an axis), is the text's column: a dot product of two such columns (``{\\bf r} \\cdot {\\bf n}``) and
the plain letter squared (``r^2``, |𝐫|²) are read with the components put in; a column set again
to other numbers, or in a later section (another body), is recorded anew, not compared."""
import kept_readings as kept

CYLINDER = (
    "# Moments\n\n## Cylinder\n\nA point of the cylinder, in cylindrical coordinates, and the axis:\n\n"
    "$$\n{\\bf n} = (0, 0, 1)\n$$\n\n"
    "$$\n{\\bf r} = (\\rho\\cos\\phi, \\rho\\sin\\phi, z)\n$$\n\n"
    "so that\n\n$$\n{\\bf r} \\cdot {\\bf n} = %s\n$$\n\n"
    "$$\nr^2 = \\rho^2 + z^2\n$$\n\n"
    "About the $x$ axis instead:\n\n$$\n{\\bf n} = (1, 0, 0)\n$$\n\n"
    "$$\n{\\bf r} \\cdot {\\bf n} = \\rho\\cos\\phi\n$$\n\n"
    "## Sphere\n\nIn spherical coordinates:\n\n"
    "$$\n{\\bf r} = (\\rho\\cos\\phi\\sin\\theta, \\rho\\sin\\phi\\sin\\theta, \\rho\\cos\\theta)\n$$\n\n"
    "$$\nr^2 = \\rho^2\n$$\n"
)


def _verdicts(text):
    return [(c.latex.strip(), c.verdict) for c in kept.check_text(text)]


def test_dot_products_and_squares_of_written_columns_are_read_with_their_components():
    got = _verdicts(CYLINDER % "z")
    judged = [v for latex, v in got if latex.startswith(("{\\mathbf{r}} \\cdot", "r^2"))]
    assert judged == ["holds"] * 4, got


def test_a_column_set_again_is_recorded_anew_not_compared():
    got = dict(_verdicts(CYLINDER % "z"))
    assert got["{\\mathbf{n}} = (1, 0, 0)"] == "unchecked"
    assert got["{\\mathbf{r}} = (\\rho\\cos\\phi\\sin\\theta, \\rho\\sin\\phi\\sin\\theta, \\rho\\cos\\theta)"] == "unchecked"


def test_a_dot_product_that_does_not_hold_is_never_flagged_as_a_reading():
    got = _verdicts(CYLINDER % "\\rho\\sin\\phi")
    assert not any(v in ("typo", "fails") for _, v in got), got


def test_an_axis_never_written_out_leaves_the_dot_product_unread():
    got = dict(_verdicts(CYLINDER.replace("$$\n{\\bf n} = (0, 0, 1)\n$$\n\n", "") % "z"))
    assert got["{\\mathbf{r}} \\cdot {\\mathbf{n}} = z"] == "unchecked"
