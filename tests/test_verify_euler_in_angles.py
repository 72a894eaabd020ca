"""Euler's equations written out in the angles of the text's sequence, with a torque of its own
(T₁ᵉ: a superscript e is a label, not a power), are checked as Euler's equations."""
import kept_readings as kept
from derive.lecture import latex as lx

HEAD = ("# Angles\n\nThe 3-1-3 angles: $R=R_3(\\theta_1)R_1(\\theta_2)R_3(\\theta_3)$. Euler's equations with an "
        "external moment $T^e$ read\n\n")
ROW3 = ("$$\n\\mathbb{I}_3\\cos{\\theta_2}\\,\\ddot{\\theta}_1+\\mathbb{I}_3\\ddot{\\theta}_3 = \\mathbb{I}_3\\dot{\\theta}_1"
        "\\dot{\\theta}_2\\sin{\\theta_2}+ (\\mathbb{I}_1-\\mathbb{I}_2)\\left(\\dot{\\theta}_1\\sin{\\theta_2}\\sin{\\theta_3}+"
        "\\dot{\\theta}_2\\cos{\\theta_3}\\right) \\left(\\dot{\\theta}_1\\sin{\\theta_2}\\cos{\\theta_3}-\\dot{\\theta}_2"
        "\\sin{\\theta_3}\\right) + T_3^e\n$$\n")


def test_a_superscript_e_on_a_symbol_is_its_label_not_a_power():
    (tok,) = [t for t in lx.scan("T_3^e") if t.kind == "atom"]
    assert tok.value.sup == "e" and tok.value.sub == "3"
    assert [t.kind for t in lx.scan("e^{x}")][:2] == ["atom", "op"]      # e itself still takes a power


def test_euler_s_third_equation_in_3_1_3_angles_with_the_text_s_torque_holds():
    (claim,) = [c for c in kept.check_text(HEAD + ROW3) if c.line == 5]
    assert claim.verdict == "holds" and "Euler's equation 3 in the angles" in claim.why


def test_a_slip_in_euler_s_equation_in_the_angles_is_never_held():
    slipped = ROW3.replace("(\\mathbb{I}_1-\\mathbb{I}_2)", "(\\mathbb{I}_2-\\mathbb{I}_1)")
    assert all(c.verdict != "holds" for c in kept.check_text(HEAD + slipped) if c.line == 5)


RATE_IN_ANGLES = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Rates\n\nThe third body component "
                  "$\\omega_3 = \\dot\\phi\\cos\\theta + \\dot\\psi$ changes at the rate\n\n"
                  "$$\\dot{\\omega}_3 = \\ddot{\\phi}\\cos\\theta SIGN \\dot{\\phi}\\dot{\\theta}\\sin\\theta + \\ddot{\\psi}$$\n")


def test_the_rate_of_a_body_component_written_in_the_angles_holds_as_kinematics_not_an_equation_of_motion():
    (claim,) = [c for c in kept.check_text(RATE_IN_ANGLES.replace("SIGN", "-")) if c.line == 9]
    assert claim.verdict == "holds" and "the rate of the angular velocity's components" in claim.why
    (slip,) = [c for c in kept.check_text(RATE_IN_ANGLES.replace("SIGN", "+")) if c.line == 9]
    assert slip.verdict != "holds"
