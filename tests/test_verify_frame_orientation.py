"""Frames in Kane's notation (derive/lecture/frame_algebra.py, frame_displays.py): hatted unit
vectors of lettered frames, direction cosine matrices {}^F C^G, simple orientations the text states,
products, transposes and inverses of DCMs, checked entry by entry in the text's own frames."""
import sympy as sp

import kept_readings as kept
from derive.symbolic.rotations import passive

HEAD = "Frames $E$ and $D$ with right-handed unit vectors.\n\n"


def verdicts(body: str) -> dict:
    """line → the set of verdicts of its claims, the body read after the head."""
    return kept.verdicts_by_line(HEAD + body)


def display(*rows: str) -> str:
    return "$$\n" + " \\\\\n".join(rows) + "\n$$\n\n"


TURN = display("\\hat{d}_1 & = \\hat{e}_1",
               "\\hat{d}_2 & = \\cos{\\phi} \\hat{e}_2 + \\sin{\\phi} \\hat{e}_3",
               "\\hat{d}_3 & = -\\sin{\\phi} \\hat{e}_2 + \\cos{\\phi} \\hat{e}_3")


def test_a_frames_unit_vectors_form_a_right_handed_set():
    assert verdicts(display("\\hat{e}_1 \\times \\hat{e}_2 = \\hat{e}_3"))[3] == {"holds"}
    assert verdicts(display("\\hat{e}_2 \\times \\hat{e}_1 = \\hat{e}_3"))[3] == {"fails"}
    assert verdicts(display("\\hat{e}_2 \\cdot \\hat{e}_2 = 1"))[3] == {"holds"}


def test_a_simple_orientation_written_row_by_row_holds_in_the_right_hand_sense_and_then_orients_the_frame():
    assert verdicts(TURN)[3] == {"holds"}
    left_handed = TURN.replace("-\\sin", "+\\sin").replace("\\cos{\\phi} \\hat{e}_2 + \\sin", "\\cos{\\phi} \\hat{e}_2 - \\sin")
    assert verdicts(left_handed)[3] == {"unchecked"}          # the text's angle may be measured that way
    again = display("\\hat{d}_2 = \\cos{\\phi} \\hat{e}_2 + \\sin{\\phi} \\hat{e}_3")
    assert verdicts(left_handed + again)[9] == {"fails"}       # but it is the frame the text stated
    no_rotation = TURN.replace("-\\sin{\\phi} \\hat{e}_2", "\\sin{\\phi} \\hat{e}_2")
    assert verdicts(no_rotation)[3] == {"fails"}


def test_a_simple_orientation_in_matrix_form_is_a_statement_of_the_frame_too():
    matrix = ("$$\n\\begin{bmatrix} \\hat{d}_x \\\\ \\hat{d}_y \\\\ \\hat{d}_z \\end{bmatrix} = "
              "\\begin{bmatrix} \\cos\\beta & 0 & -\\sin\\beta \\\\ 0 & 1 & 0 \\\\ \\sin\\beta & 0 & \\cos\\beta "
              "\\end{bmatrix} \\begin{bmatrix} \\hat{e}_x \\\\ \\hat{e}_y \\\\ \\hat{e}_z \\end{bmatrix}\n$$\n")
    assert verdicts(matrix)[3] == {"holds"}
    assert verdicts(matrix.replace("\\cos\\beta & 0 & -", "\\cos\\beta & 0 & "))[3] == {"fails"}


def test_a_stated_orientation_orients_the_frame_for_later_relations():
    dcm = "$${}^D\\mathbf{C}^E = \\begin{bmatrix} 1 & 0 & 0 \\\\ 0 & \\cos\\phi & \\sin\\phi \\\\ 0 & -\\sin\\phi & \\cos\\phi \\end{bmatrix}$$\n"
    assert verdicts(TURN + dcm)[9] == {"holds"}
    assert verdicts(TURN + dcm.replace("& \\sin\\phi", "& -\\sin\\phi"))[9] == {"fails"}
    assert verdicts(TURN + "$$\\hat{d}_2 \\cdot \\hat{e}_3 = \\sin{\\phi}$$\n")[9] == {"holds"}
    assert verdicts(TURN + "$$\\hat{d}_2 \\cdot \\hat{e}_3 = -\\sin{\\phi}$$\n")[9] == {"fails"}


