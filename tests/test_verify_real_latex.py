"""The notes reader on LaTeX as real texts write it: characters, commands, environments, macros,
the text's own names and settings, other angle sequences, corrections in the text's notation."""
import pytest

from derive.errors import SceneError
from derive.lecture import notes as nt
import kept_readings as kept
from derive.lecture import source


def verdicts(text, **kw):
    return [(c.line, c.verdict) for c in kept.check_text(text, **kw)]


@pytest.mark.parametrize("written, read", [
    ("T = \u00bd I\u2081\u03c9\u2081\u00b2 \u2212 x", r"T = \frac{1}{2} I_{1}\omega_{1}^{2} - x"),
    (r"I_3 \dot{\omega}_3 = 0 \tag{13.89}\label{eq:e3}", r"I_3 \dot{\omega}_3 = 0"),
    (r"\boxed{T = 0} \notag", "T = 0"),
    (r"\pmb{\omega} \cdot \pmb{L}", r"\boldsymbol{\omega} \cdot \boldsymbol{L}"),
    (r"\phi = 30^{\circ}", r"\phi = 30 \cdot \frac{\pi}{180}"),
    ("a &#8211; b &lt; c", "a - b < c"),
    (r"\omega^2_1 + \dfrac{1}{2}", r"\omega_1^2 + \frac{1}{2}"),
    (r"\operatorname{sin}\theta", r"\sin \theta"),
    (r"\dv{\theta}{t}", r"\frac{d \theta}{d t}"),
    (r"\varOmega", r"\Omega"),
    ("\u03b8\u0307", r"\dot{\theta}"),
    (r"\dot x + \vec N", r"\dot x + \vec N"),
])
def test_a_formula_is_read_as_the_text_writes_it(written, read):
    assert source.normalize(written) == read


def test_the_files_own_macros_are_expanded_with_their_arguments():
    macros = source.macros(r"\newcommand{\vw}[1]{\boldsymbol{\omega}_{#1}} \def\half{\frac12}")
    assert source.normalize(r"\half I \vw{3}", macros) == r"\frac{1}{2} I \boldsymbol{\omega}_{3}"


def test_what_is_not_rendered_is_not_read():
    text = ("# Notes\n\n<!-- $$T = 5$$ -->\n\n```\n$$T = 6$$\n```\n\nSee `$$T = 7$$`.\n\n"
            "$$T = \\frac{1}{2} I_1 \\omega_1^2 + \\frac{1}{2} I_2 \\omega_2^2 + \\frac{1}{2} I_3 \\omega_3^2$$\n")
    assert verdicts(text) == [(11, "holds")]


_T = "T = \\frac{1}{2} I_1 \\omega_1^2 + \\frac{1}{2} I_2 \\omega_2^2 + \\frac{1}{2} I_3 \\omega_3^2"


def test_a_latex_source_comments_out_the_rest_of_a_line_after_percent():
    text = ("\\documentclass{article}\n\\begin{document}\n% $$T = 5$$\n"
            f"A 50\\% share: $${_T}$$ % $$T = 6$$\n\\end{{document}}\n")
    assert verdicts(text) == [(4, "holds")]


def test_percent_in_markdown_prose_is_text():
    assert verdicts(f"# Notes\n\n50 % of it:\n\n$${_T}$$\n") == [(5, "holds")]


def test_latex_environments_are_displays():
    text = ("# Euler\n\n\\begin{align}\n I_1 \\dot{\\omega}_1 &= (I_2 - I_3)\\omega_2\\omega_3 \\label{a} \\\\\n"
            " I_2 \\dot{\\omega}_2 &= (I_3 - I_1)\\omega_3\\omega_1 \\nonumber\n\\end{align}\n\n"
            "\\begin{equation}\n I_3 \\dot{\\omega}_3 = (I_1 - I_2)\\omega_1\\omega_2 \\tag{3}\n\\end{equation}\n")
    assert verdicts(text) == [(3, "holds"), (3, "holds"), (8, "holds")]


