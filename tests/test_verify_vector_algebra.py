"""Textbook vector algebra (the vector grammar under derive/lecture/vector_algebra_model.py): components, matrices,
determinants, sums over particles, integrals over the mass and the torque, checked against rigid
rotation derived from first principles."""
import pytest

import kept_readings as kept
from derive.lecture import latex as lx
from derive.lecture import vector_algebra_model as va
from derive.lecture import vectors as vc

HEAD = "A point mass $m$ at $\\mathbf{r}$ turns with $\\boldsymbol{\\omega}$.\n\n"


def verdicts(body: str) -> dict:
    out = {}
    for c in kept.check_text(HEAD + body):
        out.setdefault(c.line, []).append(c.verdict)
    return out


def only(body: str) -> set:
    return {v for vs in verdicts(body).values() for v in vs}


def test_a_cross_product_in_components_and_as_a_determinant_holds():
    body = ("$$\\boldsymbol{\\omega} \\times \\mathbf{r} = \\begin{vmatrix} \\hat{\\imath} & \\hat{\\jmath} & \\hat{k} \\\\ "
            "\\omega_x & \\omega_y & \\omega_z \\\\ x & y & z \\end{vmatrix} = \\begin{bmatrix} \\omega_y z - \\omega_z y \\\\ "
            "\\omega_z x - \\omega_x z \\\\ \\omega_x y - \\omega_y x \\end{bmatrix}$$\n")
    assert only(body) == {"holds"}


@pytest.mark.parametrize("bold", ["\\boldsymbol", "\\pmb"])
def test_a_bold_hat_over_an_unbraced_dotless_i_is_the_unit_vector_in_a_determinant(bold):
    det = (f"\\begin{{vmatrix}} {bold}{{\\hat\\imath}} & {bold}{{\\hat\\jmath}} & \\mathbf{{\\hat{{k}}}} \\\\ "
           "\\omega_x & \\omega_y & \\omega_z \\\\ x & y & z \\end{vmatrix}")
    assert only(f"$$\\boldsymbol{{\\omega}} \\times \\mathbf{{r}} = {det}$$\n") == {"holds"}
    assert only(f"$$\\mathbf{{r}} \\times \\boldsymbol{{\\omega}} = {det}$$\n") & {"typo", "fails"}


@pytest.mark.parametrize("bold", ["\\boldsymbol", "\\bm", "\\pmb"])
def test_a_position_set_in_unit_vectors_reads_the_same_in_every_bold(bold):
    body = "$$\\mathbf{r}_{G} = x\\hat{i} + y\\hat{j} +z \\hat{k}$$\n"
    assert verdicts(body.replace("\\mathbf", bold)) == verdicts(body) == {3: ["holds"]}
    again = body + "\n" + body.replace("z \\hat{k}", "2 z \\hat{k}")
    assert verdicts(again.replace("\\mathbf", bold))[5] == ["unchecked"]        # set again otherwise: either may be meant


def test_a_position_set_in_unit_vectors_reads_the_same_under_an_arrow():
    body = "$$\\mathbf{r}_{G} = x\\hat{i} + y\\hat{j} +z \\hat{k}$$\n"
    assert verdicts(body.replace("\\mathbf", "\\vec")) == verdicts(body)
    again = body + "\n" + body.replace("z \\hat{k}", "2 z \\hat{k}")
    assert verdicts(again.replace("\\mathbf", "\\vec")) == verdicts(again)


def test_a_sign_slip_in_a_component_fails():
    body = ("$$\\boldsymbol{\\omega} \\times \\mathbf{r} = \\begin{bmatrix} \\omega_y z - \\omega_z y \\\\ "
            "\\omega_x z - \\omega_z x \\\\ \\omega_x y - \\omega_y x \\end{bmatrix}$$\n")
    assert only(body) == {"fails"}


def test_the_angular_momentum_of_particles_as_a_matrix_on_omega_holds():
    body = ("$$\\mathbf{L} = \\sum_{i=1}^{n} m_i \\mathbf{r}_i \\times (\\boldsymbol{\\omega} \\times \\mathbf{r}_i) = "
            "\\sum_{i=1}^{n} m_i \\begin{bmatrix} y_i^2 + z_i^2 & -x_i y_i & -x_i z_i \\\\ -x_i y_i & x_i^2 + z_i^2 & -y_i z_i "
            "\\\\ -x_i z_i & -y_i z_i & x_i^2 + y_i^2 \\end{bmatrix} \\boldsymbol{\\omega}$$\n")
    assert only(body) == {"holds"}


def test_a_wrong_entry_of_the_particle_matrix_fails():
    body = ("$$\\mathbf{L} = \\sum_{i=1}^{n} m_i \\begin{bmatrix} y_i^2 + z_i^2 & x_i y_i & -x_i z_i \\\\ -x_i y_i & x_i^2 + z_i^2 "
            "& -y_i z_i \\\\ -x_i z_i & -y_i z_i & x_i^2 + y_i^2 \\end{bmatrix} \\boldsymbol{\\omega}$$\n")
    assert only(body) == {"fails"}