def test_the_dcm_the_other_way_is_the_inverse_and_the_transpose_for_any_orientation():
    assert verdicts(display("{}^E\\mathbf{C}^D = \\left({}^D\\mathbf{C}^E\\right)^{-1} = "
                            "\\left({}^D\\mathbf{C}^E\\right)^T"))[3] == {"holds"}
    assert verdicts(display("{}^E\\mathbf{C}^D = {}^D\\mathbf{C}^E"))[3] == {"fails"}


def test_dcms_of_successive_frames_multiply_in_the_order_of_the_chain():
    assert verdicts(display("{}^R\\mathbf{C}^P = {}^R\\mathbf{C}^Q {}^Q\\mathbf{C}^P"))[3] == {"holds"}
    assert verdicts(display("{}^R\\mathbf{C}^P = {}^Q\\mathbf{C}^P {}^R\\mathbf{C}^Q"))[3] == {"fails"}
    chain = "{}^W\\mathbf{C}^P = {}^W\\mathbf{C}^V {}^V\\mathbf{C}^U \\ldots {}^Q\\mathbf{C}^P"
    assert verdicts(display(chain))[3] == {"holds"}
    unit_vectors = ("\\begin{bmatrix} \\hat{r}_1 \\\\ \\hat{r}_2 \\\\ \\hat{r}_3 \\end{bmatrix} = {}^R\\mathbf{C}^Q "
                    "{}^Q\\mathbf{C}^P \\begin{bmatrix} \\hat{p}_1 \\\\ \\hat{p}_2 \\\\ \\hat{p}_3 \\end{bmatrix}")
    assert verdicts(display(unit_vectors))[3] == {"holds"}
    assert verdicts(display(unit_vectors.replace("{}^R\\mathbf{C}^Q {}^Q", "{}^Q\\mathbf{C}^P {}^R")))[3] == {"fails"}


def test_a_dcms_entries_are_the_dot_products_of_the_two_frames_unit_vectors():
    entries = " \\\\ ".join(" & ".join(f"\\hat{{d}}_{i} \\cdot \\hat{{e}}_{j}" for j in "123") for i in "123")
    written = "{}^D\\mathbf{C}^E = \\begin{bmatrix} " + entries + " \\end{bmatrix}"
    assert verdicts(display(written))[3] == {"holds"}
    swapped = "{}^E\\mathbf{C}^D = \\begin{bmatrix} " + entries + " \\end{bmatrix}"
    assert verdicts(display(swapped))[3] == {"fails"}


def test_a_row_repeating_the_left_side_of_another_is_a_typo_for_the_one_the_block_leaves_out():
    rows = [f"\\hat{{d}}_{i} = (\\hat{{d}}_{i} \\cdot \\hat{{e}}_1) \\hat{{e}}_1 + (\\hat{{d}}_{i} \\cdot \\hat{{e}}_2) "
            f"\\hat{{e}}_2 + (\\hat{{d}}_{i} \\cdot \\hat{{e}}_3) \\hat{{e}}_3" for i in "123"]
    assert verdicts(TURN + display(*rows))[9] == {"holds"}
    slip = rows[:2] + [rows[2].replace("\\hat{d}_3 =", "\\hat{d}_1 =", 1)]
    claims = [c for c in kept.check_text(HEAD + TURN + display(*slip)) if c.verdict == "typo"]
    assert len(claims) == 1 and claims[0].correction.startswith("\\hat{d}_3 =")
    # with the frames' orientations unstated, d_1 = d_3 may be what the text means by its frames
    assert verdicts(display(*slip))[3] == {"holds", "unchecked"}


