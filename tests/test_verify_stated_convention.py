"""A text without front matter states its angle convention itself: a product of single-axis turns
(R = R_3(θ₁) R_1(θ₂) R_3(θ₃)) or prose ("3-1-2 Euler angles, a turn θ about the third axis, …"),
section by section; the front matter, when it declares one, wins."""
from derive.lecture import notes as nt
from derive.lecture.stated_convention import Stated, stated

PRODUCT = "$$\nR = R_3(\\theta_1) R_1(\\theta_2) R_3(\\theta_3)\n$$\n"


def test_a_product_of_single_axis_turns_states_the_sequence_and_the_names_of_the_angles():
    assert stated("# Angles\n\n" + PRODUCT) == [Stated(1, "z-x-z", ("theta_1", "theta_2", "theta_3"))]
    bold = "$$\n\\mathbf{R} = \\mathbf{R}_{z}(\\psi)\\,\\mathbf{R}_{y}(\\theta)\\,\\mathbf{R}_{x}(\\phi)\n$$\n"
    assert stated(bold) == [Stated(1, "z-y-x", ("psi", "theta", "phi"))]


def test_turns_whose_arguments_are_sized_brackets_state_the_sequence_as_plain_ones_do():
    sized = "$$\nR = R_3\\left(\\theta_1\\right) R_1\\bigl(\\theta_2\\bigr) R_3\\left(\\theta_3\\right)\n$$\n"
    assert stated(sized) == [Stated(1, "z-x-z", ("theta_1", "theta_2", "theta_3"))]
    assert stated("$$\nR = R_3\\left(\\theta_1\\right) R_3(\\theta_2) R_1\\left(\\theta_3\\right)\n$$\n") == []


def test_prose_naming_the_sequence_and_its_turns_states_both():
    text = ("R is parameterized by 3-1-2 Euler angles, a turn $\\theta$ about the third axis, then "
            "$\\alpha$ about the first, then $\\phi$ about the second.\n")
    assert stated(text) == [Stated(1, "z-x-y", ("theta", "alpha", "phi"))]
    assert stated("We use the z-x-z convention throughout.\n") == [Stated(1, "z-x-z", None)]


def test_turns_about_unnamed_or_repeated_axes_and_sequences_in_math_state_nothing():
    assert stated("$$\nR = R_i(\\theta_1) R_j(\\theta_2) R_k(\\theta_3)\n$$\n") == []
    assert stated("$$\nR = R_3(\\theta_1) R_3(\\theta_2) R_1(\\theta_3)\n$$\n") == []
    assert stated("the $i-j-k$ Euler angles of a $3 \\times 1$ matrix\n") == []


_TURNS = ("$$\n\\mathbf{{A}} = \\begin{{pmatrix}} \\cos\\phi & {a} & 0 \\\\ {b} & \\cos\\phi & 0 \\\\ 0 & 0 & 1 "
          "\\end{{pmatrix}},\\quad \\mathbf{{B}} = \\begin{{pmatrix}} 1 & 0 & 0 \\\\ 0 & \\cos\\theta & {c} \\\\ "
          "0 & {d} & \\cos\\theta \\end{{pmatrix}},\\quad \\mathbf{{C}} = \\begin{{pmatrix}} \\cos\\psi & {e} & 0 "
          "\\\\ {f} & \\cos\\psi & 0 \\\\ 0 & 0 & 1 \\end{{pmatrix}}\n$$\n\n")
_ACTIVE_TURNS = _TURNS.format(a="-\\sin\\phi", b="\\sin\\phi", c="-\\sin\\theta", d="\\sin\\theta",
                              e="-\\sin\\psi", f="\\sin\\psi")
_PASSIVE_TURNS = _TURNS.format(a="\\sin\\phi", b="-\\sin\\phi", c="\\sin\\theta", d="-\\sin\\theta",
                               e="\\sin\\psi", f="-\\sin\\psi")