def test_a_z_x_z_texts_omega_1_is_its_angular_velocity_not_the_lectures_frequency():
    text = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Angles\n\n"
            "The body components $\\Omega_1, \\Omega_2, \\Omega_3$ of the angular velocity are\n\n"
            "$$\\Omega_1 = \\dot\\phi \\sin\\theta \\sin\\psi + \\dot\\theta\\cos\\psi$$\n\n"
            "$$\\Omega_3 = \\dot\\phi \\cos\\theta - \\dot\\psi$$\n")
    assert verdicts(text) == [(9, "holds"), (11, "unchecked")]      # a learned name flags nothing alone


def test_a_symbols_map_says_a_texts_names_outright():
    text = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\nsymbols: {M: angular momentum, a: l}\n---\n"
            "# Top\n\n$$M_3 = I_3 \\left(\\dot\\phi\\cos\\theta + \\dot\\psi\\right)$$\n\n"
            "$$M_3 = I_3 \\left(\\dot\\phi\\cos\\theta - \\dot\\psi\\right)$$\n\n"
            "$$V = M g a \\cos\\theta$$\n")
    claims = kept.check_text(text)
    assert [(c.line, c.verdict) for c in claims][:2] == [(8, "holds"), (10, "typo")]
    assert claims[1].correction == r"M_3 = I_3 \left(\dot\phi\cos\theta + \dot\psi\right)"


@pytest.mark.parametrize("prose", [
    "Here $m$ is the top's mass, $a$ is the distance from the pivot to the centre of mass.",
    "Here $a$ is the distance from the pivot to the centre of mass, and $m$ is the mass.",
])
def test_what_the_prose_says_a_symbol_is_wins_over_a_phrase_just_before_it(prose):
    text = "---\nconvention: z-x-z\n---\n# Heavy top\n\n" + prose + "\n\n$$V = m g a \\cos\\theta$$\n"
    names = nt.parse_notes(text).names
    assert names.symbols[("a", "")] == "centre-of-mass distance"
    assert names.symbols[("m", "")] == "mass"


def test_a_symbols_map_with_a_meaning_derive_does_not_know_is_bad_input():
    with pytest.raises(SceneError, match="symbols"):
        nt.parse_notes("---\nsymbols: {M: the moon}\n---\n# x\n")


def test_a_new_name_is_recorded_and_its_rate_follows_from_it():
    text = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# u\n\n"
            "$$u = \\cos\\theta$$\n\n$$\\dot{u} = -\\sin\\theta\\,\\dot\\theta$$\n\n"
            "$$\\dot{u}^2 = (1 - u^2)\\dot\\theta^2$$\n\n$$\\dot{u} = \\sin\\theta\\,\\dot\\theta$$\n")
    assert verdicts(text) == [(7, "unchecked"), (9, "holds"), (11, "holds"), (13, "typo")]


def test_settings_and_numeric_values_are_cases_not_claims():
    text = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Example\n\n"
            "$$\\theta = 30^{\\circ}, \\quad \\psi = 90^{\\circ}$$\n\n"
            "$$\\omega_1 = \\frac{1}{2} \\dot\\phi$$\n\n"
            "$$I_1 = I_2 \\neq I_3$$\n")
    out = verdicts(text)
    assert out == [(7, "unchecked"), (7, "unchecked"), (9, "holds"), (11, "unchecked")]


def test_a_correction_is_written_in_the_texts_own_notation():
    text = "# Euler\n\nWith no torque,\n\n$$I_3 \\dot{\\omega}_3 = (I_2 - I_1)\\,\\omega_1\\omega_2$$\n"
    [claim] = kept.check_text(text)
    assert claim.verdict == "typo"
    assert claim.correction == r"I_3 \dot{\omega}_3 = (I_1 - I_2)\,\omega_1\omega_2"


