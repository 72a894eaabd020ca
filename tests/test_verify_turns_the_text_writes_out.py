"""A product of single-axis turns is held to the sense of the turns the text writes out: with its
own active turns, R_x(φ) R_y(θ) R_z(ψ) for a z-y-x (yaw-pitch-roll) sequence is neither the rotation
nor its transpose (that order is the passive turns'), so it fails; R_z(ψ) R_y(θ) R_x(φ) holds, and a
product whose turns the text never writes out is read in whichever sense makes it the rotation."""
import kept_readings as kept

HEAD = ("---\nconvention: z-y-x\n---\n# Attitude\n\n"
        "Yaw $\\psi$ about Z, then pitch $\\theta$ about Y, then roll $\\phi$ about X.\n\n")
PRODUCT = "$$\n\\mathbf{R} = \\mathbf{R}_x(\\phi) \\cdot \\mathbf{R}_y(\\theta) \\cdot \\mathbf{R}_z(\\psi)\n$$\n\n"
ACTIVE = ("The elementary turns:\n\n"
          "$$\n\\mathbf{R}_x(\\phi) = \\begin{bmatrix} 1 & 0 & 0 \\\\ 0 & \\cos\\phi & -\\sin\\phi \\\\ "
          "0 & \\sin\\phi & \\cos\\phi \\end{bmatrix}\n$$\n\n"
          "$$\n\\mathbf{R}_y(\\theta) = \\begin{bmatrix} \\cos\\theta & 0 & \\sin\\theta \\\\ 0 & 1 & 0 \\\\ "
          "-\\sin\\theta & 0 & \\cos\\theta \\end{bmatrix}\n$$\n\n"
          "$$\n\\mathbf{R}_z(\\psi) = \\begin{bmatrix} \\cos\\psi & -\\sin\\psi & 0 \\\\ \\sin\\psi & \\cos\\psi & 0 "
          "\\\\ 0 & 0 & 1 \\end{bmatrix}\n$$\n\n")


def _product(text):
    return [c.verdict for c in kept.check_text(text) if c.latex.startswith("\\mathbf{R} = \\mathbf{R}_")]


def test_active_turns_in_the_passive_order_fail():
    assert _product(HEAD + PRODUCT + ACTIVE) == ["fails"]


def test_active_turns_in_their_own_order_hold():
    right = PRODUCT.replace("\\mathbf{R}_x(\\phi) \\cdot \\mathbf{R}_y(\\theta) \\cdot \\mathbf{R}_z(\\psi)",
                            "\\mathbf{R}_z(\\psi) \\mathbf{R}_y(\\theta) \\mathbf{R}_x(\\phi)")
    assert _product(HEAD + right + ACTIVE) == ["holds"]


def test_passive_turns_written_out_in_that_order_hold():
    passive = ACTIVE.replace("-\\sin\\phi", "SINPHI").replace("\\sin\\phi & \\cos\\phi", "-\\sin\\phi & \\cos\\phi")
    passive = passive.replace("SINPHI", "\\sin\\phi")
    passive = passive.replace("& \\sin\\theta \\\\", "& -\\sin\\theta \\\\").replace("-\\sin\\theta & 0 & \\cos", "\\sin\\theta & 0 & \\cos")
    passive = passive.replace("-\\sin\\psi & 0", "\\sin\\psi & 0").replace("\\\\ \\sin\\psi & \\cos\\psi", "\\\\ -\\sin\\psi & \\cos\\psi")
    assert _product(HEAD + PRODUCT + passive) == ["holds"]


def test_turns_the_text_does_not_write_out_take_the_sense_that_fits():
    assert _product(HEAD + PRODUCT) == ["holds"]


def test_turns_written_out_with_operatorname_sines_are_the_same_turns():
    spelled = ACTIVE.replace("\\sin", "\\operatorname{sin}").replace("\\cos", "\\operatorname{cos}")
    assert _product(HEAD + PRODUCT + spelled) == ["fails"]
