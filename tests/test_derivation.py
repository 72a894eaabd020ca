"""The derivation core, each result against an independent route."""
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from derive.symbolic import inertia
from derive.symbolic import lagrangian as lg
from derive.symbolic import rotations as rot
from derive.symbolic import stability
from derive.symbolic.models import euler_angles
from derive.symbolic.effects import lookup

RNG = np.random.default_rng(20261121)


@pytest.mark.parametrize("conv", list(rot.CONVENTIONS.values()), ids=lambda c: c.name)
def test_omega_by_notes_sum_equals_omega_by_skew_matrix(conv):
    diff = (conv.omega_body_sum() - conv.omega_body_skew()).applyfunc(rot.trig_reduce)
    assert diff == sp.zeros(3, 1)


def test_rotation_matrix_is_product_of_the_slides_passive_matrices():
    R = rot.ZYZ.matrix()
    slides = rot.passive("z", rot.gamma) * rot.passive("y", rot.beta) * rot.passive("z", rot.alpha)
    assert (R.T - slides).applyfunc(rot.trig_reduce) == sp.zeros(3, 3)
    # The slides' passive z matrix, as printed.
    g = rot.gamma
    assert rot.passive("z", g) == sp.Matrix([[sp.cos(g), sp.sin(g), 0], [-sp.sin(g), sp.cos(g), 0], [0, 0, 1]])


@pytest.mark.parametrize("conv", list(rot.CONVENTIONS.values()), ids=lambda c: c.name)
def test_inverse_rate_map_recovers_rates_off_the_singular_set(conv):
    assert rot.trig_reduce(conv.singular_set() + sp.sin(rot.beta)) == 0
    w = conv.omega_body_sum()
    back = conv.rates_from_omega(list(w))
    f = sp.lambdify(rot.ANGLES + rot.RATES, list(back), "mpmath")
    for _ in range(5):
        q = RNG.uniform(-3, 3, 3)
        qd = RNG.normal(size=3)
        got = np.array(f(*q, *qd), dtype=float)
        np.testing.assert_allclose(got, qd, rtol=1e-12, atol=1e-12)


def test_omega_numerically_matches_finite_difference_of_rotation_matrix():
    R = sp.lambdify(rot.ANGLES, rot.ZYZ.matrix(), "numpy")
    w = sp.lambdify(rot.ANGLES + rot.RATES, list(rot.ZYZ.omega_body_sum()), "numpy")
    q, qd, h = RNG.uniform(0.2, 2.5, 3), RNG.normal(size=3), 1e-6
    Rdot = (R(*(q + h * qd)) - R(*(q - h * qd))) / (2 * h)
    W = R(*q).T @ Rdot
    np.testing.assert_allclose([W[2, 1], W[0, 2], W[1, 0]], w(*q, *qd), rtol=1e-8, atol=1e-9)


def test_kinetic_energy_equals_point_cloud_sum():
    """T = ½ ω̃·I·ω̃ in Euler angles vs Σ ½ m |ω × r|² over a random rigid point cloud."""
    m = RNG.uniform(0.1, 2.0, 40)
    r = RNG.normal(size=(40, 3))
    I = inertia.point_masses_numeric(m, r)
    moments, axes = inertia.principal_axes(I)
    r_body = r @ axes  # principal-axis components
    q, qd = RNG.uniform(0.3, 2.5, 3), RNG.normal(size=3)
    T_sym = sp.lambdify((lg.I1, lg.I2, lg.I3) + rot.ANGLES + rot.RATES, lg.kinetic_energy(), "numpy")
    T_angles = T_sym(*moments, *q, *qd)
    w = np.array(sp.lambdify(rot.ANGLES + rot.RATES, list(rot.ZYZ.omega_body_sum()))(*q, *qd), dtype=float)
    v = np.cross(w, r_body)
    T_points = 0.5 * np.sum(m * np.einsum("pi,pi->p", v, v))
    assert T_angles == pytest.approx(T_points, rel=1e-12)


def test_symbolic_point_mass_tensor_matches_numeric():
    ms = [1, 2, 3]
    rs = [(1, 0, 0), (0, 2, 1), (1, 1, 1)]
    I = np.array(inertia.point_masses(ms, rs), dtype=float)
    np.testing.assert_allclose(I, inertia.point_masses_numeric(ms, rs), rtol=1e-15)


def test_solids_by_integration_match_point_cloud_monte_carlo():
    """The cone about its apex, integrated symbolically, vs a random point cloud filling it."""
    cone = inertia.SOLIDS["cone"]
    I_sym = np.array(cone.tensor_about_origin.subs({inertia.M: 1, inertia.R: 0.5, inertia.H: 2.0}), dtype=float)
    n = 400_000
    pts = RNG.uniform([-0.5, -0.5, 0], [0.5, 0.5, 2.0], size=(n, 3))
    inside = np.hypot(pts[:, 0], pts[:, 1]) <= 0.5 * pts[:, 2] / 2.0
    pts = pts[inside]
    I_mc = inertia.point_masses_numeric(np.full(len(pts), 1.0 / len(pts)), pts)
    np.testing.assert_allclose(np.diag(I_sym), np.diag(I_mc), rtol=1e-2)


