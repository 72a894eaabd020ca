"""The principal moments under the text's own letters (A, B, C): bound when the prose names them,
and never a failing claim when it does not."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n# Principal axes\n\n"
DIAG = r"""

$$
\mathbf{I}' = \begin{bmatrix}A & 0 & 0 \\ 0 & B & 0 \\ 0 & 0 & C\end{bmatrix}
$$

$$
T = \frac{1}{2}(A\omega_1^2 + B\omega_2^2 + C\omega_3^2)
$$
"""


def _verdicts(prose):
    return [c.verdict for c in kept.check_text(HEAD + prose + DIAG)]


def test_letters_listed_before_the_phrase_are_the_principal_moments():
    assert _verdicts("Here $A$, $B$, $C$ are the principal moments of inertia.") == ["holds", "holds"]


def test_letters_listed_after_the_phrase_are_the_principal_moments():
    assert _verdicts("With the principal moments $A$, $B$, $C$:") == ["holds", "holds"]


def test_a_quantity_written_in_moments_the_text_never_named_is_unchecked_not_failing():
    assert _verdicts("The inertia tensor in principal axes:") == ["unchecked", "unchecked"]
