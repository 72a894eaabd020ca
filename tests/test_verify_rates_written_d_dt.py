"""A rate written d/dt reads as the dotted rate: the same symbol, so the equations of motion the
reader keeps, the rates a text sets and what it writes back see one rate however it is written."""
from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp

import kept_readings
from derive.lecture import latex as lx
from derive.lecture.spellings import spellings, written_back
from derive.lecture.written_rates import opens_with_rate
from derive.symbolic.lagrangian import ACCELS
from derive.symbolic.rotations import RATES

REAL = Path(__file__).parent / "notes" / "real"

FREE_TOP = r"""# The free symmetric top

If $I_1 = I_2$ and $\tau = 0$, the third equation gives a constant $\tilde{\omega}_3$ and with

$$\Omega \equiv \tilde{\omega}_3 \frac{I_3 - I_1}{I_1}$$

the other two read

$$RATE1 = -\Omega \tilde{\omega}_2$$

$$RATE2 = SIGN\Omega \tilde{\omega}_1$$

They are solved by a rotation of the body components at the rate $\Omega$:

$$\tilde{\omega}_1(t) = A \cos(\Omega t + \varphi)$$

$$\tilde{\omega}_2(t) = A \sin(\Omega t + \varphi)$$
"""

SPELLINGS = {
    "frac": r"\frac{d \tilde{\omega}_{i}}{dt}",
    "upright frac": r"\frac{\mathrm{d}\tilde{\omega}_{i}}{\mathrm{d}t}",
    "slash": r"d\tilde{\omega}_{i}/dt",
    "operator": r"\frac{d}{dt}\left(\tilde{\omega}_{i}\right)",
}


def _free_top(spelling: str, sign: str = "") -> list:
    text = FREE_TOP.replace("RATE1", spelling.replace("{i}", "1")).replace("RATE2", spelling.replace("{i}", "2"))
    return kept_readings.check_text(text.replace("SIGN", sign))


def _value(latex: str):
    return lx.parse(latex).members[0].value


@pytest.mark.parametrize("spelling", list(SPELLINGS.values()), ids=list(SPELLINGS))
def test_a_solution_after_equations_of_motion_written_d_dt_holds(spelling):
    claims = _free_top(spelling)
    assert [(c.line, c.verdict) for c in claims if c.kind == "solution"] == [(15, "holds"), (17, "holds")]
    assert all(c.verdict == "holds" for c in claims)


def test_a_slip_in_an_equation_of_motion_written_d_dt_is_flagged_in_its_notation():
    claims = _free_top(SPELLINGS["frac"], sign="-")
    (slip,) = [c for c in claims if c.line == 11]
    assert slip.verdict == "typo"
    assert r"\frac{d \tilde{\omega}_2}{dt}" in slip.correction and r"\dot" not in slip.correction
    assert kept_readings.check_text(FREE_TOP.replace("RATE1", r"\dot{\tilde{\omega}}_1").replace(
        "RATE2", r"\dot{\tilde{\omega}}_2").replace("SIGN", "-"))[2].verdict == "typo"     # as with dots


@pytest.mark.parametrize("written, dotted", [
    (r"\frac{d\alpha}{dt}", r"\dot\alpha"),
    (r"\frac{\mathrm d \tilde\omega_1}{\mathrm d t}", r"\dot{\tilde\omega}_1"),
    (r"d\tilde\omega_2/dt", r"\dot{\tilde\omega}_2"),
    (r"\frac{d}{dt}\tilde\omega_3", r"\dot{\tilde\omega}_3"),
    (r"\frac{d}{dt}\left(\beta\right)", r"\dot\beta"),
    (r"\frac{d^2 \gamma}{dt^2}", r"\ddot\gamma"),
    (r"\frac{d^{2}\beta}{d t^{2}}", r"\ddot\beta"),
    (r"d^2\alpha/dt^2", r"\ddot\alpha"),
    (r"\frac{d^2}{dt^2}\alpha", r"\ddot\alpha"),
])
def test_a_rate_written_d_dt_is_the_dotted_symbol(written, dotted):
    assert _value(written + " = 0") == _value(dotted + " = 0")


def test_a_rate_written_d_dt_in_a_product_and_a_partial_derivative():
    assert _value(r"I_1 d\tilde\omega_1/dt \sin\beta = 0") == _value(r"I_1 \dot{\tilde\omega}_1 \sin\beta = 0")
    momentum = _value(r"\frac{\partial L}{\partial \dot\alpha} = 0")
    assert _value(r"\frac{\partial L}{\partial \frac{d\alpha}{dt}} = 0") == momentum
    gamma = _value(r"\frac{\partial L}{\partial \dot\gamma} = 0")
    assert _value(r"\frac{\partial L}{\partial (d\gamma/dt)} = 0") == gamma


def test_a_quantitys_rate_is_read_as_its_dot_and_a_constants_as_a_derivative():
    opened = lx.Vocabulary(open=True)
    assert lx.parse(r"\frac{dE}{dt} = 0", opened).members[0].value == lx.parse(r"\dot E = 0", opened).members[0].value
    assert _value(r"\frac{d p_\gamma}{dt} = 0") == lx.DT(lx.p_gamma_sym())
    with pytest.raises(lx.NotRead):     # the orders of d and dt differ: no rate
        _value(r"\frac{d^2 \alpha}{dt} = 0")


def test_a_conserved_momentum_in_d_dt_holds_and_the_energys_rate_is_not_called_wrong():
    claims = kept_readings.check_text("# Heavy top\n\n$$\\frac{d p_\\alpha}{dt} = 0$$\n\n$$\\frac{dE}{dt} = 0$$\n")
    assert [c.verdict for c in claims] == ["holds", "unchecked"]


