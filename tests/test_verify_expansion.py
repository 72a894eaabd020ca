"""The cheaper exact steps of the notes checker: `expand` and derivatives in a polynomial ring
(`zero_test.expanded`, `zero_test.expanded_derivative`), `cancel` in the field of rational
functions (`sparse_forms.rational_zero`), `trig_reduce`'s zero test in the ring
(`sparse_forms.trig_zero`), the memoised symbols and atoms of an expression, the exact screen of a quotient's dependence (`zero_test.surely_depends`),
`trig_reduce` of an expression with no denominator, the one-coordinate reader's linear solve and
the sign of a difference under the text's orderings. Each gives what the costlier step it stands
in for gives."""
import pytest
import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import vector_algebra_model as vam
from derive.lecture import vector_models as vm
from derive.lecture import sparse_forms as sf
from derive.lecture import zero_test as zt
from derive.lecture.context import sign_under_orderings
from derive.lecture.coordinate_statements import _solutions
from derive.symbolic.rotations import trig_reduce

x, y = sp.symbols("x y", real=True)
m, R, I = sp.symbols("m R I_C", positive=True)
b, g = sp.symbols("beta gamma", real=True)
w1, w2, wd1 = sp.symbols("w1 w2 wd1", real=True)

EXPRESSIONS = [
    (x + y) ** 3 / m - x ** 3 / m,                                 # reciprocals of symbols
    x * (y + 1 / x),                                               # x·x⁻¹ = 1 once multiplied out
    (sp.sin(b) + x / m) ** 2 * m - m * sp.cos(b) ** 2,             # sin and cos of a symbol
    sp.Rational(1, 2) * (x + y) ** 2 - x * y,
    (x * y) ** -2 * (x + y) ** 2,
    (w1 * sp.tan(g) - wd1) ** 3,
    # not polynomials in the ring's generators: left to `expand`
    (x + 1) ** -1 * (x + y), sp.sqrt(x + 1) * (x + y) ** 2, sp.Float("2.5") * x * (x + 1),
    sp.sin(x + y) * (x + 1) ** 2, sp.exp(x) * (x + sp.exp(-x)), (x + sp.pi) ** 2,
]


@pytest.mark.parametrize("e", EXPRESSIONS)
def test_expanded_is_sympys_expand(e):
    assert zt.expanded(e) == sp.expand(e)


def test_a_polynomial_not_zero_once_expanded_goes_to_the_numeric_test_and_a_zero_one_holds_by_expand():
    assert zt.symbolic_zero(x * (x + 1) - x ** 2 - x) == "expand"
    assert zt.symbolic_zero(x / m + y) is None
    assert zt.symbolic_zero(x / (x + 1) + 1 / (x + 1) - 1) == "cancel"     # no polynomial: cancel still decides


RATIONAL = [
    x / (x + 1) + 1 / (x + 1) - 1,                                 # zero
    (x ** 2 - y ** 2) / (x - y) - x - y,                           # zero once the common factor goes
    1 / (m * (x + y)) - 1 / (m * x + m * y),                       # zero: the same denominator written twice
    (x + y) ** -2 * (x ** 2 + 2 * x * y + y ** 2) - 1,             # zero: a negative power of a sum
    x / (x + 1) - y / (y + 1),                                     # not zero
    sp.Rational(3, 7) * x / (x * y + 1) - sp.Rational(3, 7) / y,   # not zero
    # not a rational function of its symbols with rational coefficients: `cancel` itself decides
    sp.sqrt(x) / (x + 1) - sp.sqrt(x) / (1 + x), sp.Float("0.5") * x / (x + 1) - x / (2 * x + 2),
    sp.sin(b) / (x + 1) - sp.sin(b) / (x + 1) + x / y,
    1 / ((x + 1) ** 2 - x ** 2 - 2 * x - 1) + x,                    # a denominator that vanishes identically
]


@pytest.mark.parametrize("e", RATIONAL)
def test_a_rational_function_is_zero_in_the_field_exactly_where_cancel_finds_it_zero(e):
    assert sf.rational_zero(e) == (sp.cancel(sp.together(e)) == 0)


def test_the_field_decides_a_rational_function_and_leaves_the_rest_to_cancel():
    assert sf._rational_generators(x / (x + 1) - y) == [x, y]
    assert sf._rational_generators(sp.sqrt(x) / (x + 1)) is None
    assert sf._rational_generators(sp.Integer(3)) is None
    assert zt.symbolic_zero((x ** 2 - y ** 2) / (x - y) - x - y) == "cancel"


TRIGONOMETRIC = [
    (sp.sin(b) ** 2 + sp.cos(b) ** 2 - 1, (b,)),                                  # zero
    (x * sp.cos(b) ** 4 - x * (1 - sp.sin(b) ** 2) ** 2, (b,)),                   # zero: cos⁴ = (1 − sin²)²
    (sp.cos(b) ** 3 / x + sp.cos(b) * sp.sin(b) ** 2 / x - sp.cos(b) / x, (b,)),  # zero over a monomial
    (sp.cos(b) ** 2 * sp.cos(g) ** 2 - (1 - sp.sin(b) ** 2) * (1 - sp.sin(g) ** 2), (b, g)),
    (x * (y + 1 / x) - 1 - x * y, (b,)),                                          # x·x⁻¹ = 1
    (sp.cos(b) ** 2 - 1, (b,)),                                                   # not zero
    (sp.cos(b) ** 2 + sp.sin(b) ** 2 - 1, ()),                                    # b not an angle: not reduced
    (sp.cos(b) * sp.sin(g) - sp.sin(g) * sp.cos(b) + x * sp.sin(b), (b, g)),      # not zero
]


