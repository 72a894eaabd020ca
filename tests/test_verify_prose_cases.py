"""A sentence that states a special case and then relations for it ("$\\cos\\theta = 0$, where
$\\omega_z = \\dot\\phi$ and $\\omega_3 = \\dot\\psi$") gets no flag from relations the case decides."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Angular velocity\n\n"


def _verdicts(sentence):
    return [c.verdict for c in kept.check_text(HEAD + sentence + "\n")]


def test_relations_after_a_case_in_the_same_sentence_are_not_flagged():
    verdicts = _verdicts("For $\\cos \\theta = 0$, where $\\omega_z = \\dot{\\phi}$ and $\\omega_3 = \\dot{\\psi}$, the rates separate.")
    assert "fails" not in verdicts and "typo" not in verdicts


def test_a_relation_in_prose_that_is_no_identity_is_unchecked_and_says_how_far_it_is_from_one():
    claims = kept.check_text(HEAD + "The spin component is $\\omega_3 = \\dot{\\phi}$ in general.\n")
    assert claims[-1].verdict == "unchecked" and "as an identity" in claims[-1].why


def test_a_relation_in_prose_that_holds_is_confirmed():
    text = HEAD + "The spin component is $\\omega_3 = \\dot{\\phi}\\cos\\theta + \\dot{\\psi}$ in general.\n"
    assert _verdicts(text.replace("The spin", "The body's spin"))[-1] == "holds"


def test_a_condition_or_a_name_of_the_texts_own_in_a_sentence_is_never_flagged():
    heavy = ("---\nconvention: z-y-z\n---\n# Heavy top\n\n"
             "$$U(\\theta) = \\frac{(L_z - L_3\\cos\\theta)^2}{2I_1\\sin^2\\theta} + Mgl\\cos\\theta$$\n\n"
             "The angles where $U(\\theta)=E$ are the turning points of the nutation.\n")
    cube = ("# A cube\n\nThe first principal axis is the unit vector "
            "$\\mathbf{\\hat{e}}_1= \\frac{1}{\\sqrt{3}} \\begin{pmatrix} 1 \\\\ 1 \\\\ 1 \\end{pmatrix}$ along the diagonal.\n")
    for text in (heavy, cube):
        assert not {"typo", "fails"} & {c.verdict for c in kept.check_text(text)}, text


def test_a_coefficient_the_text_names_after_the_equation_is_read_with_that_definition():
    text = ("---\nconvention: z-x-z\n---\n\n# Symmetric top\n\nWith $I_1 = I_2$ and no torque,\n\n"
            "$$\\dot{\\omega}_{1} + \\Omega\\omega_{2} = 0$$\n\n"
            "where $\\Omega = \\left(\\frac{I_{3} - I_{1}}{I_{1}}\\right)\\omega_{3}$.\n")
    claims = kept.check_text(text)
    assert [(c.line, c.verdict) for c in claims if c.line == 9] == [(9, "holds")]
    flipped = kept.check_text(text.replace("I_{3} - I_{1}", "I_{1} - I_{3}"))
    assert [c.verdict for c in flipped if c.line == 9] == ["unchecked"]      # never a flag on a reading it had not


def test_a_rate_set_to_zero_that_eulers_equations_give_under_the_stated_moments_holds():
    text = ("---\nconvention: z-x-z\n---\n\n# Spherical top\n\nAll three moments equal, $I_1=I_2=I_3$, so that\n\n"
            "$$\\dot{\\omega}_{1} = 0$$\n")
    assert [(c.line, c.verdict) for c in kept.check_text(text) if c.line == 9] == [(9, "holds")]
    asymmetric = text.replace("All three moments equal, $I_1=I_2=I_3$, so that", "A body, and")
    assert [(c.kind, c.verdict) for c in kept.check_text(asymmetric)] == [("setting", "unchecked")]


def test_a_symbol_set_to_zero_where_the_prose_says_it_is_absent_is_the_setting_not_a_claim():
    text = ("## Free body\n\nThe body turns freely: no external moment acts, $T=0$.\n\n"
            "$$T = \\frac{1}{2}(I_1\\omega_1^2 + I_2\\omega_2^2 + I_3\\omega_3^2)$$\n")
    claims = kept.check_text(text)
    assert not [c for c in claims if c.line == 3 and c.verdict in ("typo", "fails")]
    assert [c.verdict for c in claims if c.line == 5] == ["holds"]      # the kinetic energy T is not zeroed


def test_math_standing_alone_as_its_paragraphs_line_is_judged_as_a_display():
    """Texts kept from rendered pages write their displays as `$…$` paragraphs of their own."""
    text = ("# A free body\n\nEuler's equations, with no torque:\n\n"
            "$I_1 \\dot{\\omega}_1 = (I_2 + I_3)\\omega_2\\omega_3$\n\nwhich the body obeys.\n")
    assert {"typo", "fails"} & {c.verdict for c in kept.check_text(text) if c.line == 5}
    in_a_sentence = text.replace("$I_1", "so that $I_1").replace("_3$\n", "_3$ holds.\n")
    assert {c.verdict for c in kept.check_text(in_a_sentence) if c.line == 5} == {"unchecked"}