def test_a_symmetric_body_named_in_the_prose_makes_i1_equal_i2():
    t = ("\\frac{1}{2} I_1 \\left(\\dot\\phi^2\\sin^2\\theta + \\dot\\theta^2\\right) + "
         "\\frac{1}{2} I_3 \\left(\\dot\\phi\\cos\\theta + \\dot\\psi\\right)^2")
    head = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Top\n\n"
    [stated] = kept.check_text(head + f"For a symmetric top:\n\n$$T = {t}$$\n")
    assert stated.verdict == "holds" and stated.assumes == ["I_1 = I_2 (line 7)"]
    [unstated] = kept.check_text(head + f"For a body:\n\n$$T = {t}$$\n")
    assert unstated.verdict == "holds" and unstated.assumes == ["I_1 = I_2 (not stated)"]
    assert "holds if I₁ = I₂" in unstated.why
    # where the text writes I_2 as well, the moments differ: no symmetric reading rescues a slip
    [slip] = kept.check_text(head + "$$T = \\frac{1}{2} I_1 \\omega_1^2 + \\frac{1}{2} I_2 \\omega_2^2 "
                                  "+ \\frac{1}{2} I_1 \\omega_3^2$$\n")
    assert slip.verdict == "typo"


def test_euler_rates_in_an_aerospace_sequence():
    head = "---\nconvention: z-y-x\nangles: [\\psi, \\theta, \\phi]\n---\n# Rates\n\n"
    right = "$$\\omega_1 = \\dot\\phi - \\dot\\psi \\sin\\theta$$\n"
    wrong = "$$\\omega_1 = \\dot\\phi + \\dot\\psi \\sin\\theta$$\n"
    assert verdicts(head + right) == [(7, "holds")]
    assert verdicts(head + wrong) == [(7, "typo")]


def test_a_consequence_of_eulers_equations_holds():
    text = ("# Free body\n\nWith no torque,\n\n"
            "$$I_1^2 \\omega_1 \\dot{\\omega}_1 + I_2^2 \\omega_2 \\dot{\\omega}_2 + I_3^2 \\omega_3 \\dot{\\omega}_3 = 0$$\n")
    assert verdicts(text) == [(5, "holds")]


def test_a_condition_between_free_variables_is_not_judged():
    assert verdicts("# Steady\n\n$$(I_2 - I_3)\\,\\omega_2 \\omega_3 = 0$$\n") == [(3, "unchecked")]


_HEAD = "---\nconvention: z-x-z\n---\n\n"


def test_a_quad_that_only_spaces_a_chain_keeps_it_one_statement():
    text = _HEAD + ("Newton's law for rotation, where $\\vec N$ is the external torque:\n\n"
                    "$$\n\\left(\\frac{d\\vec{L}}{dt}\\right)_\\mathrm{fixed} = \\quad\\left(\\frac{d\\vec{L}}{dt}"
                    "\\right)_\\mathrm{body} + \\quad \\vec{\\omega}\\times\\vec{L} \\quad = \\quad \\vec{N}\n$$\n")
    claims = kept.check_text(text)
    assert [c.verdict for c in claims] == ["holds", "unchecked"]
    assert claims[1].kind == "law"


def test_a_function_the_text_names_with_its_variables_is_checked_through_what_it_names():
    text = _HEAD + ("$$\\frac{d\\omega_{1}}{dt} = f_{1}(\\omega_{1}, \\omega_{2}, \\omega_{3})$$\n\nwhere\n\n"
                    "$$f_{1} = \\frac{(I_{2} - I_{3})}{I_{1}}\\omega_{2}\\omega_{3}$$\n\nand\n\n"
                    "$$f_{1} = \\frac{(I_{3} - I_{2})}{I_{1}}\\omega_{2}\\omega_{3}$$\n")
    claims = kept.check_text(text)
    assert [(c.kind, c.verdict) for c in claims] == [("new symbol", "unchecked"), ("equation of motion", "holds"),
                                                     ("equation of motion", "typo")]


