"""The notes reader on a thin, medium or negative space between factors (``\\,``, ``\\;``, ``\\!``): the
forms it recognises read the same spaced — a theorem a text states, the moment of a force about an
axis with its bracket spaced off, a frame's prescript spaced off its vector, and the arithmetic of
numbers written with spacing — and a form that is not the rule is still not taken for it."""
import pytest

import kept_readings as kept
from derive.lecture.arithmetic import arithmetic

SPACES = ("\\,", "\\;", "\\!")


def _at(text: str, line: int) -> set:
    return {c.verdict for c in kept.check_text(text) if c.line == line}


@pytest.mark.parametrize("space", SPACES)
def test_a_theorem_stated_with_spacing_between_its_factors_is_recognised(space):
    head = "# Moments\n\nA body in plane motion, its centre of mass $C$:\n\n"
    koenig = f"$$T = \\frac{{1}}{{2}} {space} m {space} v_c^2 + \\frac{{1}}{{2}} {space} J_C {space} \\omega^2$$\n"
    assert _at(head + koenig, 5) == {"holds"}
    assert "holds" not in _at(head + koenig.replace("v_c^2", "v_c"), 5)
    about = f"$$T=\\frac{{1}}{{2}}\\mathbf{{\\omega {space} H_B}}$$\n"
    assert _at(head + about, 5) == {"holds"}


_FIXED_AXIS = "# Fixed axis\n\nA body turns about the fixed $z$ axis.\n\n$$L_z = \\omega \\sum_i m_i r_i^2 = J_z \\omega$$\n\n"


@pytest.mark.parametrize("space", SPACES)
def test_the_moment_of_a_force_with_its_bracket_spaced_off_is_the_moment_applied_to_the_force(space):
    torques = f"\\sum_{{i=1}}^n M_z {space} (\\vec F_i)"
    assert _at(_FIXED_AXIS + f"$$J_z \\alpha = {torques}$$\n", 7) == {"holds"}
    assert _at(_FIXED_AXIS + f"$$2 J_z \\alpha = {torques}$$\n", 7) & {"typo", "fails"}


@pytest.mark.parametrize("space", SPACES)
def test_a_frames_prescript_spaced_off_its_vector_is_still_the_frame(space):
    head = "Particles $P_i$ of masses $m_i$, at positions relative to a point $O$.\n\n"
    holds = f"$${{}}^A {space} \\bar{{H}}^{{B/B_o}} = \\breve{{I}}^{{B/B_o}} \\cdot {{}}^A {space} \\bar{{\\omega}}^B$$\n"
    assert _at(head + holds, 3) == {"holds"}
    halved = holds.replace("= \\breve", "= \\frac{1}{2} \\breve")
    assert _at(head + halved, 3) & {"typo", "fails"}


def test_the_arithmetic_of_numbers_written_with_spacing_is_worked_and_a_list_is_not():
    assert [v for v, _ in arithmetic(r"x = \frac{1}{2} \, 4 \; \cdot 3 = 6")] == ["holds"]
    assert [v for v, _ in arithmetic(r"x = \frac{1}{2} \, 4 = 7")] == ["fails"]
    assert arithmetic(r"x = 1, 2 = 3") == []
