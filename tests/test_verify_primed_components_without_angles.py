"""ω′ᵢ in a statement that writes no angle: the reader takes primed components on the primed axes
ê′ᵢ, and texts also prime the body's components (ω′ = Rᵀω); the principal-frame kinetic energy
½(I₁ω₁′² + I₂ω₂′² + I₃ω₃′²) holds only with them the body components (unless I₁ = I₂), so it is
kept read so, saying which. A slip in it is still flagged; a statement in the angles keeps ê′ᵢ."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n\n# Kinetic energy\n\nIn the principal frame:\n\n$$%s$$\n"


def _claims(formula):
    return kept.check_text(HEAD % formula)


def test_the_principal_frame_energy_in_primed_components_holds_as_the_body_components():
    for formula in (r"T_{rot} = \frac{1}{2}(I_1\omega_1'^2 + I_2\omega_2'^2 + I_3\omega_3'^2)",
                    r"T = \frac{1}{2}(I_1{\omega'_1}^2 + I_2{\omega'_2}^2 + I_3{\omega'_3}^2)"):
        claims = _claims(formula)
        assert [c.verdict for c in claims] == ["holds"], formula
        assert "as the body components" in claims[0].why


def test_a_slip_in_the_primed_energy_is_still_flagged():
    claims = _claims(r"T_{rot} = \frac{1}{2}(I_1\omega_1'^2 + I_2\omega_2'^2 + 2I_3\omega_3'^2)")
    assert [c.verdict for c in claims] in (["typo"], ["fails"])


def test_a_primed_component_written_in_the_angles_stays_on_the_primed_axes():
    claims = _claims(r"\omega_1' = \dot{\phi}\sin\theta\sin\psi + \dot{\theta}\cos\psi")
    assert [c.verdict for c in claims] in (["typo"], ["fails"])
    assert _claims(r"\omega_1' = \dot{\theta}")[0].verdict == "holds"
