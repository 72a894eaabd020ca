"""Vector statements as introductory textbooks write them: one particle's 𝐋 = 𝐫 × 𝐩 among sums over
a body's particles, the book's own differential macro, a cross product by components, and the
integrals of the free body stated as constants."""
import kept_readings as kept

HEAD = "A rigid body of particles $m_i$ at $\\mathbf{r}_i$ turns with $\\boldsymbol{\\omega}$.\n\n"
BODY = "$$\\mathbf{L} = \\sum_i m_i \\mathbf{r}_i \\times (\\boldsymbol{\\omega} \\times \\mathbf{r}_i)$$\n\n"


def verdicts(body: str, head: str = HEAD) -> dict:
    out = {}
    for c in kept.check_text(head + body):
        out.setdefault(c.line, []).append(c.verdict)
    return out


def at(body: str, line: int, head: str = HEAD) -> set:
    return set(verdicts(body, head).get(line, ()))


def test_one_particles_momentum_without_an_index_speaks_of_that_particle_after_a_sum_over_the_body():
    holds = BODY + "For one particle:\n\n$$\\mathbf{L} = \\mathbf{r} \\times \\mathbf{p}$$\n"
    assert at(holds, 3) == {"holds"}
    assert at(holds, 7) == {"holds"}
    swapped = BODY + "For one particle:\n\n$$\\mathbf{L} = \\mathbf{p} \\times \\mathbf{r}$$\n"
    assert at(swapped, 7) & {"typo", "fails"}


def test_a_cross_product_by_components_holds_and_a_swapped_pair_fails():
    rows = ("$$\\begin{aligned} (\\mathbf{A}\\times\\mathbf{B})_x &= A_yB_z - B_yA_z \\\\ "
            "(\\mathbf{A}\\times\\mathbf{B})_{y} &= A_zB_x - B_zA_x \\end{aligned}$$\n")
    assert at(rows, 3) == {"holds"}
    assert at("$$(\\mathbf{A}\\times\\mathbf{B})_z = A_yB_x - B_yA_x$$\n", 3) == {"fails"}


def test_a_component_of_a_scalar_in_brackets_is_not_read():
    assert at("$$(\\mathbf{A}\\cdot\\mathbf{B})_x = A_x B_x$$\n", 3) <= {"unchecked"}


def test_a_books_differential_macro_with_its_kerning_is_the_derivative():
    head = HEAD + "\\newcommand{\\der}{\\operatorname{d\\!}}\n\n"
    body = BODY + "$$\\frac{\\der\\mathbf{L}}{\\der t} = \\sum_i \\frac{\\der}{\\der t}(\\mathbf{r}_i\\times\\mathbf{p}_i)$$\n"
    assert at(body, 7, head) == {"holds"}


def test_upright_text_is_read_as_text_and_a_numbered_constant_as_a_constant():
    from derive.lecture import source, statements
    assert "\\text{N}" in source.normalize("15 \\textup{N}")
    assert statements._CONST.search("\\text{constant \\#2}") and statements._CONST.search("\\text{const}")
    assert not statements._CONST.search("\\text{constant torque}")


FREE = "A free body, no torque, in its principal axes $x$, $y$, $z$.\n\n"


def test_the_free_bodys_integrals_in_the_texts_components_hold():
    body = ("$$L_x^2 + L_y^2 + L_z^2 = \\text{constant}$$\n\n"
            "$$\\frac{1}{I_{xx}}L_x^2 + \\frac{1}{I_{yy}}L_y^2 + \\frac{1}{I_{zz}}L_z^2 = \\text{constant \\#2}$$\n")
    assert at(body, 3, FREE) == {"holds"}
    assert at(body, 5, FREE) == {"holds"}


def test_a_quantity_the_free_body_does_not_conserve_is_never_judged():
    body = "$$L_x^2 + 2 L_y^2 + L_z^2 = \\text{constant}$$\n"
    assert at(body, 3, FREE) == {"unchecked"}


def test_the_torque_on_a_system_is_the_sum_of_the_moments_of_the_forces_on_its_particles():
    assert at("$$\\boldsymbol{\\tau} = \\sum_i \\mathbf{r}_i\\times\\mathbf{F}_i$$\n", 3) == {"holds"}
    assert at("$$\\boldsymbol{\\tau} = \\sum_i \\mathbf{F}_i\\times\\mathbf{r}_i$$\n", 3) & {"typo", "fails"}


KINETIC = ("$$\\begin{aligned} K &= \\sum_i \\frac{1}{2} m_i v_i^2 \\\\ "
           "&= \\frac{1}{2} \\sum_i m_i (\\boldsymbol{\\omega} \\times \\mathbf{r}_i) \\cdot (\\boldsymbol{\\omega} \\times "
           "\\mathbf{r}_i) \\end{aligned}$$\n\n")


