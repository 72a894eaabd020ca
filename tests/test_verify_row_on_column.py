"""A row on a column of the body's vectors, ``\\mathbf{H}^T \\mathbf{H}``, is their dot product (a
number); and a new plain name heading a chain at a vector's length, ``H = |\\mathbf{H}| = …``, names
that length from there on."""
from kept_readings import check_text

HEAD = ("---\ntitle: free body\n---\n# A free body\n\nIn principal axes, with no torque, the angular momentum is\n\n"
        "$$\n\\mathbf{H} = \\mathbf{I}\\boldsymbol{\\omega}\n$$\n\n")
LENGTH = r"H = |\mathbf{H}| = \sqrt{H_1^2 + H_2^2 + H_3^2}"


def _verdicts(*displays):
    text = HEAD + "".join(f"Then\n\n$$\n{d}\n$$\n\n" for d in displays)
    return [c.verdict for c in check_text(text)][1:]


def test_a_transposed_vector_on_a_vector_is_their_dot_product():
    assert _verdicts(r"\mathbf{H}^T \mathbf{H} = I_1^2\omega_1^2 + I_2^2\omega_2^2 + I_3^2\omega_3^2") == ["holds"]
    assert _verdicts(r"\boldsymbol{\omega}^T \mathbf{H} = I_1\omega_1^2 + I_2\omega_2^2 + I_3\omega_3^2") == ["holds"]
    assert "fails" in _verdicts(r"\mathbf{H}^T \mathbf{H} = I_1^2\omega_1^2 + I_2^2\omega_2^2 + I_3\omega_3^2")


def test_a_new_name_heading_a_chain_at_a_length_names_that_length():
    assert _verdicts(LENGTH, r"H^2 = \mathbf{H}\cdot\mathbf{H}") == ["holds", "holds"]
    assert _verdicts(LENGTH, r"H^2 = 2\mathbf{H}\cdot\mathbf{H}") == ["holds", "typo"]
    assert _verdicts(LENGTH, r"H^2 = \mathbf{H}^T \mathbf{H}") == ["holds", "holds"]


def test_a_new_name_heading_a_chain_at_anything_else_stays_unnamed():
    assert _verdicts(r"H = I_1\omega_1 + I_2\omega_2 = \omega_1 I_1 + \omega_2 I_2", r"H^2 = 2 I_1^2\omega_1^2")[-1] \
        == "unchecked"
