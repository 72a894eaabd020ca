"""A rate seen from a frame written with the frame's letter before it, ``^N\\frac{\\text{d}\\vec{H}}{\\text{d}t}``
(Kane's and Schaub's notation, N the inertial frame, B the body's), the differential set in text:
it is the same derivative in a frame as ``\\left(\\frac{d\\vec{H}}{dt}\\right)_{N}``, the frame's letter
before a vector and ω's ``_{B/N}`` naming the vector read in body components, so the transport
theorem written so is checked (and its sign slip flagged)."""
from __future__ import annotations

import kept_readings as kept

TEXT = r"""# The rate of a vector seen from two frames

A vector $\vec{\mathbf{H}}$ of the body, the body frame $B$, the inertial frame $N$ and the angular
velocity $\vec{\boldsymbol{\omega}}_{B/N}$ of the body in it.

$$
^N\frac{\text{d}\vec{\mathbf{H}}}{\text{d}t} = ^B\frac{\text{d}\vec{\mathbf{H}}}{\text{d}t} SIGN \vec{\boldsymbol{\omega}}_{B/N} \times ^B\vec{\mathbf{H}}
$$
"""


def _verdicts(text: str) -> list[str]:
    return [c.verdict for c in kept.check_text(text) if c.line == 6]


def test_the_transport_theorem_with_frame_prescripts_holds():
    assert _verdicts(TEXT.replace("SIGN", "+")) == ["holds"]


def test_the_transport_theorem_with_frame_prescripts_and_its_sign_slipped_is_flagged():
    verdicts = _verdicts(TEXT.replace("SIGN", "-"))
    assert verdicts and all(v in ("typo", "fails") for v in verdicts)


def test_a_frame_letter_the_reader_does_not_know_leaves_the_rate_unread():
    text = TEXT.replace("SIGN", "+").replace("^N", "^Q").replace("frame $N$", "frame $Q$")
    assert "holds" not in _verdicts(text)


def _as_operator(text: str, opening: str, closing: str) -> str:
    """The body-frame rate written as the operator ``^B\\frac{d}{dt}`` on a bracket round ``^B\\vec{H}``."""
    return text.replace(r"= ^B\frac{\text{d}\vec{\mathbf{H}}}{\text{d}t}",
                        r"= ^B\frac{\text{d}}{\text{d}t}" + opening + r"^B\vec{\mathbf{H}}" + closing)


def test_the_rate_from_a_frame_as_an_operator_on_a_plain_bracket_is_read_as_on_a_sized_one():
    for opening, closing in ((r"\left(", r"\right)"), ("(", ")")):
        assert _verdicts(_as_operator(TEXT.replace("SIGN", "+"), opening, closing)) == ["holds"]
        slipped = _verdicts(_as_operator(TEXT.replace("SIGN", "-"), opening, closing))
        assert slipped and all(v in ("typo", "fails") for v in slipped)


SUPERSCRIPTED = r"""# The transport theorem

The inertial frame $\mathcal{N}$, the body frame $\mathcal{B}$ and the body's angular velocity
$\boldsymbol{\omega}_{\mathcal{B}/\mathcal{N}}$ in it.

$$
\left( \frac{d\vec{r}}{dt} \right)^{\mathcal{N}} = \left( \frac{d\vec{r}}{dt} \right)^{\mathcal{B}} SIGN \boldsymbol{\omega}_{\mathcal{B}/\mathcal{N}} \times \vec{r}
$$
"""


def test_the_frame_written_as_a_superscript_on_the_rates_bracket_is_read_as_its_subscript():
    assert _verdicts(SUPERSCRIPTED.replace("SIGN", "+")) == ["holds"]
    slipped = _verdicts(SUPERSCRIPTED.replace("SIGN", "-"))
    assert slipped and all(v in ("typo", "fails") for v in slipped)
