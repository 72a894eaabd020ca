"""ω′ᵢ written beside the primed axes ê′ᵢ (the frame after the first two turns) are the angular
velocity's components on those axes, ê′ᵢ·𝛚, not its body components: a text that resolves 𝛚 on
the primed axes and names the components ``\\omega_i'`` is judged so."""
import kept_readings as kept

HEAD = "---\nconvention: z-y-z\nangles: [\\phi, \\theta, \\psi]\n---\n\n# Angular velocity\n\n$$%s$$\n"


def _verdicts(formula):
    return [c.verdict for c in kept.check_text(HEAD % formula)]


def test_the_primed_components_hold():
    assert _verdicts(r"\omega_1' = -\dot{\phi}\sin\theta") == ["holds"]
    assert _verdicts(r"\omega_3' = \dot{\psi} + \dot{\phi}\cos\theta") == ["holds"]
    assert _verdicts(r"\boldsymbol{\omega} = \sum_{i} \omega_i'\boldsymbol{e_{i}}'") in (["holds"], ["unchecked"])


def test_a_body_component_written_as_a_primed_one_is_flagged():
    # ω̃₁ = −φ̇ sin θ cos ψ + θ̇ sin ψ is the body component; on the primed axis it is −φ̇ sin θ
    assert _verdicts(r"\omega_1' = -\dot{\phi}\sin\theta\cos\psi + \dot{\theta}\sin\psi") in (["typo"], ["fails"])
