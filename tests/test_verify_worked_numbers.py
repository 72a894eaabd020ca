"""A worked example's numbers: units after a number, a thousands separator, and the arithmetic
between the plain numbers of a chain (derive/lecture/units.py, derive/lecture/arithmetic.py)."""
import sympy as sp

import kept_readings as kept

from derive.lecture.arithmetic import arithmetic
from derive.lecture.statements import statements
from derive.lecture.units import plain_numbers
from derive.lecture.worked_values import unchecked


def test_a_unit_after_a_number_is_dropped_and_a_subscript_word_stays():
    text = plain_numbers(r"I_z = \frac{1}{2}(2.50\text{ kg})(0.18\text{ m})^2 = 0.04050\text{ kg}\cdot\text{m}^2")
    assert r"\text" not in text and "0.04050" in text
    assert plain_numbers(r"r_{\text{cm}} m g = 9.81\text{ m/s}^2") == r"r_{\text{cm}} m g = 9.81 "
    assert plain_numbers(r"|\vec{L}| = \text{constante}") == r"|\vec{L}| = \text{constante}"


def test_a_thousands_separator_and_a_product_of_two_numbers_are_read_as_numbers():
    assert plain_numbers(r"\frac{10{,}000 \times 2\pi}{60}") == r"\frac{10000 \cdot 2\pi}{60}"
    assert r"\times" in plain_numbers(r"\vec{r} \times \vec{F}")


def test_the_arithmetic_of_a_chain_holds_to_the_digits_it_writes():
    assert [v for v, _ in arithmetic(r"\tau = (0.25)(2.50)(9.81) = 6.13125 \approx 6.13")] == ["holds", "holds"]
    assert [v for v, _ in arithmetic(r"\omega_n = \frac{L}{I_x} = \frac{1.01}{0.17650} \approx 5.72")] == ["holds"]


def test_an_arithmetic_slip_fails_and_a_value_off_in_its_last_digits_is_left_unchecked():
    assert [v for v, _ in arithmetic(r"\omega_n = \frac{1.01}{0.17650} \approx 5.27")] == ["fails"]
    assert [v for v, _ in arithmetic(r"\omega_n = \frac{1.01}{0.17650} \approx 5.75")] == ["unchecked"]


def test_a_space_before_a_decimal_point_is_not_a_product():
    # math mode sets no space there: 0 .8976 is 0.8976, never 0 times .8976
    assert "0.8976" in plain_numbers(r"\Omega_1= i0 .8976\omega_1")
    assert plain_numbers(r"x = 2 y") == r"x = 2 y"


def test_links_with_symbols_are_not_judged_by_the_numbers():
    # the symbols' values are not substituted: L may be a later "effective" value
    assert arithmetic(r"\omega_n = \frac{L}{I_x} = 5.72") == []


def test_a_worked_example_with_units_is_checked_in_notes_and_a_wrong_product_is_flagged():
    good = "$$L = I_z \\omega_s = (0.04050\\text{ kg}\\cdot\\text{m}^2)(1047.19755\\text{ rad/s}) \\approx 42.4115\\text{ N}\\cdot\\text{m}\\cdot\\text{s}$$\n"
    claims = kept.check_text(good)
    assert any(c.kind == "arithmetic" and c.verdict == "holds" for c in claims)
    assert not any(c.verdict in ("typo", "fails") for c in claims)
    bad = good.replace("42.4115", "24.4115")
    assert any(c.kind == "arithmetic" and c.verdict == "fails" for c in kept.check_text(bad))


def test_a_rate_written_after_its_function_of_time_holds_as_its_derivative_and_is_never_flagged():
    head = ("Here $\\Omega_p$ and $\\omega_n$ are constants.\n\n"
            "$$\\phi(t) = \\Omega_p t - \\frac{\\Omega_p}{\\omega_n} \\sin(\\omega_n t)$$\n\n")
    good = kept.check_text(head + "$$\\dot{\\phi}(t) = \\Omega_p \\left[1 - \\cos(\\omega_n t)\\right]$$\n")
    assert any(c.kind == "rate" and c.verdict == "holds" for c in good)
    off = kept.check_text(head + "$$\\dot{\\phi}(t) = \\Omega_p \\left[1 + \\cos(\\omega_n t)\\right]$$\n")
    assert any(c.kind == "rate" and c.verdict == "unchecked" for c in off)
    assert not any(c.verdict in ("typo", "fails") for c in off)


