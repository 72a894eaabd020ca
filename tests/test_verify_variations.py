"""δx, a small variation of x (derive/lecture/variations.py, the scanner in vocabulary.py): a δ written
directly before a symbol is one symbol of the text's, never δ times that symbol; Kronecker's δ_ij and
a δ the text uses as its own quantity (a phase) read as before."""
import sympy as sp

import kept_readings as kept
from derive.lecture import latex as lx

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
    assert not lx.delta_quantity("$$I_{ij} = \\delta_{ij} r^2, \\quad \\omega_1 = \\Omega + \\delta\\omega_1$$")
    delta, w1 = sp.Symbol("delta", real=True), lx.W[0]
    value = lx.parse("\\delta\\omega_1", lx.Vocabulary(open=True, delta_quantity=True)).members[0].value
    assert sp.expand(value - delta * w1) == 0
    phase = ("# A phase\n\nThe solution is $\\omega_1 = A\\cos(\\Omega t + \\delta)$, with $\\delta$ the phase.\n\n"
             "$$\\dot\\omega_1 = \\delta\\dot\\omega_1$$\n")
    assert [c.verdict for c in kept.check_text(phase)] == ["unchecked", "fails"]   # δ = 1 does not follow