@pytest.mark.parametrize("e, angles", TRIGONOMETRIC)
def test_a_polynomial_in_sines_and_cosines_is_zero_in_the_ring_exactly_where_trig_reduce_gives_0(e, angles):
    assert sf.trig_zero(e, angles) == (trig_reduce(e, angles) == 0)


def test_what_the_ring_does_not_read_is_left_to_trig_reduce():
    assert sf.trig_zero(sp.tan(b) * sp.cos(b) - sp.sin(b), (b,)) is None          # tan: a denominator cos
    assert sf.trig_zero(sp.cos(b) ** 2 / (x + 1), (b,)) is None                   # a quotient by a sum
    assert sf.trig_zero(sp.sin(2 * b) - 2 * sp.sin(b) * sp.cos(b), (b,)) is None  # sin of no symbol
    assert zt.symbolic_zero(sp.sin(b) ** 2 * x + sp.cos(b) ** 2 * x - x + sp.tan(b) - sp.tan(b)) == "trig_reduce"


def test_the_memoised_symbols_and_atoms_are_sympys_and_a_mutable_matrix_is_walked_each_time():
    e = sp.sin(b) * x + sp.sqrt(y + 1) / m
    assert sf.free_symbols(e) == frozenset(e.free_symbols)
    assert sf.free_symbols(e) is sf.free_symbols(sp.sin(b) * x + sp.sqrt(1 + y) / m)   # kept per expression
    assert sf.atoms(e, sp.Pow) == frozenset(e.atoms(sp.Pow))
    assert sf.atoms(e, sp.sin, sp.cos) == {sp.sin(b)}
    M = sp.Matrix([[x, y]])
    assert sf.free_symbols(M) == {x, y}
    M[0, 1] = m
    assert sf.free_symbols(M) == {x, m}


def test_a_quotient_that_moves_with_the_variables_is_proved_to_and_a_true_multiple_never_is():
    euler = I * wd1 - (m - R) * w1 * w2
    assert not zt.surely_depends((m + sp.cos(b)) * euler, euler, {w1, w2, wd1})
    assert zt.surely_depends(w1 * euler, euler, {w1, w2, wd1})
    assert zt.surely_depends(euler + w2, euler, {w1, w2, wd1})
    assert not zt.surely_depends(sp.sqrt(w1) * euler, euler, {w1, w2, wd1})   # a root: not evaluated, not proved


def test_trig_reduce_of_an_expression_without_denominator_keeps_its_content_in_each_term():
    assert trig_reduce(2 * x * sp.sin(b) ** 2 + 2 * x * sp.cos(b) ** 2, (b,)) == 2 * x
    assert trig_reduce(x * sp.cos(b) ** 2 / 2 + y / 2, (b,)) == x / 2 + y / 2 - x * sp.sin(b) ** 2 / 2
    assert trig_reduce(sp.tan(b) * sp.cos(b) - sp.sin(b), (b,)) == 0     # a denominator: together as before


def test_a_relation_linear_in_its_unknown_is_solved_as_solve_solves_it():
    (value,) = _solutions(m * R ** 2 - I - 4 * m * R ** 2 / sp.pi ** 2, I)
    assert sp.simplify(value - sp.solve(m * R ** 2 - I - 4 * m * R ** 2 / sp.pi ** 2, I)[0]) == 0
    assert _solutions(I + m, I) == [] == sp.solve(I + m, I)              # I_C > 0 rules out −m
    assert sorted(_solutions(x ** 2 - 1, x)) == [-1, 1]                  # not linear: solve's roots


def test_the_sign_under_the_orderings_follows_the_chain_and_repeats_its_answer():
    chain = ((m, R, I),)
    assert sign_under_orderings(I - m, (I, m), chain) == "positive"
    assert sign_under_orderings(m - R, (R, m), chain) == "negative"
    assert sign_under_orderings(x - m, (m, x), chain) == "mixed"
    assert sign_under_orderings(I - m, (I, m), chain) == "positive"


@pytest.mark.parametrize("e", EXPRESSIONS)
def test_a_derivative_in_the_ring_is_the_expanded_derivative(e):
    for v in (x, y, b, g):
        assert zt.expanded_derivative(e, v) == zt.expanded(sp.diff(e, v))
    assert zt.expanded_derivative(e, x, y) == zt.expanded(sp.diff(e, x, y))
    field = {x: w1 * y, b: wd1, y: sp.Integer(2)}
    assert zt.expanded_derivative(e, field=field) == zt.expanded(sum(sp.diff(e, s) * v for s, v in field.items()))


def test_the_vector_models_tensors_and_torque_are_the_derivatives_of_their_l():
    for system in ("single", "body"):
        L = vam.momentum(system)
        assert vam.tensor(system) == L.applyfunc(zt.expanded).jacobian(vam.W).applyfunc(zt.expanded)
        assert vam.torque(system) == L.applyfunc(lambda e: vam._rate(e)).applyfunc(zt.expanded)
        assert vam.rate(L) == vam.torque(system)
    kinetic = zt.expanded(vm.Model("particle").kinetic)
    assert vm._tensor("particle") == sp.hessian(kinetic, list(lx.W)).applyfunc(zt.expanded)