def test_a_product_of_matrices_written_out_as_single_axis_turns_states_the_sequence():
    active = "# Angles\n\n" + _ACTIVE_TURNS + "$$\n\\mathbf{U} = \\mathbf{A} \\mathbf{B} \\mathbf{C}\n$$\n"
    assert stated(active) == [Stated(1, "z-x-z", ("phi", "theta", "psi"))]
    # written as transposes (a passive A = BCD): the rightmost turn is the first
    passive = "# Angles\n\n" + _PASSIVE_TURNS + "$$\n\\mathbf{R} = \\mathbf{C} \\mathbf{B} \\mathbf{A}\n$$\n"
    assert stated(passive) == [Stated(1, "z-x-z", ("phi", "theta", "psi"))]
    # a text's own macro for bold is read as bold; an aligned product (`& =`) is a product
    macro = ("\\newcommand{\\mbf}{\\boldsymbol}\n\\section{A}\n" + _ACTIVE_TURNS.replace("\\mathbf", "\\mbf")
             + "\\begin{align}\n\\mbf{U} & = \\mbf{A} \\mbf{B} \\mbf{C} \\nonumber \\\\\n& = X\n\\end{align}\n")
    assert [s.convention for s in stated(macro)] == ["z-x-z"]


def test_matrices_that_are_not_single_axis_turns_or_mix_senses_state_nothing():
    mixed = _ACTIVE_TURNS.replace("\\cos\\psi & -\\sin\\psi", "\\cos\\psi & \\sin\\psi").replace(
        "\\\\ \\sin\\psi & \\cos\\psi", "\\\\ -\\sin\\psi & \\cos\\psi")
    assert stated("# A\n\n" + mixed + "$$\n\\mathbf{U} = \\mathbf{A} \\mathbf{B} \\mathbf{C}\n$$\n") == []
    scaled = _ACTIVE_TURNS.replace("0 & 0 & 1", "0 & 0 & 2")
    assert stated("# A\n\n" + scaled + "$$\n\\mathbf{U} = \\mathbf{A} \\mathbf{B} \\mathbf{C}\n$$\n") == []
    assert stated("# A\n\n" + _ACTIVE_TURNS + "$$\n\\mathbf{U} = \\mathbf{A} \\mathbf{A} \\mathbf{C}\n$$\n") == []


def test_the_stated_turns_decide_how_the_body_rates_are_read():
    text = ("\\section{Angles}\n" + _ACTIVE_TURNS + "$$\n\\mathbf{U} = \\mathbf{A} \\mathbf{B} \\mathbf{C}\n$$\n\n"
            "$$\n\\omega_1 = \\dot{\\phi} \\sin \\theta \\sin \\psi + \\dot{\\theta} \\cos \\psi\n$$\n")
    assert [v for _, v in _verdicts(text)][-1] == "holds"
    wrong = text.replace("\\dot{\\theta} \\cos \\psi", "\\dot{\\theta} \\sin \\psi")
    assert [v for _, v in _verdicts(wrong)][-1] in ("typo", "fails")


def test_each_section_states_its_own_convention_and_the_first_holds_from_the_start():
    text = ("# Disk\n\nThe notes use 3-1-2 Euler angles, a turn $\\theta$ about the third axis, then "
            "$\\alpha$ about the first, then $\\phi$ about the second.\n\n# Gimbal\n\n" + PRODUCT)
    notes = nt.parse_notes(text)
    assert (notes.convention, notes.angles) == ("z-x-y", ("theta", "alpha", "phi"))
    switches = [(i.line, i.text, i.symbols) for i in notes.items if i.kind == "convention"]
    assert switches == [(5, "z-x-z", ("theta_1", "theta_2", "theta_3"))]
    assert nt.angle_aliases(notes) == ()          # θ alone is no angle of a text that names θ₁, θ₂, θ₃


def test_a_latex_section_command_starts_a_section():
    text = "\\subsection{Top}\n3-1-3 Euler angles\n\\subsection{Gimbal}\n" + PRODUCT
    assert [(s.line, s.convention) for s in stated(text)] == [(1, "z-x-z"), (3, "z-x-z")]


