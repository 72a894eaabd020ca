"""The notes reader on products of the text's own matrices: a dotted matrix name and a transpose
keep their places in a product, and 𝐈ᵢ named as the identity's columns is that unit column."""
from derive.lecture import notes_check as nc

ZYX = "---\nconvention: z-y-x\nangles: [\\psi, \\theta, \\phi]\n---\n# Notes\n\n"
R3 = ("$$\\mathbf{R}_3 = \\left[ \\begin{array}{ccc} \\cos \\psi & \\sin \\psi & 0 \\\\ "
      "-\\sin \\psi & \\cos \\psi & 0 \\\\ 0 & 0 & 1 \\end{array} \\right]$$\n\n")


def verdicts(text):
    out = {}
    for c in nc.check_text(text):
        out.setdefault(c.line, set()).add(c.verdict)
    return out


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
