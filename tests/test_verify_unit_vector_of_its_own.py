"""A bold hatted letter of no basis (𝐧̂, ``\\bm{\\hat{n}}``) among a text's named vectors is a unit vector of
a direction of its own (derive/lecture/named_vectors.py): a statement that holds only because its length
is 1 holds; a slip in one is still flagged."""
import kept_readings as kept

HEAD = "# Turning a vector\n\nA vector $x$ is turned about an axis along the unit vector $n$.\n\n"


def _verdicts(*displays):
    body = "".join(f"$$\n{d}\n$$\n\nThen\n\n" for d in displays)
    return [c.verdict for c in kept.check_text(HEAD + body)]


def test_a_statement_that_needs_the_unit_length_holds():
    assert _verdicts("(\\bm{\\hat{n}}\\times\\bm{x})\\times\\bm{\\hat{n}} = \\bm{x} - (\\bm{x}\\cdot\\bm{\\hat{n}})"
                     "\\bm{\\hat{n}}") == ["holds"]


def test_a_restated_turn_about_a_unit_vector_holds():
    assert _verdicts("\\bm{y} = (\\bm{x}\\cdot\\bm{\\hat{n}})\\bm{\\hat{n}} + \\cos\\vartheta(\\bm{x}"
                     " - (\\bm{x}\\cdot\\bm{\\hat{n}})\\bm{\\hat{n}}) + \\sin\\vartheta (\\bm{\\hat{n}}\\times\\bm{x})",
                     "\\bm{y} = \\bm{x} \\cos\\vartheta + (1 - \\cos\\vartheta) (\\bm{\\hat{n}}\\cdot\\bm{x})"
                     "\\bm{\\hat{n}} + (\\bm{\\hat{n}}\\times\\bm{x})\\sin\\vartheta")[-1] == "holds"


def test_a_sign_slip_beside_a_unit_vector_is_flagged():
    assert _verdicts("(\\bm{\\hat{n}}\\times\\bm{x})\\times\\bm{\\hat{n}} = \\bm{x} + (\\bm{x}\\cdot\\bm{\\hat{n}})"
                     "\\bm{\\hat{n}}") == ["typo"]

