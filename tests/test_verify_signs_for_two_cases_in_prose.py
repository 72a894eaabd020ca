"""The notes reader on a formula written with ± for two cases the prose names just before it
("setting $\\theta=0$ or $\\pi$ gives"): the upper signs read in the first case, the lower in the
second (or the other way round when only that pairing holds), each with the case set
(`derive.lecture.two_cases`)."""
import kept_readings as kept

TURNS = ("# Euler angles\n\n"
         "The z-x-z angles: $\\phi$ about $z$, $\\theta$ about the line of nodes, $\\psi$ about the body's axis.\n\n"
         "$$U_1 = \\begin{pmatrix} \\cos \\phi & -\\sin \\phi & 0 \\\\ \\sin \\phi & \\cos \\phi & 0 \\\\ 0 & 0 & 1 "
         "\\end{pmatrix},\\quad U_2 = \\begin{pmatrix} 1 & 0 & 0 \\\\ 0 & \\cos \\theta & -\\sin \\theta \\\\ 0 & "
         "\\sin \\theta & \\cos \\theta \\end{pmatrix},\\quad U_3 = \\begin{pmatrix} \\cos \\psi & -\\sin \\psi & 0 "
         "\\\\ \\sin \\psi & \\cos \\psi & 0 \\\\ 0 & 0 & 1 \\end{pmatrix}$$\n\n"
         "$$U = U_1 U_2 U_3$$\n\n"
         "Where the angles lock, setting $\\theta=0$ or $\\pi$ gives\n\n")
LOCKED = ("U = \\begin{pmatrix} \\cos(\\phi \\pm \\psi) & \\mp\\sin(\\phi \\pm \\psi) & 0 \\\\ \\sin(\\phi \\pm \\psi) "
          "& \\pm\\cos(\\phi \\pm \\psi) & 0 \\\\ 0 & 0 & \\pm 1 \\end{pmatrix}")


def _verdicts(display, before=TURNS):
    text = before + "$$" + display + "$$\n"
    return [c.verdict for c in kept.by_line(text).get(kept.line_of(text, "$$" + display), [])]


def test_a_matrix_with_its_signs_for_the_two_locked_cases_holds():
    assert _verdicts(LOCKED) == ["holds", "holds"]


def test_a_lower_sign_that_does_not_give_the_second_case_is_flagged():
    slipped = LOCKED.replace("0 & 0 & \\pm 1", "0 & 0 & 1")
    assert "fails" in _verdicts(slipped)


def test_the_cases_named_the_other_way_round_still_hold():
    swapped = TURNS.replace("$\\theta=0$ or $\\pi$", "$\\theta=\\pi$ or $0$")
    assert _verdicts(LOCKED, swapped) == ["holds", "holds"]


def test_a_sign_with_no_cases_named_is_left_as_it_was():
    plain = TURNS.replace("setting $\\theta=0$ or $\\pi$ gives", "one gets")
    assert not {"holds", "fails", "typo"} & set(_verdicts(LOCKED, plain))
