"""The rates of a frame that tilts with the body but does not spin (the line of nodes and the
symmetry axis): a display giving all three ωᵢ so holds as that frame's angular velocity and names
the text's ωᵢ from there on; one component without the spin, or a triple with a row off, is read
against the body's rates as before."""
from kept_readings import verdicts_by_line as verdicts

ZXZ = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# A rolling wheel\n\n"
FRAME = ("$$\n\\begin{align} \\omega_1 = \\dot{\\theta} \\\\ \\omega_2 = \\dot{\\phi} \\sin \\theta \\\\ "
         "\\omega_3 = \\dot{\\phi} \\cos \\theta \\end{align}\n$$\n\n")
WHEEL = "$$\n\\Omega_3 = \\omega_3 + \\dot{\\psi} = \\dot{\\phi} \\cos \\theta + \\dot{\\psi}\n$$\n"


def test_three_rates_without_the_spin_hold_as_the_unspun_frames_and_name_the_texts_omega():
    got = verdicts(ZXZ + FRAME + WHEEL)
    assert got[7] == {"holds"}
    assert got[11] == {"holds"}          # the wheel's rate: the frame's plus the spin


def test_a_row_off_in_the_triple_is_judged_against_the_body():
    off = FRAME.replace("\\omega_2 = \\dot{\\phi} \\sin \\theta", "\\omega_2 = \\dot{\\phi} \\cos \\theta")
    assert verdicts(ZXZ + off)[7] & {"typo", "fails"}


def test_one_component_without_its_spin_rate_is_still_a_slip():
    assert verdicts(ZXZ + "$$\n\\omega_3 = \\dot{\\phi} \\cos \\theta\n$$\n")[7] & {"typo", "fails"}