@pytest.mark.parametrize("written, read", [
    (r"\vec{r_i} = [x, y, z]^T", r"\vec{r_i} = \begin{bmatrix} x \\ y \\ z \end{bmatrix}"),
    (r"\vec{w} = \left[p, q, r\right]^{\top}", r"\vec{w} = \begin{bmatrix} p \\ q \\ r \end{bmatrix}"),
    (r"R (a, f(x, y), c)^T", r"R \begin{bmatrix} a \\ f(x, y) \\ c \end{bmatrix}"),
])
def test_a_row_of_entries_transposed_is_the_column_vector_it_means(written, read):
    assert source.normalize(written) == read


@pytest.mark.parametrize("written", [r"f(x, y)^T", r"(a + b)^T", r"A^T = [a]^T"])
def test_a_call_or_a_single_entry_transposed_is_left_as_written(written):
    assert source.normalize(written) == written


_TO_BODY = ("---\nconvention: z-y-x\nangles: [\\psi, \\theta, \\phi]\n---\n# Frames\n\nFrom inertial to body axes:\n\n"
            "$$\nR_{i \\rightarrow b} = \\begin{bmatrix} \\cos\\theta\\cos\\psi & \\cos\\theta\\sin\\psi & -\\sin\\theta \\\\ "
            "\\sin\\phi\\sin\\theta\\cos\\psi - \\cos\\phi\\sin\\psi & \\sin\\phi\\sin\\theta\\sin\\psi + \\cos\\phi\\cos\\psi "
            "& \\sin\\phi\\cos\\theta \\\\ \\cos\\phi\\sin\\theta\\cos\\psi + \\sin\\phi\\sin\\psi & \\cos\\phi\\sin\\theta"
            "\\sin\\psi - \\sin\\phi\\cos\\psi & \\cos\\phi\\cos\\theta \\end{bmatrix}\n$$\n\nThe inertial z axis in body "
            "axes:\n\n$$\nR_{i \\rightarrow b} [0, 0, 1]^T = [SIGN\\sin\\theta, \\sin\\phi\\cos\\theta, \\cos\\phi\\cos\\theta]^T\n$$\n")


def test_a_rotation_of_a_column_written_as_transposed_rows_holds_and_a_slip_never_does():
    assert [c.verdict for c in kept.check_text(_TO_BODY.replace("SIGN", "-"))] == ["holds", "holds"]
    assert kept.check_text(_TO_BODY.replace("SIGN", ""))[-1].verdict != "holds"


def test_a_symbol_in_braces_before_its_index_is_that_symbol_indexed():
    text = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Rates\n\n"
            "$$\n{\\omega}_3 = \\dot{\\phi}\\cos{\\theta}+\\dot{\\psi}\n$$\n")
    assert [c.verdict for c in kept.check_text(text)] == ["holds"]
    slipped = [c.verdict for c in kept.check_text(text.replace("+\\dot{\\psi}", "-\\dot{\\psi}"))]
    assert slipped and set(slipped) <= {"typo", "fails"}


def test_a_hat_or_a_bar_over_an_unbraced_greek_letter_is_that_accented_letter():
    assert source.normalize("{}^A\\hat\\omega^B \\times \\hat{b}_x") == "^A\\hat{\\omega}^B \\times \\hat{b}_x"
    assert source.normalize("\\bar \\omega^B + \\check\\Omega") == "\\bar{\\omega}^B + \\check{\\Omega}"
    assert source.normalize("\\hat\\omegaa") == "\\hat\\omegaa"         # another command: no letter of its own


ACCENTED = "# Notes\n\n$$\\bar{\\omega} \\equiv \\omega_1 + \\omega_2$$\n\n"


def test_a_symbol_under_an_accent_without_meaning_here_is_the_texts_own_and_read_through_its_definition():
    got = dict(verdicts(ACCENTED + "$$\\bar{\\omega} = \\omega_2 + \\omega_1$$\n\n$$\\bar{\\omega} = \\omega_1 - \\omega_2$$\n"))
    assert got[3] == "unchecked" and got[5] == "holds" and got[7] in ("typo", "fails")


