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


def test_prose_naming_the_sequence_and_its_turns_states_both():
    text = ("R is parameterized by 3-1-2 Euler angles, a turn $\\theta$ about the third axis, then "
            "$\\alpha$ about the first, then $\\phi$ about the second.\n")
    assert stated(text) == [Stated(1, "z-x-y", ("theta", "alpha", "phi"))]
    assert stated("We use the z-x-z convention throughout.\n") == [Stated(1, "z-x-z", None)]


def test_turns_about_unnamed_or_repeated_axes_and_sequences_in_math_state_nothing():
    assert stated("$$\nR = R_i(\\theta_1) R_j(\\theta_2) R_k(\\theta_3)\n$$\n") == []
    assert stated("$$\nR = R_3(\\theta_1) R_3(\\theta_2) R_1(\\theta_3)\n$$\n") == []
    assert stated("the $i-j-k$ Euler angles of a $3 \\times 1$ matrix\n") == []


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