def test_the_front_matter_wins_over_what_the_text_states():
    notes = nt.parse_notes("---\nconvention: z-y-z\n---\n# Angles\n\n" + PRODUCT)
    assert (notes.convention, notes.angles) == ("z-y-z", nt.DEFAULT_ANGLES["z-y-z"])
    assert not [i for i in notes.items if i.kind == "convention"]
    assert nt.parse_notes(PRODUCT, convention="z-y-x").convention == "z-y-x"


def test_a_text_that_states_no_convention_keeps_the_default():
    notes = nt.parse_notes("# Notes\n\n$$\nT = \\frac{1}{2} I_1 \\omega_1^2\n$$\n")
    assert (notes.convention, notes.angles) == ("z-y-z", nt.DEFAULT_ANGLES["z-y-z"])


# ---- what a text in its stated angles then gets checked ------------------------------------------
import kept_readings as kept  # noqa: E402
from derive.lecture import hat_maps  # noqa: E402

_HEAD = ("# Gimbal\n\nThe rotation is parameterized by 3-1-3 Euler angles, with $c_i\\triangleq \\cos{\\theta_i}$ "
         "and $s_i\\triangleq \\sin{\\theta_i}$:\n\n$$\nR=R_3(\\theta_1)R_1(\\theta_2)R_3(\\theta_3)=\\begin{bmatrix}\n")
_ACTIVE = ("c_1c_3-c_2s_1s_3 & -c_1s_3-c_2c_3s_1 & s_1s_2 \\\\\nc_3s_1+c_1c_2s_3 & c_1c_2c_3-s_1s_3 & -c_1s_2 \\\\\n"
           "s_2s_3 & c_3s_2 & c_2\n")


def _verdicts(text):
    return [(c.line, c.verdict) for c in kept.check_text(text)]


def test_a_definition_with_a_free_index_stands_for_its_three_components():
    assert nt.components(r"c_i \equiv \cos{\theta_i}") == [r"c_{1} \equiv \cos{\theta_{1}}", r"c_{2} \equiv \cos{\theta_{2}}",
                                                          r"c_{3} \equiv \cos{\theta_{3}}"]
    assert nt.components(r"L_i \equiv \sum_j I_{ij}\omega_j") == [r"L_i \equiv \sum_j I_{ij}\omega_j"]
    assert nt.components(r"I_i = m r_i^2") == [r"I_i = m r_i^2"]       # an equation, not a definition


def test_triangleq_and_colon_equals_define_like_equiv():
    notes = nt.parse_notes("# A\n\nwith $u \\triangleq \\cos\\theta$ and $$\nk := 2\n$$\n")
    assert [i.latex.replace(" ", "") for i in notes.items if i.kind in ("assumption", "display")] == \
        ["u\\equiv\\cos\\theta", "k\\equiv2"]


def test_the_stated_product_of_turns_equals_the_matrix_written_in_its_abbreviations():
    # R = (the turns) = (the matrix): each step of the chain holds
    assert set(_verdicts(_HEAD + _ACTIVE + "\\end{bmatrix}\n$$\n")) == {(5, "holds")}


def test_a_matrix_that_is_not_the_stated_product_of_turns_is_flagged():
    transposed = _ACTIVE.replace("-c_1s_3-c_2c_3s_1", "X").replace("c_3s_1+c_1c_2s_3", "-c_1s_3-c_2c_3s_1").replace(
        "X", "c_3s_1+c_1c_2s_3")
    assert {v for _, v in _verdicts(_HEAD + transposed + "\\end{bmatrix}\n$$\n")} & {"fails", "typo"}


def test_a_hat_map_of_the_rotation_binds_the_body_angular_velocity():
    assert hat_maps.body_velocities("so $R^T\\dot{R}=\\widehat{\\Omega}$ and\n$$\n\\dot R = R [\\omega]_\\times\n$$\n") == \
        [(1, "\\Omega"), (2, "\\omega")]
    # the space angular velocity's hat map, and a hat over no single symbol, bind nothing
    assert hat_maps.body_velocities("$\\dot R R^T = \\hat\\omega$, $\\dot{R} = R\\,\\widehat{\\mathbb{I}^{-1}\\Pi}$") == []


