"""`derive verify` on notes written for it: tests/notes/ (issue 19, steps 5-6).

* rigid-body-zyz.md — the lecture's derivation in its own convention (z-y-z, α β γ, body
  components with a tilde), written correctly: every display holds.
* Planted errors — one single edit at a time (a sign, an index, sin ↔ cos, a factor of 2, a
  power, a wrong moment), made on the LaTeX text of one display: the edited display must be
  flagged (typo or fails) and no other display may be.
* rigid-body-zxz.md — the same physics in Goldstein's z-x-z convention (φ θ ψ): it holds under its
  front matter and fails when read in the z-y-z convention.
"""
from pathlib import Path

from derive.lecture import notes_check as nc

NOTES = Path(__file__).parent / "notes"
ZYZ = NOTES / "rigid-body-zyz.md"
FLAGGED = ("typo", "fails")


def test_own_notes_every_display_holds():
    claims = nc.check_notes(ZYZ)
    checked = [c for c in claims if c.verdict != "unchecked"]
    assert len(checked) >= 20, len(checked)
    assert [c for c in claims if c.verdict in FLAGGED] == []
    # every display of the file is a claim that holds (none left unchecked)
    displays = {i + 1 for i, line in enumerate(ZYZ.read_text(encoding="utf-8").split("\n")) if line.startswith("$$")}
    held = {c.line for c in claims if c.verdict == "holds"}
    assert displays <= held, sorted(displays - held)
    kinds = {c.kind for c in checked}
    assert {"definition", "approximation", "inequality", "equation of motion", "solution",
            "steady precession"} <= kinds, kinds


def test_reader_assumption_at_the_opening_of_a_sentence():
    from derive.lecture import notes as nt
    text = ("# Top\nFor a symmetric top, $I_1 = I_2$, and so on. The energy is $E = T + V$ here.\n\n"
            "If the spin is large, with\n\n$$\\Omega \\equiv \\tilde{\\omega}_3$$\n")
    kinds = [(i.kind, i.latex) for i in nt.parse_notes(text).items if i.kind != "heading"]
    assert kinds == [("assumption", "I_1 = I_2"), ("inline", "E = T + V"), ("display", "\\Omega \\equiv \\tilde{\\omega}_3")]


def test_steady_precession_and_squared_stability_condition():
    base = "# Steady precession\n\nFor a steady precession, $\\dot{\\beta} = 0$, so\n\n$$M g l = %s$$\n"
    right = nc.check_text(base % "\\dot{\\alpha} \\left(p_{\\gamma} - I_1 \\dot{\\alpha} \\cos\\beta\\right)")
    wrong = nc.check_text(base % "\\dot{\\alpha} \\left(p_{\\gamma} + I_1 \\dot{\\alpha} \\cos\\beta\\right)")
    assert [(c.kind, c.verdict) for c in right] == [("steady precession", "holds")]
    assert [(c.kind, c.verdict) for c in wrong] == [("steady precession", "typo")]
    stab = "# Sleeping\n\n$$p_{\\gamma}^2 %s 4 M g l %s$$\n"
    assert [c.verdict for c in nc.check_text(stab % ("\\ge", "I_1"))] == ["holds"]
    wrong_moment = nc.check_text(stab % ("\\ge", "I_3"))
    assert [c.verdict for c in wrong_moment] == ["typo"] and "I_{1}" in wrong_moment[0].correction
    assert [c.verdict for c in nc.check_text(stab % ("\\le", "I_1"))] == ["typo"]