def test_parallel_axis_shift_equals_direct_integration_about_apex():
    cone = inertia.SOLIDS["cone"]
    com = cone.centre_of_mass[2]
    shifted = cone.about_pivot(-com)
    assert (shifted - cone.tensor_about_origin).applyfunc(sp.simplify) == sp.zeros(3, 3)


@pytest.mark.parametrize("hi", [sp.pi, 2 * sp.pi])
def test_exact_integration_rules_are_sympy_integrate(hi):
    """The solids' integrals term by term (powers; cos^m sin^n over [0, π] and a whole period;
    harmonics of a whole period; anything else by sympy.integrate) equal sympy.integrate."""
    v, u, k = sp.symbols("v u k", positive=True)
    terms = [k * v**3 * u, sp.cos(v)**4 * sp.sin(v)**2, sp.cos(v)**3 * sp.sin(v)**2, sp.sin(v)**5,
             sp.cos(v)**2 * sp.sin(v)**3 * u**2, sp.sin(2 * v + u), sp.cos(3 * v), sp.exp(v) * sp.cos(v)]
    for f in terms:
        got = inertia.integrate_terms(f, v, 0, hi)
        assert sp.simplify(got - sp.integrate(f, (v, 0, hi))) == 0, f
    assert sp.expand(inertia.integrate_terms(k * v**2 + v, v, -u, u * k) - (k * (u**3 * k**3 + u**3) / 3
                                                                           + (u**2 * k**2 - u**2) / 2)) == 0


def test_principal_axes_diagonalise_and_are_right_handed():
    I = inertia.point_masses_numeric(RNG.uniform(1, 2, 10), RNG.normal(size=(10, 3)))
    moments, axes = inertia.principal_axes(I)
    np.testing.assert_allclose(axes.T @ I @ axes, np.diag(moments), atol=1e-12 * moments.max())
    assert np.linalg.det(axes) == pytest.approx(1.0)


def test_cyclic_coordinates_are_alpha_and_gamma():
    assert lg.heavy_symmetric_top().cyclic == (rot.alpha, rot.gamma)


def _divided_by_each_pythagorean_identity(expr):
    """The reference remainder: divide by c² + s² − 1 for one angle at a time."""
    pairs = [(x, sp.Dummy("s"), sp.Dummy("c")) for x in rot.ANGLES]
    for x, s_, c_ in pairs:
        expr = expr.xreplace({sp.sin(x): s_, sp.cos(x): c_})
    poly = sp.expand(expr)
    for _, s_, c_ in pairs:
        poly = sp.rem(sp.Poly(poly, c_), sp.Poly(c_**2 + s_**2 - 1, c_)).as_expr()
    back = {v: f(x) for x, s_, c_ in pairs for v, f in ((s_, sp.sin), (c_, sp.cos))}
    return sp.expand(poly).xreplace(back)


@pytest.mark.parametrize("expr", [
    sp.cos(rot.alpha)**5 * sp.cos(rot.beta)**4 * lg.I1 + sp.sin(rot.gamma)**2 * sp.cos(rot.gamma)**3 - lg.I3,
    (sp.cos(rot.beta) + sp.sin(rot.beta) * rot.alpha_d)**4 * sp.cos(rot.gamma)**2 + sp.sqrt(2) * sp.cos(rot.alpha)**2,
    sp.cos(rot.alpha)**2 + sp.sin(rot.alpha)**2 - 1,
])
def test_trig_reduce_is_the_remainder_of_each_pythagorean_identity(expr):
    assert rot.trig_reduce(expr) == _divided_by_each_pythagorean_identity(expr)


@pytest.mark.parametrize("sequence", ["z-y-z", "z-x-z", "x-y-z", "z-y-x"])
def test_rates_from_momenta_give_back_the_momenta(sequence):
    top = lg.heavy_symmetric_top(rot.convention(sequence))
    rates = lg.Reduction(top).rates_from_momenta
    assert set(rates) == {rot.alpha_d, rot.gamma_d}
    for q, p in ((rot.alpha, lg.p_alpha), (rot.gamma, lg.p_gamma)):
        assert sp.simplify(top.momentum(q).xreplace(rates) - p) == 0


def test_energy_function_is_T_plus_V():
    el = lg.heavy_symmetric_top()
    T = lg.kinetic_energy_symmetric()
    assert rot.trig_reduce(el.energy - T - lg.gravity_potential()) == 0


def _heavy_top_rhs():
    el = lg.heavy_symmetric_top()
    acc = sp.lambdify(rot.ANGLES + rot.RATES + (lg.I1, lg.I3, lg.Mass, lg.g, lg.l), list(el.accelerations))

    def f(t, y, *p):
        return np.concatenate([y[3:], np.array(acc(*y, *p), dtype=float)])

    return el, f