def test_a_rate_with_its_dot_over_an_unbraced_symbol_is_checked_as_the_derivative_of_the_function():
    head = ("Here $\\Omega_p$ and $\\omega_n$ are constants.\n\n"
            "$$\\phi(t) = \\Omega_p t - \\frac{\\Omega_p}{\\omega_n} \\sin(\\omega_n t)$$\n\n")
    good = kept.check_text(head + "$$\\dot\\phi(t) = \\Omega_p \\left[1 - \\cos(\\omega_n t)\\right]$$\n")
    assert any(c.kind == "rate" and c.verdict == "holds" for c in good)
    off = kept.check_text(head + "$$\\dot\\phi(t) = \\Omega_p \\left[1 + \\cos(\\omega_n t)\\right]$$\n")
    assert not any(c.verdict in ("holds", "typo", "fails") for c in off)


def test_the_torque_law_with_a_torque_labelled_by_its_source_holds_and_a_factor_on_it_does_not():
    text = "The weight's torque about the pivot is $\\vec{\\tau}_g$.\n\n$$\\frac{d\\vec{L}}{dt} = \\vec{\\tau}_g$$\n"
    assert [c.verdict for c in kept.check_text(text)] == ["holds"]
    assert "holds" not in [c.verdict for c in kept.check_text(text.replace("= \\vec{\\tau}_g$$", "= 2\\vec{\\tau}_g$$"))]


def test_a_scalar_product_set_to_zero_is_the_texts_perpendicularity_not_a_slip():
    text = ("The weight's torque $\\vec{\\tau}_g$ is perpendicular to $\\vec{L}$.\n\n"
            "$$\\frac{d\\vec{L}}{dt} = \\vec{\\tau}_g$$\n\n"
            "$$\\frac{d}{dt}|\\vec{L}|^2 = 2 \\vec{L} \\cdot \\frac{d\\vec{L}}{dt} = 2 \\vec{L} \\cdot \\vec{\\tau}_g = 0$$\n")
    claims = kept.check_text(text)
    assert not any(c.verdict in ("typo", "fails") for c in claims)
    assert any(c.line == 5 and c.verdict == "holds" for c in claims)


def test_the_rate_of_a_squared_length_written_alone_is_left_unchecked_not_an_error():
    claims = kept.check_text("$$\\frac{d}{dt}|\\vec{L}|^2 = 2 \\vec{L} \\cdot \\frac{d\\vec{L}}{dt}$$\n")
    assert [c.verdict for c in claims] == ["unchecked"]


def test_a_member_in_symbols_the_text_gave_numbers_is_worked_out_and_only_ever_confirmed():
    head = "A disk on a support:\n\n- $r=0.1~m$\n"
    good = kept.check_text(head + "- $d = 2r = 0.2~m$\n")
    assert any(c.kind == "arithmetic" and c.verdict == "holds" and "values the text gave" in c.why for c in good)
    off = kept.check_text(head + "- $d = 2r = 0.5~m$\n")        # r may mean something else there
    assert not any(c.kind == "arithmetic" for c in off)
    assert not any(c.verdict in ("typo", "fails") for c in off)


_FREQUENCY = ("A body with principal moments $I_1$, $I_2$, $I_3$ spins about a principal axis; a small "
              "disturbance oscillates with\n\n"
              "$$\n\\Omega_1 = \\omega_1 \\sqrt{\\frac{ (I_1 - I_3) (I_1 - I_2)}{ I_2I_3}}\n$$\n\n"
              "For a racquet, whose moments a table gives, the frequency is\n\n")


def test_a_worked_value_beside_a_formula_in_moments_the_text_gives_no_value_is_not_flagged():
    claims = kept.check_text(_FREQUENCY + "$$\n\\Omega_1= 0 .8976\\omega_1\n$$\n")
    worked = [c for c in claims if c.line == 9]
    assert worked and all(c.verdict == "unchecked" and "a worked value" in c.why for c in worked)
    assert "I_1" in worked[0].why or "I_{1}" in worked[0].why


