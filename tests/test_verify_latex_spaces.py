"""The notes reader on LaTeX's spaces (derive/lecture/latex_spaces.py, the one place that says what a
space is): every reader that recognises a form reads it the same whatever space sets its factors
apart — whitespace, thin ``\\,``, medium ``\\:``, thick ``\\;``, negative thin ``\\!``, the control
space ``\\ `` or a tie ``~`` — and a quad, the space a text sets between two statements, is not taken
for a space between factors where a reader reads factors across it."""
from types import SimpleNamespace

import pytest

from derive.lecture import fixed_axis, formula_names, hat_maps, imaginary_unit, kane_notation, source, stated_convention
from derive.lecture import chain_end_names
from derive.lecture import latex as lx
from derive.lecture import names as nm
from derive.lecture import stated_theorems, texmacros, vector_models
from derive.lecture import vector_algebra_model as va
from derive.lecture import vocabulary as vc
from derive.lecture.arithmetic import arithmetic
from derive.lecture.statements import statements
from derive.lecture.units import plain_numbers

import kept_readings as kept

SPACES = (" ", "\\,", "\\:", "\\;", "\\!", "\\ ", "~")
SYMBOLS = ("\\,", "\\:", "\\;", "\\!", "\\ ")
QUADS = (" \\quad ", " \\qquad ")


@pytest.mark.parametrize("space", SPACES)
def test_an_angular_velocity_spaced_off_its_unit_vector_sets_the_axis(space):
    assert fixed_axis.setting(f"\\vec\\omega = \\omega{space}\\hat k") == 2


@pytest.mark.parametrize("quad", QUADS)
def test_a_unit_vector_after_a_quad_sets_no_axis(quad):
    assert fixed_axis.setting(f"\\vec\\omega = \\omega{quad}\\hat k") is None


@pytest.mark.parametrize("space", SPACES)
def test_the_weight_spaced_between_mass_and_gravity_names_the_mass(space):
    names = nm.Names()
    formula_names.learn(names, f"$V = m{space}g d \\cos\\theta$")
    assert names.symbols[("m", "")] == "mass"


@pytest.mark.parametrize("quad", QUADS)
def test_a_mass_and_a_gravity_in_two_statements_name_nothing(quad):
    names = nm.Names()
    formula_names.learn(names, f"$x = m{quad}g = 9.81$")
    assert ("m", "") not in names.symbols


@pytest.mark.parametrize("space", SPACES)
def test_the_moment_of_a_force_spaced_off_its_bracket_is_read(space):
    assert va.prepare(f"M_z{space}(\\vec F_i)") == "(\\vec r_i \\times \\vec F_i)_z"


@pytest.mark.parametrize("quad", QUADS)
def test_a_bracket_after_a_quad_is_no_moments_argument(quad):
    assert "M_z" in va.prepare(f"M_z{quad}(\\vec F_i)")


@pytest.mark.parametrize("space", SPACES)
def test_a_frames_prescript_spaced_off_its_vector_is_dropped(space):
    assert "^A" not in kane_notation.rewrite(f"{{}}^A{space}\\bar{{H}}^{{B/B_o}} = 0", known=True)


@pytest.mark.parametrize("quad", QUADS)
def test_a_superscript_before_a_quad_is_no_frame_of_the_next_statements_vector(quad):
    assert "^A" in kane_notation.rewrite(f"x^A{quad}\\bar{{H}}^{{B/B_o}} = 0", known=True)


@pytest.mark.parametrize("space", SPACES)
def test_koenigs_theorem_with_any_space_between_its_factors_is_recognised(space):
    s = space
    stated = f"T = \\frac{{1}}{{2}}{s}m{s}v_c^2 + \\frac{{1}}{{2}}{s}J_C{s}\\omega^2"
    assert stated_theorems.theorem(stated) == stated_theorems.KOENIG
    assert stated_theorems.theorem(stated.replace("v_c^2", "v_c")) is None


@pytest.mark.parametrize("space", SPACES + QUADS)
def test_a_hat_map_read_across_any_spacing_of_its_display(space):
    # a display is read whole there, before it is cut into statements: a quad may space one statement
    body = f"$$R^T{space}\\dot R ={space}\\widehat{{\\Omega}}$$"
    assert hat_maps.body_velocities(body) == [(1, "\\Omega")]


