"""A text that states no convention is not judged in the lecture's z-y-z by default: the first
formula of the angles that is flagged in z-y-z and holds in exactly one other sequence sets the
text's convention (its reason says so); a text that writes a formula of z-y-z keeps z-y-z, its
slips flagged."""
from derive.lecture import notes as nt
from derive.lecture import notes_check as nc

_RATES = ("# Body rates\n\nThe body components of the angular velocity:\n\n"
          "$$\n\\omega_1 = {w1}\n$$\n\n$$\n\\omega_2 = {w2}\n$$\n\n$$\n\\omega_3 = \\dot\\phi \\cos\\theta + \\dot\\psi\n$$\n")
ZXZ_RATES = _RATES.format(w1="\\dot\\phi \\sin\\theta \\sin\\psi + \\dot\\theta \\cos\\psi",
                          w2="\\dot\\phi \\sin\\theta \\cos\\psi - \\dot\\theta \\sin\\psi")
# z-y-z's ω₂ written right, its ω₁ written as z-x-z's ω₁ (the same as z-y-z's ω₂: an index slip)
ZYZ_SLIP = _RATES.format(w1="\\dot\\phi \\sin\\theta \\sin\\psi + \\dot\\theta \\cos\\psi",
                         w2="\\dot\\phi \\sin\\theta \\sin\\psi + \\dot\\theta \\cos\\psi")


def _verdicts(text):
    return {c.line: (c.verdict, c.why) for c in nc.check_text(text)}


def test_z_x_z_body_rates_in_a_text_that_states_no_convention_hold_and_name_the_sequence_read():
    out = _verdicts(ZXZ_RATES)
    assert [v for v, _ in out.values()] == ["holds"] * 3
    assert "reads the text's convention as z-x-z from line 5" in out[5][1]


def test_a_slip_in_a_text_that_writes_a_formula_of_z_y_z_is_still_flagged():
    out = _verdicts(ZYZ_SLIP)
    assert out[5][0] == "typo" and "convention" not in out[5][1]
    assert out[9][0] == out[13][0] == "holds"


def test_a_stated_convention_is_never_replaced_by_one_inferred():
    out = _verdicts("---\nconvention: z-y-z\n---\n" + ZXZ_RATES)
    assert out[8][0] == "typo" and out[12][0] == "fails"
    assert all("convention" not in why for _, why in out.values())


def test_a_formula_that_holds_in_several_other_sequences_is_not_judged_and_names_them():
    # the axial rate about x: the same in x-y-x and x-z-x, no single sequence to read the text in
    out = _verdicts("# Body rates\n\n$$\n\\omega_1 = \\dot\\phi \\cos\\theta + \\dot\\psi\n$$\n")
    assert out[3][0] == "unchecked"
    assert "holds in x-y-x, x-z-x, not in z-y-z" in out[3][1]


ZYZ_THEN_SLIP = _RATES.format(w1="-\\dot\\phi \\sin\\theta \\cos\\psi + \\dot\\theta \\sin\\psi",
                              w2="\\dot\\phi \\sin\\theta \\sin\\psi + \\dot\\theta \\cos\\psi") + (
    "\nThe kinetic energy of the symmetric top:\n\n"
    "$$\nT = \\frac{1}{2} I_1 (\\dot\\theta^2 + \\dot\\phi^2 \\sin^2\\theta) + \\frac{1}{2} I_3 (\\dot\\psi + \\dot\\phi \\cos\\theta)^3\n$$\n")


def test_a_slip_after_displays_that_show_z_y_z_is_flagged_and_not_read_again():
    # ω₁, ω₂, ω₃ of z-y-z hold as read and are flagged in every other sequence: before the slip in
    # T (a cube for a square) is read again anywhere, they rule every other sequence out
    checker = nc.Checker(nt.parse_notes(ZYZ_THEN_SLIP))
    claims = checker.run()
    slip = max(c.line for c in claims)
    assert checker.reading.probes[slip] == {} and checker.reading.open == [] and checker.reading.done
    out = _verdicts(ZYZ_THEN_SLIP)
    assert out[slip][0] in ("typo", "fails") and "convention" not in out[slip][1]
    assert out[5][0] == out[9][0] == out[13][0] == "holds"


def test_a_slip_that_holds_in_another_sequence_reads_again_the_displays_that_held_before_it():
    # ω₂ of z-y-z right, then ω₁ written as z-x-z's ω₁: z-x-z is ruled out by the ω₂ read again in it
    text = ("# Body rates\n\n$$\n\\omega_2 = \\dot\\phi \\sin\\theta \\sin\\psi + \\dot\\theta \\cos\\psi\n$$\n\n"
            "$$\n\\omega_1 = \\dot\\phi \\sin\\theta \\sin\\psi + \\dot\\theta \\cos\\psi\n$$\n")
    checker = nc.Checker(nt.parse_notes(text))
    checker.run()
    assert checker.reading.probes[3][("z-x-z", None)] == (True, False)
    assert ("z-x-z", None) not in checker.reading.open
    out = _verdicts(text)
    assert out[3][0] == "holds" and out[7][0] == "typo" and "convention" not in out[7][1]