def test_a_letter_the_text_sets_to_a_sum_stands_for_it_in_the_rows_and_statements_that_follow():
    body = KINETIC + ("$$\\begin{aligned} K &= \\frac{1}{2} \\sum_i m_i \\left[ \\mathbf{r}_i \\times (\\boldsymbol{\\omega} "
                      "\\times \\mathbf{r}_i) \\right] \\cdot \\boldsymbol{\\omega} \\\\ &= \\frac{1}{2} \\mathbf{L} \\cdot "
                      "\\boldsymbol{\\omega} \\end{aligned}$$\n")
    assert "holds" in at(body, 3) and at(body, 5) == {"holds"}
    slip = KINETIC + "$$K = \\mathbf{L} \\cdot \\boldsymbol{\\omega}$$\n"
    assert at(slip, 5) & {"typo", "fails"}


def test_a_letter_set_again_to_a_number_is_not_compared_with_its_earlier_expression():
    assert not at(KINETIC + "$$K = 2$$\n", 5) & {"typo", "fails"}


def test_one_component_set_to_a_constant_stays_a_setting_and_a_named_integral_is_compared_with_its_name():
    assert at("$$\\omega_3 = \\Omega = \\text{const}$$\n", 3, FREE) == {"unchecked"}
    slip = "$$\\sum_{i=1}^3 I_i \\omega_i^2 = T = \\text{const}$$\n"
    assert at(slip, 3, FREE) & {"typo", "fails"}


def test_a_link_left_unchecked_for_a_symbol_of_the_texts_names_that_symbol():
    """A link the reader leaves unchecked because one side holds a symbol the text never tied to
    the body says which symbol (and nothing else)."""
    text = ("A body turns about the fixed $z$ axis, $\\vec\\omega = \\omega \\hat k$; particle $i$ has "
            "mass $m_i$ at distance $r_i$ from the axis.\n\n"
            "$$L_z = \\omega \\sum_i m_i r_i^2 = J_z \\omega$$\n")
    loose = [c.why for c in kept.check_text(text) if "has not tied to the body" in c.why]
    assert loose == ["involves J, which the text has not tied to the body"]


def test_a_bold_alpha_with_a_particles_index_is_not_the_bodys_angular_acceleration():
    """𝛂ᵢ is particle i's (an acceleration a text names so), not the body's 𝛂: a display that
    equates −mᵢ𝛂ᵢ with the in-plane inertial force is left unread, never judged against −mᵢ𝛂."""
    text = ("A body turns about the fixed $z$ axis, $\\vec\\omega = \\omega \\hat k$, with angular "
            "acceleration $\\alpha$; particle $i$ has mass $m_i$ at $(x_i, y_i)$.\n\n"
            "$$\\vec F_i = - m_i \\vec\\alpha_i = m_i (\\alpha y_i + \\omega^2 x_i) \\hat i "
            "+ m_i (\\omega^2 y_i - \\alpha x_i) \\hat j$$\n")
    assert {c.verdict for c in kept.check_text(text) if "alpha_i" in c.latex} <= {"unchecked"}


EULER_VECTORS = "$$\\vec{M_{cm}} = I\\dot{\\vec{\\omega}}+\\vec{\\omega}\\times(I\\vec{\\omega})$$\n"


def test_a_vector_of_the_texts_alone_against_eulers_equation_in_vectors_is_the_torque():
    assert at(EULER_VECTORS, 3, head="# Notes\n\n") == {"holds"}
    assert at("$$I\\dot{\\boldsymbol{\\omega}} + \\boldsymbol{\\omega}\\times(I\\boldsymbol{\\omega}) = \\mathbf{N}$$\n",
              3, head="# Notes\n\n") == {"holds"}
    slip = EULER_VECTORS.replace("+\\vec{\\omega}", "-\\vec{\\omega}")
    assert at(slip, 3, head="# Notes\n\n") & {"typo", "fails"}


def test_a_vector_of_the_texts_alone_beside_no_full_eulers_equation_is_not_taken_for_the_torque():
    # the torque law without ω × Iω may be one a text sets for a fixed axis; an acceleration is no torque
    assert at("$$\\vec{N} = I\\dot{\\vec{\\omega}}$$\n", 3, head="# Notes\n\n") == {"unchecked"}
    assert at("$$\\vec{a} = \\dot{\\vec\\omega}\\times\\vec{r} + \\vec\\omega\\times(\\vec\\omega\\times\\vec r)$$\n",
              3, head="# Notes\n\n") == {"unchecked"}