@pytest.mark.parametrize("entry, holds", [
    ("I_{xx} = \\int (y^2 + z^2) \\, dm", True),
    ("I_{xx} = \\int (x^2 + y^2) \\, dm", False),
    ("I_{xy} = -\\int x y \\, dm", True),
    ("I_{ij} = \\int (r^2 \\delta_{ij} - x_i x_j) \\, dm", True),
    ("\\mathbf{I} = \\int (r^2 \\mathbb{I} - \\mathbf{r} \\otimes \\mathbf{r}) \\, dm", True),
])
def test_the_inertia_tensor_as_an_integral_over_the_mass(entry, holds):
    assert only(f"$${entry}$$\n") == ({"holds"} if holds else {"fails"})


def test_the_torque_is_the_rate_of_the_angular_momentum_not_the_tensor_times_alpha():
    body = ("$$\\mathbf{L} = \\int (r^2 \\mathbb{I} - \\mathbf{r} \\otimes \\mathbf{r}) \\, dm \\; \\boldsymbol{\\omega}$$\n\n"
            "$$\\boldsymbol{\\tau} = \\frac{d}{dt} \\mathbf{I} \\boldsymbol{\\omega} = \\mathbf{I} \\dot{\\boldsymbol{\\omega}} "
            "+ \\boldsymbol{\\omega} \\times (\\mathbf{I} \\boldsymbol{\\omega})$$\n\n"
            "$$\\boldsymbol{\\tau} = \\mathbf{I} \\boldsymbol{\\alpha}$$\n")
    v = verdicts(body)
    lines = sorted(v)
    assert set(v[lines[1]]) == {"holds"}
    assert set(v[lines[2]]) == {"fails"}


def test_a_letter_set_equal_to_r_cross_f_is_the_texts_torque():
    body = ("$$\\mathbf{T} = \\mathbf{r} \\times \\mathbf{F} = \\sum_{i}^{N} \\mathbf{r}_i \\times \\dot{\\mathbf{p}}_i$$\n\n"
            "$$T_x = I_{xx} \\alpha_x + I_{xy} \\alpha_y + I_{xz} \\alpha_z$$\n")
    v = verdicts(body)
    first, second = sorted(v)
    assert "holds" in v[first] and set(v[second]) == {"fails"}


def test_a_diagonal_tensor_holds_if_the_axes_are_principal():
    body = ("$$I_{xx} = \\int (y^2 + z^2) \\, dm$$\n\n"
            "$$\\mathbf{I} = \\begin{bmatrix} I_{xx} & 0 & 0 \\\\ 0 & I_{yy} & 0 \\\\ 0 & 0 & I_{zz} \\end{bmatrix}$$\n")
    claims = [c for c in kept.check_text(HEAD + body) if "bmatrix" in c.latex]
    assert [c.verdict for c in claims] == ["holds"] and "principal" in claims[0].why


def test_principal_moments_after_a_point_mass_are_left_unjudged_never_flagged():
    # the point mass is an earlier statement's; the text may speak of a body in its principal axes here
    text = ("# Principal axes\n\nOne particle of mass $m$ at $\\vec r$ has\n\n$$\\vec L = m \\vec r \\times \\vec v$$\n\n"
            "For a body, in its principal axes,\n\n$$L_x = I_{xx}\\omega_x$$\n")
    claims = {c.line: c for c in kept.check_text(text)}
    assert claims[5].verdict == "holds" and claims[9].verdict == "unchecked", claims[9].why
    body = text.replace("$$L_x = I_{xx}\\omega_x$$", "$$L_x = I_{xx}\\omega_x + I_{xy}\\omega_y + I_{xz}\\omega_z$$")
    assert {c.line: c.verdict for c in kept.check_text(body)}[9] == "holds"   # every entry written: judged


def test_a_product_of_inertia_with_the_other_sign_convention_is_the_texts_own():
    assert only("$$I_{xy} = \\int x y \\, dm$$\n") == {"holds"}


def test_the_vector_triple_product_holds_for_any_vectors_and_an_undefined_vector_is_unchecked():
    assert only("$$\\mathbf{a} \\times (\\mathbf{b} \\times \\mathbf{c}) = (\\mathbf{a} \\cdot \\mathbf{c}) \\mathbf{b} "
                "- (\\mathbf{a} \\cdot \\mathbf{b}) \\mathbf{c}$$\n") == {"holds"}
    assert "fails" not in only("$$\\mathbf{F} = m \\mathbf{a} \\times \\mathbf{r}$$\n")


def test_the_lectures_own_vector_notation_is_left_to_its_reader():
    assert va.lecture_notation("T = \\sum_p \\frac{1}{2} m_p v_p^2")
    assert not va.lecture_notation("\\mathbf{L} = \\sum_i m_i \\mathbf{r}_i \\times \\mathbf{v}_i")