@pytest.mark.parametrize("accent", ["bar", "breve", "check", "acute", "mathring"])
def test_an_accented_letter_is_never_the_letter_without_its_accent(accent):
    # T̄ equal to one more than the kinetic energy is the text's definition of T̄, not a slip in T
    text = (f"# Notes\n\n$$\\{accent}{{T}} = \\frac{{1}}{{2}} I_1 \\omega_1^2 + \\frac{{1}}{{2}} I_2 \\omega_2^2 "
            "+ \\frac{1}{2} I_3 \\omega_3^2 + 1$$\n")
    claims = kept.check_text(text)
    assert [c.verdict for c in claims] == ["unchecked"] and "defines the text's symbol" in claims[0].why


def test_a_dot_product_of_the_bodys_vectors_with_scalar_factors_is_read():
    holds = "# Notes\n\n$$\\boldsymbol{\\omega} \\cdot \\frac{\\mathbf{L}}{L} = \\frac{2T}{L}$$\n"
    assert dict(verdicts(holds))[3] == "holds"
    assert dict(verdicts(holds.replace("\\frac{2T}{L}", "\\frac{T}{L}")))[3] in ("typo", "fails")


def test_a_body_axis_dotted_with_a_body_vector_is_its_component():
    # ê₃ · 𝐋 is a scalar, L's third body component; read as a plain product it was "a product of
    # unit vectors" and a correct display was flagged
    holds = "# Notes\n\n$$\\hat{\\mathbf{e}}_3 \\cdot \\mathbf{L} = I_3 \\omega_3$$\n"
    assert dict(verdicts(holds))[3] == "holds"
    omega = "# Notes\n\n$$\\boldsymbol{\\omega} \\cdot \\hat{\\mathbf{e}}_1 = \\omega_1$$\n"
    assert dict(verdicts(omega))[3] == "holds"
    assert dict(verdicts(holds.replace("I_3 \\omega_3", "I_1 \\omega_3")))[3] != "holds"


def test_spacing_inside_a_script_sets_no_part_of_its_label_apart():
    assert source.normalize(r"\phi_{\beta \, \alpha} + \omega_{b\;i}^{2\!}") == r"\phi_{\beta \alpha} + \omega_{b i}^{2 }"
    head = "---\nconvention: z-x-z\n---\n# Rates\n\nThe body turns.\n\n$$\n"
    omega = r"\dot\phi \sin\theta \sin\psi + \dot\theta \cos\psi" + "\n$$\n"
    assert verdicts(head + r"\omega_{1 \, } = " + omega) == verdicts(head + r"\omega_{1} = " + omega) == [(8, "holds")]


def test_a_chain_of_new_names_ending_in_a_value_defines_each_of_them_as_that_value():
    # a₁ = a₂ = a₃ = b/2 sets the three as a₁ = b/2 alone sets one; a later step in them is then read
    text = ("# A corner\n\nThe vector from a corner of a cube of side $b$ to its centre.\n\n"
            "$$a_1 = a_2 = a_3 = \\frac{b}{2}$$\n\n$$M (a_2^2 + a_3^2) = \\frac{1}{2} M b^2$$\n\n"
            "$$M (a_1^2 + a_3^2) = M b^2$$\n")
    claims = kept.check_text(text)
    assert claims[0].verdict == "unchecked" and "defines the text's symbols a_{1}, a_{2}, a_{3}" in claims[0].why
    assert claims[1].verdict == "holds"
    assert claims[2].verdict != "holds"      # ½ M b² is not M b²: never read as holding (b, M untied, never a flag)
    # a chain that does not end in a value in other names is no such definition
    loop = kept.check_text("# Names\n\n$$u = v = u + 1$$\n")
    assert all("defines the text's symbols" not in c.why for c in loop)


def test_unicode_letters_in_math_are_their_commands_for_every_reader_of_the_text():
    # the readers that learn a text's names from its raw math meet C_x(θ) as the prose's C_x(\theta)
    text = "The matrix $C_x(θ)$ turns by the angle θ.\n\n$$C_x(θ) = R_{ω₃}$$\n"
    assert source.rendered(text) == "The matrix $C_x(\\theta)$ turns by the angle θ.\n\n$$C_x(\\theta) = R_{\\omega_{3}}$$\n"
