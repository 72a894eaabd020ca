"""The notes reader on the angular velocities of single turns (𝛚_φ, 𝛚_θ, 𝛚_ψ: each turn's rate about
its own axis) and their components in a frame: space, body, or {x′, y′, z′} read as the frame after
as many turns as primes; a slip is flagged where the frames are named space or body, left
unchecked where a frame is named by primes (a text may count them otherwise)."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n\n# Turns\n\nThe turns are by $\\phi$, $\\theta$, $\\psi$.\n\n"


def _verdicts(display):
    text = HEAD + "$$" + display + "$$\n"
    return kept.verdicts_by_line(text)[kept.line_of(text, "$$" + display)]


def _col(a, b, c):
    return f"\\left[\\begin{{array}}{{c}} {a} \\\\ {b} \\\\ {c} \\end{{array}}\\right]"


def test_the_angular_velocity_is_the_sum_of_the_turns_and_one_left_out_fails():
    assert _verdicts("\\vec{\\omega} = \\vec{\\omega}_{\\phi} + \\vec{\\omega}_{\\theta} + \\vec{\\omega}_{\\psi}") == {"holds"}
    assert _verdicts("\\vec{\\omega} = \\vec{\\omega}_{\\phi} + \\vec{\\omega}_{\\psi}") == {"fails"}


def test_a_turns_angular_velocity_in_the_frames_named_by_primes_holds():
    assert _verdicts("(\\vec{\\omega}_{\\theta})_{\\{x',y',z'\\}} = (\\vec{\\omega}_{\\theta})_{\\{x'',y'',z''\\}} = "
                     + _col("\\dot{\\theta}", "0", "0")) == {"holds"}


def test_a_turns_angular_velocity_in_body_axes_holds_and_its_slip_fails():
    body = _col("\\dot\\phi \\sin\\theta \\sin\\psi", "\\dot\\phi \\sin\\theta \\cos\\psi", "\\dot\\phi \\cos\\theta")
    assert _verdicts("(\\vec{\\omega}_{\\phi})_\\mathrm{body} = " + body) == {"holds"}
    assert _verdicts("(\\vec{\\omega}_{\\phi})_\\mathrm{body} = " + _col("0", "0", "\\dot{\\phi}")) == {"fails"}


def test_a_slip_in_a_frame_named_by_primes_is_left_unchecked():
    assert _verdicts("(\\vec{\\omega}_{\\phi})_{\\{x'',y'',z''\\}} = " + _col("0", "0", "\\dot{\\phi}")) == {"unchecked"}


def test_a_turns_angular_velocity_as_a_column_in_sized_or_plain_brackets_reads_as_in_left_right_ones():
    body = _col("\\dot\\phi \\sin\\theta \\sin\\psi", "\\dot\\phi \\sin\\theta \\cos\\psi", "\\dot\\phi \\cos\\theta")
    for opened, closed in (("\\bigl[", "\\bigr]"), ("\\Bigl[", "\\Bigr]"), ("[", "]")):
        sized = body.replace("\\left[", opened).replace("\\right]", closed)
        assert _verdicts("(\\vec{\\omega}_{\\phi})_\\mathrm{body} = " + sized) == {"holds"}
        slipped = _col("0", "0", "\\dot{\\phi}").replace("\\left[", opened).replace("\\right]", closed)
        assert _verdicts("(\\vec{\\omega}_{\\phi})_\\mathrm{body} = " + slipped) == {"fails"}


def test_a_turns_angular_velocity_in_a_frame_in_sized_brackets_reads_as_in_plain_ones():
    body = _col("\\dot\\phi \\sin\\theta \\sin\\psi", "\\dot\\phi \\sin\\theta \\cos\\psi", "\\dot\\phi \\cos\\theta")
    for opened, closed in (("\\left(", "\\right)"), ("\\bigl(", "\\bigr)"), ("\\Big(", "\\Big)")):
        framed = f"{opened}\\vec{{\\omega}}_{{\\phi}}{closed}"
        assert _verdicts(framed + "_\\mathrm{body} = " + body) == {"holds"}
        assert _verdicts(framed + "_\\mathrm{body} = " + _col("0", "0", "\\dot{\\phi}")) == {"fails"}
        assert _verdicts(f"{opened}\\vec{{\\omega}}_{{\\theta}}{closed}_{{\\{{x',y',z'\\}}}} = "
                         + _col("\\dot{\\theta}", "0", "0")) == {"holds"}


_FIXED = "A fixed frame has the basis $(\\bm e_X, \\bm e_Y, \\bm e_Z)$, the body the basis $(\\bm e_x, \\bm e_y, \\bm e_z)$.\n\n"


def _in(display, convention="z-x-z", prose=_FIXED):
    text = HEAD.replace("z-x-z", convention) + prose + "$$" + display + "$$\n"
    return kept.verdicts_by_line(text)[kept.line_of(text, "$$" + display)]


_RIGHT = "\\bm\\omega = \\dot{\\phi} \\bm e_Z + \\dot{\\theta} \\bm e_N + \\dot{\\psi} \\bm e_z"
_SWAPPED = "\\bm\\omega = \\dot{\\psi} \\bm e_Z + \\dot{\\theta} \\bm e_N + \\dot{\\phi} \\bm e_z"


def test_the_rates_about_lettered_axes_hold_in_their_turns_order_and_a_swapped_pair_fails():
    assert _in(_RIGHT) == {"holds"}
    # a frame bar naming the axes it is written along is dropped; hats name the axes as well
    assert _in("\\bm\\omega\\big|_{(Z,N,z)} = \\dot{\\phi} \\hat{Z} + \\dot{\\theta} \\hat{N} + \\dot{\\psi} \\hat{z}") == {"holds"}
    assert _in(_SWAPPED) == {"fails"}
    # the line of nodes is the second turn's axis: in z-y-z the y axis after the first turn
    assert _in(_RIGHT, "z-y-z") == {"holds"}
    assert _in(_RIGHT.replace("psi", "theta"), "z-y-z") == {"fails"}


def test_which_frame_the_capital_axes_name_is_the_prose_s_to_say():
    # unsaid, a swap of the first and third rates is the same sum as capitals read as the body's axes
    assert _in(_SWAPPED, prose="") == {"unchecked"}
    assert _in(_RIGHT, prose="") == {"holds"}
    body = "The body frame has the basis $(\\bm e_X, \\bm e_Y, \\bm e_Z)$ and the fixed one $(\\bm e_x, \\bm e_y, \\bm e_z)$.\n\n"
    assert _in(_SWAPPED, prose=body) == {"holds"}
    assert _in(_RIGHT, prose=body) == {"fails"}


def test_rates_about_axes_of_one_case_only_are_not_read_so():
    # small letters alone say nothing of which frame they are
    assert not {"holds", "fails"} & _in("\\bm\\omega = \\dot{\\phi} \\bm e_z + \\dot{\\theta} \\bm e_x")


def test_the_rates_about_axes_lettered_i_j_k_read_as_x_y_z():
    fixed = "The fixed axes are $\\hat I, \\hat J, \\hat K$ and the body's $\\hat i, \\hat j, \\hat k$.\n\n"
    assert _in("\\boldsymbol\\omega = \\dot\\phi \\hat{K} + \\dot\\theta \\hat{N} + \\dot\\psi \\hat{k}", prose=fixed) == {"holds"}
    assert _in("\\boldsymbol\\omega = \\dot\\phi \\mathbf{K} + \\dot\\theta \\mathbf{N} + \\dot\\psi \\mathbf{k}", prose=fixed) == {"holds"}
    assert _in("\\boldsymbol\\omega = \\dot\\psi \\hat{K} + \\dot\\theta \\hat{N} + \\dot\\phi \\hat{k}", prose=fixed) == {"fails"}