_OMEGA = ("For frames with $R^T\\dot{R}=\\widehat{\\Omega}$, in the 3-1-3 angles:\n\n$$\nR=R_3(\\theta_1)R_1(\\theta_2)R_3(\\theta_3)\n$$\n\n"
          "$$\n\\Omega = \\begin{bmatrix} \\dot{\\theta}_1\\sin{\\theta_2}\\sin{\\theta_3}+\\dot{\\theta}_2\\cos{\\theta_3}\\\\ "
          "\\dot{\\theta}_1\\sin{\\theta_2}\\cos{\\theta_3}-\\dot{\\theta}_2\\sin{\\theta_3}\\\\ \\dot{\\theta}_1\\cos{\\theta_2}+\\dot{\\theta}_3 "
          "\\end{bmatrix}\n$$\n")


def test_the_hatted_plain_letter_is_the_column_of_body_angular_velocity_components_and_a_slip_is_not_held():
    assert _verdicts("# Angles\n\n" + _OMEGA)[-1] == (9, "holds")
    slipped = _OMEGA.replace("\\dot{\\theta}_1\\cos{\\theta_2}+", "\\dot{\\theta}_1\\sin{\\theta_2}+")
    last = kept.check_text("# Angles\n\n" + slipped)[-1]
    # a name learned from the text is not trusted to flag alone: the slip is named, not judged
    assert last.verdict != "holds" and "sin ↔ cos" in last.why


def test_the_general_form_of_a_sequence_of_turns_is_no_claim():
    from derive.lecture.stated_convention import general_form
    assert general_form("R=R_i(\\theta_1)R_j(\\theta_2)R_k(\\theta_3)")
    assert not general_form("R=R_3(\\theta_1)R_1(\\theta_2)R_3(\\theta_3)")
    claims = kept.check_text("# A\n\n$$\nR=R_i(\\theta_1)R_j(\\theta_2)R_k(\\theta_3)\n$$\n")
    assert [(c.verdict, c.why.startswith("not a claim")) for c in claims] == [("unchecked", True)]


def test_the_rate_of_the_hatted_letter_is_the_column_of_its_components_rates():
    rate = ("$$\n\\dot{\\Omega} = \\begin{bmatrix} \\ddot{\\theta}_1\\sin{\\theta_2}\\sin{\\theta_3}+\\dot{\\theta}_1\\dot{\\theta}_2"
            "\\cos{\\theta_2}\\sin{\\theta_3}+\\dot{\\theta}_1\\dot{\\theta}_3\\sin{\\theta_2}\\cos{\\theta_3}+\\ddot{\\theta}_2\\cos{\\theta_3}"
            "-\\dot{\\theta}_2\\dot{\\theta}_3\\sin{\\theta_3}\\\\ \\ddot{\\theta}_1\\sin{\\theta_2}\\cos{\\theta_3}+\\dot{\\theta}_1\\dot{\\theta}_2"
            "\\cos{\\theta_2}\\cos{\\theta_3}-\\dot{\\theta}_1\\dot{\\theta}_3\\sin{\\theta_2}\\sin{\\theta_3}-\\ddot{\\theta}_2\\sin{\\theta_3}"
            "-\\dot{\\theta}_2\\dot{\\theta}_3\\cos{\\theta_3}\\\\ \\ddot{\\theta}_1\\cos{\\theta_2}-\\dot{\\theta}_1\\dot{\\theta}_2\\sin{\\theta_2}"
            "+\\ddot{\\theta}_3 \\end{bmatrix}\n$$\n")
    assert _verdicts("# Angles\n\n" + _OMEGA + "\n" + rate)[-1] == (13, "holds")
    slipped = rate.replace("+\\ddot{\\theta}_3", "-\\ddot{\\theta}_3")
    assert kept.check_text("# Angles\n\n" + _OMEGA + "\n" + slipped)[-1].verdict != "holds"


def test_a_rotation_named_at_the_time_is_the_stated_product_of_turns():
    text = "# Top\n\nThe 3-1-3 Euler angles are introduced by\n\n$$\nR(t)=R_3(\\phi)R_1(\\theta)R_3(\\psi)\n$$\n"
    assert _verdicts(text) == [(5, "holds")]
