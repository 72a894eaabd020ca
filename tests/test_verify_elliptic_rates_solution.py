"""Body rates written in Jacobi's elliptic functions (derive/lecture/elliptic_solution.py): a row
ωᵢ = A sn(λt) is a claimed solution of Euler's free equations, never a definition of the model's ωᵢ
compared with it; a row the reader cannot tie stays unchecked naming what stopped it, and a formula
holding SymPy's infinity (an edit the reader tries) has no value rather than raising."""
import mpmath
import pytest
import sympy as sp

import kept_readings as kept
from derive.lecture import mp_values

HEAD = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n## The free asymmetric body\n\nA body turns about its centre of mass with no torque; $L$ is the constant "
        "magnitude of its angular momentum $\\mathbf{L}$ and $T$ its constant kinetic energy. Euler's equations without a torque, with $I_1 < I_2 < I_3$:\n\n"
        "$$I_1\\dot\\omega_1 = (I_2-I_3)\\omega_2\\omega_3$$\n\nThe two integrals:\n\n"
        "$$L^2 = I_1^2\\omega_1^2 + I_2^2\\omega_2^2 + I_3^2\\omega_3^2$$\n\n$$2T = I_1\\omega_1^2 + I_2\\omega_2^2 + I_3\\omega_3^2$$\n\nLet\n\n$$\\tau = \\lambda t$$\n\n"
        "$$k^2 = \\frac{(I_2-I_1)(2I_3T-L^2)}{(I_3-I_2)(L^2-2I_1T)}$$\n\n")
ARG = "\\left(\\sqrt{\\frac{(I_3-I_2)(L^2-2I_1T)}{I_1I_2I_3}}t\\right)"
ROWS = ("\\omega_1 &= \\sqrt{\\frac{2I_3T-L^2}{I_1(I_3-I_1)}}\\cn " + ARG + " \\\\\n"
        "\\omega_2 &= \\sqrt{\\frac{2I_3T-L^2}{I_2(I_3-I_2)}}\\sn " + ARG + " \\\\\n"
        "\\omega_3 &= \\sqrt{\\frac{L^2-2I_1T}{I_3(I_3-I_1)}}\\dn " + ARG + "\n")


def claims(rows: str) -> list:
    text = HEAD + "The solution:\n\n$$\\begin{aligned}\n" + rows + "\\end{aligned}$$\n"
    return [c for c in kept.check_text(text) if c.latex.startswith("\\omega_")]


def test_rates_in_elliptic_functions_that_solve_euler_equations_hold():
    got = claims(ROWS)
    assert [(c.kind, c.verdict) for c in got] == [("solution", "holds")] * 3


def test_a_planted_amplitude_slip_is_not_taken_as_holding_nor_as_a_definition():
    got = claims(ROWS.replace("{I_2(I_3-I_2)}}\\sn", "{I_1(I_3-I_2)}}\\sn"))
    assert len(got) == 3
    assert all(c.kind == "solution" and c.verdict == "unchecked" for c in got)
    assert "not shown to solve them" in got[0].why


def test_a_modulus_the_text_never_gives_leaves_the_rows_unchecked():
    text = HEAD.split("$$k^2")[0] + "The solution:\n\n$$\\begin{aligned}\n" + ROWS + "\\end{aligned}$$\n"
    got = [c for c in kept.check_text(text) if c.latex.startswith("\\omega_")]
    assert [c.verdict for c in got] == ["unchecked"] * 3
    assert "modulus" in got[0].why


def test_a_rate_alone_is_left_unchecked_naming_the_missing_rates():
    got = claims(ROWS.split(" \\\\\n")[1] + "\n")
    assert [c.verdict for c in got] == ["unchecked"]
    assert "all three body rates" in got[0].why


def test_a_formula_holding_an_infinity_has_no_value():
    x = sp.Symbol("x")
    f = mp_values.evaluator([x], [x * sp.zoo])
    with pytest.raises(ZeroDivisionError), mpmath.workdps(15):
        f(mpmath.mpf(1))
