"""Rigid-body kinetics as engineering courses write it: 𝐇 about the centre of mass derived through
integrals in i, j, k, the body's unit vectors ê_i and their time derivatives, the principal moments
beside a frame derivative, a period as a dot product, "and" between two statements, and a sum whose
summand does not run with its index."""
import kept_readings as kept
from derive.lecture import rearranged
from derive.lecture import statements as st
from derive.lecture import summation_index as si

E1, E2, E3 = (f"\\hat{{\\boldsymbol{{e_{k}}}}}" for k in (1, 2, 3))


def verdicts(*displays: str) -> list:
    text = "# Body axes\n\n" + "".join(f"\\begin{{equation}}\n{d}\n\\end{{equation}}\n\n" for d in displays)
    return [c.verdict for c in kept.check_text(text)]


def test_a_period_between_two_vectors_is_their_dot_product():
    assert verdicts("\\vec{a}\\times(\\vec{b}\\times\\vec{c}) = (\\vec{a}.\\vec{c})\\vec{b} - (\\vec{a}.\\vec{b})\\vec{c}") \
        == ["holds"]
    assert verdicts("\\vec{a}\\times(\\vec{b}\\times\\vec{c}) = (\\vec{a}.\\vec{b})\\vec{c} - (\\vec{a}.\\vec{c})\\vec{b}") \
        == ["fails"]


def test_an_integrand_runs_to_its_dm_across_plus_and_minus():
    assert verdicts("\\vec{H_{cm}} = \\int \\vec{r} \\times (\\vec{\\omega}\\times\\vec{r})\\,dm = "
                    "\\int (r_x^2 + r_y^2+r_z^2)\\vec{\\omega} - (r_x\\omega_x + r_y\\omega_y+r_z\\omega_z)\\vec{r}\\,dm") \
        == ["holds", "holds"]
    assert {"fails", "typo"} & set(verdicts("\\vec{H_{cm}} = \\int \\vec{r} \\times (\\vec{\\omega}\\times\\vec{r})\\,dm = "
                               "\\int (r_x^2 + r_y^2+r_z^2)\\vec{\\omega} + (r_x\\omega_x + r_y\\omega_y+r_z\\omega_z)\\vec{r}\\,dm"))


def test_an_index_slip_in_the_angular_momentum_about_the_centre_of_mass_is_flagged():
    right = ("\\vec{H_{cm}}=\\left(\\omega_xI_{xx}^{cm}+ \\omega_yI_{xy}^{cm} + \\omega_zI_{xz}^{cm}\\right)\\hat{\\boldsymbol{i}}"
             " + \\left(\\omega_xI_{xy}^{cm} +\\omega_yI_{yy}^{cm} + \\omega_zI_{yz}^{cm}\\right)\\hat{\\boldsymbol{j}}"
             "+\\left(\\omega_xI_{XZ}^{cm} + \\omega_yI_{yz}^{cm} + \\omega_zI_{zz}^{cm}\\right)\\hat{\\boldsymbol{k}}")
    assert verdicts(right.replace("XZ", "xz")) == ["holds"]
    assert verdicts(right.replace("XZ", "yz"))[0] in ("fails", "typo")


def test_a_body_axis_turns_with_the_body():
    assert verdicts(f"\\frac{{d{E1}}}{{dt}} = \\vec{{\\omega}} \\times {E1}") == ["holds"]
    assert verdicts(f"\\frac{{d{E1}}}{{dt}} = {E1} \\times \\vec{{\\omega}}")[0] in ("fails", "typo")


def test_the_angular_momentum_along_the_principal_axes():
    good = f"\\vec{{H_{{cm}}}} = I_1\\omega_1 {E1} + I_2\\omega_2 {E2} + I_3\\omega_3 {E3}"
    assert set(verdicts(good.replace("=", "= I\\vec{\\omega} =", 1))) == {"holds"}
    assert verdicts(f"\\vec{{H_{{cm}}}} = I\\vec{{\\omega}} = I_2\\omega_1 {E1} + I_2\\omega_2 {E2} + I_3\\omega_3 {E3}") \
        [-1] in ("fails", "typo")


def test_the_principal_moments_beside_a_frame_derivative_give_euler_s_terms():
    rates = " + ".join(f"I_{k}\\dot{{\\omega_{k}}}{e}" for k, e in zip((1, 2, 3), (E1, E2, E3)))
    turns = " + ".join(f"I_{k}\\omega_{k}\\frac{{d{e}}}{{dt}}" for k, e in zip((1, 2, 3), (E1, E2, E3)))
    assert verdicts(f"\\frac{{d\\vec{{H_{{cm}}}}}}{{dt}} = {rates} + {turns}") == ["holds"]
    assert verdicts(f"\\frac{{d\\vec{{H_{{cm}}}}}}{{dt}} = {rates} + {turns.replace('I_2', 'I_3')}")[0] in ("fails", "typo")


def test_rows_that_end_and_open_with_equals_are_one_chain():
    assert [" ".join(s.split()) for s in st.statements("\\begin{align}a =& b =\\\\ =& c\\end{align}")] == ["a = b = c"]


def test_and_in_words_between_two_statements_cuts_them():
    assert st.statements("a = b ~~~~\\text{and} ~~~ c = d") == ["a = b", "c = d"]
    assert st.statements("x = 1 \\quad\\text{and}\\quad y = 2") == ["x = 1", "y = 2"]


def test_a_sum_whose_summand_ignores_its_index_is_a_typo():
    fixed, why = si.slip("\\vec{F} = \\sum\\limits_{i=1}^n \\vec{F_n}")
    assert fixed == "\\vec{F} = \\sum\\limits_{i=1}^n \\vec{F_i}" and "upper limit n" in why
    assert si.slip("\\vec{F} = \\sum_{i=1}^n \\vec{F_i}") is None
    assert si.slip("T = \\sum_{i=1}^3 I_i \\omega_i^2") is None
    assert verdicts("\\vec{F} = \\sum\\limits_{i=1}^n \\vec{F_n}") == ["typo"]


def test_a_moment_component_set_to_euler_s_left_side_is_euler_s_equation():
    assert verdicts("M_{cm_1} = I_1\\dot{\\omega_1} + \\omega_2\\omega_3(I_3-I_2)") == ["holds"]
    assert verdicts("M_{cm_1} = I_1\\dot{\\omega_1} + \\omega_2\\omega_3(I_2-I_3)") == ["fails"]
    assert verdicts("M_{cm_1} = I_1\\dot{\\omega_1}") == ["unchecked"]


def test_an_equation_solved_for_a_term_after_an_arrow_is_the_same_equation():
    assert rearranged.check("F_{O_z} - mg = ma_{cm_z} \\rightarrow F_{O_z} = ma_{cm_z} + mg")[0] == "holds"
    verdict, why = rearranged.check("F_{O_z} - mg = ma_{cm_z} \\rightarrow F_{O_z} = ma_{cm_z} - mg")
    assert verdict == "fails" and "without changing its sign" in why
    assert rearranged.check("\\dot\\omega_3 = 0 \\rightarrow \\omega_3 = c") is None     # a consequence, not judged
    assert rearranged.check("x^2 = 4 \\rightarrow x = 2") is None
    assert rearranged.check("R_{i \\rightarrow b} = R_{b \\rightarrow i}^T") is None
