"""δx, a small variation of x (derive/lecture/variations.py, the scanner in vocabulary.py): a δ written
directly before a symbol is one symbol of the text's, never δ times that symbol; Kronecker's δ_ij and
a δ the text uses as its own quantity (a phase) read as before."""
import sympy as sp

import kept_readings as kept
from derive.lecture import latex as lx
from derive.lecture.source import normalize

DISTURBED = ("# Small disturbances\n\nA body spins steadily about its axis 3; small disturbances of the "
             "spin are written with a delta.\n\n"
             "$$\\delta\\dot{\\theta} = \\delta \\omega_1$$\n\n"
             "$$\\dot\\omega_1 = \\delta x$$\n\n"
             "$$\\dot\\omega_1 = \\delta\\dot\\omega_1$$\n")


def test_a_delta_before_a_symbol_is_never_delta_times_the_symbol():
    # as δ times the symbol, δθ̇ = δω₁ is θ̇ = ω₁ and ω̇₁ = δω̇₁ is δ = 1: both would fail
    claims = kept.check_text(DISTURBED)
    assert len(claims) == 3
    assert {c.verdict for c in claims} == {"unchecked"}
    assert all("\\delta" in c.why for c in claims)      # the why names the variation as the text writes it


def test_the_scanner_reads_a_variation_as_one_symbol_with_or_without_a_space_and_with_accents():
    for latex, base, dots in [("\\delta\\omega_1", "omega", 0), ("\\delta \\theta", "theta", 0),
                              ("\\delta\\dot\\omega_1", "omega", 1), ("\\delta\\dot{\\theta}", "theta", 1),
                              ("\\delta x", "x", 0), ("\\delta\\,\\omega_2", "omega", 0)]:
        toks = lx.scan(latex)
        assert len(toks) == 1 and toks[0].value.base == base and toks[0].value.dots == dots, latex
        value = lx.parse(latex, lx.Vocabulary(open=True)).members[0].value
        assert isinstance(value, lx.Generic) and not value.free_symbols & {sp.Symbol("delta", real=True)}


def test_kronecker_delta_and_a_phase_are_unchanged():
    toks = lx.scan("\\delta_{ij} r^2")
    assert toks[0].value.base == "delta" and toks[0].value.sub == "ij"
    toks = lx.scan("\\cos(\\Omega t + \\delta)")
    assert [tok.value.base for tok in toks if tok.kind == "atom"] == ["Omega", "t", "delta"]


def test_a_text_that_writes_delta_alone_keeps_delta_times_the_symbol():
    assert lx.delta_quantity("$\\omega_1 = A\\cos(\\Omega t + \\delta)$, with $\\delta$ the phase")
    assert lx.delta_quantity("$$\\delta = \\pi/2$$")
    assert lx.delta_quantity("The solution has a phase δ, the phase of the oscillation.")
    assert not lx.delta_quantity("The variation δω₁ stays small.")
    assert not lx.delta_quantity("$$I_{ij} = \\delta_{ij} r^2, \\quad \\omega_1 = \\Omega + \\delta\\omega_1$$")
    delta, w1 = sp.Symbol("delta", real=True), lx.W[0]
    value = lx.parse("\\delta\\omega_1", lx.Vocabulary(open=True, delta_quantity=True)).members[0].value
    assert sp.expand(value - delta * w1) == 0
    phase = ("# A phase\n\nThe solution is $\\omega_1 = A\\cos(\\Omega t + \\delta)$, with $\\delta$ the phase.\n\n"
             "$$\\dot\\omega_1 = \\delta\\dot\\omega_1$$\n")
    assert [c.verdict for c in kept.check_text(phase)] == ["unchecked", "fails"]   # δ = 1 does not follow


SPIN = ("# Intermediate axis\n\nA steady spin about axis 2, disturbed slightly:\n\n"
        "$$\\vec{\\omega}(t) = \\begin{pmatrix} \\delta\\omega_1(t) \\\\ \\Omega_0 + \\delta\\omega_2(t) \\\\ "
        "\\delta\\omega_3(t) \\end{pmatrix}, \\qquad |\\delta\\omega_1|, |\\delta\\omega_3| \\ll \\Omega_0$$\n\n"
        "To first order in the disturbances:\n\n"
        "$$\\frac{d(\\delta\\omega_1)}{dt} \\approx \\frac{I_2 - I_3}{I_1} \\Omega_0 \\delta\\omega_3$$\n\n"
        "$$\\frac{d(\\delta\\omega_3)}{dt} \\approx \\frac{I_1 - I_2}{I_3} \\Omega_0 \\delta\\omega_1$$\n\n"
        "$$\\frac{d^2(\\delta\\omega_1)}{dt^2} = \\frac{(I_2 - I_3)(I_1 - I_2)}{I_1 I_3} \\Omega_0^2 \\delta\\omega_1$$\n")


