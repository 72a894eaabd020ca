"""A gyroscope's names given only in prose ("spinning at $\\omega_s$", "the precession rate is"),
judged against the heavy symmetric top the reader derives (derive/lecture/gyro_names.py,
derive/lecture/spin_threshold.py, derive/lecture/fast_top.py, derive/lecture/rereading.py).

The notes are written for these tests the way equation sheets on gyroscopes write them: each
name said once in a sentence, the formulas in those names only.
"""
from derive.lecture import names as nm
from derive.lecture.notes_check import check_text

HEAD = """---
convention: z-x-z
angles: [\\phi, \\theta, \\psi]
---

# Gyroscope

For a spinning top of mass $M$ whose centre of mass is at distance $r$ from the pivot, spinning at $\\omega_s$ about its axis with moment $I_z$ there, the precession rate is

$$\\Omega_{p} = \\frac{M g r}{I_{z} \\omega_{s}}$$

and the spin must exceed a threshold for the top not to tip over:

"""


def verdicts(display: str, head: str = HEAD) -> list:
    return [(c.line, c.verdict, c.why) for c in check_text(head + "$$" + display + "$$\n")]


def test_the_spin_rate_the_precession_rate_and_the_moment_about_the_spin_axis_are_learned_from_prose():
    names = nm.learn("A rotor of moment $I_s$ about its spin axis, spinning at $\\omega_s$, with the nutation "
                     "frequency $\\omega_n$ and the precession rate $\\Omega_p$.")
    assert names.symbols[("I", "s")].startswith("axial moment")
    assert names.symbols[("omega", "s")] == "spin rate"
    assert names.symbols[("omega", "n")] == "nutation rate"
    assert names.symbols[("Omega", "p")] == "precession rate"


def test_a_precession_rate_named_in_prose_is_judged_against_the_fast_top():
    got = verdicts("\\omega_{s} > \\frac{2\\sqrt{I_1 M g r}}{I_{z}}")
    assert got[0][:2] == (10, "holds") and "fast" in got[0][2], got


def test_a_correct_spin_threshold_in_prose_names_holds_squared_or_solved():
    for right in ("\\omega_{s} > \\frac{2\\sqrt{I_1 M g r}}{I_{z}}", "I_z^2\\omega_{s}^2 \\geq 4 I_1 M g r",
                  "\\omega_{s}^2 > \\frac{4 I_1 M g r}{I_{z}^2}"):
        got = verdicts(right)
        assert [v for _, v, _ in got] == ["holds", "holds"], (right, got)
        assert "threshold" in got[1][2]


def test_a_spin_threshold_without_the_transverse_moment_is_flagged_once_the_names_are_confirmed():
    got = verdicts("\\omega_{s} > \\sqrt{\\frac{M g r}{I_{z}}}")
    assert got[1][1] == "fails", got
    assert "confirmed by" in got[1][2] and "stability condition" in got[1][2]


def test_a_wrong_factor_in_the_fast_tops_rate_in_prose_names_is_never_called_right():
    head = HEAD.replace("$$\\Omega_{p} = \\frac{M g r}{I_{z} \\omega_{s}}$$", "$$\\Omega_{p} = \\frac{M g r}{2 I_{z} \\omega_{s}}$$")
    got = verdicts("\\omega_{s} > \\sqrt{\\frac{M g r}{I_{z}}}", head)
    assert "holds" not in [v for _, v, _ in got[:1]], got
    assert got[1][1] == "unchecked", got      # no formula held with those names: the reading is not confirmed


def test_a_formula_in_a_symbol_the_held_one_did_not_use_stays_unchecked():
    # a plain L is not the angular momentum the prose named (the reader takes it for the Lagrangian)
    got = verdicts("\\Omega_{p} = \\frac{M g r}{L}")
    assert got[1][1] == "unchecked", got
