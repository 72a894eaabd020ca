"""The notes reader on products of the text's own matrices: a dotted matrix name and a transpose
keep their places in a product, and 𝐈ᵢ named as the identity's columns is that unit column."""
import kept_readings as kept

ZYX = "---\nconvention: z-y-x\nangles: [\\psi, \\theta, \\phi]\n---\n# Notes\n\n"
R3 = ("$$\\mathbf{R}_3 = \\left[ \\begin{array}{ccc} \\cos \\psi & \\sin \\psi & 0 \\\\ "
      "-\\sin \\psi & \\cos \\psi & 0 \\\\ 0 & 0 & 1 \\end{array} \\right]$$\n\n")


verdicts = kept.verdicts_by_line


def test_a_product_with_a_dotted_matrix_and_a_transpose_is_multiplied_in_its_written_order():
    text = ZYX + R3 + ("$$-\\dot{\\mathbf{R}}_3 \\mathbf{R}^T_3 = \\left[ \\begin{pmatrix} 0 \\\\ 0 \\\\ 1 \\end{pmatrix} "
                       "\\right]_\\times \\dot{\\psi}$$\n\n"
                       "$$-\\mathbf{R}^T_3 \\dot{\\mathbf{R}}_3 = \\left[ \\begin{pmatrix} 0 \\\\ 0 \\\\ 1 \\end{pmatrix} "
                       "\\right]_\\times \\dot{\\psi}$$\n\n"
                       "$$\\dot{\\mathbf{R}}_3 \\mathbf{R}^T_3 = \\left[ \\begin{pmatrix} 0 \\\\ 0 \\\\ 1 \\end{pmatrix} "
                       "\\right]_\\times \\dot{\\psi}$$\n")
    got = verdicts(text)
    assert got[9] == {"holds"} and got[11] == {"holds"}      # about z the two orders agree
    assert "holds" not in got[13]                              # the sign is wrong


def test_bold_i_named_as_the_identitys_columns_is_the_unit_column():
    text = ZYX + ("With $\\mathbf{I}_i$ the $i$-th column of the $3\\times 3$ identity matrix:\n\n" + R3 +
                  "$$-\\dot{\\mathbf{R}}_3 \\mathbf{R}^T_3 = \\left[ \\mathbf{I}_3 \\right]_\\times \\dot{\\psi}$$\n\n"
                  "$$-\\dot{\\mathbf{R}}_3 \\mathbf{R}^T_3 = \\left[ \\mathbf{I}_2 \\right]_\\times \\dot{\\psi}$$\n")
    got = verdicts(text)
    assert got[11] == {"holds"}
    assert "holds" not in got[13]


def test_bold_i_without_such_words_stays_the_texts_own_symbol():
    text = ZYX + R3 + "$$-\\dot{\\mathbf{R}}_3 \\mathbf{R}^T_3 = \\left[ \\mathbf{I}_3 \\right]_\\times \\dot{\\psi}$$\n"
    assert verdicts(text)[9] == {"unchecked"}


TURNS = ("The rotation factors as $\\mathbf{C} = \\mathbf{R}_1(\\phi) \\mathbf{R}_2(\\theta) \\mathbf{R}_3(\\psi)$, "
         "and $\\boldsymbol{\\omega}^b_{ab}$ is the body angular velocity.\n\n")


def test_axis_named_matrices_applied_to_the_angles_are_the_single_axis_turns_of_the_sequence():
    text = ZYX + TURNS + ("$$-\\dot{\\mathbf{R}}_2 \\mathbf{R}^T_2 = \\left[ \\begin{pmatrix} 0 \\\\ 1 \\\\ 0 \\end{pmatrix} "
                          "\\right]_\\times \\dot{\\theta}$$\n\n"
                          "$$\\dot{\\mathbf{R}}_2 \\mathbf{R}^T_2 = \\left[ \\begin{pmatrix} 0 \\\\ 1 \\\\ 0 \\end{pmatrix} "
                          "\\right]_\\times \\dot{\\theta}$$\n")
    got = verdicts(text)
    assert "holds" in got[7]                     # C = R₁R₂R₃ is the passive matrix Rᵀ: the sense found
    assert got[9] == {"holds"} and "holds" not in got[11]


