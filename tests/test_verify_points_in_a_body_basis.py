"""The notes reader on a body's points and velocities written in the text's own basis 𝐞₁, 𝐞₂, 𝐞₃
(𝐫_Q = b 𝐞₂ + h 𝐞₃, 𝐯_Q = 𝛚 × 𝐫_Q = …), as texts on rolling bodies write them: the cross product
taken on a right-handed orthonormal basis, with the vectors and the relations the text set
before (`derive.lecture.basis_vectors`)."""
import kept_readings as kept

HEAD = ("# A disk rolling on a cone\n\n"
        "The body's basis is $\\mathbf{e}_1, \\mathbf{e}_2, \\mathbf{e}_3$. Its angular velocity is\n\n"
        "$$\\boldsymbol{\\omega} = s \\mathbf{e}_1 + \\Omega \\mathbf{e}_3$$\n\n"
        "and rolling ties the spin to the turn about the vertical:\n\n"
        "$$s = \\frac{h}{b} \\Omega$$\n\n"
        "With $\\mathbf{r}_Q = b \\mathbf{e}_2 + h \\mathbf{e}_3$ for a point of the rim, its velocity is\n\n")


def _claims(display):
    text = HEAD + "$$" + display + "$$\n"
    return kept.by_line(text).get(kept.line_of(text, "$$" + display), [])


def _verdicts(display):
    return {c.verdict for c in _claims(display) if c.kind == "identity"}


def test_the_velocity_of_a_point_as_a_cross_product_in_the_body_basis_holds():
    assert _verdicts("\\mathbf{v}_Q = \\boldsymbol{\\omega} \\times \\mathbf{r}_Q = -\\Omega b \\mathbf{e}_1 "
                     "- \\frac{h^2}{b} \\Omega \\mathbf{e}_2 + h \\Omega \\mathbf{e}_3") == {"holds"}


def test_a_component_of_the_velocity_with_its_sign_slipped_fails():
    assert _verdicts("\\mathbf{v}_Q = \\boldsymbol{\\omega} \\times \\mathbf{r}_Q = -\\Omega b \\mathbf{e}_1 "
                     "+ \\frac{h^2}{b} \\Omega \\mathbf{e}_2 + h \\Omega \\mathbf{e}_3") == {"fails"}


def test_the_cross_product_taken_the_other_way_round_fails():
    assert _verdicts("\\mathbf{v}_Q = \\mathbf{r}_Q \\times \\boldsymbol{\\omega} = -\\Omega b \\mathbf{e}_1 "
                     "- \\frac{h^2}{b} \\Omega \\mathbf{e}_2 + h \\Omega \\mathbf{e}_3") == {"fails"}


def test_a_chain_of_the_angular_velocity_that_disagrees_with_the_text_s_relation_fails():
    assert _verdicts("\\boldsymbol{\\omega} = s \\mathbf{e}_1 + \\Omega \\mathbf{e}_3 = \\frac{h}{b} \\Omega "
                     "\\mathbf{e}_1 - \\Omega \\mathbf{e}_3") == {"fails"}
    assert not {"fails", "typo"} & _verdicts("\\boldsymbol{\\omega} = s \\mathbf{e}_1 + \\Omega \\mathbf{e}_3 = "
                                             "\\frac{h}{b} \\Omega \\mathbf{e}_1 + \\Omega \\mathbf{e}_3")


def test_a_velocity_in_a_symbol_the_text_never_related_is_left_unchecked():
    claims = [c for c in _claims("\\mathbf{v}_Q = \\boldsymbol{\\omega} \\times \\mathbf{r}_Q = -\\Omega c "
                                 "\\mathbf{e}_1 - \\frac{h^2}{b} \\Omega \\mathbf{e}_2 + h \\Omega \\mathbf{e}_3")
              if c.kind == "identity"]
    assert [c.verdict for c in claims] == ["unchecked"]
    assert "c" in claims[0].why


def test_a_hatted_basis_is_left_to_the_body_axes_reader():
    text = ("# Notes\n\n$$\\boldsymbol{\\omega} = \\omega_1 \\hat{\\mathbf{e}}_1 + \\omega_3 \\hat{\\mathbf{e}}_3$$\n\n"
            "$$\\mathbf{v} = \\boldsymbol{\\omega} \\times \\hat{\\mathbf{e}}_3 = -\\omega_1 \\hat{\\mathbf{e}}_2$$\n")
    assert not any("basis" in c.why and "right-handed" in c.why for c in kept.check_text(text))


WHEEL = ("# A wheel rolling on the floor\n\n"
         "Its centre moves with $\\mathbf{v}_C = v \\mathbf{i}$ and the wheel turns with\n\n"
         "$$\\boldsymbol{\\omega} = \\frac{v}{R} \\mathbf{j}$$\n\n"
         "so for the top of the wheel, with $\\mathbf{r}_T = R \\mathbf{k}$,\n\n")


def test_a_point_of_a_wheel_in_a_frame_s_bold_i_j_k_is_read_with_its_centre_s_velocity():
    def verdicts(display):
        text = WHEEL + "$$" + display + "$$\n"
        return {c.verdict for c in kept.by_line(text).get(kept.line_of(text, "$$" + display), [])
                if c.kind == "identity"}
    assert verdicts("\\mathbf{v}_T = \\mathbf{v}_C + \\boldsymbol{\\omega} \\times \\mathbf{r}_T = 2 v \\mathbf{i}") \
        == {"holds"}
    assert verdicts("\\mathbf{v}_T = \\mathbf{v}_C + \\boldsymbol{\\omega} \\times \\mathbf{r}_T = v \\mathbf{i}") \
        == {"fails"}


def test_a_relation_opening_with_an_accent_over_an_unbraced_letter_is_put_in():
    head = HEAD.replace("s \\mathbf{e}_1", "\\dot\\psi \\mathbf{e}_1").replace("$$s = ", "$$\\dot\\psi = ")

    def verdicts(display):
        text = head + "$$" + display + "$$\n"
        return {c.verdict for c in kept.by_line(text).get(kept.line_of(text, "$$" + display), [])
                if c.kind == "identity"}
    right = ("\\mathbf{v}_Q = \\boldsymbol{\\omega} \\times \\mathbf{r}_Q = -\\Omega b \\mathbf{e}_1 "
             "- \\frac{h^2}{b} \\Omega \\mathbf{e}_2 + h \\Omega \\mathbf{e}_3")
    assert verdicts(right) == {"holds"}
    assert verdicts(right.replace("- \\frac{h^2}", "+ \\frac{h^2}")) == {"fails"}


def test_a_rate_written_in_upright_differentials_is_the_dotted_rate():
    head = ("# A disk\n\nThe body's basis is $\\mathbf{e}_x, \\mathbf{e}_y, \\mathbf{e}_z$. Its angular velocity is\n\n"
            "$$\\boldsymbol{\\omega} = \\dot{\\phi} \\mathbf{e}_z$$\n\n"
            "With $\\mathbf{r}_P = R \\mathbf{e}_x$ for a point of the rim, its velocity is\n\n")
    good = "\\mathbf{v}_P = \\boldsymbol{\\omega} \\times \\mathbf{r}_P = R \\frac{\\mathrm{d} \\phi}{\\mathrm{d} t} \\mathbf{e}_y"
    for display, verdict in ((good, "holds"), (good.replace("= R", "= -R"), "fails")):
        text = head + "$$" + display + "$$\n"
        claims = kept.by_line(text).get(kept.line_of(text, "$$" + display), [])
        assert {c.verdict for c in claims if c.kind == "identity"} == {verdict}, display
