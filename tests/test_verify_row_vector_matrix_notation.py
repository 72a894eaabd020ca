"""A bold vector written transposed (``\\boldsymbol{\\omega}^{\\mathrm{T}}``) puts its statement in matrix
notation: the inertia tensor acts on the column beside it by juxtaposition, so the kinetic energy as
a quadratic form is checked, and a wrong factor flagged."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n# Energy\n\n"


def _verdicts(text):
    return [c.verdict for c in kept.check_text(text)]


def test_the_kinetic_energy_as_a_quadratic_form_holds():
    for mark in ("^{\\mathrm{T}}", "^T", "^\\top"):
        text = HEAD + f"$$\nT = \\frac{{1}}{{2}} \\boldsymbol{{\\omega}}{mark} \\boldsymbol{{I}} \\boldsymbol{{\\omega}}\n$$\n"
        assert _verdicts(text) == ["holds"], mark


def test_a_quadratic_form_with_a_wrong_factor_is_flagged():
    text = HEAD + "$$\nT = \\boldsymbol{\\omega}^{\\mathrm{T}} \\boldsymbol{I} \\boldsymbol{\\omega}\n$$\n"
    assert _verdicts(text) in (["typo"], ["fails"])


def test_without_a_transposed_vector_a_tensor_beside_a_dot_is_not_read_as_a_product():
    text = HEAD + "$$\nT = \\frac{1}{2} \\boldsymbol{\\omega} \\cdot \\boldsymbol{I} \\boldsymbol{\\omega}\n$$\n"
    assert _verdicts(text) == ["unchecked"]