PENDULUM = r"""# A pendulum

A bob on a light rod of length $l$ swings in a plane; $\theta$ is its angle from the vertical.

$$L(\theta, RATE) = \frac{m l^2}{2} \left(RATE\right)^2 + m g l \cos\theta$$

$$\frac{d}{dt}\frac{\partial L}{\partial (RATE)} = \frac{\partial L}{\partial\theta}$$

$$m l^2 SECOND = - m g l \sin\theta$$

$$m l^2 SECOND = m g l \sin\theta$$
"""


@pytest.mark.parametrize("rate, second", [(r"\frac{d\theta}{dt}", r"\frac{d^2\theta}{dt^2}"),
                                          (r"d\theta/dt", r"d^2\theta/dt^2")])
def test_a_one_coordinate_text_in_d_dt_reads_as_with_dots(rate, second):
    def verdicts(r, s):
        return [c.verdict for c in kept_readings.check_text(PENDULUM.replace("RATE", r).replace("SECOND", s))]
    assert verdicts(rate, second) == verdicts(r"\dot\theta", r"\ddot\theta") == ["unchecked", "holds", "holds", "fails"]


def test_a_rate_written_d_dt_at_a_time_is_the_texts_value_as_with_a_dot():
    opened = lx.Vocabulary(open=True)
    at = lambda latex: lx.parse(latex, opened).members[1].value  # noqa: E731
    assert at(r"x = \frac{d\omega_y}{dt}(0)") == at(r"x = \dot\omega_y(0)")


def test_a_statement_opening_with_a_rate_written_d_dt_is_a_rate_first():
    assert opens_with_rate(r"\frac{d\phi}{dt} = \omega_p")
    assert opens_with_rate(r"\dot\phi = \omega_p") and opens_with_rate(r"d\psi/dt = \omega_s")
    assert not opens_with_rate(r"\frac{d}{dt}\left(I_1\omega_1\right) = 0")
    assert not opens_with_rate(r"\frac{d\phi}{dt}") and not opens_with_rate(r"\phi = \omega_p t")


def test_a_rate_written_d_dt_is_written_back_as_written():
    spelled = spellings(r"I_1 \frac{\mathrm d \tilde\omega_1}{\mathrm dt} + d\alpha/dt + \frac{d^2\beta}{dt^2} = 0",
                        lx.Vocabulary(), {*lx.WD, *RATES, *ACCELS})
    assert spelled == {lx.WD[0]: r"\frac{\mathrm d \tilde\omega_1}{\mathrm dt}", RATES[0]: r"d\alpha/dt",
                       ACCELS[1]: r"\frac{d^2\beta}{dt^2}"}
    squared = written_back(sp.latex(3 * lx.WD[0] ** 2, symbol_names=spelled), spelled)
    assert squared == r"3 \left(\frac{\mathrm d \tilde\omega_1}{\mathrm dt}\right)^{2}"


def test_a_text_writing_d_dt_gets_its_correction_with_its_rates():
    """A second-order chain of a real text in d/dt (its slip: I₃₃ for I₂₂ in a denominator): the
    correction keeps the text's dω₂/dt, and the index edit that would only make the member
    unreadable (I₁₃, a symbol the display never writes) is not offered."""
    claims = kept_readings.check_notes(REAL / "zhao-ucas-notes-euler-equations-intermediate-axis.tex")
    (slip,) = [c for c in claims if c.line == 167 and c.verdict == "typo"]
    assert r"\frac{\mathrm d \boldsymbol \omega_2}{\mathrm dt}" in slip.correction
    assert r"{\mathrm I_{22}}" in slip.correction and "I_{13}" not in slip.correction


def test_a_transpose_of_a_name_without_a_shape_is_left_unchecked():
    claims = kept_readings.check_text(r"$$\frac{d}{dt}\mathrm{KE} = \frac{1}{2}\left(M\left(\frac{do}{dt}\right)^T"
                                      r"\frac{d^2 o}{dt^2} + M\left(\frac{d^2 o}{dt^2}\right)^T\frac{do}{dt}\right)"
                                      r" = M\left(\frac{do}{dt}\right)^T\frac{d^2 o}{dt^2}$$" + "\n")
    assert [c.verdict for c in claims] == ["unchecked"]


def test_the_operator_d_dt_before_a_bracket_is_the_rate_of_the_bracket_times_what_follows():
    assert _value(r"\frac{d}{dt}\left(\alpha\right) \sin\beta = 0") == _value(r"\dot\alpha \sin\beta = 0")
    assert _value(r"\frac{d}{dt}(\beta) \cos\alpha + \frac{d}{dt}(\gamma) = 0") == \
        _value(r"\dot\beta \cos\alpha + \dot\gamma = 0")


@pytest.mark.parametrize("unclear", [
    r"\frac{d}{dt}\alpha \sin\beta = 0",          # the rate of α times sin β, or of the product
    r"\frac{d}{dt}\left(\beta\right)^2 = 0",      # the rate squared, or the rate of the square
])
def test_the_operator_d_dt_before_a_product_of_a_rate_is_not_read(unclear):
    with pytest.raises(lx.NotRead):
        _value(unclear)


def test_a_product_of_constants_after_the_operator_d_dt_is_its_rate():
    assert _value(r"\frac{d}{dt} I_1 \tilde\omega_1 = 0") == _value(r"\frac{d}{dt}\left(I_1 \tilde\omega_1\right) = 0")
