"""The numeric parts of the notes checker's zero test: formulas evaluated with mpmath by walking
their trees (`derive.lecture.mp_values`) and the interval screen that spares the costly symbolic
steps a difference it proves non-zero (`derive.lecture.zero_test`)."""
import random

import mpmath
import pytest
import sympy as sp

from derive.lecture import comparing, mp_values
from derive.lecture import named_vector_claims as nvc
from derive.lecture import notes_check as nc
from derive.lecture import vector_algebra_model as va
from derive.lecture import zero_test as zt
from derive.lecture.elliptic import JacobiSN

x, y = sp.symbols("x y", positive=True)
a = sp.Symbol("a", real=True)
I1, I2, I3 = sp.symbols("I1 I2 I3", positive=True)

FORMULAS = [
    sp.sqrt(x) * sp.sin(a) - 3 * y / (x + 2) ** 3 + sp.Rational(2, 7) * sp.cos(x * a) ** 2,
    1 / sp.sqrt(x + y) + x ** sp.Rational(1, 3) - sp.Float("0.125") * sp.pi * sp.exp(-a),
    sp.Abs(a) * sp.atan2(y, a) + sp.tan(x) / sp.log(y + 1) - sp.E ** x,
    x ** a + sp.sqrt(a - 2) * sp.acos(1 / (1 + x)),              # a root of a negative number: complex
    JacobiSN(x * a, y / (1 + y)) ** 2,
]


@pytest.mark.parametrize("point", [(1.5, 0.7, -1.3), (2.25, 1.75, 0.4)])
def test_walked_values_are_lambdifys_to_the_working_precision(point):
    syms = [a, x, y]
    walked = mp_values.evaluator(syms, FORMULAS)
    printed = sp.lambdify(syms, FORMULAS, modules="mpmath")
    order = {s.name: v for s, v in zip([x, y, a], point)}
    with mpmath.workdps(50):
        args = [mpmath.mpf(order[s.name]) for s in syms]
        for u, v in zip(walked(*args), printed(*args)):
            assert abs(u - v) <= mpmath.mpf(10) ** -45 * max(1, abs(v))


def test_a_pole_raises_as_lambdify_does_and_an_unknown_function_is_left_to_lambdify():
    walked = mp_values.evaluator([x], [1 / (x - 1)])
    with pytest.raises(ZeroDivisionError):
        walked(mpmath.mpf(1))
    gamma = mp_values.evaluator([x], [sp.gamma(x) + x])
    assert gamma(mpmath.mpf(5)) == [29]


def test_the_screen_proves_a_slip_with_a_root_non_zero_where_its_radicand_is_positive_for_one_ordering():
    # the radicand (I₂ − I₁)(I₃ − I₂) is positive only where I₂ lies between the others
    root = sp.sqrt(I1 * I2 - I1 * I3 - I2**2 + I2 * I3)
    assert not zt.surely_nonzero(root * sp.Abs(a) - 2 * a)
    assert zt._nonzero_somewhere(root * sp.Abs(a) - 2 * a)
    assert zt.symbolic_zero(root * sp.Abs(a) - 2 * a) is None


def test_a_vector_difference_with_a_root_shown_non_zero_is_left_expanded_and_an_identity_still_reaches_zero():
    # the vector reader's difference (a distance |r| = sqrt(x² + y²) in it): simplify only where the
    # screen cannot show the difference non-zero
    slip = x * sp.sqrt(x**2 + y**2) - x**2
    assert zt.nonzero_somewhere(slip)
    assert va.difference(slip, 0) == zt.expanded(slip)
    identity = sp.sqrt(x**2 * y**2 + x**2) - x * sp.sqrt(y**2 + 1)
    assert not zt.nonzero_somewhere(identity) and va.difference(identity, 0) == 0
    assert not zt.nonzero_somewhere(sp.Matrix([x]))


def test_the_screen_never_calls_an_identity_non_zero_and_the_symbolic_steps_still_show_it():
    identities = [sp.sqrt(3 + 2 * sp.sqrt(2)) - 1 - sp.sqrt(2), sp.sin(a) ** 2 + sp.cos(a * y / y) ** 2 - 1,
                  sp.cosh(x) ** 2 - sp.sinh(x) ** 2 - 1]
    assert not any(zt._nonzero_somewhere(d) for d in identities)
    assert not zt._nonzero_somewhere(sp.sqrt(x + 2 * sp.sqrt(x) + 1) - sp.sqrt(x) - 1)
    assert [zt.symbolic_zero(d) for d in identities] == ["simplify", "trig_reduce", "simplify"]


