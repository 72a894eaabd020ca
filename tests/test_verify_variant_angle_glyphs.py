"""A text that writes its Euler angles in the variant glyphs ϑ and φ (``\\vartheta``, ``\\varphi``)
and never the plain θ is read with those as the usual angles, as φ, θ, ψ would be: its formulas in
the angles are judged, not left as the text's own symbols. A text that writes θ keeps the usual
names (its ``\\varphi`` may be a phase)."""
import kept_readings as kept
from derive.lecture import notes as nt

BODY = "---\nconvention: z-y-z\n---\n\n# A top\n\nThe Euler angles are $(\\vartheta, \\varphi, \\psi)$.\n\n$$%s$$\n"


def _one(formula):
    claims = [c for c in kept.check_text(BODY % formula) if c.latex.strip() == formula]
    assert len(claims) == 1, [(c.latex, c.verdict, c.why) for c in claims]
    return claims[0]


def test_the_spin_in_variant_glyphs_holds():
    assert _one(r"\omega_3 = \dot{\varphi}\cos\vartheta + \dot{\psi}").verdict == "holds"


def test_a_slip_in_variant_glyphs_is_flagged():
    assert _one(r"\omega_3 = \dot{\varphi}\sin\vartheta + \dot{\psi}").verdict in ("typo", "fails")


def test_the_usual_names_are_kept_when_the_text_writes_theta():
    notes = nt.parse_notes("# x\n\n$\\theta$ and a phase $\\varphi$: $x = A\\cos(\\Omega t + \\varphi)$\n")
    assert nt.angle_aliases(notes) == ("phi", "theta", "psi")
    notes = nt.parse_notes("# x\n\n$\\vartheta$, $\\varphi$, $\\psi$\n")
    assert nt.angle_aliases(notes) == ("varphi", "vartheta", "psi")


def test_a_varphi_whose_rate_the_text_writes_is_the_first_angle():
    # θ written, but φ as \varphi with its rate and never \phi: an angle, not a phase (a phase has no rate)
    notes = nt.parse_notes("# x\n\n$\\theta$, $\\dot{\\varphi}$ and $\\psi$\n")
    assert nt.angle_aliases(notes) == ("varphi", "theta", "psi")
    notes = nt.parse_notes("# x\n\n$\\phi$, $\\theta$, and a rate $\\dot{\\varphi}$\n")
    assert nt.angle_aliases(notes) == ("phi", "theta", "psi")