def test_a_perturbation_written_as_variations_has_its_linearised_equations_checked():
    by_line = kept.verdicts_by_line(SPIN)
    lines = [kept.line_of(SPIN, marker) for marker in ("d(\\delta\\omega_1)}{dt} \\approx", "d(\\delta\\omega_3)}{dt}",
                                                        "d^2(\\delta\\omega_1)")]
    assert [by_line[n] for n in lines] == [{"holds"}] * 3


def test_a_wrong_linearised_equation_in_variations_fails():
    wrong = SPIN.replace("\\frac{I_2 - I_3}{I_1} \\Omega_0 \\delta\\omega_3", "\\frac{I_3 - I_2}{I_1} \\Omega_0 \\delta\\omega_3")
    assert wrong != SPIN
    claims = [c for c in kept.check_text(wrong) if "I_3 - I_2" in c.latex]
    assert [c.verdict for c in claims] == ["fails"] and "order 0" not in claims[0].why


def test_a_list_of_components_set_to_variations_names_a_perturbation():
    # the variation keeps its δ apart from the component: δω̇₁ is the rate of δω₁, not ω̃̇₁
    text = ("# Spin\n\n$$\\omega_1 = \\delta\\omega_1, \\quad \\omega_2 = \\Omega + \\delta\\omega_2, \\quad "
            "\\omega_3 = \\delta\\omega_3$$\n\n"
            "$$I_1 \\delta\\dot\\omega_1 = (I_2 - I_3)(\\Omega + \\delta\\omega_2)\\,\\delta\\omega_3$$\n\n"
            "$$I_3 \\delta\\dot\\omega_3 \\approx (I_1 - I_2)\\,\\Omega\\,\\delta\\omega_1$$\n\n"
            "$$I_1 \\delta\\dot\\omega_1 = (I_3 - I_2)\\,\\Omega\\,\\delta\\omega_3$$\n")
    # exact; to first order after the ≈; the sign of the first-order term turned
    assert [c.verdict for c in kept.check_text(text) if "dot" in c.latex] == ["holds", "holds", "fails"]


def test_the_second_rate_of_a_bracket_is_read_as_the_second_derivative_of_what_it_holds():
    assert normalize("\\frac{d^2(\\delta\\omega_1)}{dt^2} = x") == "\\frac{d^2}{dt^2}(\\delta\\omega_1) = x"
    assert normalize("\\frac{d^{2}(m v)}{dt^{2}}") == "\\frac{d^2}{dt^2}(m v)"
    assert normalize("\\frac{d^2(x)}{dt}") == "\\frac{d^2(x)}{dt}"        # the powers disagree: left as written


def test_the_rate_of_a_sized_bracket_or_in_upright_differentials_is_the_rate_of_what_it_holds():
    assert normalize("\\frac{d\\left(\\delta\\omega_1\\right)}{dt}") == "\\frac{d}{dt}(\\delta\\omega_1)"
    assert normalize("\\frac{d^2\\left(m v\\right)}{dt^2}") == "\\frac{d^2}{dt^2}(m v)"
    assert normalize("\\frac{\\mathrm{d}(\\delta\\omega_1)}{\\mathrm{d}t}") == "\\frac{d}{dt}(\\delta\\omega_1)"
    assert normalize("\\frac{\\mathrm{d}\\phi}{\\sqrt{1 - k^2}}") == "\\frac{\\mathrm{d}\\phi}{\\sqrt{1 - k^2}}"   # no rate
    sized = SPIN.replace("d(\\delta\\omega_1)}", "d\\left(\\delta\\omega_1\\right)}")
    assert sized != SPIN
    line = kept.line_of(sized, "d\\left(\\delta\\omega_1\\right)}{dt}")
    assert kept.verdicts_by_line(sized)[line] == {"holds"}


def test_the_rate_of_a_component_perturbed_about_a_steady_spin_is_the_rate_of_its_variation():
    # ωᵢ = cᵢ + δωᵢ with cᵢ constant: ω̇₁ = δω̇₁ holds; as δ times ω̇₁ it would fail
    text = ("# Perturbed spin\n\nA body spins about its axis 3 with a small disturbance.\n\n"
            "$$\\omega_1 = \\delta\\omega_1, \\quad \\omega_2 = \\delta\\omega_2, \\quad \\omega_3 = \\Omega + \\delta\\omega_3$$\n\n"
            "$$\\dot\\omega_1 = \\delta\\dot\\omega_1$$\n\n"
            "$$\\dot\\omega_1 \\approx 2\\,\\delta\\dot\\omega_1$$\n")
    by_line = kept.verdicts_by_line(text)
    assert by_line[kept.line_of(text, "= \\delta\\dot")] == {"holds"}
    assert by_line[kept.line_of(text, "\\approx 2")] == {"fails"}      # off by ω̇₁ itself, first order in δω₂