def test_the_quick_screen_of_candidates_tells_equal_sides_from_a_slip_with_or_without_the_walk():
    from derive.lecture.comparing import quick_equal
    f = sp.Function("f")
    assert quick_equal(sp.sqrt(x) * sp.cos(a) ** 2, sp.sqrt(x) - sp.sqrt(x) * sp.sin(a) ** 2)
    assert not quick_equal(sp.sqrt(x) * sp.cos(a) ** 2, sp.sqrt(x) - sp.sqrt(x) * sp.sin(a) ** 2 + x / 10**6)
    assert not quick_equal(JacobiSN(x, y) ** 2, 1 - JacobiSN(x, y) ** 2)
    # a function with no values is not walked, and evalf gives no number: not screened in
    assert not quick_equal(f(x) * 2, 3 * f(x) - f(x))


def test_a_large_trig_difference_is_left_unexpanded_and_a_polynomial_is_always_expanded():
    big = sum((sp.sin(k * a) + x) ** 2 * (sp.cos(a) + k * y) ** 3 / (x + k) for k in range(1, 30))
    assert zt._size(big) > zt._EXPAND_MAX_NODES
    assert zt.bounded_expand(big) is big
    poly = sum((x + k * y + a) ** 3 * (x - k) for k in range(1, 40))
    assert zt._size(poly) > zt._EXPAND_MAX_NODES
    assert zt.bounded_expand(poly) == sp.expand(poly)
    assert zt.bounded_expand(sp.sin(a) * (x + 1) - sp.sin(a) * x - sp.sin(a)) == 0


def test_the_first_point_counterexample_is_the_full_numeric_tests_outcome_and_none_for_an_identity():
    slip = sp.Matrix([sp.sin(a) ** 2 + sp.cos(a) ** 2 + x / 10 ** 6])
    one = sp.Matrix([1])
    found = zt.counterexample(slip, one, "seed")
    assert found is not None and found == zt.numeric_zero(slip, one, "seed")
    assert not found.ok
    identity = sp.Matrix([sp.sin(a) ** 2 + sp.cos(a) ** 2])
    assert zt.counterexample(identity, one, "seed") is None
    assert zt.counterexample(sp.Matrix([x + y]), sp.Matrix([y + x + 1]), "s") == \
        zt.numeric_zero(sp.Matrix([x + y]), sp.Matrix([y + x + 1]), "s")


def test_the_exact_screen_with_roots_takes_a_square_root_as_its_square_and_proves_a_slip():
    r = sp.sqrt(a * y + x)
    # zero once (√X)² = X is used, as expand and cancel use it: never called non-zero
    assert not zt.surely_nonzero_with_roots(r * (y + r) - y * r - a * y - x)
    assert not zt.surely_nonzero_with_roots(sp.sqrt(x / y) * sp.sqrt(y) - sp.sqrt(x))
    # a slip under the root, or beside it, is proved non-zero
    assert zt.surely_nonzero_with_roots(r * (y + r) - y * r - a * y)
    assert zt.surely_nonzero_with_roots(sp.sqrt(a * y + x) - sp.sqrt(a * y + 2 * x))
    # a root of a number is left to the symbolic steps
    assert not zt.surely_nonzero_with_roots(sp.sqrt(2) * x - x)


def test_an_equation_of_motion_is_refused_by_the_exact_screen_only_when_no_euler_reading_can_hold():
    from derive.lecture import latex as lx
    from derive.lecture import comparing
    from derive.symbolic.lagrangian import I1 as J1, I2 as J2, I3 as J3
    w, wd = lx.W, lx.WD
    euler = [J1 * wd[0] - (J2 - J3) * w[1] * w[2], J2 * wd[1] - (J3 - J1) * w[2] * w[0],
             J3 * wd[2] - (J1 - J2) * w[0] * w[1]]
    # a multiple of one equation, and a combination of them, are never refused
    assert not comparing.not_a_consequence(sp.expand(-3 * euler[0] / J2), euler)
    assert not comparing.not_a_consequence(sp.expand(J1 * w[0] * euler[0] + J2 * w[1] * euler[1]), euler)
    # a wrong sign, and a root the equations do not have, are
    assert comparing.not_a_consequence(J1 * wd[0] + (J2 - J3) * w[1] * w[2], euler)
    assert comparing.not_a_consequence(J2 * wd[1] - sp.sqrt((J3 - J1) ** 2 * w[2] ** 2 * w[0] ** 2 + J1), euler)


