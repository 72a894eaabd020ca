"""The notes reader on ``\\tan^{-1}``, ``\\sin^{-1}``, ``\\cos^{-1}``: the power −1 on a function's name is
its inverse, as texts write it (the arctangent), never the reciprocal, so a worked angle holds to the
digits written and a wrong one is still flagged; a square on the name stays a square."""
import sympy as sp

import kept_readings as kept
from derive.lecture import latex as lx

verdicts, line_of = kept.verdicts_by_line, kept.line_of


def test_an_inverse_written_as_a_power_minus_one_is_the_inverse_function():
    vocab = lx.Vocabulary(open=True)
    for latex, want in ((r"\tan^{-1}(\sqrt{3})", sp.pi / 3), (r"\sin^{-1}\left(\frac{1}{2}\right)", sp.pi / 6),
                        (r"\cos^{-1} 0", sp.pi / 2), (r"\sin^{2}(\pi/4)", sp.Rational(1, 2))):
        assert sp.simplify(lx.parse(latex, vocab).members[0].value - want) == 0, latex


def test_a_worked_arctangent_holds_and_a_wrong_one_is_flagged():
    text = ("# Angle\n\n$$\\theta = \\tan^{-1}\\left(\\frac{75}{125}\\right) = 0.5404$$\n\n"
            "$$\\phi = \\tan^{-1}\\left(\\frac{75}{125}\\right) = 1.4617$$\n")
    got = verdicts(text)
    assert "holds" in got[line_of(text, "$$\\theta")] and not got[line_of(text, "$$\\theta")] & {"typo", "fails"}
    assert got[line_of(text, "$$\\phi")] & {"typo", "fails"}