def test_the_body_angular_velocity_with_frame_labels_is_read_through_the_texts_turns():
    right = ("\\left[ \\boldsymbol{\\omega}^b_{ab} \\right]_\\times = \\left[ \\mathbf{R}_1 \\mathbf{R}_2 "
             "\\begin{pmatrix} 0 \\\\ 0 \\\\ 1 \\end{pmatrix} \\dot{\\psi} \\right]_\\times + \\left[ \\mathbf{R}_1 "
             "\\begin{pmatrix} 0 \\\\ 1 \\\\ 0 \\end{pmatrix} \\dot{\\theta} \\right]_\\times + \\left[ "
             "\\begin{pmatrix} 1 \\\\ 0 \\\\ 0 \\end{pmatrix} \\dot{\\phi} \\right]_\\times")
    wrong = right.replace("\\mathbf{R}_1 \\begin{pmatrix} 0 \\\\ 1", "\\mathbf{R}_2 \\begin{pmatrix} 0 \\\\ 1")
    chain = "\\left[ \\boldsymbol{\\omega}^b_{ab} \\right]_\\times = -\\dot{\\mathbf{C}} \\left( \\mathbf{C} \\right)^{T}"
    text = ZYX + TURNS + "$$" + right + "$$\n\n$$" + wrong + "$$\n\n$$" + chain + "$$\n"
    got = verdicts(text)
    assert got[9] == {"holds"} and "holds" not in got[11] and got[13] == {"holds"}


def test_a_bold_name_before_a_bracketed_bold_name_is_a_product_not_an_argument():
    text = ZYX + R3 + "$$\\mathbf{R}_3 \\left( \\mathbf{R}_3 \\right)^{T} = \\begin{pmatrix} 1 & 0 & 0 \\\\ 0 & 1 & 0 \\\\ " \
        "0 & 0 & 1 \\end{pmatrix}$$\n"
    assert verdicts(text)[9] == {"holds"}


def test_a_name_defined_by_a_chain_is_the_member_in_names_the_text_has_given():
    text = ZYX + ("Here $\\mathbf{C} = \\mathbf{A}^{x}_{y} \\mathbf{A}^{y}_{z} \\mathbf{A}^{z}_{w} = "
                  "\\mathbf{R}_1(\\phi) \\mathbf{R}_2(\\theta) \\mathbf{R}_3(\\psi)$, with $\\boldsymbol{\\omega}^b_{ab}$ "
                  "the body angular velocity.\n\n"
                  "$$\\left[ \\boldsymbol{\\omega}^b_{ab} \\right]_\\times = -\\dot{\\mathbf{C}} \\mathbf{C}^{T}$$\n\n"
                  "$$\\left[ \\boldsymbol{\\omega}^b_{ab} \\right]_\\times = \\dot{\\mathbf{C}} \\mathbf{C}^{T}$$\n")
    got = verdicts(text)
    assert got[9] == {"holds"} and "holds" not in got[11]


_TURNS = ("---\nconvention: z-x-z\n---\n\n"
          "$$R_{z}(\\phi) = \\begin{bmatrix} \\cos\\phi & \\sin\\phi & 0 \\\\ -\\sin\\phi & \\cos\\phi & 0 \\\\ 0 & 0 & 1 \\end{bmatrix}$$\n\n"
          "$$R_{x'}(\\theta) = \\begin{bmatrix} 1 & 0 & 0 \\\\ 0 & \\cos{ANGLE} & \\sin{ANGLE} \\\\ 0 & -\\sin{ANGLE} & \\cos{ANGLE} \\end{bmatrix}$$\n\n"
          "$$R_{z''}(\\psi) = \\begin{bmatrix} \\cos\\psi & \\sin\\psi & 0 \\\\ -\\sin\\psi & \\cos\\psi & 0 \\\\ 0 & 0 & 1 \\end{bmatrix}$$\n\n"
          "$$R = R_{z''}(\\psi) R_{x'}(\\theta) R_{z}(\\phi)$$\n")


def test_a_turn_whose_entries_are_in_another_angle_than_its_name_says_is_a_typo():
    claims = kept.check_text(_TURNS.replace("ANGLE", "\\phi"))
    assert [c.verdict for c in claims] == ["holds", "typo", "holds", "holds"]
    assert "\\cos{\\theta}" in claims[1].correction and "\\phi" not in claims[1].correction.split("=", 1)[1]


def test_a_turn_written_in_the_angle_its_name_says_holds():
    claims = kept.check_text(_TURNS.replace("ANGLE", "\\theta"))
    assert [c.verdict for c in claims] == ["holds", "holds", "holds", "holds"]



def _z_turn(angle):
    return (f"\\begin{{bmatrix}} \\cos{angle} & \\sin{angle} & 0 \\\\ -\\sin{angle} & \\cos{angle} & 0 \\\\ "
            f"0 & 0 & 1 \\end{{bmatrix}}")


_BOUND = ("---\nconvention: z-x-z\n---\n\n"
          "$$\\mathbf{R}_{z}(\\phi) = " + _z_turn("\\phi") + "$$\n\n"
          "$$\\mathbf{R}_{x}(\\theta) = \\begin{bmatrix} 1 & 0 & 0 \\\\ 0 & \\cos\\theta & \\sin\\theta \\\\ "
          "0 & -\\sin\\theta & \\cos\\theta \\end{bmatrix}$$\n\n")
_PLAIN = _BOUND.replace("\\mathbf{R}", "R")