def test_the_ratio_screen_reads_jacobi_functions_and_roots_and_never_parts_a_constant_multiple():
    from derive.lecture import restated
    m = y / (1 + y)
    root = sp.sqrt(I1 * x ** 2 + I2 * y ** 2)
    old = sp.sqrt(I1 - I3 * x) * JacobiSN(x * a + 1, m) * root - I2
    # a number times old, however it is written, is never shown to vary, and the restatement still holds
    for k in (3, -sp.Rational(1, 2)):
        assert not zt.ratio_varies(sp.expand(k * old), old, "seed")
        assert restated._multiple((sp.expand(k * old), sp.S.Zero), (old, sp.S.Zero))
    assert not zt.ratio_varies(old, old * (1 + 0 * x), "seed")
    # a slip in an argument of sn, under the root, or in the factor is shown to vary
    assert zt.ratio_varies(sp.sqrt(I1 - I3 * x) * JacobiSN(x * a + 2, m) * root - I2, old, "seed")
    assert zt.ratio_varies(sp.sqrt(I1 - I3 * x) * JacobiSN(x * a + 1, m) * root - I2 * x, old, "seed")
    assert zt.ratio_varies(sp.sqrt(I1 + I3 * x) * JacobiSN(x * a + 1, m) * root - I2, old, "seed")
    assert not restated._multiple((sp.sqrt(I1 + I3 * x) * JacobiSN(x * a + 1, m) * root, I2), (old, sp.S.Zero))
    # nothing to evaluate at a real point: left to `cancel`
    assert not zt.ratio_varies(sp.sqrt(-1 - x) * y, y, "seed")


def test_a_difference_shown_at_a_point_is_never_an_identity_and_an_identity_is_never_shown():
    m = y / (1 + y)
    side = JacobiSN(x * a, m) * sp.sqrt(x + y) * (x - y)
    # the same value written out, a scalar or a matrix of one shape: no point parts them
    assert not zt.differs_somewhere(sp.expand(side), side, "seed")
    assert not zt.differs_somewhere(sp.Matrix([sp.expand(side), x]), sp.Matrix([side, x]), "seed")
    # a slip in the factor or in sn's argument is shown, so `expand` of the difference is spared
    assert zt.differs_somewhere(JacobiSN(x * a, m) * sp.sqrt(x + y) * (x + y), side, "seed")
    assert zt.differs_somewhere(JacobiSN(2 * x * a, m) * sp.sqrt(x + y) * (x - y), side, "seed")
    # matrices of two shapes, or a matrix beside a scalar, are left to the caller
    assert not zt.differs_somewhere(sp.Matrix([x, y]), sp.Matrix([[x, y]]), "seed")
    assert not zt.differs_somewhere(sp.Matrix([x]), x + 1, "seed")


def test_the_numeric_screens_leave_a_formula_with_no_value_to_the_symbolic_steps():
    f = sp.Function("f")(a)
    # an undefined function has no value at a point: neither screen decides, nor raises
    assert not zt.differs_somewhere(f * x, f, "seed") and not zt.ratio_varies(f * x, f, "seed")
    assert not zt.differs_somewhere(sp.Derivative(f, a) * x, sp.Derivative(f, a), "seed")


def test_an_angle_recovered_by_its_arctangent_holds_on_the_principal_branch_whichever_points_are_drawn():
    # γ = arctan(sin γ / cos γ) agrees where γ lies in (−π/2, π/2) and is a multiple of π off elsewhere:
    # the verdict must not follow which seeded points (the seed is the display's text) fall in that range
    g = sp.Symbol("gamma")
    claim, recovered = sp.Matrix([g]), sp.Matrix([sp.atan(sp.sin(g) / sp.cos(g))])
    assert all(comparing.zero(claim, recovered, f"seed {k}")[0] for k in range(12))
    for slip in (sp.atan(sp.cos(g) / sp.sin(g)), -sp.atan(sp.sin(g) / sp.cos(g)), sp.atan(2 * sp.sin(g) / sp.cos(g))):
        assert not any(comparing.zero(claim, sp.Matrix([slip]), f"seed {k}")[0] for k in range(6))
    for brackets in (("\\left(", "\\right)"), ("(", ")"), ("\\bigl(", "\\bigr)")):
        text = "# T\n\n$$\n\\gamma = \\arctan{0}\\frac{{\\sin\\gamma}}{{\\cos\\gamma}}{1}\n$$\n".format(*brackets)
        assert [c.verdict for c in nc.check_text(text)] == ["holds"], text


def test_named_vectors_numeric_test_walks_its_points_and_decides_as_the_substitution_does():
    def substituted(diffs):     # the test with each point substituted and evaluated at 30 digits
        names = sorted({s for d in diffs for s in d.free_symbols}, key=lambda s: s.name)
        rng = random.Random(20)
        for _ in range(3):
            point = {s: sp.Rational(rng.randint(100, 200), 100) * (1 if s.is_positive else rng.choice((-1, 1)))
                     for s in names}
            if any(abs(complex(sp.N(d.subs(point), 30))) > 1e-12 for d in diffs):
                return False
        return True

    f = sp.Function("f")
    cases = [[sp.sin(a) ** 2 + sp.cos(a) ** 2 - 1], [x * y - y * x + sp.Float("1e-14") * a],
             [sp.Float("1e-9") * x], [1 / (x - y) - 1 / (x - y)], [sp.sqrt(a) ** 2 - a, x - 1],
             [f(x) - f(x), sp.sin(x) - sp.cos(x)]]
    for diffs in cases:
        assert nvc._numerically_zero(diffs) == substituted(diffs), diffs
