"""The notes reader on vectors written as sums on hatted unit vectors (a î + b ĵ + c k̂, Î Ĵ K̂, î′ ĵ′ k̂′)
and their rates: the basis right-handed and orthonormal, a vector the text set recorded and its
restatement compared, a chain judged link by link, rates read with the basis fixed and turning
(`derive.lecture.hat_basis`)."""
import kept_readings as kept

MOMENT = ("# The moment of a force\n\n"
          "$$\\mathbf{M} = (r_x\\,\\mathbf{\\hat{i}} + r_y\\,\\mathbf{\\hat{j}} + r_z\\,\\mathbf{\\hat{k}}) \\times "
          "(F_x\\,\\mathbf{\\hat{i}} + F_y\\,\\mathbf{\\hat{j}} + F_z\\,\\mathbf{\\hat{k}})$$\n\n"
          "Expanded:\n\n")
COMPONENTS = ("# A moving vector\n\n"
              "$$\\boldsymbol{B} = B_x\\boldsymbol{\\hat{i}} + B_y\\boldsymbol{\\hat{j}} + B_z\\boldsymbol{\\hat{k}}$$\n\n"
              "and in the fixed frame\n\n"
              "$$\\boldsymbol{B} = B_X\\boldsymbol{\\hat{I}} + B_Y\\boldsymbol{\\hat{J}} + B_Z\\boldsymbol{\\hat{K}}$$\n\n"
              "Its rate:\n\n")


def _verdicts(head, display):
    text = head + "$$" + display + "$$\n"
    return [c.verdict for c in kept.by_line(text).get(kept.line_of(text, "$$" + display), [])
            if "unit vectors" in c.why or "over dt" in c.why]


def test_a_vector_restated_on_hatted_unit_vectors_as_its_expanded_cross_product_holds():
    assert _verdicts(MOMENT, "\\mathbf{M} = (r_y F_z - r_z F_y)\\mathbf{\\hat{i}} + (r_z F_x - r_x F_z)\\mathbf{\\hat{j}} "
                             "+ (r_x F_y - r_y F_x)\\mathbf{\\hat{k}}") == ["holds"]
    assert _verdicts(MOMENT, "\\mathbf{M} = \\det \\begin{bmatrix} \\mathbf{\\hat{i}} & \\mathbf{\\hat{j}} & "
                             "\\mathbf{\\hat{k}} \\\\ r_x & r_y & r_z \\\\ F_x & F_y & F_z \\end{bmatrix}") == ["holds"]


def test_a_vector_set_again_to_another_value_is_recorded_anew_never_flagged():
    display = ("\\mathbf{M} = (r_y F_z + r_z F_y)\\mathbf{\\hat{i}} + (r_z F_x - r_x F_z)\\mathbf{\\hat{j}} "
               "+ (r_x F_y - r_y F_x)\\mathbf{\\hat{k}}")
    text = MOMENT + "$$" + display + "$$\n"
    assert kept.verdicts_by_line(text)[kept.line_of(text, "$$" + display)] == {"unchecked"}


def test_a_chain_on_hatted_unit_vectors_with_a_slipped_component_fails():
    head = "# A cross product\n\n"
    assert _verdicts(head, "\\mathbf{u} = (a\\hat{i} + b\\hat{j}) \\times (c\\hat{i} + e\\hat{k}) = "
                           "b e\\hat{i} - a e\\hat{j} - b c\\hat{k}") == ["unchecked", "holds"]
    assert _verdicts(head, "\\mathbf{u} = (a\\hat{i} + b\\hat{j}) \\times (c\\hat{i} + e\\hat{k}) = "
                           "b e\\hat{i} + a e\\hat{j} - b c\\hat{k}") == ["unchecked", "fails"]


def test_the_product_rule_on_a_turning_basis_holds():
    assert _verdicts(COMPONENTS, "\\frac{d\\boldsymbol{B}}{dt} = \\frac{dB_x}{dt}\\boldsymbol{\\hat{i}} + B_x "
                                 "\\frac{d\\boldsymbol{\\hat{i}}}{dt} + \\frac{dB_y}{dt}\\boldsymbol{\\hat{j}} + B_y "
                                 "\\frac{d\\boldsymbol{\\hat{j}}}{dt} + \\frac{dB_z}{dt}\\boldsymbol{\\hat{k}} + B_z "
                                 "\\frac{d\\boldsymbol{\\hat{k}}}{dt}") == ["holds"]


def test_the_rate_on_a_basis_read_fixed_holds():
    assert _verdicts(COMPONENTS, "\\frac{d\\boldsymbol{B}}{dt} = \\frac{dB_X}{dt}\\boldsymbol{\\hat{I}} + "
                                 "\\frac{dB_Y}{dt}\\boldsymbol{\\hat{J}} + \\frac{dB_Z}{dt}\\boldsymbol{\\hat{K}}") == ["holds"]


def test_a_component_over_dt_without_its_d_is_a_typo():
    text = COMPONENTS + ("$$\\frac{d\\boldsymbol{B}}{dt} = \\frac{dB_X}{dt}\\boldsymbol{\\hat{I}} + "
                         "\\frac{B_Y}{dt}\\boldsymbol{\\hat{J}} + \\frac{dB_Z}{dt}\\boldsymbol{\\hat{K}}$$\n")
    claims = kept.by_line(text)[kept.line_of(text, "$$\\frac{d\\boldsymbol{B}}{dt} = \\frac{dB_X}")]
    assert [c.verdict for c in claims] == ["typo"]
    assert "\\frac{dB_Y}{dt}" in claims[0].correction


def test_a_component_over_an_upright_dt_without_its_d_is_a_typo_too():
    text = COMPONENTS + ("$$\\frac{d\\boldsymbol{B}}{\\mathrm{d}\\,t} = \\frac{dB_X}{\\mathrm{d}\\,t}\\boldsymbol{\\hat{I}} + "
                         "\\frac{B_Y}{\\mathrm{d}\\,t}\\boldsymbol{\\hat{J}} + \\frac{dB_Z}{\\mathrm{d}\\,t}\\boldsymbol{\\hat{K}}$$\n")
    claims = kept.by_line(text)[kept.line_of(text, "$$\\frac{d\\boldsymbol{B}}")]
    assert [c.verdict for c in claims] == ["typo"]


def test_a_hatted_sum_beside_a_vector_the_text_never_set_is_not_read_here():
    head = "# Notes\n\n"
    assert _verdicts(head, "\\mathbf{v} = \\boldsymbol{\\omega} \\times (a\\hat{i} + b\\hat{j}) = "
                           "c\\hat{i} + e\\hat{j}") == []


def test_a_hat_over_the_letters_of_a_command_with_its_backslash_lost_is_a_typo():
    text = COMPONENTS + ("$$\\boldsymbol{a} = \\frac{d v_x}{dt} \\boldsymbol{\\hat{\\imath}} + \\frac{d v_y}{dt} "
                         "\\boldsymbol{\\hat{\\jmath}} = a_x \\boldsymbol{\\hat{imath}} + a_y \\boldsymbol{\\hat{\\jmath}}$$\n")
    claims = kept.by_line(text)[kept.line_of(text, "$$\\boldsymbol{a} = ")]
    assert [c.verdict for c in claims] == ["typo"]
    assert "\\hat{\\imath}" in claims[0].correction
