"""The "reduced-u" formulation: the symmetric top in u = cos β with ü = f′(u)/2.

References are independent of the model's derivation: the closed-form heavy top
(`derive.reference.exact.heavy_top`), the other formulations at tight tolerance, the conserved
quantities written out from the scene's numbers, and the Routh polynomial typed here from the
notes, f(u) = (2/I₁)(1 − u²)(E′ − M g l u) − (p_α − p_γ u)²/I₁².

The global axis error over 10 s is required within 10 rtol (the tolerance bounds the error per
step; a few hundred steps add up) and to fall with the tolerance (it is the tolerance's, not a
floor).
"""
import math

import numpy as np
import pytest
import sympy as sp

import derive
from derive.bench.runner import axis_error, exact_axis
from derive.errors import IntegrationError
from derive.reference import exact
from derive.runtime import catalogue
from derive.runtime.integrate import ModelKernel
from derive.runtime.kernel import Kernel
from derive.sim.auto import formulation as auto_formulation
from derive.sim.inputs import inputs_of, params_of
from derive.sim.scene import load_scene
from derive.symbolic.formulations import POLE_CLEARANCE, REGISTRY

I1, I3, MGL = 1.0, 0.5, 1.0


def scene(beta=0.8, alpha_dot=-0.4, beta_dot=0.3, gamma_dot=6.0, omega=None, t_end=10.0,
          samples=101, **sim):
    """The benchmark's reference top (defaults) or a variation of it."""
    initial = {"alpha": 0.3, "beta": beta, "gamma": -0.2}
    if omega is None:
        initial.update(alpha_dot=alpha_dot, beta_dot=beta_dot, gamma_dot=gamma_dot)
    else:
        initial["omega"] = list(omega)
    return {"body": {"I1": I1, "I3": I3}, "gravity": {"M": 1.0, "g": 1.0, "l": MGL},
            "initial": initial,
            "simulate": {"t_end": t_end, "samples": samples, "rtol": 1e-10, "atol": 1e-12,
                         **sim}}


SCENES = {
    "reference": scene(),
    "omega-given": scene(beta=1.1, omega=(0.4, -0.7, 5.0)),
    "hanging": scene(beta=2.6, alpha_dot=0.8, beta_dot=-0.5, gamma_dot=3.0),
    "wide-nutation": scene(beta=0.5, alpha_dot=0.5, beta_dot=0.0, gamma_dot=4.0),
}


def run(d, **over):
    return derive.simulate(d, formulation="reduced-u", **over)


@pytest.mark.parametrize("name", sorted(SCENES))
def test_axis_matches_the_exact_heavy_top(name):
    d = SCENES[name]
    errs = []
    for rtol in (1e-8, 1e-10):
        res = run(d, method="dop853", rtol=rtol, atol=rtol / 100)
        assert res.formulation == "reduced-u"
        errs.append(axis_error(res.axis, exact_axis(d, res.t)))
        assert errs[-1] <= 10 * rtol, (name, rtol, errs[-1])
    assert errs[1] < errs[0] / 10


def test_taylor_axis_matches_the_exact_heavy_top():
    """The quadratures α, γ are in the Taylor step control at the scale of their rates (they
    feed nothing back, but their integrand is singular nearer than u's own singularities)."""
    failures = []
    for name, d in sorted(SCENES.items()):
        for rtol in (1e-8, 1e-10, 1e-12):
            res = run(d, method="taylor", rtol=rtol, atol=rtol / 100)
            err = axis_error(res.axis, exact_axis(d, res.t))
            if err > 10 * rtol:
                failures.append((name, rtol, err))
    assert not failures


def _init(d):
    """(y, p, parameter names) of the reduced-u model's init map for scene dict ``d``."""
    sc = load_scene(d)
    desc = catalogue.describe(("reduced-u", True, ("gravity",)))
    kernel = ModelKernel.load(desc, "dop853")
    y, p, rc = kernel.init(inputs_of(sc), params_of(sc, desc))
    assert rc == 0
    return y, dict(zip(desc.params, p))


