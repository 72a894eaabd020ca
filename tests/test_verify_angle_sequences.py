"""The notes reader on texts in any of the twelve angle sequences: their rotation matrices
(active or passive, by single turns and as products), changes of frame written coordinate by
coordinate, the matrices of the rates, the space components of ω, and what holds only on the
motion the text describes."""
import pytest
import sympy as sp

from kept_readings import by_line, verdicts_by_line
from derive.lecture import source
from derive.symbolic import rotations as rot

ZYX = "---\nconvention: z-y-x\nangles: [\\psi_{\\beta \\alpha}, \\theta_{\\beta \\alpha}, \\phi_{\\beta \\alpha}]\n---\n# Notes\n\n"
ZXZ = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Notes\n\n"


verdicts = verdicts_by_line


def line_of(text, start):
    return next(k for k, row in enumerate(text.split("\n"), start=1) if row.startswith(start))


SEQUENCES = ["z-y-z", "z-x-z", "x-y-x", "x-z-x", "y-x-y", "y-z-y",
             "z-y-x", "z-x-y", "x-y-z", "x-z-y", "y-x-z", "y-z-x"]


@pytest.mark.parametrize("sequence", [s if s in ("z-y-z", "z-y-x") else pytest.param(s, marks=pytest.mark.slow)
                                      for s in SEQUENCES])  # a proper Euler and a Tait-Bryan one fast
def test_the_space_angular_velocity_is_r_times_the_body_one_in_every_sequence(sequence):
    conv = rot.convention(sequence)
    R = conv.matrix()
    assert (conv.omega_space() - R * conv.omega_body_skew()).applyfunc(rot.trig_reduce) == sp.zeros(3, 1)
    assert (conv.space_rate_matrix() * sp.Matrix(rot.RATES) - conv.omega_space()).applyfunc(sp.expand) == sp.zeros(3, 1)


def test_frame_labelled_passive_matrices_with_abbreviated_sines_hold_and_a_flipped_sign_is_a_typo():
    rows = r"\left[ \begin{array}{ccc} c(\theta_{\beta \alpha}) & 0 & -s(\theta_{\beta \alpha}) \\ 0 & 1 & 0 \\ s(\theta_{\beta \alpha}) & 0 & c(\theta_{\beta \alpha}) \end{array} \right]"
    text = ZYX + f"$$\n\\mathbf{{R}}^{{\\theta}}_{{\\psi}} = {rows}\n$$\n\n$$\n\\mathbf{{R}}^{{\\phi}}_{{\\theta}} = {rows.replace('& -s', '& s', 1)}\n$$\n"
    got = by_line(text)
    assert [c.verdict for c in got[7]] == ["holds"] and "passive turn about y" in got[7][0].why
    assert [c.verdict for c in got[11]] == ["typo"]


def test_bare_letters_of_subscripted_angles_are_the_angles_and_a_row_ending_in_a_full_stop_reads():
    text = ZYX + ("$$\n\\mathbf{R}_3 = \\left[ \\begin{array}{ccc} \\cos \\psi & \\sin \\psi & 0 \\\\ "
                  "-\\sin \\psi & \\cos \\psi & 0 \\\\ 0 & 0 & 1. \\end{array} \\right]\n$$\n\n"
                  "$$\n\\dot{\\mathbf{R}}_3 = \\left[ \\begin{array}{ccc} -\\dot{\\psi} \\sin \\psi & \\dot{\\psi} \\cos \\psi & 0 \\\\ "
                  "-\\dot{\\psi} \\cos \\psi & - \\dot{\\psi} \\sin \\psi & 0 \\\\ 0 & 0 & 0 \\end{array} \\right].\n$$\n")
    assert verdicts(text) == {7: {"holds"}, 11: {"holds"}}


def test_a_change_of_frame_written_coordinate_by_coordinate_is_checked_as_a_turn():
    good = (r"& x^{\theta} = x^{\psi} c(\theta_{\beta \alpha}) - z^{\psi} s(\theta_{\beta \alpha}) \\"
            "\n" r"& y^{\theta} = y^{\psi} \\" "\n" r"& z^{\theta} = x^{\psi} s(\theta_{\beta \alpha}) + z^{\psi} c(\theta_{\beta \alpha}),")
    text = ZYX + "$$\n\\begin{align}\n" + good + "\n\\end{align}\n$$\n"
    got = by_line(text)
    assert [c.verdict for c in got[7]] == ["holds"] and "about y" in got[7][0].why
    wrong = text.replace(r"- z^{\psi} s(", r"+ z^{\psi} s(")
    assert "holds" not in verdicts(wrong).get(7, set())