def test_unit_vectors_of_two_frames_set_equal_are_no_slip_while_neither_is_stated():
    assert verdicts(display("\\hat{b}_3 = \\hat{a}_3"))[3] == {"unchecked"}
    assert verdicts(TURN + display("\\hat{d}_1 = \\hat{e}_1"))[9] == {"holds"}
    assert verdicts(TURN + display("\\hat{d}_2 = \\hat{e}_2"))[9] == {"fails"}


def test_a_matrix_alone_is_held_to_the_sense_of_the_texts_simple_orientations():
    alone = "$$\n\\begin{bmatrix} \\cos\\psi & \\sin\\psi & 0 \\\\ -\\sin\\psi & \\cos\\psi & 0 \\\\ 0 & 0 & 1 \\end{bmatrix}\n$$\n"
    assert verdicts(TURN + alone)[9] == {"holds"}
    assert verdicts(TURN + alone.replace("-\\sin\\psi & \\cos", "\\sin\\psi & \\cos"))[9] == {"fails"}
    other_sense = alone.replace("\\cos\\psi & \\sin", "\\cos\\psi & -\\sin").replace("-\\sin\\psi & \\cos", "\\sin\\psi & \\cos")
    assert verdicts(TURN + other_sense)[9] == {"unchecked"}        # a rotation matrix may be meant
    assert verdicts(alone)[3] == {"unchecked"}                     # no orientation stated: no sense to hold it to


def test_direction_cosines_named_by_the_row_and_column_indices_hold():
    rows = [f"\\hat{{d}}_{i} = " + " + ".join(f"\\cos\\beta_{{{i}{j}}} \\hat{{e}}_{j}" for j in "xyz") for i in "xyz"]
    assert verdicts(TURN + display(*rows))[9] == {"holds"}
    swapped = [rows[0].replace("\\beta_{xy}", "\\beta_{yx}")] + rows[1:]
    assert verdicts(TURN + display(*swapped))[9] == {"unchecked"}


def test_entries_the_text_names_are_no_claim_and_leave_the_stated_orientation():
    named = display(*[f"\\hat{{d}}_{i} = c_{{{i}1}} \\hat{{e}}_1 + c_{{{i}2}} \\hat{{e}}_2 + c_{{{i}3}} \\hat{{e}}_3"
                      for i in "123"])
    assert verdicts(TURN + named)[9] == {"unchecked"}
    assert verdicts(TURN + named + "$$\\hat{d}_2 \\cdot \\hat{e}_3 = \\sin{\\phi}$$\n")[15] == {"holds"}


def test_a_relation_in_angles_no_stated_orientation_carries_is_not_judged():
    # B's orientation in A stated in words only: its DCM written out is no slip to the reader
    written = "$${}^B\\mathbf{C}^A = \\begin{bmatrix} \\cos\\alpha & \\sin\\alpha & 0 \\\\ -\\sin\\alpha & \\cos\\alpha & 0 \\\\ 0 & 0 & 1 \\end{bmatrix}$$\n"
    assert verdicts(written)[3] == {"holds"}            # a statement of B: the simple turn about z
    assert verdicts("$$\\hat{b}_1 \\cdot \\hat{a}_2 = \\sin\\alpha$$\n")[3] == {"unchecked"}
    assert verdicts(TURN + "$$\\hat{d}_2 \\cdot \\hat{e}_3 = \\sin{\\phi} \\cos{\\phi}$$\n")[9] == {"fails"}


