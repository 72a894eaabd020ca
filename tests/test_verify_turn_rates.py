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


def test_a_turns_angular_velocity_as_a_column_in_sized_brackets_reads_as_in_left_right_ones():
    body = _col("\\dot\\phi \\sin\\theta \\sin\\psi", "\\dot\\phi \\sin\\theta \\cos\\psi", "\\dot\\phi \\cos\\theta")
    for opened, closed in (("\\bigl[", "\\bigr]"), ("\\Bigl[", "\\Bigr]")):
        sized = body.replace("\\left[", opened).replace("\\right]", closed)
        assert _verdicts("(\\vec{\\omega}_{\\phi})_\\mathrm{body} = " + sized) == {"holds"}
        slipped = _col("0", "0", "\\dot{\\phi}").replace("\\left[", opened).replace("\\right]", closed)
        assert _verdicts("(\\vec{\\omega}_{\\phi})_\\mathrm{body} = " + slipped) == {"fails"}
