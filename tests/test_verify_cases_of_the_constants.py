"""Readings a careful reader gives a text's constants of the motion: a square root is the branch
the text takes (`derive.lecture.comparing`: θ̇ = −√(2(E − U)/I₁) holds where the derived θ̇ takes
either sign with the motion and the squares agree), and a relation of the constants alone written in
the prose (``In the limit $L^2=2I_3T$,``) is a case of the motion the reader does not impose, under
which a statement it would flag is left unchecked (`derive.lecture.constant_cases`)."""
import kept_readings as kept

TOP = ("---\ntitle: a heavy top\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# The heavy symmetric top\n\n"
       "A symmetric top, $I_1 = I_2$, turns about its fixed tip; its centre of mass is at distance $l$ on the axis, "
       "$L_Z$ and $L_3$ the conserved angular momentum components along the vertical and the symmetry axis, "
       "$E$ the energy.\n\n")
RATES = (r"\dot{\phi} = \frac{L_Z-L_3\cos\theta}{I_1\sin^2\theta}, \quad \dot{\psi} = \frac{L_3}{I_3}"
         r"-\frac{(L_Z-L_3\cos\theta)\cos\theta}{I_1\sin^2\theta}")
U = r"U(\theta) = \frac{(L_Z-L_3\cos\theta)^2}{2I_1\sin^2\theta}+\frac{L_3^2}{2I_3}+Mgl\cos\theta"
NUTATION = r"\frac12 I_1\dot{\theta}^2 + U(\theta) = E"

FREE = ("---\ntitle: a free body\n---\n# The free asymmetric body\n\nA rigid body turns freely about its centre "
        "of mass, $\\omega_i$ the body components of its angular velocity, $L$ the magnitude of its angular "
        "momentum and $T$ its kinetic energy, both constant.\n\n"
        "$$\nI_1^2 \\omega_1^2+I_2^2 \\omega_2^2+I_3^2 \\omega_3^2 = L^2, \\quad I_1 \\omega_1^2+I_2 \\omega_2^2+I_3 \\omega_3^2 = 2T\n$$\n\n")
PERMANENT = r"\omega_1 = \omega_2 = 0,\quad \omega_3 = \sqrt{\frac{2T}{I_3}}"


def _top(rate):
    text = TOP + "".join(f"\n$$\n{d}\n$$\n" for d in (RATES, U, NUTATION, rate))
    return [c.verdict for c in kept.check_text(text)][-1]


def _free(prose_and_displays):
    return [(c.line, c.kind, c.verdict, c.why) for c in kept.check_text(FREE + prose_and_displays)]


def test_a_rate_equal_to_a_root_holds_on_either_branch_when_its_square_holds():
    assert _top(r"\frac{\mathrm{d} \theta}{\mathrm{d} t} = -\sqrt{\frac{2(E-U(\theta))}{I_1}}") == "holds"
    assert _top(r"\dot{\theta} = \sqrt{\frac{2(E-U(\theta))}{I_1}}") == "holds"


def test_a_root_whose_square_does_not_hold_is_still_flagged():
    assert _top(r"\dot{\theta} = -\sqrt{\frac{2(E-U(\theta))}{I_3}}") == "fails"
    assert _top(r"\dot{\theta} = -\sqrt{\frac{E-U(\theta)}{I_1}}") == "fails"


def test_a_relation_of_the_constants_alone_in_the_prose_is_a_case_not_a_claim():
    claims = _free("In the limit $L^2=2I_3T$,\n\n$$\n" + PERMANENT + "\n$$\n")
    case = [c for c in claims if c[0] == 12]
    assert [c[1:3] for c in case] == [("setting", "unchecked")]
    under = [c for c in claims if c[0] == 14]
    assert all(c[2] == "unchecked" for c in under)
    assert [c[1] for c in under if "in the case L^2=2I_3T" in c[3]] == ["definition"]      # ω₃ = √(2T/I₃)


def test_a_statement_that_holds_ends_the_case_and_what_follows_is_judged_again():
    after = ("In the limit $L^2=2I_3T$,\n\n$$\n" + PERMANENT + "\n$$\n\nIn general\n\n$$\n"
             r"\omega_1^2 = \frac{(2I_3T-L^2)-I_2(I_3-I_2)\omega_2^2}{I_1(I_3-I_1)}" + "\n$$\n\nand again\n\n$$\n"
             + PERMANENT + "\n$$\n")
    claims = _free(after)
    assert [c[2] for c in claims if c[0] == 20] == ["holds"]
    assert any(c[2] in ("typo", "fails") for c in claims if c[0] == 26)


def test_without_the_case_the_same_display_is_flagged():
    claims = _free("$$\n" + PERMANENT + "\n$$\n")
    assert any(c[2] in ("typo", "fails") for c in claims if c[0] == 12)


def test_a_chain_of_components_equal_to_a_value_sets_each_of_them():
    claims = _free("$$\n\\omega_1 = \\omega_2 = 0\n$$\n")
    assert [(c[1], c[2]) for c in claims if c[0] == 12] == [("setting", "unchecked"), ("setting", "unchecked")]