def test_conserved_quantities_constant_along_integrated_heavy_top():
    el, f = _heavy_top_rhs()
    p = (1.0, 0.4, 1.0, 9.81, 0.1)
    y0 = np.array([0.0, 0.7, 0.0, 1.5, 0.3, 25.0])
    sol = solve_ivp(f, (0, 2), y0, args=p, method="DOP853", rtol=1e-12, atol=1e-12, dense_output=True)
    args = rot.ANGLES + rot.RATES + (lg.I1, lg.I3, lg.Mass, lg.g, lg.l)
    for expr in (el.energy, el.momentum(rot.alpha), el.momentum(rot.gamma)):
        q = sp.lambdify(args, expr)
        vals = np.array([q(*y, *p) for y in sol.sol(np.linspace(0, 2, 50)).T])
        assert np.ptp(vals) < 1e-9 * np.max(np.abs(vals))


def test_asymmetric_euler_angle_equations_agree_with_euler_equations():
    """q̈ from the Euler-angle Lagrangian (general I₁, I₂, I₃) turned into ω̃̇ equals Euler's equations."""
    model = euler_angles(False, ())
    w = rot.ZYZ.omega_body_sum()
    f = sp.lambdify(rot.ANGLES + rot.RATES + (lg.I1, lg.I2, lg.I3), list(model.rhs))
    J = sp.lambdify(rot.ANGLES + rot.RATES, w.jacobian(sp.Matrix(rot.ANGLES + rot.RATES)))
    wf = sp.lambdify(rot.ANGLES + rot.RATES, list(w))
    euler = sp.lambdify(sp.symbols("omega1:4", real=True) + (lg.I1, lg.I2, lg.I3), list(stability.euler_rhs()))
    for _ in range(5):
        y = np.concatenate([RNG.uniform(0.3, 2.8, 3), RNG.normal(size=3)])
        I = np.sort(RNG.uniform(1, 2, 3))
        ydot = np.array(f(*y, *I), dtype=float)
        wdot = np.array(J(*y), dtype=float) @ ydot
        np.testing.assert_allclose(wdot, euler(*wf(*y), *I), rtol=1e-10, atol=1e-12)


def test_damping_enters_euler_angles_as_generalised_force():
    """With damping only, dE/dt = −c |ω̃|² along the Euler-angle equations."""
    model = euler_angles(True, lookup(["damping"]))
    obs = model.observables
    E = obs["energy"]
    dE = sum(sp.diff(E, s) * f for s, f in zip(model.states, model.rhs))
    w2 = sum(wi**2 for wi in obs["omega"])
    c = [p for p in model.params if str(p) == "c"][0]
    fn = sp.lambdify(model.states + model.params, dE + c * w2)
    y = np.array([0.1, 0.9, 0.2, 0.5, -0.3, 4.0])
    assert abs(fn(*y, 1.0, 0.5, 0.3)) < 1e-12


def test_sleeping_top_threshold_matches_series():
    s = stability.sleeping_top()
    assert sp.simplify(s.threshold - 2 * sp.sqrt(lg.I1 * lg.Mass * lg.g * lg.l)) == 0
    assert sp.simplify(s.coefficient(2) - (lg.p_gamma**2 / (8 * lg.I1) - lg.Mass * lg.g * lg.l / 2)) == 0
    assert s.quartic_at_threshold.is_positive


def test_sleeping_top_threshold_matches_numerical_eigenvalues():
    """Linearise the reduced β equation at β = 0 numerically; the eigenvalues turn real at the threshold."""
    red = lg.Reduction(lg.heavy_symmetric_top())
    I1, M, g, l = 1.0, 1.0, 9.81, 0.1
    crit = np.sqrt(4 * M * g * l * I1)
    V = sp.lambdify((rot.beta, lg.p_gamma), red.effective_potential.subs(
        {lg.p_alpha: lg.p_gamma, lg.I1: I1, lg.Mass: M, lg.g: g, lg.l: l}), "mpmath")
    import mpmath as mp

    def max_real_eig(p):
        # V_eff has a removable 0/0 at β = 0: take its curvature just beside it (error O(β²)).
        k = float(mp.diff(lambda b: V(b, p), mp.mpf("0.001"), 2))
        A = np.array([[0.0, 1.0], [-k / I1, 0.0]])
        return np.max(np.linalg.eigvals(A).real)

    assert max_real_eig(crit * 1.01) < 1e-9
    assert max_real_eig(crit * 0.99) > 1e-3


def test_intermediate_axis_growth_rate_matches_numerical_eigenvalues():
    I = (1.0, 2.0, 3.0)
    w0 = 1.7
    subs = {lg.I1: I[0], lg.I2: I[1], lg.I3: I[2], stability.omega0: w0}
    for axis in range(3):
        ss = stability.SteadySpin(axis)
        J = np.array(ss.jacobian.subs(subs), dtype=float)
        lam = np.linalg.eigvals(J)
        lam2 = float(ss.eigenvalue_squared.subs(subs))
        if axis == 1:
            assert lam2 > 0
            assert np.max(lam.real) == pytest.approx(np.sqrt(lam2), rel=1e-12)
        else:
            assert lam2 < 0
            assert np.max(np.abs(lam.real)) < 1e-12
            assert np.max(lam.imag) == pytest.approx(np.sqrt(-lam2), rel=1e-12)