def test_init_map_from_the_euler_rates():
    b, a, g = 0.8, 0.3, -0.2
    ad, bd, gd = -0.4, 0.3, 6.0
    y, p = _init(scene(beta=b, alpha_dot=ad, beta_dot=bd, gamma_dot=gd))
    pg = I3 * (gd + ad * math.cos(b))                  # ∂L/∂γ̇
    pa = I1 * ad * math.sin(b) ** 2 + pg * math.cos(b)  # ∂L/∂α̇
    Ep = 0.5 * I1 * (bd**2 + ad**2 * math.sin(b) ** 2) + MGL * math.cos(b)
    assert p["p_gamma"] == pytest.approx(pg, rel=1e-15)
    assert p["p_alpha"] == pytest.approx(pa, rel=1e-15)
    assert p["E_prime"] == pytest.approx(Ep, rel=1e-15)
    assert y == pytest.approx([a, math.cos(b), g, -math.sin(b) * bd], rel=1e-15)


def test_init_map_from_omega():
    b, a, g = 1.1, 0.3, -0.2
    w = np.array([0.4, -0.7, 5.0])
    y, p = _init(scene(beta=b, omega=w))
    R = exact.euler_matrix(a, b, g)
    L = R @ (np.array([I1, I1, I3]) * w)                # inertial angular momentum
    T = 0.5 * float(np.dot([I1, I1, I3], w**2))
    pg = I3 * w[2]
    assert p["p_gamma"] == pytest.approx(pg, rel=1e-15)
    assert p["p_alpha"] == pytest.approx(L[2], rel=1e-14)
    assert p["E_prime"] == pytest.approx(T + MGL * R[2, 2] - pg**2 / (2 * I3), rel=1e-14)
    beta_dot = w[0] * math.sin(g) + w[1] * math.cos(g)  # the rates of ω̃ = B(q) q̇
    assert y == pytest.approx([a, math.cos(b), g, -math.sin(b) * beta_dot], rel=1e-14)


def test_conserved_quantities_and_energy_from_the_state():
    d = SCENES["omega-given"]
    res = run(d, rtol=1e-12, atol=1e-14)
    w = np.array(d["initial"]["omega"])
    R = exact.euler_matrix(d["initial"]["alpha"], d["initial"]["beta"], d["initial"]["gamma"])
    E0 = 0.5 * float(np.dot([I1, I1, I3], w**2)) + MGL * R[2, 2]
    assert np.max(np.abs(res.energy - E0)) <= 1e-10 * E0
    assert np.ptp(res.energy) > 0  # computed from (u, u̇): it shows the drift, not a constant
    # p_α = ẑ·L and p_γ = I₃ ω̃₃ from the output ω̃ and axes, against the conserved parameters.
    L_z = np.einsum("ij,ij->i", res.n, res.L)
    assert np.max(np.abs(L_z - res.p_alpha)) <= 1e-9 * np.max(np.abs(res.p_alpha))
    assert np.max(np.abs(I3 * res.omega[:, 2] - res.p_gamma)) <= 1e-9 * abs(res.p_gamma[0])


@pytest.mark.parametrize("other", ["reduced", "euler-angles"])
def test_agrees_with_the_other_formulations(other):
    d = SCENES["reference"]
    ours = run(d, rtol=1e-12, atol=1e-14)
    theirs = derive.simulate(d, formulation=other, rtol=1e-12, atol=1e-14)
    assert np.max(np.abs(ours.axis - theirs.axis)) <= 1e-10
    assert np.max(np.abs(np.unwrap(ours.alpha) - np.unwrap(theirs.alpha))) <= 1e-10
    assert np.max(np.abs(np.unwrap(ours.gamma) - np.unwrap(theirs.gamma))) <= 1e-9
    assert np.max(np.abs(ours.beta - theirs.beta)) <= 1e-10
    assert np.max(np.abs(ours.omega - theirs.omega)) <= 1e-9 * np.max(np.abs(theirs.omega))


def test_start_close_to_the_pole_clearance():
    """sin β stays in [0.104, 0.141], just clear of reduced-u's clearance (0.1): the axis error
    δu/sin β is amplified about tenfold here, and stays within 10 rtol at 1e-10."""
    clearance = REGISTRY["reduced-u"].clearance
    d = scene(beta=0.105, alpha_dot=0.0, beta_dot=0.0, gamma_dot=6.0, t_end=5.0)
    ref = derive.simulate(d, formulation="euler-poisson", rtol=1e-13, atol=1e-15)
    assert clearance < np.min(np.sin(ref.beta)) < 1.1 * clearance
    res = run(d, rtol=1e-10, atol=1e-12)
    assert res.formulation == "reduced-u"
    assert np.max(np.abs(res.axis - ref.axis)) <= 10 * 1e-10


