"""A text that turns frames by matrices of change of coordinates: its passive single-axis turns
written out with their axis and angle (C_X(φ) = …) make a product of them (C_z(ψ) C_x(θ) C_z(φ))
turn first by its rightmost factor; an axis may be named by a capital (R_Z(φ)); a matrix whose name
says its turn is held to that turn entry by entry; and a macro's upright differential
(``\\mathop{}\\!\\mathrm{d}``) is the differential d."""
import kept_readings as kept
from derive.lecture import source
from derive.lecture.stated_convention import Stated, stated

_C = ("$$\n\\begin{{align*}} C_X(\\phi) &= \\begin{{pmatrix}} 1 & 0 & 0 \\\\ 0 & \\cos \\phi & {x} \\\\ 0 & {mx} & "
      "\\cos \\phi \\end{{pmatrix}}\\\\\nC_Y(\\phi) &= \\begin{{pmatrix}} \\cos \\phi & 0 & {my} \\\\ 0 & 1 & 0 \\\\ "
      "{y} & {zero} & \\cos \\phi\\end{{pmatrix}}\\\\\nC_Z(\\phi) &= \\begin{{pmatrix}} \\cos \\phi & {z} & 0 \\\\ {mz} & "
      "\\cos \\phi & 0 \\\\ 0 & 0 & 1 \\end{{pmatrix}}\n\\end{{align*}}\n$$\n\n")
PASSIVE = _C.format(x="\\sin \\phi", mx="-\\sin \\phi", my="-\\sin \\phi", y="\\sin \\phi", z="\\sin \\phi",
                    mz="-\\sin \\phi", zero="0")
ACTIVE = _C.format(x="-\\sin \\phi", mx="\\sin \\phi", my="\\sin \\phi", y="-\\sin \\phi", z="-\\sin \\phi",
                   mz="\\sin \\phi", zero="0")
PRODUCT = ("# Euler angles\n\n$$\n\\begin{pmatrix} x \\\\ y \\\\ z \\end{pmatrix} = C_z(\\psi) C_x(\\theta) C_z(\\phi) "
           "\\begin{pmatrix} X \\\\ Y \\\\ Z \\end{pmatrix}\n$$\n\n")
OMEGA = ("$$\n\\omega_1 = \\dot{\\phi} \\sin \\theta \\sin \\psi + \\dot{\\theta} \\cos\\psi\n$$\n")


def _verdicts(text):
    return [(c.line, c.verdict) for c in kept.check_text(text)]


def test_a_product_of_turns_the_text_writes_out_as_passive_turns_first_turns_by_its_rightmost_factor():
    assert stated("# Matrices\n\n" + PASSIVE + PRODUCT) == [Stated(10, "z-x-z", ("phi", "theta", "psi"))]
    # the same letters written out as active turns: the written order is the order of the turns
    assert stated("# Matrices\n\n" + ACTIVE + PRODUCT) == [Stated(10, "z-x-z", ("psi", "theta", "phi"))]
    # and no letter written out: the written order stands, as before
    assert stated(PRODUCT) == [Stated(1, "z-x-z", ("psi", "theta", "phi"))]


def test_an_axis_named_by_a_capital_letter_is_that_axis():
    text = "$$\nR(\\phi,\\theta,\\psi) = R_Z(\\phi) R_X(\\theta) R_Z(\\psi)\n$$\n"
    assert stated(text) == [Stated(1, "z-x-z", ("phi", "theta", "psi"))]


def test_the_body_rates_are_read_in_the_order_of_the_passive_product():
    text = "# Matrices\n\n" + PASSIVE + PRODUCT + OMEGA
    assert _verdicts(text)[-1] == (16, "holds")
    wrong = text.replace("\\dot{\\theta} \\cos\\psi", "\\dot{\\theta} \\sin\\psi")
    assert _verdicts(wrong)[-1][1] in ("typo", "fails")


def test_a_matrix_whose_name_says_its_turn_is_held_to_it_entry_by_entry():
    held = dict(_verdicts(PASSIVE))
    assert held == {2: "holds"} or set(v for _, v in _verdicts(PASSIVE)) == {"holds"}
    slip = PASSIVE.replace("\\sin \\phi & 0 & \\cos \\phi\\end", "\\sin \\phi & 1 & \\cos \\phi\\end")
    got = [c for c in kept.check_text(slip) if c.verdict != "holds"]
    assert [c.verdict for c in got] == ["typo"]
    assert "row 3, column 2" in got[0].why
    # two entries off: the name alone decides nothing, nothing is flagged
    two = PASSIVE.replace("\\sin \\phi & 0 & \\cos \\phi\\end", "\\sin \\phi & 1 & 2\\cos \\phi\\end")
    assert not {c.verdict for c in kept.check_text(two)} & {"typo", "fails"}
    # a matrix of no name that says a turn, one entry off a turn: not held to it
    bare = "$$\nM = \\begin{pmatrix} \\cos \\phi & 0 & -\\sin \\phi \\\\ 0 & 1 & 0 \\\\ \\sin \\phi & 1 & \\cos \\phi\\end{pmatrix}\n$$\n"
    assert not {c.verdict for c in kept.check_text(bare)} & {"typo", "fails"}


def test_an_empty_operator_before_a_negative_thin_space_sets_an_upright_differential():
    assert source.normalize("\\frac{\\mathop{}\\!\\mathrm{d} x}{\\mathop{}\\!\\mathrm{d} t}").replace(" ", "") == \
        source.normalize("\\frac{\\mathrm{d} x}{\\mathrm{d} t}").replace(" ", "")
    text = ("---\nconvention: z-y-z\n---\n\\newcommand{\\D}{\\mathop{}\\!\\mathrm{d}}\n\n$$\n\\omega_3 = "
            "\\frac{\\D \\phi}{\\D t} \\cos\\theta + \\frac{\\D \\psi}{\\D t}\n$$\n")
    assert [v for _, v in _verdicts(text)] == ["holds"]
    assert _verdicts(text.replace("\\cos\\theta", "\\sin\\theta"))[0][1] in ("typo", "fails")
