"""A sentence that states a special case and then relations for it ("$\\cos\\theta = 0$, where
$\\omega_z = \\dot\\phi$ and $\\omega_3 = \\dot\\psi$") gets no flag from relations the case decides."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Angular velocity\n\n"


def _verdicts(sentence):
    return [c.verdict for c in kept.check_text(HEAD + sentence + "\n")]


def test_relations_after_a_case_in_the_same_sentence_are_not_flagged():
    verdicts = _verdicts("For $\\cos \\theta = 0$, where $\\omega_z = \\dot{\\phi}$ and $\\omega_3 = \\dot{\\psi}$, the rates separate.")
    assert "fails" not in verdicts and "typo" not in verdicts


def test_a_relation_in_prose_with_no_case_before_it_is_still_judged():
    assert _verdicts("The spin component is $\\omega_3 = \\dot{\\phi}$ in general.")[-1] == "fails"