def test_pole_check_refuses_a_motion_that_reaches_a_pole():
    """Its own clearance: a start inside it is not applicable; a start outside whose motion
    comes within it is refused by the compiled pole check; auto takes another formulation."""
    clearance = REGISTRY["reduced-u"].clearance
    d = scene(beta=0.3, alpha_dot=0.0, beta_dot=-2.0, gamma_dot=6.0, t_end=5.0)
    ref = derive.simulate(d, formulation="euler-poisson", rtol=1e-12, atol=1e-14)
    assert POLE_CLEARANCE < np.min(np.abs(np.sin(ref.beta))) < clearance  # inside reduced-u's only
    with pytest.raises(IntegrationError, match="pole"):
        run(d)
    assert auto_formulation(load_scene(d)) != "reduced-u"
    near = scene(beta=0.05)
    assert REGISTRY["reduced-u"].applicable(load_scene(near)) is not None
    assert auto_formulation(load_scene(near)) != "reduced-u"


def test_auto_prefers_reduced_u_where_it_applies_for_either_method():
    assert auto_formulation(load_scene(SCENES["reference"])) == "reduced-u"
    assert auto_formulation(load_scene(scene(method="taylor"))) == "reduced-u"


def _model_kernel():
    """The compiled rhs and Jacobian of the generated model (its .h and .c alone)."""
    desc = catalogue.describe(("reduced-u", True, ("gravity",)))
    src = {n: desc.source(f"c/{n}") for n in (f"{desc.name}.h", f"{desc.name}.c")}
    return Kernel.from_sources(desc.name, len(desc.states), src, methods=["dop853"])


def test_rhs_and_jacobian_match_the_notes_polynomial():
    """The compiled rhs and Jacobian against the notes' equations, differentiated here."""
    u, ud, a, g = sp.symbols("u u_d alpha gamma", real=True)
    i1, i3, m, gg, ll, pa, pg, Ep = sp.symbols("I1 I3 M g l p_alpha p_gamma E_prime", real=True)
    f = 2 / i1 * (1 - u**2) * (Ep - m * gg * ll * u) - (pa - pg * u) ** 2 / i1**2
    ad = (pa - pg * u) / (i1 * (1 - u**2))
    rhs = sp.Matrix([ad, ud, pg / i3 - u * ad, sp.diff(f, u) / 2])
    y_sym, p_sym = (a, u, g, ud), (i1, i3, m, gg, ll, pa, pg, Ep)
    F = sp.lambdify([y_sym, p_sym], rhs, "mpmath")
    J = sp.lambdify([y_sym, p_sym], rhs.jacobian(sp.Matrix(y_sym)), "mpmath")
    desc = catalogue.describe(("reduced-u", True, ("gravity",)))
    assert desc.states == ("alpha", "u", "gamma", "u_d")
    assert desc.params == ("I1", "I3", "M", "g", "l", "p_alpha", "p_gamma", "E_prime")
    kernel = _model_kernel()
    rng = np.random.default_rng(20)
    for _ in range(20):
        y = np.array([rng.uniform(-3, 3), rng.uniform(-0.99, 0.99), rng.uniform(-3, 3),
                      rng.normal()])
        p = np.array([rng.uniform(0.5, 2), rng.uniform(0.2, 2), 1.0, rng.uniform(0, 10),
                      rng.uniform(0.1, 1), rng.normal(), rng.normal(), rng.normal()])
        want = np.array(F(y, p).tolist(), dtype=float).ravel()
        np.testing.assert_allclose(kernel.rhs(0.0, y, p), want, rtol=1e-13, atol=1e-13 * np.max(np.abs(want)))
        want_j = np.array(J(y, p).tolist(), dtype=float)
        np.testing.assert_allclose(kernel.jac(0.0, y, p).reshape(4, 4), want_j, rtol=1e-13,
                                   atol=1e-13 * np.max(np.abs(want_j)))


def test_alpha_rate_is_exact_at_p_alpha_equal_p_gamma():
    """The guarded partial fraction: p_α = p_γ near u = 1 gives (p_α + p_γ)/(2 I₁ (1 + u)), no
    0/0, and no cancellation (against mpmath at 50 digits)."""
    import mpmath as mp

    kernel = _model_kernel()
    p = np.array([1.0, 0.5, 1.0, 1.0, 1.0, 3.0, 3.0, 2.0])
    for uu in (1 - 1e-6, 1 - 1e-12, 1.0):
        got = kernel.rhs(0.0, np.array([0.0, uu, 0.0, 0.0]), p)[0]
        mp.mp.dps = 50
        want = float(mp.mpf(6) / (2 * (1 + mp.mpf(uu))))
        assert got == pytest.approx(want, rel=1e-15)