# frames in motion (derive/lecture/frame_motion.py)
def test_a_unit_vector_fixed_in_a_frame_changes_in_another_by_the_angular_velocity_crossed_with_it():
    rate = "\\frac{{}^E d\\hat{d}_2}{dt} = "
    assert verdicts(display(rate + "{}^E\\bar{\\omega}^D \\times \\hat{d}_2"))[3] == {"holds"}
    assert verdicts(display(rate + "\\hat{d}_2 \\times {}^E\\bar{\\omega}^D"))[3] == {"fails"}
    assert verdicts(display(rate + "{}^D\\bar{\\omega}^E \\times \\hat{d}_2"))[3] == {"fails"}
    size = rate + "\\left| {}^E\\bar{\\omega}^D \\right| \\left( {}^E\\hat{\\omega}^D \\times \\hat{d}_2 \\right)"
    assert verdicts(display(size))[3] == {"holds"}


def test_a_vectors_derivative_seen_from_two_frames_differs_by_the_angular_velocity_crossed_with_it():
    w = "$$\\bar{w} = w_1\\hat{d}_1 + w_2\\hat{d}_2 + w_3\\hat{d}_3$$\n\n"
    rows = display("\\frac{{}^D d\\bar{w}}{dt} = \\dot{w}_1\\hat{d}_1 + \\dot{w}_2\\hat{d}_2 + \\dot{w}_3\\hat{d}_3",
                   "\\frac{{}^E d\\bar{w}}{dt} = \\frac{{}^D d\\bar{w}}{dt} + {}^E\\bar{\\omega}^D \\times \\bar{w}")
    assert verdicts(w)[3] == {"unchecked"}                 # sets the text's vector
    assert verdicts(w + rows)[5] == {"holds"}
    assert verdicts(w + rows.replace("+ {}^E", "- {}^E"))[5] == {"holds", "fails"}


def test_angular_velocities_of_successive_frames_add_and_their_accelerations_do_not():
    add = "{}^P\\bar{\\omega}^S = {}^P\\bar{\\omega}^Q + {}^Q\\bar{\\omega}^R + {}^R\\bar{\\omega}^S"
    assert verdicts(display(add))[3] == {"holds"}
    assert verdicts(display(add.replace("{}^Q\\bar{\\omega}^R", "{}^R\\bar{\\omega}^Q")))[3] == {"fails"}
    chain = "{}^P\\bar{\\omega}^T = {}^P\\bar{\\omega}^Q + \\ldots + {}^S\\bar{\\omega}^T"
    assert verdicts(display(chain))[3] == {"holds"}
    acc = "{}^P\\bar{\\alpha}^S \\neq {}^P\\bar{\\alpha}^Q + {}^Q\\bar{\\alpha}^R + {}^R\\bar{\\alpha}^S"
    assert verdicts(display(acc))[3] == {"holds"}
    assert verdicts(display(acc.replace("\\neq", "=")))[3] == {"fails"}


def test_the_angular_acceleration_is_the_same_seen_from_either_frame():
    assert verdicts(display("\\frac{{}^E d}{dt} {}^E\\bar{\\omega}^D = \\frac{{}^D d}{dt} {}^E\\bar{\\omega}^D"))[3] == {"holds"}
    assert verdicts(display("{}^E\\bar{\\alpha}^D = \\frac{{}^D d}{dt} {}^E\\bar{\\omega}^D"))[3] == {"holds"}
    assert verdicts(display("{}^E\\bar{\\alpha}^D = \\frac{{}^D d}{dt} {}^D\\bar{\\omega}^E"))[3] == {"fails"}


def test_a_relation_in_names_whose_rates_the_text_never_writes_is_not_judged():
    v = "$$\\bar{v} = v\\hat{d}_1$$\n\n"       # v constant, said in words
    claim = "$$\\frac{{}^E d\\bar{v}}{dt} = v {}^E\\bar{\\omega}^D \\times \\hat{d}_1$$\n"
    assert verdicts(v + claim)[5] == {"holds"}
    assert verdicts(v + claim.replace("= v", "= 2 v"))[5] == {"unchecked"}