def test_the_matrix_of_the_rates_holds_with_the_rates_in_the_texts_order():
    text = ZYX + (r"$$\mathbf{S}(\phi_{\beta \alpha}, \theta_{\beta \alpha}) = \left[ \begin{array}{ccc} "
                  r"1 & 0 & -\sin \theta_{\beta \alpha} \\ 0 & \cos \phi_{\beta \alpha} & \sin \phi_{\beta \alpha} \cos \theta_{\beta \alpha} \\ "
                  r"0 & -\sin \phi_{\beta \alpha} & \cos \phi_{\beta \alpha} \cos \theta_{\beta \alpha} \end{array} \right]$$" "\n")
    got = by_line(text)
    assert [c.verdict for c in got[7]] == ["holds"] and "body components" in got[7][0].why
    assert "holds" not in verdicts(text.replace(r"& -\sin \phi", r"& \sin \phi"))[7]


def test_space_components_of_omega_are_read_as_such():
    text = ZXZ + ("$$\\omega_3 = \\dot{\\phi} \\cos \\theta + \\dot{\\psi}$$\n\n"
                  "$$\\omega_x = \\dot{\\theta} \\cos \\phi + \\dot{\\psi} \\sin \\theta \\sin \\phi$$\n\n"
                  "$$\\omega_z = \\dot{\\phi} + \\dot{\\psi} \\cos \\theta$$\n")
    got = by_line(text)
    assert {k: [c.verdict for c in v] for k, v in got.items()} == {7: ["holds"], 9: ["holds"], 11: ["holds"]}
    assert "space (inertial) component" in got[9][0].why


LAMBDA = {
    "phi": r"\begin{pmatrix} \cos \phi & \sin \phi & 0 \\ - \sin \phi & \cos \phi & 0 \\ 0 & 0 & 1 \end{pmatrix}",
    "theta": r"\begin{pmatrix} 1 & 0 & 0 \\ 0 & \cos \theta & \sin \theta \\ 0 & - \sin \theta & \ cos \theta \end{pmatrix}",
    "psi": r"\begin{pmatrix} \cos \psi & \sin \psi & 0 \\ - \sin\psi & \cos \psi & 0 \\ 0 & 0 & 1 \end{pmatrix}",
}


def test_a_product_of_the_texts_matrices_its_inverse_and_its_transpose_are_checked():
    full = sp.latex(rot.convention("z-x-z").matrix(*sp.symbols("phi theta psi")).T, mat_str="pmatrix",
                    mat_delim="").replace(r"\left(", "(").replace(r"\right)", ")")
    text = ZXZ + "".join(f"$$\\lambda_{{\\{a}}} = {m}$$\n\n" for a, m in LAMBDA.items()) + \
        "$$\\lambda = \\lambda_{\\psi} \\lambda_{\\theta} \\lambda_{\\phi}$$\n\n" + \
        f"$$\\lambda^{{-1}} = \\lambda^T = {full}^T$$\n"
    got = verdicts(text)
    assert got == {7: {"holds"}, 9: {"holds"}, 11: {"holds"}, 13: {"holds"}, 15: {"holds"}}


def test_a_numeric_matrix_after_an_angle_set_in_running_text_is_that_turn():
    text = ZXZ + ("The first turn is $\\phi = 30^{\\circ}$:\n\n$$\\lambda_{\\phi} = \\begin{pmatrix} "
                  "\\frac{\\sqrt{3}}{2} & \\frac{1}{2} & 0 \\\\ -\\frac{1}{2} & \\frac{\\sqrt{3}}{2} & 0 \\\\ 0 & 0 & 1 \\end{pmatrix}$$\n")
    assert verdicts(text)[9] == {"holds"}


def test_a_trigonometric_name_typed_without_its_backslash_is_the_function():
    assert source.normalize(r"0 & - \sin \theta & \ cos \theta") == r"0 & - \sin \theta & \ \cos \theta"
    assert source.normalize(r"\text{cos} + \mathrm{sin}") == r"\text{cos} + \mathrm{sin}"


def test_braces_and_cross_matrices_are_read():
    assert source.normalize(r"\underbrace{a}_{\mathbf{S}} = \overbrace{b}^{\cdot}") == r"a = \frac{d}{dt}(b)"
    assert source.normalize(r"\left[ \mathbf{r} \right]_\times") == r"\crossmatrix\left( \mathbf{r} \right)"


