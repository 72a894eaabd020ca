"""A relation the prose writes between the text's own names for quantities of the motion (a name
it defined by the rates, as L_z or its spin n) and its untied letters (C) is a case of the motion,
``L_z = Cn`` for a top started upright: a setting, never flagged, and a display after it that the
reader would flag, and that does not vanish on the case exactly (a form to an order in a small tilt),
is left unchecked in that case. Without the case the same display is flagged."""
import kept_readings as kept

HEAD = ("---\nconvention: z-y-z\nangles: [\\phi, \\theta, \\psi]\n---\n\n# Upright start\n\n"
        "$$L_z = A\\dot{\\phi}\\sin^2\\theta + Cn\\cos\\theta, \\qquad n = \\dot{\\psi} + \\dot{\\phi}\\cos\\theta$$\n\n")
AFTER = "$$\\frac{1}{2}Cn\\theta^2 = A\\dot{\\phi}\\theta^2$$\n"


def test_a_case_of_the_text_s_named_constants_is_a_setting_and_holds_back_a_flag():
    claims = kept.check_text(HEAD + "A top started upright has $L_z = Cn$, so\n\n" + AFTER)
    case = [c for c in claims if c.latex.strip() == "L_z = Cn"]
    assert case and all((c.kind, c.verdict) == ("setting", "unchecked") for c in case)
    after = [c for c in claims if c.latex.strip().startswith("\\frac{1}{2}Cn")]
    assert after and all(c.verdict == "unchecked" for c in after)


def test_without_the_case_the_display_is_flagged():
    claims = kept.check_text(HEAD + "So\n\n" + AFTER)
    assert [c.verdict for c in claims if c.latex.strip().startswith("\\frac{1}{2}Cn")] in (["typo"], ["fails"])