def test_a_vector_the_prose_sets_is_read_in_the_displays_after_it():
    prose = "For $\\bar{v} = v\\hat{d}_1$ with $v$ constant, it follows that\n\n"
    claim = "$$\\frac{{}^E d\\bar{v}}{dt} = {}^E\\bar{\\omega}^D \\times v\\hat{d}_1 = {}^E\\bar{\\omega}^D \\times \\bar{v}$$\n"
    assert verdicts(prose + claim)[5] == {"holds"}
    assert verdicts(claim)[3] <= {"unchecked"}          # v̄ never set: not read


def _written(m) -> str:
    return "\\begin{bmatrix} " + " \\\\ ".join(" & ".join(sp.latex(e) for e in m.row(i)) for i in range(3)) + " \\end{bmatrix}"


def test_euler_angles_are_the_product_of_the_simple_orientations_the_text_states():
    psi, theta, phi = sp.symbols("psi theta phi", real=True)
    turns = [("B", "A", "z", psi), ("C", "B", "x", theta), ("D", "C", "z", phi)]
    body = "".join(f"$${{}}^{f}\\mathbf{{C}}^{g} = {_written(passive(axis, q))}$$\n\n" for f, g, axis, q in turns)
    product = passive("z", phi) * passive("x", theta) * passive("z", psi)
    chain = f"$${{}}^D\\mathbf{{C}}^A = {{}}^D\\mathbf{{C}}^C {{}}^C\\mathbf{{C}}^B {{}}^B\\mathbf{{C}}^A = {_written(product)}$$\n"
    found = verdicts(body + chain)
    assert [found[k] for k in (3, 5, 7, 9)] == [{"holds"}] * 4
    slip = product.copy()
    slip[0, 2] = -slip[0, 2]
    assert verdicts(body + f"$${{}}^D\\mathbf{{C}}^A = {_written(slip)}$$\n")[9] == {"fails"}
    reversed_order = f"$${{}}^D\\mathbf{{C}}^A = {_written(passive('z', psi) * passive('x', theta) * passive('z', phi))}$$\n"
    assert verdicts(body + reversed_order)[9] == {"fails"}


def test_the_rate_of_a_dcm_times_its_transpose_is_skew_and_gives_the_angular_velocitys_measure_numbers():
    rate = "\\frac{d{}^D\\mathbf{C}^E}{dt}"
    skew = f"{rate} \\left({{}}^D\\mathbf{{C}}^E\\right)^T + {{}}^D\\mathbf{{C}}^E \\left({rate}\\right)^T = 0"
    assert verdicts(display(skew))[3] == {"holds"}
    assert verdicts(display(skew.replace("^T + {}", "^T - {}")))[3] == {"fails"}
    measure = "{}^E\\bar{\\omega}^D \\cdot \\hat{d}_1 = \\frac{{}^E d\\hat{d}_2}{dt} \\cdot \\hat{d}_3"
    assert verdicts(display(measure))[3] == {"holds"}
    assert verdicts(display(measure.replace("\\cdot \\hat{d}_3", "\\cdot \\hat{d}_1")))[3] == {"fails"}


def test_measure_numbers_rates_in_upright_differentials_are_read_as_their_dots():
    w = "$$\\bar{w} = w_1\\hat{d}_1 + w_2\\hat{d}_2 + w_3\\hat{d}_3$$\n\n"
    rate = "\\frac{{}^D \\mathrm{d}\\bar{w}}{\\mathrm{d} t} = "
    rows = display(rate + "\\frac{\\mathrm{d} w_1}{\\mathrm{d} t}\\hat{d}_1 + \\frac{d w_2}{d t}\\hat{d}_2 + \\dot{w}_3\\hat{d}_3")
    assert verdicts(w + rows)[5] == {"holds"}
    assert verdicts(w + rows.replace("\\hat{d}_2 +", "\\hat{d}_3 +"))[5] == {"fails"}
