"""A hat map of the rotation, R^T Ṙ = Ω̂, written in a section makes Ω₁, Ω₂, Ω₃ of that section the body
angular velocity's components, so rows giving them in the text's angles are checked; a ``\\noalign``
between a written matrix's rows is spacing, not mathematics."""
import kept_readings as kept

_DISK = ("# Disk\n\nA frame is fixed on the disk, $R$ in the 3-1-2 Euler angles, $R=R_3(\\theta)R_1(\\alpha)R_2(\\phi)$.\n\n"
         "From $\\widehat{{\\Omega}}=R^T\\dot{{R}}$ the notes give:\n"
         "\\begin{{align}}\n{{\\Omega}}_1 & = \\dot{{\\alpha}}\\cos{{\\phi}}-\\dot{{\\theta}}\\cos{{\\alpha}}\\sin{{\\phi}}, \\\\\n"
         "{{\\Omega}}_2 & = \\dot{{\\phi}}{sign}\\dot{{\\theta}}\\sin{{\\alpha}}, \\\\\n"
         "{{\\Omega}}_3 & = \\dot{{\\theta}}\\cos{{\\alpha}}\\cos{{\\phi}}+\\dot{{\\alpha}}\\sin{{\\phi}}.\n\\end{{align}}\n")


def _rows(text):
    return [(c.line, c.verdict) for c in kept.check_text(text) if c.line >= 6]


def test_the_components_of_the_hatted_letter_in_its_section_are_the_body_rates():
    assert _rows(_DISK.format(sign="+")) == [(6, "holds")] * 3
    # the sign slip of the second row is flagged, its correct neighbours hold
    assert [v for _, v in _rows(_DISK.format(sign="-"))] == ["holds", "typo", "holds"]


def test_in_another_section_the_components_are_not_read_by_the_hat_map():
    text = _DISK.format(sign="-").replace("\\begin{align}", "# Another\n\n\\begin{align}")
    assert all(v == "unchecked" for _, v in _rows(text))


def test_noalign_between_the_rows_of_a_written_matrix_is_dropped():
    text = ("# Turn\n\nThe first turn of the 3-1-3 angles:\n\n$$\nR=\\left[\\begin{array}{ccc} \\cos\\phi & -\\sin\\phi & 0 \\\\"
            "\\noalign{\\bigskip} \\sin\\phi & \\cos\\phi & 0 \\\\\\noalign{\\bigskip} 0 & 0 & 1 \\end{array}\\right]\n$$\n")
    assert [(c.verdict, c.why) for c in kept.check_text(text)] == [("holds", "the active turn about z by \\phi")]
