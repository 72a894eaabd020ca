"""Frames a text names with letters of its own ("an inertial frame $S_0$ that coincides with the body
frame $S$") and brackets labelled with them, ``[\\dot{\\bm{A}}]_{S_0}`` the rate seen from the inertial
frame, ``[\\dot{\\bm{A}}]_{S}`` the rate seen from the body, ``[\\bm{L}]_{S}`` the body components: the
transport theorem and the angular momentum written so are checked and their slips flagged; a letter the
prose does not name as a frame leaves its bracket unread."""
from __future__ import annotations

import kept_readings as kept

TEXT = r"""# Euler's approach

Take an inertial frame $S_0$ that coincides with the body frame $S$ at an instant. For the angular
velocity $\bm{\omega}$ any vector $\bm{A}$ changes as

$$
[\dot{\bm{A}}]_{S_0} = [\dot{\bm{A}}]_{S} SIGN \bm{\omega} \times [\bm{A}]_{S}
$$

and in the principal axes

$$
[\bm{L}]_S = (I_1\omega_1, I_2\omega_INDEX, I_3\omega_3)
$$
"""


def _verdicts(text: str, line: int) -> list[str]:
    return [c.verdict for c in kept.check_text(text) if c.line == line]


def _correct() -> str:
    return TEXT.replace("SIGN", "+").replace("INDEX", "2")


def test_the_transport_theorem_between_frames_named_by_letters_holds():
    assert _verdicts(_correct(), 6) == ["holds"]


def test_the_transport_theorem_between_frames_named_by_letters_with_its_sign_slipped_is_flagged():
    verdicts = _verdicts(_correct().replace("} + \\bm{\\omega}", "} - \\bm{\\omega}"), 6)
    assert verdicts and all(v in ("typo", "fails") for v in verdicts)


def test_a_vector_in_the_body_frame_named_by_a_letter_is_read_in_body_components():
    assert _verdicts(_correct(), 12) == ["holds"]
    slipped = _verdicts(TEXT.replace("SIGN", "+").replace("INDEX", "1"), 12)
    assert slipped and all(v in ("typo", "fails") for v in slipped)


def test_a_letter_the_prose_does_not_name_as_a_frame_leaves_its_bracket_unread():
    text = _correct().replace("an inertial frame $S_0$", "a frame $S_0$")
    assert "holds" not in _verdicts(text, 6)


def test_a_letter_the_prose_names_as_both_frames_names_neither():
    text = _correct().replace("the body frame $S$ at an instant", "the body frame $S$ and the fixed frame $S$")
    assert "holds" not in _verdicts(text, 6) and "holds" not in _verdicts(text, 12)


def test_a_vector_bracketed_with_the_inertial_frames_letter_keeps_its_label():
    text = _correct().replace("[\\bm{L}]_S", "[\\bm{L}]_{S_0}")
    assert "holds" not in _verdicts(text, 12)


def test_a_non_inertial_frame_is_not_read_as_an_inertial_one():
    text = _correct().replace("an inertial frame $S_0$", "a non-inertial frame $S_0$")
    assert "holds" not in _verdicts(text, 6)


def test_a_body_fixed_frame_is_the_body_frame():
    text = _correct().replace("the body frame $S$", "the body-fixed frame $S$")
    assert _verdicts(text, 6) == ["holds"] and _verdicts(text, 12) == ["holds"]


def test_a_label_whose_own_index_is_braced_is_the_same_frame():
    assert _verdicts(_correct().replace("]_{S_0}", "]_{S_{0}}"), 6) == ["holds"]