def test_the_same_statement_without_a_decimal_number_is_still_compared():
    claims = kept.check_text(_FREQUENCY + "$$\n\\Omega_1= 2\\omega_1\n$$\n")
    assert any(c.line == 9 and c.verdict in ("typo", "fails") for c in claims)


def test_a_proportion_is_one_statement_never_a_label_before_a_setting_of_its_last_name():
    assert statements(r"I_{11} : I_{22} : I_{33} = 2.5833 : 0.2550 : 2.8333") == \
        [r"I_{11} : I_{22} : I_{33} = 2.5833 : 0.2550 : 2.8333"]
    assert statements(r"\theta: \omega_z = \omega_3") == [r"\omega_z = \omega_3"]      # a label stays one
    claims = kept.check_text("The moments are in the ratio $I_{11} : I_{22} : I_{33} = 2.5833 : 0.2550 : 2.8333$.\n")
    assert not any(c.kind == "setting" for c in claims)


def test_i_in_an_exponent_of_e_is_the_imaginary_unit_and_an_index_i_stays_a_letter():
    assert plain_numbers(r"\lambda (t) = Ae^{i\Omega t} + Be^{-i\Omega t}") == \
        r"\lambda (t) = Ae^{\sqrt{-1}\Omega t} + Be^{-\sqrt{-1}\Omega t}"
    assert plain_numbers(r"\sum_i m_i x_i + \angle^{i}") == r"\sum_i m_i x_i + \angle^{i}"


def test_a_worked_chain_that_ends_with_its_sign_holds_and_a_sign_the_wrong_way_round_fails():
    assert [v for v, _ in arithmetic(r"(I_2 - I_3) = 2.4 - 4.2 = -1.8 < 0")] == ["holds", "holds"]
    assert [v for v, _ in arithmetic(r"(I_2 - I_3)(I_1 - I_2) = (-1.8)(-1.4) = +2.52 > 0")] == ["holds", "holds"]
    assert [v for v, _ in arithmetic(r"k = 2.4 - 4.2 = -1.8 \ge 0")] == ["holds", "fails"]
    # equal to the digits written: no verdict on the sign; symbols never compared
    assert [v for v, _ in arithmetic(r"x = 0.30 \le 0.3")] == ["holds"]
    assert [v for v, _ in arithmetic(r"0.30 < 0.3")] == ["unchecked"]
    assert arithmetic(r"0 < \theta < \pi") == [] and arithmetic(r"2I_1T \le L^2 \le 2I_3T") == []


def test_a_sign_stated_after_a_worked_value_is_read_in_notes():
    claims = kept.check_text("$$(I_2 - I_3) = 2.4 - 4.2 = -1.8 < 0$$\n")
    assert [c.verdict for c in claims if c.kind == "arithmetic"] == ["holds", "holds"]
    bad = kept.check_text("$$(I_2 - I_3) = 2.4 - 4.2 = -1.8 > 0$$\n")
    assert [c.verdict for c in bad if c.kind == "arithmetic"] == ["holds", "fails"]


SPHERE = "## Worked values\n\nThe sphere has mass $M$ and radius $R$; the spin is $\\Omega_0$.\n\n"


def test_a_worked_decimal_times_the_texts_symbols_is_compared_by_the_ratio_of_the_two_sides():
    claims = kept.check_text(SPHERE + "$$\\lambda = \\Omega_0 \\sqrt{\\frac{1.4 \\times 1.8}{1.0 \\times 4.2}} = "
                                      "\\Omega_0 \\sqrt{0.6} \\approx 0.7746 \\Omega_0$$\n")
    assert [c.verdict for c in claims if c.kind == "arithmetic"] == ["holds", "holds"]
    rounded = kept.check_text(SPHERE + "$$I = \\frac{2}{5} M R^2 = 0.4 M R^2$$\n")
    assert [c.verdict for c in rounded if c.kind == "arithmetic"] == ["holds"]