@pytest.mark.parametrize("space", SPACES + QUADS)
def test_three_turns_set_side_by_side_state_their_sequence(space):
    body = f"$$R = R_3(\\phi){space}R_1(\\theta){space}R_3(\\psi)$$"
    assert [(s.convention, s.angles) for s in stated_convention.stated(body)] == [("z-x-z", ("phi", "theta", "psi"))]


@pytest.mark.parametrize("space", SPACES)
def test_a_unit_spaced_off_its_number_is_dropped(space):
    assert plain_numbers(f"m = 2{space}\\text{{kg}}").strip() == "m = 2"
    assert plain_numbers(f"m = 0.1~kg{space}").strip() == "m = 0.1"


@pytest.mark.parametrize("space", SYMBOLS)
def test_a_space_inside_a_script_or_an_operator_name_sets_nothing_apart(space):
    assert source.normalize(f"x_{{\\beta{space}\\alpha}} = \\operatorname{{d{space}}}t") == \
        "x_{\\beta \\alpha} = \\mathrm{d}t"


@pytest.mark.parametrize("space", SPACES)
def test_a_relative_rate_spaced_after_its_differentials_is_the_rate_in_the_body(space):
    s = space
    assert vector_models.frame_rates(f"\\frac{{\\tilde{{d}}{s}\\vec{{n}}}}{{d{s}t}} = 0") == \
        "\\left(\\frac{d \\vec{n}}{dt}\\right)_{b} = 0"


@pytest.mark.parametrize("space", SPACES + QUADS)
def test_words_after_a_statement_go_with_the_spacing_before_them(space):
    assert statements(f"\\omega_x {space}\\text{{is constant}}") == ["\\omega_x"]
    assert statements(f"a = b {space}\\text{{and}}{space} c = d") == ["a = b", "c = d"]


@pytest.mark.parametrize("quad", QUADS)
def test_numbers_on_either_side_of_a_quad_are_not_a_product(quad):
    assert arithmetic(f"x = 2{quad}3 = 6") == []
    assert [v for v, _ in arithmetic("x = 2 \\, 3 = 6")] == ["holds"]


@pytest.mark.parametrize("space", SYMBOLS + QUADS)
def test_the_scanner_skips_every_spacing_command(space):
    assert [t.kind for t in vc.scan(f"a{space} b")] == ["atom", "atom"]


@pytest.mark.parametrize("space", SYMBOLS + ("~",))
def test_an_equals_sign_set_apart_by_small_spaces_is_the_plain_one(space):
    assert source.normalize(f"L(\\theta) {space}={space} \\frac{{1}}{{2}} I") == "L(\\theta) = \\frac{1}{2} I"
    assert source.normalize("x \\\\ = y") == "x \\\\ = y"          # a row break before = is no control space


@pytest.mark.parametrize("space", SYMBOLS)
def test_a_function_defined_with_a_spaced_equals_sign_is_the_texts_definition(space):
    text = ("# A hoop\n\nThe moment of inertia about the contact point is $I_p(\\theta)$ and the potential $V(\\theta)$.\n\n"
            f"$$L(\\theta, \\dot\\theta) {space}={space} \\frac{{1}}{{2}} I_p(\\theta) \\dot\\theta^2 - V(\\theta)$$\n\n"
            f"$$p_\\theta {space}={space} \\frac{{\\partial L}}{{\\partial \\dot\\theta}} {space}={space} I_p(\\theta) \\dot\\theta$$\n")
    plain = text.replace(f" {space}={space} ", " = ")
    assert kept.verdicts_by_line(text) == kept.verdicts_by_line(plain)
    assert "holds" in kept.verdicts_by_line(plain)[kept.line_of(plain, "p_\\theta")]


def test_a_unicode_letter_is_spaced_off_only_a_letter_after_it():
    assert source.characters("I_p(θ) + θx + ω₃") == "I_p(\\theta) + \\theta x + \\omega_{3}"


