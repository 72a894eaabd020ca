"""The notes reader on a dot over more than one symbol (``\\dot{\\theta\\cos\\phi}``): the time
derivative of the product it covers, so a text that dots a product where it meant one factor's
rate is judged as written, and a dot over one symbol reads as before."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n\n# Notes\n\n"
OMEGA3 = "$$\\omega_3 = \\dot{\\phi}\\cos\\theta + \\dot{\\psi}$$\n"


def _claims(text):
    return [c for c in kept.check_text(HEAD + text) if c.line == kept.line_of(HEAD + text, "$$")]


def test_the_spin_component_with_each_rate_dotted_alone_holds():
    assert {c.verdict for c in _claims(OMEGA3)} == {"holds"}


def test_a_dot_over_the_product_of_a_rate_and_a_cosine_is_flagged():
    claims = _claims(OMEGA3.replace("\\dot{\\phi}\\cos\\theta", "\\dot{\\phi\\cos\\theta}"))
    assert {c.verdict for c in claims} <= {"fails", "typo"} and claims


def test_a_dot_over_a_product_is_the_rate_of_the_product():
    # (φ cos θ)˙ = φ̇ cos θ − φ θ̇ sin θ: written out, the dotted product holds as that rate
    claims = _claims("$$\\dot{\\phi\\cos\\theta} = \\dot{\\phi}\\cos\\theta - \\phi\\dot{\\theta}\\sin\\theta$$\n")
    assert {c.verdict for c in claims} == {"holds"}