def test_a_scaled_value_off_by_a_slip_fails_and_one_off_in_its_last_digit_is_left_unchecked():
    wrong = kept.check_text(SPHERE + "$$\\mu = \\Omega_0 \\sqrt{0.6} \\approx 0.9746 \\Omega_0$$\n")
    assert [c.verdict for c in wrong if c.kind == "arithmetic"] == ["fails"]
    near = kept.check_text(SPHERE + "$$I = \\frac{2}{5} M R^2 = 0.5 M R^2$$\n")
    assert [c.verdict for c in near if c.kind == "arithmetic"] == ["unchecked"]
    # different symbols on the two sides, or no worked decimal: no arithmetic verdict
    assert not [c for c in kept.check_text(SPHERE + "$$\\mu = \\Omega_0 \\sqrt{0.6} \\approx 0.7746 M$$\n")
                if c.kind == "arithmetic"]
    assert not [c for c in kept.check_text(SPHERE + "$$I = \\frac{2}{5} M R^2 = \\frac{4}{10} M R^2$$\n")
                if c.kind == "arithmetic"]


def test_a_decimal_datum_inside_a_worked_expression_lends_it_no_rounding():
    # the 0.2 in (0.2)^2 is the text's datum, not a rounded result: ¼ (0.2)² M = 0.01 M, never 0.02 M
    half = kept.check_text(SPHERE + "$$I_z = \\frac{1}{2} M (0.2)^2 = 0.02\\, M$$\n")
    assert [c.verdict for c in half if c.kind == "arithmetic"] == ["holds"]
    quarter = kept.check_text(SPHERE + "$$I_x = \\frac{1}{4} M (0.2)^2 = 0.02\\, M$$\n")
    assert "holds" not in [c.verdict for c in quarter if c.kind == "arithmetic"]


def test_a_written_value_holds_when_rounded_or_cut_at_its_last_place_and_never_a_unit_above_it():
    assert [v for v, _ in arithmetic(r"x = 2\pi(3) = 19")] == ["holds"]           # 18.85 rounded
    assert [v for v, _ in arithmetic(r"x = 2\pi(3) = 18")] == ["holds"]           # 18.85 cut
    assert [v for v, _ in arithmetic(r"T = \frac{1}{2}(2)(3)^2 = 9")] == ["holds"]
    assert [v for v, _ in arithmetic(r"T = \frac{1}{2}(2)(3)^2 = 8")] != ["holds"]   # 9 is never written 8


def test_whole_number_arithmetic_off_by_more_than_its_rounding_fails_and_a_trailing_zero_may_be_rounded():
    assert [v for v, _ in arithmetic(r"T = \frac{1}{2}(2)(3)^2 = 8")] == ["fails"]
    assert [v for v, _ in arithmetic(r"z = 7 \cdot 3 = 24")] == ["fails"]
    assert [v for v, _ in arithmetic(r"x = (2)(970) = 2000")] == ["unchecked"]    # one significant figure
    assert [v for v, _ in arithmetic(r"x = \frac{100}{3} \cdot 3 = 99")] == ["unchecked"]   # within 3 %


def test_a_worked_number_in_whole_numbers_named_as_a_quantity_is_not_compared_with_its_formula():
    claims = kept.check_text("A wheel of moment of inertia 2 spins at 3 rad/s; its energy is\n\n"
                             "$$ T = \\frac{1}{2}(2)(3)^2 = 9 $$\n")
    assert not any(c.verdict in ("typo", "fails") for c in claims)
    assert any(c.kind == "arithmetic" and c.verdict == "holds" for c in claims)
    assert any(c.verdict == "unchecked" and "a worked value" in c.why for c in claims)


def test_a_relation_set_to_zero_or_an_equation_set_to_one_is_no_worked_value():
    x, t = sp.symbols("x T")
    assert unchecked("T = 9", sp.Integer(9), [x], str, t) is not None
    assert unchecked(r"\frac{x}{2} = 1", sp.Integer(1), [x], str, x / 2) is None       # an equation of a surface
    assert unchecked("T = 0", sp.Integer(0), [x], str, t) is None


def test_a_letter_before_a_decimal_in_brackets_raised_to_a_power_is_a_product_not_a_value_at_a_time():
    ball = "## Ball\n\nA ball of mass $m$ has a radius of gyration of 40 mm.\n\n"
    claims = kept.check_text(ball + "$$I_x = m (0.04)^2 = 0.0016\\, m$$\n")
    assert "holds" in [c.verdict for c in claims]
    assert "holds" not in [c.verdict for c in kept.check_text(ball + "$$I_x = m (0.04)^2 = 0.016\\, m$$\n")]