@pytest.mark.parametrize("law", [
    "\\boldsymbol{\\tau} = 0",
    "\\mathbf{F} = -k \\mathbf{r}",
    "\\boldsymbol{\\tau} = \\mathbf{r} \\times m \\mathbf{g}",
])
def test_a_torque_or_force_the_text_gives_without_a_rate_is_never_flagged(law):
    assert not only(f"$${law}$$\n") & {"fails", "typo"}


def test_a_sum_up_to_three_is_over_the_axes_not_the_particles():
    with pytest.raises(Exception):
        va.read("\\mathbf{L} = \\sum_{i=1}^{3} m_i \\mathbf{r}_i \\times \\mathbf{v}_i", va.State())


def _planted_sign_slips(slug):
    """Each '- x' of a correct display of a corpus text turned into '+ x', one at a time (at most two
    per line): (display line, the edited text)."""
    import re
    import sys
    from pathlib import Path
    real = Path(__file__).resolve().parent / "notes" / "real"
    sys.path.insert(0, str(real))
    import measure
    lines = (real / f"{slug}.md").read_text().split("\n")
    holds = [r["line"] for r in measure.truth(slug) if r["verdict"] == "holds"]
    for start in holds:
        k = start - 1
        while True:
            for m in list(re.finditer(r"(?<=[\s(&])- (?=[a-z\\])", lines[k]))[:2]:
                edited = lines[:]
                edited[k] = lines[k][:m.start()] + "+ " + lines[k][m.end():]
                yield start, holds, "\n".join(edited)
            body = lines[k].strip()
            if body.endswith("$$") and (k > start - 1 or body.count("$$") == 2):
                break
            k += 1


@pytest.mark.slow  # (every planted slip is a whole text read again)
@pytest.mark.parametrize("slug", ["inertia-tensor-derivation-blog", "rigid-body-inertia-tensor-blog-nrsyed"])
def test_a_sign_planted_in_an_inertia_tensor_text_is_flagged_on_its_display_only(slug):
    planted = 0
    for line, holds, text in _planted_sign_slips(slug):
        flagged = {c.line for c in kept.check_text(text) if c.verdict in ("typo", "fails")}
        assert line in flagged, line
        assert not flagged & (set(holds) - {line}), (line, flagged)
        planted += 1
    assert planted >= 5


def test_a_cross_product_in_the_wrong_order_is_a_typo_corrected_in_the_texts_notation():
    claims = kept.check_text(HEAD + "$$\\mathbf{L} = m \\mathbf{r} \\times (\\mathbf{r} \\times \\boldsymbol{\\omega})$$\n")
    assert [c.verdict for c in claims if "bmatrix" not in c.latex and "L" in c.latex] == ["typo"]
    fixed = [c.correction for c in claims if c.verdict == "typo"][0]
    assert "\\times (\\boldsymbol{\\omega} \\times \\mathbf{r})" in fixed


def test_one_grammar_reads_both_notations_and_the_model_decides_what_juxtaposed_matrices_mean():
    # textbook matrices act on a column by juxtaposition: 𝐈𝛚 is 𝐋
    reading = va.read("\\mathbf{L} = \\mathbf{I} \\boldsymbol{\\omega}", va.State())
    (left, right), = reading.members
    assert left.value.shape == (3, 1) and all(x == 0 for x in va.difference(left.value, right.value))
    # the lecture writes a tensor on a vector with ·, and the same grammar refuses Ï ω without it
    principal = vc.read("\\mathbf{L} = \\ddot{I} \\cdot \\boldsymbol{\\omega}", lx.Vocabulary(), None)
    assert principal.model == "principal" and vc.holds(principal, 1, "s")[0]
    with pytest.raises(lx.NotRead):
        vc.read("\\mathbf{L} = \\ddot{I} \\boldsymbol{\\omega}", lx.Vocabulary(), None)


@pytest.mark.parametrize("tensor", [
    "\\mathbf{I} = \\begin{bmatrix} 5 m & 0 & 0 \\\\ 0 & 7 m & 0 \\\\ 0 & 0 & 5 m \\end{bmatrix}",
    "I_b = \\begin{bmatrix} m (0.04)^2 & 0 & 0 \\\\ 0 & m (0.07)^2 & 0 \\\\ 0 & 0 & m (0.04)^2 \\end{bmatrix}",
    "I_{zz} = 0.3\\, m"])
def test_a_worked_examples_inertia_in_numbers_is_never_flagged_against_the_general_body(tensor):
    assert only(f"$${tensor}$$\n") == {"unchecked"}
    # one in the positions of the points is still judged against them
    slip = ("\\mathbf{I} = \\begin{bmatrix} m(y^2+z^2) & -m x y & -m x z \\\\ -m x y & m(x^2+z^2) & -m y z \\\\ "
            "-m x z & -m y z & m(x^2-y^2) \\end{bmatrix}")
    assert only(f"$${slip}$$\n") & {"typo", "fails"}
