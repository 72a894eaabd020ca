"""A rate seen from a frame written in plain TeX, ``\\left({d{\\bf G}\\over dt}\\right)_{\\rm space}``:
the fraction keeps the group ``\\over`` writes around it and the vector stands in a group of its
own, yet it is the same derivative in a frame as ``\\left(\\frac{d\\mathbf{G}}{dt}\\right)_{space}``,
so the transport theorem written so is checked (and its sign slip flagged)."""
from __future__ import annotations

import kept_readings as kept

TEXT = r"""# The rate of a vector on two sets of axes

A general vector ${\bf G}$ of the body, and the angular velocity $\boldsymbol\omega$ of the body.

$$
\left({d{\bf G}\over dt}\right)_{\rm space} = \left({d{\bf G}\over dt}\right)_{\rm body} SIGN \boldsymbol\omega \times {\bf G}
$$
"""


def _verdict(sign: str) -> str:
    claims = [c for c in kept.check_text(TEXT.replace("SIGN", sign)) if c.line == 5]
    assert len(claims) == 1
    return claims[0].verdict


def test_the_transport_theorem_in_plain_tex_fractions_holds():
    assert _verdict("+") == "holds"


def test_the_transport_theorem_in_plain_tex_fractions_with_its_sign_slipped_is_flagged():
    assert _verdict("-") in ("typo", "fails")


def test_the_same_theorem_in_braced_fractions_reads_alike():
    text = TEXT.replace(r"{d{\bf G}\over dt}", r"{\frac{d\mathbf{G}}{dt}}").replace("SIGN", "+")
    assert [c.verdict for c in kept.check_text(text) if c.line == 5] == ["holds"]


BAR = r"""# The rate of a vector on two sets of axes

A general vector ${\bf G}$ of the body, and the angular velocity $\boldsymbol\omega$ of the body.

$$
\left.{d{\bf G}\over dt}\right|_{i} = \left.{d{\bf G}\over dt}\right|_{b} SIGN \boldsymbol\omega \times {\bf G}
$$
"""


def test_the_rate_at_a_frames_bar_in_plain_tex_holds_and_its_sign_slip_is_flagged():
    right = [c.verdict for c in kept.check_text(BAR.replace("SIGN", "+")) if c.line == 5]
    wrong = [c.verdict for c in kept.check_text(BAR.replace("SIGN", "-")) if c.line == 5]
    assert right == ["holds"] and wrong in (["typo"], ["fails"])
