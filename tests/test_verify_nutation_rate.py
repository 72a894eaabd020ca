"""A nutation rate the prose names ("the nutation frequency is"), judged against the fast top's
nutation the reader derives from its own V_eff and momenta (derive/lecture/nutation_rate.py).

The notes are written for these tests the way equation sheets on gyroscopes write them: each name
said once in a sentence, the formula in those names only.
"""
from derive.lecture.notes_check import check_text

HEAD = """---
convention: z-x-z
angles: [\\phi, \\theta, \\psi]
---

# Gyroscope

For a spinning top of mass $M$ whose centre of mass is at distance $r$ from the pivot, spinning at $\\omega_s$ about its axis with moment $I_z$ there, the precession rate is

$$\\Omega_{p} = \\frac{M g r}{I_{z} \\omega_{s}}$$

Its transverse moment $I_x$ is the same about every axis across the spin. For small oscillations about the steady precession, the nutation frequency is

"""


def nutation(display: str) -> list:
    return [(c.verdict, c.why) for c in check_text(HEAD + "$$" + display + "$$\n") if c.kind == "nutation rate"]


def test_the_fast_tops_nutation_rate_holds_if_the_spin_is_fast():
    (verdict, why), = nutation("\\omega_{n} = \\frac{I_{z} \\omega_{s}}{I_{x}}")
    assert verdict == "holds" and "holds if the spin" in why


def test_the_sleeping_tops_exact_nutation_rate_holds_to_leading_order():
    (verdict, _), = nutation("\\omega_{n} = \\frac{\\sqrt{I_{z}^{2} \\omega_{s}^{2} - 4 I_{x} M g r}}{I_{x}}")
    assert verdict == "holds"


def test_the_rate_seen_from_the_body_holds():
    (verdict, why), = nutation("\\omega_{n} = \\frac{(I_{z} - I_{x}) \\omega_{s}}{I_{x}}")
    assert verdict == "holds" and "from the body" in why


def test_a_nutation_rate_that_grows_as_the_bare_spin_is_flagged():
    (verdict, why), = nutation("\\omega_{n} = \\sqrt{\\frac{M g r}{I_{z}} + \\omega_{s}^{2}}")
    assert verdict == "fails" and "leads with" in why


def test_a_planted_square_root_is_flagged():
    (verdict, _), = nutation("\\omega_{n} = \\omega_{s} \\sqrt{\\frac{I_{z}}{I_{x}}}")
    assert verdict == "fails"


def test_a_nutation_rate_in_an_untied_symbol_stays_unchecked_naming_it():
    (verdict, why), = nutation("\\omega_{n} = \\frac{I_{z} \\omega_{s}}{J}")
    assert verdict == "unchecked" and "J" in why


def test_a_moment_named_just_before_the_nutation_frequency_is_the_transverse_moment():
    head = HEAD.replace("Its transverse moment $I_x$ is the same about every axis across the spin. For small oscillations "
                        "about the steady precession, the nutation frequency is",
                        "For a symmetric top with transverse moment $I_x$, the free nutation frequency, the small "
                        "oscillation of the spin axis about its steady precession, is given as")
    assert head != HEAD
    found = [(c.verdict, c.why) for c in check_text(head + "$$\\omega_{n} = \\omega_{s} \\sqrt{\\frac{I_{z} - I_{x}}{I_{x}}}$$\n")
             if c.kind == "nutation rate"]
    assert [v for v, _ in found] == ["fails"]


def test_a_number_times_the_derived_rate_is_not_flagged():
    # half the fast rate or a frequency in cycles may measure the same motion otherwise (a text's own definition)
    (verdict, why), = nutation("\\omega_{n} = \\frac{I_{z} \\omega_{s}}{2 I_{x}}")
    assert verdict == "unchecked" and "a number times" in why
    cycles = check_text(HEAD + "$$f_{n} = \\frac{I_{z} \\omega_{s}}{2 \\pi I_{x}}$$\n")
    assert not [c for c in cycles if c.verdict in ("typo", "fails")]
