"""The notes reader on the inertia tensor set beside the angular velocity, ``\\mathbf{I}\\boldsymbol{\\omega}``
(matrix notation, no ·): after the text writes the tensor's diagonal form in principal axes, the angular
momentum as the tensor on 𝛚 written out as a column is checked (a wrong entry flagged), with or without the
arrow over the bold letters."""
from kept_readings import by_line, line_of

TEXT = ("# Principal axes\n\nIn the principal axes frame:\n\n$$\n\\mathbf{I} = \\begin{bmatrix} I_1 & 0 & 0 \\\\ "
        "0 & I_2 & 0 \\\\ 0 & 0 & I_3 \\end{bmatrix}\n$$\n\nThe angular momentum:\n\n$$\nROW\n$$\n")
PLAIN = (r"\mathbf{L} = \mathbf{I} \boldsymbol{\omega} = \begin{bmatrix} I_1 \omega_1 \\ I_2 \omega_2 \\ "
         r"I_3 \omega_3 \end{bmatrix}")
ARROWED = (r"\vec{\mathbf{L}} = \mathbf{I} \vec{\boldsymbol{\omega}} = \begin{bmatrix} I_1 \omega_1 \\ I_2 \omega_2 \\ "
           r"I_3 \omega_3 \end{bmatrix}")


def _verdicts(row: str) -> list[str]:
    text = TEXT.replace("ROW", row)
    return [c.verdict for c in by_line(text)[line_of(text, "$$\n" + row)]]


def test_the_tensor_beside_omega_written_out_as_a_column_holds():
    assert set(_verdicts(PLAIN)) == {"holds"}


def test_the_tensor_beside_an_arrowed_omega_holds():
    assert set(_verdicts(ARROWED)) == {"holds"}


def test_a_wrong_entry_of_the_column_is_flagged():
    assert set(_verdicts(PLAIN.replace(r"\\ I_2 \omega_2", r"\\ I_3 \omega_2"))) & {"fails", "typo"}