def test_a_display_that_opens_with_a_minus_and_states_its_own_relation_is_not_a_continuation():
    text = ZXZ + "$$T = \\frac{1}{2} I_1 \\omega_1^2 + \\frac{1}{2} I_2 \\omega_2^2 + \\frac{1}{2} I_3 \\omega_3^2.$$\n\n" \
        "$$-\\omega_3 = -\\dot{\\phi} \\cos \\theta - \\dot{\\psi}$$\n"
    assert verdicts(text) == {7: {"holds"}, 9: {"holds"}}


def test_the_square_of_omega_holds_and_a_wrong_sign_fails():
    row = (r"\boldsymbol{\omega} \cdot \boldsymbol{\omega} = | \omega |^2 = \omega^2_1 + \omega^2_2 + \omega^2_3 = "
           r"\dot{\phi}^2 + \dot{\theta}^2 + \dot{\psi}^2 + 2 \dot{\phi}\dot{\psi} \cos \theta")
    text = ZXZ + f"$$\n{row}\n$$\n\n$$\n{row.replace('+ 2', '- 2')}\n$$\n"
    got = verdicts(text)
    assert got[7] == {"holds"} and got[11] & {"typo", "fails"}


def test_a_display_flagged_only_through_a_definition_in_running_text_is_unchecked():
    text = ZXZ + ("| a | b | c |\n| --- | --- | --- |\n| $\\dot{\\phi}_3 = \\dot{\\phi} \\cos \\theta$ | "
                  "$\\dot{\\theta}_3 = 0$ | $\\dot{\\psi}_3 = \\psi$ |\n\n"
                  "$$\\omega_3 = \\dot{\\phi}_3 + \\dot{\\theta}_3 + \\dot{\\psi}_3 = \\dot{\\phi} \\cos \\theta + \\dot{\\psi}$$\n\n"
                  "$$\\omega_3 = \\dot{\\phi}_3 + \\dot{\\theta}_3 + \\dot{\\psi}_3 = \\dot{\\phi} \\cos \\theta - \\dot{\\psi}$$\n")
    got = verdicts(text)
    assert got[11] == {"holds"} or got[11] == {"holds", "unchecked"}
    assert got[13] & {"typo", "fails"}


def test_what_holds_on_the_texts_motion_and_lagranges_equation_hold_but_a_rate_is_not_checked_against_itself():
    text = ZXZ + ("For a free symmetric top, $I_1 = I_2$:\n\n"
                  "$$L = \\frac{1}{2} I_1 (\\dot{\\phi}^2 \\sin^2 \\theta + \\dot{\\theta}^2) + "
                  "\\frac{1}{2} I_3 (\\dot{\\phi} \\cos \\theta + \\dot{\\psi})^2$$\n\n"
                  "$$\\dot{\\phi} = \\frac{A}{I_1}$$\n\n$$\\dot{\\psi} = A \\cos \\theta \\left( \\frac{1}{I_3} - \\frac{1}{I_1} \\right)$$\n\n"
                  "$$\\frac{\\partial L}{\\partial \\theta} = \\frac{A^2}{I_1} \\sin \\theta \\cos \\theta - \\frac{A^2}{I_1} \\sin \\theta \\cos \\theta = 0$$\n\n"
                  "$$\\frac{\\partial L}{\\partial \\theta} = \\frac{d}{dt} \\left( \\frac{\\partial L}{\\partial \\dot{\\theta}} \\right)$$\n\n"
                  "$$\\dot{\\phi} = \\frac{A}{I_1}$$\n")
    got = by_line(text)
    assert {c.verdict for c in got[9]} == {"holds"}
    assert {c.verdict for c in got[15]} == {"holds"} and "in the motion the text describes" in got[15][-1].why
    assert {c.verdict for c in got[17]} == {"holds"} and "Lagrange's equation" in got[17][0].why
    assert "holds" not in {c.verdict for c in got[19]}


def test_a_wrong_sign_in_a_matrix_is_corrected_in_the_texts_own_matrix():
    row = (r"\begin{pmatrix} \omega_1 \\ \omega_2 \\ \omega_3 \end{pmatrix} = \begin{pmatrix} \sin \theta \sin \psi & \cos \psi & 0 \\ "
           r"\sin \theta \cos \psi & \sin \psi & 0 \\ \cos \theta & 0 & 1 \end{pmatrix} \cdot "
           r"\begin{pmatrix} \dot{\phi} \\ \dot{\theta} \\ \dot{\psi} \end{pmatrix}")
    claims = by_line(ZXZ + f"$${row}$$\n")[7]
    typo = [c for c in claims if c.verdict == "typo"]
    assert typo and typo[0].correction == row.replace(r"& \sin \psi & 0", r"& - \sin \psi & 0")
