"""An angle the running text holds at a number ("the nutation angle stays $\\theta = \\frac{\\pi}{2}$") is part
of the motion the text describes, with no rate: a later display that holds there holds (never
flagged for what it leaves out), a display that does not is still judged, and an angle held at two
numbers in one section names cases, neither put in."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n# Disk\n\n"
UPRIGHT = "The disk stands upright: its nutation angle stays $\\theta = \\dfrac{\\pi}{2}$.\n\n"


def _verdicts(text, start):
    return [c.verdict for c in kept.check_text(text) if c.latex.startswith(start)]


def test_a_display_that_holds_at_the_held_angle_holds():
    text = HEAD + UPRIGHT + "$$\n\\omega_1 = \\dot{\\phi} \\sin \\psi\n$$\n\n$$\n\\omega_3 = \\dot{\\psi}\n$$\n"
    assert _verdicts(text, "\\omega_1") == ["holds"] and _verdicts(text, "\\omega_3") == ["holds"]
    claim = next(c for c in kept.check_text(text) if c.latex.startswith("\\omega_1"))
    assert "in the motion the text describes" in claim.why and "line 6" in claim.why


def test_a_display_that_does_not_hold_there_is_still_judged():
    text = HEAD + UPRIGHT + "$$\n\\omega_1 = \\dot{\\phi} \\cos \\psi\n$$\n"
    assert _verdicts(text, "\\omega_1") in (["typo"], ["fails"])


def test_an_angle_held_at_two_numbers_names_cases_and_neither_is_put_in():
    text = HEAD + "At $\\theta = 0$ or $\\theta = \\pi$ the line of nodes is lost.\n\n$$\n\\omega_3 = \\dot{\\phi} + \\dot{\\psi}\n$$\n"
    assert _verdicts(text, "\\omega_3") != ["holds"]
    assert _verdicts(HEAD + "At $\\theta = 0$ the line of nodes is lost.\n\n$$\n\\omega_3 = \\dot{\\phi} + \\dot{\\psi}\n$$\n",
                     "\\omega_3") == ["holds"]


def test_the_held_angle_ends_with_its_section():
    text = HEAD + UPRIGHT + "# Top\n\n$$\n\\omega_1 = \\dot{\\phi} \\sin \\psi\n$$\n"
    assert _verdicts(text, "\\omega_1") != ["holds"]