# z-y-z's body rates in α, β, γ, the names the z-y-z reading takes for a text that names none, after
# a phase φ (no Euler angle), then a slip in T (a cube for a square)
ZYZ_ALPHA_THEN_SLIP = (
    "# Body rates\n\nA free spin turns with a phase $\\varphi$, no Euler angle.\n\n"
    "$$\n\\omega_1 = -\\dot\\alpha \\sin\\beta \\cos\\gamma + \\dot\\beta \\sin\\gamma\n$$\n\n"
    "$$\n\\omega_2 = \\dot\\alpha \\sin\\beta \\sin\\gamma + \\dot\\beta \\cos\\gamma\n$$\n\n"
    "$$\n\\omega_3 = \\dot\\alpha \\cos\\beta + \\dot\\gamma\n$$\n\n"
    "The kinetic energy of the symmetric top:\n\n"
    "$$\nT = \\frac{1}{2} I_1 (\\dot\\beta^2 + \\dot\\alpha^2 \\sin^2\\beta) + \\frac{1}{2} I_3 (\\dot\\gamma + \\dot\\alpha \\cos\\beta)^3\n$$\n")


def test_body_rates_in_alpha_beta_gamma_show_z_y_z_and_a_later_slip_is_not_read_again():
    # the other sequences read α, β, γ as z-y-z reads them (first, second, third turn): ω₁, ω₂ of
    # z-y-z are flagged in each, which rules it out before the slip in T is read again anywhere
    checker = nc.Checker(nt.parse_notes(ZYZ_ALPHA_THEN_SLIP))
    claims = checker.run()
    slip = max(c.line for c in claims)
    assert checker.reading.probes.get(slip) == {} and checker.reading.open == [] and checker.reading.done
    out = _verdicts(ZYZ_ALPHA_THEN_SLIP)
    assert out[slip][0] in ("typo", "fails") and "convention" not in out[slip][1]
    assert out[5][0] == out[9][0] == out[13][0] == "holds"


ZXZ_ALPHA_RATES = ("# Body rates\n\n"
                   "$$\n\\omega_1 = \\dot\\alpha \\sin\\beta \\sin\\gamma + \\dot\\beta \\cos\\gamma\n$$\n\n"
                   "$$\n\\omega_2 = \\dot\\alpha \\sin\\beta \\cos\\gamma - \\dot\\beta \\sin\\gamma\n$$\n\n"
                   "$$\n\\omega_3 = \\dot\\alpha \\cos\\beta + \\dot\\gamma\n$$\n")


def test_z_x_z_body_rates_in_alpha_beta_gamma_hold_and_name_the_sequence_read():
    # read again in z-x-z, α, β, γ are its first, second and third turns, as in the probe
    out = _verdicts(ZXZ_ALPHA_RATES)
    assert [v for v, _ in out.values()] == ["holds"] * 3
    assert "reads the text's convention as z-x-z from line 3" in out[3][1]


def test_a_display_read_in_the_texts_own_frames_is_neither_probed_nor_evidence():
    # Kane's unit vectors turned by φ, then a frame relation that fails: both read alike in every
    # sequence (the frames are the text's own), so neither is read again in another one
    text = ("Frames $E$ and $D$ with right-handed unit vectors.\n\n$$\n\\hat{d}_1 = \\hat{e}_1 \\\\\n"
            "\\hat{d}_2 = \\cos{\\phi} \\hat{e}_2 + \\sin{\\phi} \\hat{e}_3 \\\\\n"
            "\\hat{d}_3 = -\\sin{\\phi} \\hat{e}_2 + \\cos{\\phi} \\hat{e}_3\n$$\n\n"
            "$$\n\\hat{d}_2 = \\cos{\\phi} \\hat{e}_2 - \\sin{\\phi} \\hat{e}_3\n$$\n")
    checker = nc.Checker(nt.parse_notes(text))
    claims = checker.run()
    assert {c.kind for c in claims} == {"frame"}
    assert [(c.line, c.verdict) for c in claims] == [(3, "holds"), (9, "fails")]
    assert checker.reading.probes == {} and checker.reading.shown == []


def test_a_display_read_in_the_texts_own_coordinate_is_neither_probed_nor_evidence():
    # a hoop's one coordinate θ in the text's own Lagrangian: its relations are judged by the text's
    # functions alone, so a slip among them is read in no other sequence of Euler angles
    text = ("A hoop rolling with one coordinate $\\theta$.\n\n"
            "$$\nL(\\theta, \\dot{\\theta}) = m R^2 \\dot{\\theta}^2 + m g R \\cos\\theta\n$$\n\n"
            "$$\n\\frac{\\partial L}{\\partial \\theta} = m g R \\sin\\theta\n$$\n\n"
            "$$\n\\frac{\\partial L}{\\partial \\dot{\\theta}} = 2 m R^2 \\dot{\\theta}\n$$\n")
    checker = nc.Checker(nt.parse_notes(text))
    claims = checker.run()
    judged = {c.line: c.verdict for c in claims if c.verdict != "unchecked"}
    assert judged == {7: "fails", 11: "holds"}
    assert all(c.sequence_free for c in claims if c.line in judged)
    assert checker.reading.probes == {} and checker.reading.shown == []
