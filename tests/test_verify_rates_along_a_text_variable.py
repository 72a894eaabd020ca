"""A text's rate of one of its names along another (``\\frac{\\mathrm{d}s}{\\mathrm{d}\\tau}`` with its
τ = p t) is ṡ/τ̇, never the quotient s/τ (`derive.lecture.written_rates.rate_along`); an equation of
motion with a square root of the ω̃ᵢ is compared once ω̃̇ is taken from Euler's equations, on the
branch the text takes (`derive.lecture.motion`); ds/dτ = g(s) is kept as the text's equation for s,
and a closed form in τ (s = sn τ) is put into it (`derive.lecture.text_motion`); and L read as the
angular momentum's magnitude stays so in the definitions that follow (`derive.lecture.rereading`)."""
import kept_readings as kept

FREE = ("---\ntitle: a free body\n---\n# The free asymmetric body\n\nA rigid body turns freely about its centre "
        "of mass, $\\omega_i$ the body components of its angular velocity, $L$ the magnitude of its angular "
        "momentum and $T$ its kinetic energy, both constant.\n\n"
        "$$\nI_1^2 \\omega_1^2+I_2^2 \\omega_2^2+I_3^2 \\omega_3^2 = L^2, \\quad I_1 \\omega_1^2+I_2 \\omega_2^2+I_3 \\omega_3^2 = 2T\n$$\n\n"
        "With the new variables\n\n$$\n\\tau = \\sqrt{\\frac{(I_3-I_2)(L^2-2I_1T)}{I_1I_2I_3}}t,\\quad "
        "s = \\sqrt{\\frac{I_2(I_3-I_2)}{2I_3T-L^2}}\\omega_2\n$$\n\nand the parameter\n\n$$\n"
        "k^2 = \\frac{(I_2-I_1)(2I_3T-L^2)}{(I_3-I_2)(L^2-2I_1T)}\n$$\n\nthe equation for $\\omega_2$ becomes\n\n")
RATE = r"\frac{\mathrm{d}s}{\mathrm{d}\tau} = \sqrt{(1-s^2)(1-k^2s^2)}"
PREAMBLE = "\n$$\n\\newcommand{\\sn}{\\mathrm{sn}\\,}\n\\newcommand{\\cn}{\\mathrm{cn}\\,}\n$$\n\n"


def _last(*displays):
    text = FREE + "".join(f"\n$$\n{d}\n$$\n\nso that\n" for d in displays)
    claims = kept.check_text(text.replace("# The free", PREAMBLE + "# The free"))
    last = max(c.line for c in claims)
    return [c.verdict for c in claims if c.line == last]


def test_the_rate_of_a_text_name_along_its_own_time_variable_holds_on_the_root_s_branch():
    assert _last(RATE) == ["holds"]


def test_it_is_no_quotient_of_the_two_names():
    assert "holds" not in _last(r"\frac{\mathrm{d}s}{\mathrm{d}\tau} = \frac{s}{\tau}")


def test_a_wrong_right_side_does_not_hold():
    assert "holds" not in _last(r"\frac{\mathrm{d}s}{\mathrm{d}\tau} = \sqrt{(1-s^2)(1+k^2s^2)}")


def test_a_closed_form_in_the_time_variable_solves_the_texts_equation():
    assert _last(RATE, r"s = \sn \tau") == ["holds"]
    assert "holds" not in _last(RATE, r"s = \cn \tau")


def test_the_texts_equation_without_a_root_is_solved_exactly():
    rate = r"\frac{\mathrm{d}s}{\mathrm{d}\tau} = 1-s^2"
    text = FREE.replace(RATE, "") + f"\n$$\n{rate}\n$$\n\nwhose solution is\n\n$$\ns = \\tanh \\tau\n$$\n"
    claims = kept.check_text(text)
    assert [c.verdict for c in claims if c.latex.strip() == r"s = \tanh \tau"] == ["holds"]