def _last(text):
    return kept.check_text(text)[-1]


def test_a_plain_turn_name_at_another_angle_is_the_turn_by_that_angle_in_the_sense_learned():
    claim = _last(_PLAIN + "$$R = R_{z}(\\psi) R_{x}(\\theta) R_{z}(\\phi)$$\n")
    assert claim.verdict == "holds" and "passive" in claim.why


def test_a_bold_turn_name_bound_at_one_angle_and_used_at_another_is_left_unchecked():
    for statement in ("\\mathbf{R} = \\mathbf{R}_{z}(\\psi) \\mathbf{R}_{x}(\\theta) \\mathbf{R}_{z}(\\phi)",
                      "\\mathbf{R}_{z}(\\psi) = " + _z_turn("\\psi")):
        claim = _last(_BOUND + "$$" + statement + "$$\n")
        assert claim.verdict == "unchecked" and "turn by \\psi is not read" in claim.why


def test_a_slip_with_a_turn_name_at_another_angle_is_never_held():
    # the factors in the wrong order: R_z(φ) R_x(θ) R_z(ψ) is no rotation of the z-x-z sequence
    assert _last(_PLAIN + "$$R = R_{z}(\\phi) R_{x}(\\theta) R_{z}(\\psi)$$\n").verdict != "holds"
    # R_z(ψ) written out in φ, and a product with φ for ψ: the bound R_z(φ) would make them identities
    assert _last(_BOUND + "$$\\mathbf{R}_{z}(\\psi) = " + _z_turn("\\phi") + "$$\n").verdict != "holds"
    assert _last(_BOUND + "$$\\mathbf{R}_{z}(\\psi) \\mathbf{R}_{z}(\\phi) = \\mathbf{R}_{z}(\\phi) "
                 "\\mathbf{R}_{z}(\\phi)$$\n").verdict != "holds"


def test_a_bound_turn_used_at_its_own_angle_is_read_as_bound():
    eye = "\\begin{bmatrix} 1 & 0 & 0 \\\\ 0 & 1 & 0 \\\\ 0 & 0 & 1 \\end{bmatrix}"
    right = _last(_BOUND + "$$\\mathbf{R}_{z}(\\phi) \\mathbf{R}_{z}(\\phi)^{T} = " + eye + "$$\n")
    wrong = _last(_BOUND + "$$\\mathbf{R}_{z}(\\phi) \\mathbf{R}_{z}(\\phi) = " + eye + "$$\n")
    assert right.verdict == "holds" and wrong.verdict != "holds"


def whys(text):
    return {c.line: c.why for c in kept.check_text(text) if c.verdict == "unchecked"}


def test_a_matrix_of_the_text_added_to_a_name_of_no_given_shape_is_unchecked_naming_that_name():
    text = ("# Notes\n\nThe velocity in body components is $\\vec{V_b} = [u, v, w]^T$.\n\n"
            "$$\\vec{V_a} = \\vec{V_b} - \\vec{W}$$\n")
    assert verdicts(text)[5] == {"unchecked"}
    assert "adds a matrix to a term in W" in whys(text)[5]


def test_a_product_with_a_matrix_of_the_text_beside_another_term_is_unchecked_not_a_failed_step():
    text = ("# Notes\n\n$$R = \\begin{bmatrix} 1 & 0 \\\\ 0 & 1 \\end{bmatrix}$$\n\n"
            "$$T^1 = R\\, T^u + Q$$\n")
    assert verdicts(text)[5] == {"unchecked"}
    assert "failed" not in whys(text)[5] and "no matrix" in whys(text)[5]


COLUMNS = ("$$\\begin{bmatrix} v_1 \\\\ v_2 \\\\ v_3 \\end{bmatrix}_A \\otimes \\begin{bmatrix} w_1 \\\\ w_2 \\\\ w_3 "
           "\\end{bmatrix}_A = \\begin{bmatrix} v_1w_1 & v_1w_2 & v_1w_3 \\\\ v_2w_1 & v_2w_2 & v_2w_3 \\\\ "
           "v_3w_1 & v_3w_2 & v_3w_3 \\end{bmatrix}_A$$\n")


def test_the_outer_product_of_two_written_columns_in_one_frame_is_their_matrix():
    assert verdicts("# Notes\n\n" + COLUMNS)[3] == {"holds"}
    assert "holds" not in verdicts("# Notes\n\n" + COLUMNS.replace("v_3w_1 &", "v_1w_3 &"))[3]


def test_written_matrices_labelled_with_two_frames_are_not_compared():
    text = "# Notes\n\n" + COLUMNS.replace("v_3w_3 \\end{bmatrix}_A", "v_3w_3 \\end{bmatrix}_B")
    assert verdicts(text)[3] == {"unchecked"}
    assert "two frames (A, B)" in whys(text)[3]