@pytest.mark.parametrize("kern", ("\\mkern-1.5mu", "\\mkern -1.5 mu", "\\kern0.1em", "\\mskip 2mu"))
def test_a_kern_by_a_length_is_dropped_before_any_reader(kern):
    # texts set a transpose's T closer to its vector: ω^{\mkern-1.5mu T} is ωᵀ
    assert "kern" not in source.normalize(f"\\omega^{{{kern}\\mathsf{{T}}}}") \
        and "skip" not in source.normalize(f"\\omega^{{{kern}\\mathsf{{T}}}}")


def test_a_kinetic_energy_written_with_a_kerned_transpose_is_read():
    # a macro for the transpose, as a book's preamble defines it, expands to the kern too
    head = ("---\nconvention: z-x-z\n---\n# Energy\n\n$$\n\\newcommand{\\trans}{^{\\mkern-1.5mu\\mathsf{T}}}\n$$\n\n"
            "In the principal axes of the body:\n\n")
    right = head + "$$\nT = \\frac{1}{2}\\boldsymbol{\\omega}\\trans\\cdot\\mathbf{I}\\cdot\\boldsymbol{\\omega}\n$$\n"
    slip = head + "$$\nT = \\boldsymbol{\\omega}\\trans\\cdot\\mathbf{I}\\cdot\\boldsymbol{\\omega}\n$$\n"
    assert [c.verdict for c in kept.check_text(right) if c.latex.startswith("T =")] == ["holds"]
    assert [c.verdict for c in kept.check_text(slip) if c.latex.startswith("T =")] in (["fails"], ["typo"])


@pytest.mark.parametrize("space", SPACES)
def test_a_turn_written_out_with_a_space_in_its_cells_is_still_that_turn(space):
    # C_X(φ) written out is the passive turn whatever sets its first and last cells apart, so the
    # product of the passive turns turns first by its rightmost factor: φ first
    cells = f"{space}1 & 0 & 0 \\\\ 0 & \\cos \\phi & \\sin \\phi \\\\ 0 & -\\sin \\phi & \\cos \\phi{space}"
    body = (f"$$C_X(\\phi) = \\begin{{pmatrix}}{cells}\\end{{pmatrix}}$$\n\n"
            "$$\\begin{pmatrix} x \\\\ y \\\\ z \\end{pmatrix} = C_z(\\psi) C_x(\\theta) C_z(\\phi) "
            "\\begin{pmatrix} X \\\\ Y \\\\ Z \\end{pmatrix}$$\n")
    assert [(s.convention, s.angles) for s in stated_convention.stated(body)] == [("z-x-z", ("phi", "theta", "psi"))]


def test_a_thin_space_in_a_transposed_bracket_is_no_comma_between_entries():
    # [C_z(ψ) \, C_x(θ)]^T is the transpose of a product, not a column of entries cut at the \, 's comma
    assert source.normalize("R = [C_z(\\psi) \\, C_x(\\theta)]^T") == "R = [C_z(\\psi) \\, C_x(\\theta)]^T"
    assert source.normalize("v = [a \\, b, c]^T") == "v = \\begin{bmatrix} a \\, b \\\\ c \\end{bmatrix}"


@pytest.mark.parametrize("space", SPACES)
def test_an_angular_velocity_spaced_off_its_body_axis_states_its_components(space):
    # ω = ω₁ ê₁ is a spin about the first axis (ω₂ = ω₃ = 0), a case of the text, whatever the space
    text = ("# A free body\n\nFor a body with $I_3 > I_2 > I_1$ let it spin about the axis of the smallest moment:\n\n"
            f"$$\n\\boldsymbol{{\\omega}} = \\omega_1{space}\\widehat{{\\mathbf{{e}}}}_1\n$$\n")
    assert [(c.verdict, "a case of the text" in c.why) for c in kept.check_text(text)] == [("unchecked", True)]


