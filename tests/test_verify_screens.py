"""The exact screens the reader runs before its expensive symbolic steps decide as those steps do."""
import sympy as sp

from derive.lecture import comparing, restated, zero_test


def test_an_equation_solved_for_a_name_is_still_recognised_after_the_screen():
    x, a, b = sp.symbols("x a b", positive=True)
    assert restated._solved_for(x, a * x - b, b / a)


def test_a_value_proved_different_at_a_point_is_no_solution_of_the_equation():
    x, a, b = sp.symbols("x a b", positive=True)
    assert not restated._solved_for(x, a * x - b, b / a + a)


def test_a_formula_holding_sympys_infinity_has_no_value_at_any_point():
    x, y = sp.symbols("x y", positive=True)
    claim = sp.ImmutableMatrix([sp.sqrt(x) * sp.zoo * (y + 1)])
    derived = sp.ImmutableMatrix([sp.sqrt(x) * y])
    assert comparing._real_zero(claim, derived, "seed") is None
    assert zero_test.numeric_zero(claim, derived, "seed").method == "mpmath 50 digits at 0 points"
    assert not zero_test.numeric_zero(claim, derived, "seed").ok
    assert comparing.zero(claim, derived, "seed")[0] is False
