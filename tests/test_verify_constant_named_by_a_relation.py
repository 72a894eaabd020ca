"""A constant letter of the text's (A, B, C, δ, ε, φ) that a relation of the motion names:
``\\mathbf{L}^2 = I_1^2A^2 + I_3^2\\omega_3^2`` with A the radius of the circle 𝛚 turns on says what A is
in this motion; the relation is recorded, and the statements after it are judged with that A
(derive/lecture/conditions.py)."""
import kept_readings as kept

from derive.lecture import conditions
from derive.lecture import notes_check as nc

_HEAD = ("A free symmetric body, $I_1 = I_2$, with angular momentum $\\mathbf{L}$. The angular velocity turns "
         "on a circle of radius $A$ about the third axis, so\n\n$$\n\\mathbf{L}^2 = I_1^2A^2 + I_3^2\\omega_3^2\n$$\n\n")
_COS = ("\\cos\\tau = \\frac{\\mathbf{L}\\cdot\\mathbf{e}_3}{|\\mathbf{L}|} = \\frac{I_3\\omega_3}{\\sqrt{I_1^2A^2 + %s}} "
        "= \\frac{\\omega_3}{\\sqrt{\\frac{I_1^2}{I_3^2}A^2 + \\omega_3^2}}")


def _at(text, line):
    return [c for c in kept.check_text(text) if c.line == line]


def test_the_relation_names_the_constant_and_is_no_claim():
    named = _at(_HEAD, 3)
    assert [c.verdict for c in named] == ["unchecked"] and "names the text's constant A" in named[0].why


def test_the_statements_after_it_are_judged_with_the_named_constant():
    good = _at(_HEAD + "$$\nT = \\frac{1}{2}(I_1A^2 + I_3\\omega_3^2)\n$$\n", 7)
    assert [c.verdict for c in good] == ["holds"]
    slip = _at(_HEAD + "$$\nT = \\frac{1}{2}(I_1A^2 + I_1\\omega_3^2)\n$$\n", 7)
    assert [c.verdict for c in slip] == ["typo"]
    assert [c.verdict for c in _at(_HEAD + "$$\n" + _COS % "I_3^2\\omega_3^2" + "\n$$\n", 7)] == ["holds", "holds"]
    assert "fails" in [c.verdict for c in _at(_HEAD + "$$\n" + _COS % "I_2^2\\omega_3" + "\n$$\n", 7)]


def test_a_letter_that_a_solution_already_ties_is_not_named_again():
    text = ("A free symmetric body, $I_1 = I_2$, with $\\Omega = \\frac{I_3 - I_1}{I_1}\\omega_3$:\n\n"
            "$$\nI_1\\dot{\\omega}_1 = (I_1 - I_3)\\omega_2\\omega_3, \\quad I_1\\dot{\\omega}_2 = (I_3 - I_1)\\omega_3\\omega_1\n$$\n\n"
            "$$\n\\omega_1 = A\\cos\\Omega t, \\quad \\omega_2 = A\\sin\\Omega t\n$$\n\n"
            "$$\n\\mathbf{L}^2 = I_1^2A^2 + I_3^2\\omega_3\n$$\n")
    claims = kept.check_text(text)
    assert [c.verdict for c in claims if c.line == 7] == ["holds", "holds"]     # the solution, A its constant
    assert not any("names the text's constant" in c.why for c in claims)



def test_the_same_relation_read_again_is_simplified_once_with_the_same_claims():
    conditions._simplified.cache_clear()
    first, again = nc.check_text(_HEAD), nc.check_text(_HEAD)
    info = conditions._simplified.cache_info()
    assert info.misses == 1 and info.hits >= 1
    assert [(c.line, c.verdict, c.why) for c in first] == [(c.line, c.verdict, c.why) for c in again]