@pytest.mark.parametrize("space", SPACES)
def test_a_frame_bar_spaced_off_its_vector_is_dropped(space):
    # Ω|_(Z,N,z) = φ̇ e_Z + θ̇ e_N + ψ̇ e_z: the bar names the axes, whatever space stands before it
    s = space
    text = ("# Euler angles\n\nThe fixed frame has the basis $(\\bm e_X,\\bm e_Y,\\bm e_Z)$ and the body frame "
            "$(\\bm e_x,\\bm e_y,\\bm e_z)$.\n\n"
            "$$R = R_Z(\\phi) R_X(\\theta) R_Z(\\psi)$$\n\n"
            "The angular velocity $\\bm \\Omega$ is written along the three axes of the turns:\n\n"
            f"$$\\bm \\Omega{s}\\big|_{{(Z,N,z)}} = \\dot{{\\phi}}{s}\\bm e_Z + \\dot{{\\theta}}{s}\\bm e_N + "
            f"\\dot{{\\psi}}{s}\\bm e_z{s}\\big|_{{(Z,N,z)}}$$\n")
    line = kept.line_of(text, "\\bm \\Omega" + s + "\\big|")
    assert kept.verdicts_by_line(text)[line] == {"holds"}


@pytest.mark.parametrize("space", SPACES)
def test_the_imaginary_unit_spaced_off_its_factors_is_still_the_imaginary_unit(space):
    s = space
    assert imaginary_unit.read(f"\\dot{{u}} - \\Omega{s}i{s}u = \\alpha") == f"\\dot{{u}} - \\Omega{s}\\sqrt{{-1}}{s}u = \\alpha"
    assert imaginary_unit.read(f"x_i{s}= 2") == f"x_i{s}= 2"


@pytest.mark.parametrize("space", SPACES)
def test_a_volume_element_spaced_off_its_upright_d_with_the_density_is_the_mass_element(space):
    prepared = va.prepare(f"I_x = \\int(y^2 + z^2)\\rho\\,\\mathrm{{d}}{space}V")
    assert "dm" in prepared and "\\rho" not in prepared and "V" not in prepared


@pytest.mark.parametrize("space", SPACES)
def test_a_font_switch_spaced_off_its_letter_sets_that_letter(space):
    assert texmacros.font_switches(f"{{\\bf{space}G}} + {{\\rm{space}body}}") == "{\\mathbf{G}} + {\\mathrm{body}}"


@pytest.mark.parametrize("space", SYMBOLS + ("~",))
def test_small_spaces_setting_a_relation_apart_are_the_plain_sign(space):
    s = space
    assert source.normalize(f"\\Omega {s}\\coloneqq{s} \\frac{{I_1 - I_3}}{{I_1}}\\omega_3") == \
        "\\Omega \\equiv \\frac{I_1 - I_3}{I_1}\\omega_3"
    assert source.normalize(f"a {s}\\le{s} b {s}<{s} c") == "a \\le b < c"
    assert source.normalize("\\left( a + c \\right) \\leq \\, b") == "\\left( a + c \\right) \\leq b"


@pytest.mark.parametrize("space", SPACES)
def test_a_space_set_around_plain_tex_s_over_sets_nothing_apart(space):
    s = space
    assert source.normalize(f"F = {{d(m \\cdot v) {s}\\over{s} dt}}") == source.normalize("F = {d(m \\cdot v) \\over dt}")
    assert source.normalize(f"{{dh{s}\\over{s}dt}}") == "{\\frac{dh}{dt}}"


@pytest.mark.parametrize("space", SPACES)
def test_the_mass_of_a_piece_spaced_off_its_delta_is_the_particles_mass(space):
    prepared = va.prepare(f"\\mathbf{{L}} = \\sum_i \\mathbf{{r}}_i \\times \\Delta{space}m_i \\dot{{\\mathbf{{r}}}}_i")
    assert "\\Delta" not in prepared and "m_i" in prepared


class _ChainReader(chain_end_names.ChainEndNames):
    """The mixin with what it uses of the checker: an open vocabulary and the context's definitions."""

    def __init__(self):
        self.vocab, self.ctx = lx.Vocabulary(open=True), SimpleNamespace(defs={})


@pytest.mark.parametrize("space", SPACES)
def test_a_name_defined_at_a_chains_end_spaced_off_its_factor_is_put_in_later(space):
    reader = _ChainReader()
    reader._named_at_chain_end(f"L_z = \\omega \\sum_i m_i r_i^2 = J_z{space}\\omega", 3)
    later = chain_end_names.put_in("\\sum_i m_i(x_i^2 + y_i^2) = J_z", reader.chain_end_latex, 9)
    assert later.startswith("\\sum_i m_i(x_i^2 + y_i^2) = \\left(\\frac{\\omega \\sum_i m_i r_i^2}{")
