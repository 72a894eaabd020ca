"""Tops on a table: the derived contact equations against independent derivations, the phases
and their events, the integrals each case keeps, the analysis, and bad scenes."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from compile_once import compiles_once
from derive.contact import analysis, driver
from derive.contact.kernel import OUTPUTS, kernel
from derive.contact.phases import quaternion_matrix
from derive.contact.scene import read
from derive.contact.simulate import initial_state, params, quaternion, run_scene
from derive.errors import IntegrationError, SceneError
from kept_results import kept

O = {name: i for i, name in enumerate(OUTPUTS)}
TIPPE = {"body": {"I1": 8e-7, "I3": 7e-7}, "gravity": {"M": 0.006, "g": 9.81},
         "contact": {"shape": "sphere", "radius": 0.015, "offset": 0.003, "friction": "coulomb", "mu": 0.3},
         "initial": {"beta": 0.1, "omega": [0.0, 0.0, 180.0]}}


def _scene(base, **tables):
    d = {k: dict(v) for k, v in base.items()}
    for k, v in tables.items():
        d.setdefault(k, {}).update(v)
    return d


def _state(shape, law, p, angles, w, rolling=False):
    """A state touching the plane (z and v_z from the contact; v = −ω × a when rolling)."""
    k = kernel(shape, law)
    q = quaternion(*angles)
    y = np.concatenate([q, w, np.zeros(6)])
    a = k.outputs(2, y, p, np.zeros(3))[O["a_x"]:O["a_z"] + 1]
    y[9] = -a[2]
    v = -np.cross(quaternion_matrix(q) @ w, a)
    y[10:13] = v if rolling else (0.3, -0.2, v[2])
    return k, y


def _slip_rate(k, phase, y, p, d, h=1e-6):
    """d/dt of the contact point's velocity (inertial) along the phase's flow, central differences."""
    dy = k.rhs(phase, y, p, d)

    def u(yy):
        o = k.outputs(2, yy, p, d)
        return yy[10:13] + np.cross(quaternion_matrix(yy[:4]) @ yy[4:7], o[O["a_x"]:O["a_z"] + 1])
    return (u(y + h * dy) - u(y - h * dy)) / (2 * h)


def reference(name, args, compute):
    """``compute()``, an independent derivation's numbers, kept between test runs
    (tests/kept_results.py) under ``name``, its arguments and this file's bytes: the contact
    equations are held to it on every run, it is derived again when this file or the
    environment changes."""
    return kept("contact-reference", (name, args), compute, [Path(__file__)])


P_TIPPE = np.array([8e-7, 8e-7, 7e-7, 0.006, 9.81, 0.015, 0.003, 0.3, 0.0, 0.0, 0.0])


def test_a_body_at_rest_upright_presses_with_its_weight():
    for shape in ("point", "sphere"):
        k, y = _state(shape, "none", P_TIPPE, (0.0, 0.0, 0.0), np.zeros(3))
        y[10:13] = 0.0
        assert k.outputs(0, y, P_TIPPE, np.zeros(3))[O["N"]] == pytest.approx(0.006 * 9.81, rel=1e-14)


@pytest.mark.parametrize("shape,law", [("sphere", "coulomb"), ("sphere", "viscous"), ("disc", "coulomb"),
                                       ("point", "coulomb_regularized")])
def test_the_sliding_normal_force_keeps_the_contact_on_the_plane(shape, law):
    p = P_TIPPE.copy()
    p[6] = 0.0 if shape == "disc" else p[6]
    k, y = _state(shape, law, p, (0.3, 0.7, 1.1), np.array([3.0, -2.0, 40.0]))
    assert abs(_slip_rate(k, 0, y, p, np.array([1.0, 0, 0]))[2]) < 1e-7


@pytest.mark.parametrize("shape", ["sphere", "disc"])
def test_the_rolling_force_keeps_the_contact_point_at_rest(shape):
    p = P_TIPPE.copy()
    k, y = _state(shape, "rolling", p, (0.3, 0.9, 1.1), np.array([3.0, -2.0, 40.0]), rolling=True)
    assert np.max(np.abs(_slip_rate(k, 1, y, p, np.zeros(3)))) < 1e-7


def _pointed_top_on_a_frictionless_plane(I1, I3, M, g, l, state):
    """z̈ and ω̃ of a pointed top on a frictionless plane at ``state`` (α, β, γ and their rates)
    from L = ½ M ż² + T_rot − M g z(β), z = l cos β, with the Euler–Lagrange equations written
    out here."""
    b, a_, g_ = sp.symbols("b a c", real=True)
    bd, ad, gd = sp.symbols("bd ad gd", real=True)
    w1 = -ad * sp.sin(b) * sp.cos(g_) + bd * sp.sin(g_)
    w2 = ad * sp.sin(b) * sp.sin(g_) + bd * sp.cos(g_)
    w3 = ad * sp.cos(b) + gd
    z = l * sp.cos(b)
    zd = sp.diff(z, b) * bd
    L = M * zd**2 / 2 + (I1 * (w1**2 + w2**2) + I3 * w3**2) / 2 - M * g * z
    q, qd = (a_, b, g_), (ad, bd, gd)
    qdd = sp.symbols("add bdd gdd")
    eqs = [sum(sp.diff(L, v, w) * x for w, x in zip(qd, qdd)) + sum(sp.diff(L, v, w) * x for w, x in zip(q, qd))
           - sp.diff(L, c) for v, c in zip(qd, q)]
    sol = sp.solve(eqs, qdd, dict=True)[0]
    state = dict(zip((a_, b, g_, ad, bd, gd), state))
    bdd = float(sol[qdd[1]].subs(state))
    zdd = float((sp.diff(z, b, 2) * bd**2).subs(state)) + float(sp.diff(z, b).subs(state)) * bdd
    return zdd, np.array([float(e.subs(state)) for e in (w1, w2, w3)])


def test_the_normal_force_equals_an_independent_lagrangian_derivation():
    """A pointed top on a frictionless plane from L = ½ M ż² + T_rot − M g z(β), z = l cos β, with
    the Euler–Lagrange equations written out here: N = M (g + z̈)."""
    I1, I3, M, g, l = 1e-4, 5e-5, 0.1, 9.81, 0.04
    args = (I1, I3, M, g, l, (0.2, 0.6, 0.4, 2.0, 1.5, 90.0))
    zdd, w = reference("pointed-top-lagrangian", args, lambda: _pointed_top_on_a_frictionless_plane(*args))
    p = np.array([I1, I1, I3, M, g, 0.0, -l, 0.0, 0.0, 0.0, 0.0])
    k, y = _state("point", "none", p, (0.2, 0.6, 0.4), w)
    assert k.outputs(0, y, p, np.zeros(3))[O["N"]] == pytest.approx(M * (g + zdd), rel=1e-12)


def test_jellett_and_routh_are_constant_along_the_rolling_equations():
    p = np.array([1e-3, 1e-3, 0.9e-3, 1.0, 9.81, 0.05, 0.01, 0.0, 0.0, 0.0, 0.0])
    k, y = _state("sphere", "rolling", p, (0.3, 1.0, 2.0), np.array([2.0, -1.0, 5.0]), rolling=True)
    dy = k.rhs(1, y, p, np.zeros(3))
    h = 1e-6
    up, dn = (k.outputs(1, y + s * h * dy, p, np.zeros(3)) for s in (1, -1))
    for name in ("jellett", "routh", "energy"):
        scale = abs(k.outputs(1, y, p, np.zeros(3))[O[name]])
        assert abs(up[O[name]] - dn[O[name]]) / (2 * h) / scale < 1e-7, name


def test_a_frictionless_top_keeps_its_energy_and_both_momenta():
    r = run_scene(read_example("frictionless_top"), t_end=0.5)
    for v in (r.energy, r.p_alpha, r.p_gamma):
        assert np.max(np.abs(v - v[0])) <= 1e-12 * abs(v[0])
    assert set(r.phase) == {"slide"} and not r.switches


def test_rouths_sphere_keeps_energy_jellett_and_routh():
    r = run_scene(read_example("rolling_sphere"), t_end=2.0)
    for v in (r.energy, r.integrals["jellett"], r.integrals["routh"]):
        assert np.max(np.abs(v - v[0])) <= 1e-11 * abs(v[0])
    assert np.max(r.slip_speed) < 1e-9


def test_exact_coulomb_tippe_top_is_captured_into_rolling_at_a_located_event_keeping_jellett():
    r = run_scene(_scene(TIPPE, simulate={"t_end": 0.1, "samples": 201}))
    assert [(s.event, s.before, s.after) for s in r.switches] == [("stick", "slide", "roll")]
    assert 0.03 < r.switches[0].t < 0.04
    J = r.integrals["jellett"]
    assert np.max(np.abs(J - J[0])) <= 1e-10 * abs(J[0])
    sliding = r.phase == "slide"
    assert np.all(np.diff(r.energy[sliding]) <= 1e-15 * r.energy[0])
    rolling = r.phase == "roll"
    assert np.ptp(r.energy[rolling]) <= 1e-11 * r.energy[0]


def test_a_knocked_top_lifts_off_at_a_located_event_and_lands():
    d = {"body": {"I1": 2e-5, "I3": 1.5e-5}, "gravity": {"M": 0.05, "g": 9.81},
         "contact": {"shape": "sphere", "radius": 0.005, "offset": -0.01, "friction": "coulomb", "mu": 0.3},
         "initial": {"beta": 0.5, "gamma_dot": 150.0, "beta_dot": 40.0}, "simulate": {"t_end": 0.1, "samples": 401}}
    r = run_scene(d)
    events = [s.event for s in r.switches]
    assert events[:3] == ["landing", "lift-off", "landing"]  # the knock starts it in the air
    for s in r.switches:
        if s.event == "lift-off":
            assert s.energy_after == pytest.approx(s.energy_before, rel=1e-12)
        else:
            assert s.energy_after <= s.energy_before  # an inelastic impact loses energy
    flight = np.where(r.phase == "flight")[0]
    assert len(flight) > 2 and np.all(r.gap[flight] >= -1e-12)
    runs = np.split(flight, np.where(np.diff(flight) > 1)[0] + 1)
    for idx in runs:
        assert np.ptp(r.energy[idx]) <= 1e-10 * r.energy[0]
    J = r.integrals["jellett"]
    assert np.max(np.abs(J - J[0])) <= 1e-9 * abs(J[0])


def test_the_analysis_derives_the_inversion_interval_and_final_spin():
    assert analysis.inversion_interval() == (1 - analysis.RATIO, 1 + analysis.RATIO)
    spin = analysis.final_spin().subs({analysis.RATIO: 0.2, analysis.N0: 180.0, analysis.THETA0: 0.1})
    assert float(spin) == pytest.approx(-119.2506, abs=1e-4)
    out = analysis.analyze(read(TIPPE))
    assert out["inversion"]["inverts"] and [i["name"] for i in out["integrals"]] == ["jellett"]


def test_the_sleeping_top_on_a_frictionless_plane_uses_the_moment_about_the_centre_of_mass():
    from derive.contact.equations import I1, I3, MASS, GRAV
    from derive.contact.geometry import OFFSET

    # the tip at s = −l below the centre of mass: I₃²ω₃² > 4 I₁ M g l, I₁ about the centre of mass
    expected = I3**2 * analysis.SPIN**2 + 4 * I1 * MASS * GRAV * OFFSET
    assert sp.expand(analysis.sleeping_condition("point") - expected) == 0
    assert sp.expand(analysis.sleeping_condition("sphere") - expected) == 0


@pytest.mark.parametrize("change,key", [
    ({"contact": {"mu": -0.1}}, "contact.mu"),
    ({"contact": {"shape": "cube"}}, "contact.shape"),
    ({"contact": {"radius": -0.01}}, "contact.radius"),
    ({"gravity": {"l": 0.1}}, "gravity.l"),
    ({"gravity": {"com": [0, 0, 0.1]}}, "gravity.com"),
    ({"contact": {"friction": "viscous", "regularization": 0.01}}, "contact.regularization"),
    ({"contact": {"friction": "rolling", "mu": None}, "initial": {"vx": 0.1}}, "initial.vx"),
    ({"contact": {"friction": "none", "mu": None, "regularization": 0.01}}, "contact.regularization"),
    ({"contact": {"friction": "sticky"}}, "contact.friction"),
    ({"simulate": {"rtol": 1e-16}}, "simulate.rtol"),
    ({"body": {"I3": 2.0e-6}}, "body"),
    ({"damping": {"c": 0.1}}, "damping"),
])
def test_a_bad_contact_scene_names_its_key(change, key):
    d = _scene(TIPPE, **change)
    d["contact"] = {k: v for k, v in d["contact"].items() if v is not None}
    with pytest.raises(SceneError, match=rf": {key}: "):
        read(d, "top.toml")


def test_the_command_line_runs_a_contact_scene_and_refuses_a_bad_one(tmp_path, capsys):
    from derive.cli import main

    out = tmp_path / "r.npz"
    assert main(["simulate", "rolling_sphere", "--t-end", "0.2", "-o", str(out)]) == 0
    data = np.load(out)
    for name in ("com", "contact", "normal_force", "slip_speed", "phase", "integral_jellett", "integral_routh"):
        assert name in data.files
    bad = tmp_path / "bad.toml"
    bad.write_text('[body]\nI1 = 1.0\nI3 = 0.5\n[gravity]\nM = 1.0\ng = 9.81\n'
                   '[contact]\nshape = "sphere"\nradius = 0.1\nfriction = "coulomb"\nmu = -1.0\n')
    capsys.readouterr()
    assert main(["simulate", str(bad), "-o", str(tmp_path / "x.npz")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "contact.mu" in err and not (tmp_path / "x.npz").exists()
    assert main(["analyze", "tippe_top", "--format", "json"]) == 0
    assert '"final_spin": -119.25' in capsys.readouterr().out


def read_example(name):
    import tomllib

    from derive.codegen.render import data_dir

    return tomllib.loads((data_dir("scenes") / "contact" / f"{name}.toml").read_text(encoding="utf-8"))


def test_initial_state_touches_the_plane_with_no_normal_velocity():
    sc = read(TIPPE)
    y = initial_state(sc)
    o = kernel("sphere", "coulomb").outputs(0, y, params(sc), np.zeros(3))
    assert o[O["gap"]] == 0.0 and abs(o[O["u_n"]]) < 1e-15


@pytest.mark.slow
def test_the_tippe_top_with_viscous_friction_inverts_to_jelletts_spin():
    r = run_scene(_scene(TIPPE, contact={"friction": "viscous"}, simulate={"t_end": 3.0, "samples": 3001}))
    assert np.all(np.diff(r.energy) <= 1e-15 * r.energy[0])  # Ė = −μ|u_t|² ≤ 0
    near = np.where(r.beta > np.pi - 0.02)[0]
    assert len(near) > 0
    expected = 180.0 * (0.2 - np.cos(0.1)) / 1.2
    assert abs(r.omega[near[0], 2] - expected) <= 1e-3 * abs(expected)
    J = r.integrals["jellett"]
    assert np.max(np.abs(J - J[0])) <= 1e-10 * abs(J[0])


def _compiles_clean(pairs):
    """Each evaluator as the libraries compile it (``generated/contact``, which test_codegen
    holds equal to its derivation), with what it includes, under the strict flags."""
    from derive.contact import kernel as ck

    for shape, law in pairs:  # each kept for its exact sources (tests/compile_once.py)
        files = ck.reduced_sources(shape) if law == "reduced" else ck.model_sources(shape, law)
        compiles_once(files, f"contact_{shape}_{law}.c")


def test_the_contact_kernels_compile_clean_under_the_strict_flags():
    # a representative of each kind (no contact force, sliding, rolling, reduced): the others are slow
    _compiles_clean([("point", "none"), ("sphere", "coulomb"), ("sphere", "rolling"), ("point", "reduced")])


@pytest.mark.slow
def test_every_contact_kernel_compiles_clean_under_the_strict_flags():
    _compiles_clean([(s, law) for s in ("point", "sphere", "disc")
                     for law in ("none", "coulomb", "coulomb_regularized", "viscous", "rolling", "reduced")])


def test_exact_coulomb_moves_less_than_a_thousandth_when_the_tolerance_is_tightened_tenfold():
    runs = [run_scene(_scene(TIPPE, simulate={"t_end": 0.3, "samples": 301, "rtol": rtol, "atol": rtol * 1e-2}))
            for rtol in (1e-9, 1e-10)]
    (a, b) = runs
    assert [s.event for s in a.switches] == [s.event for s in b.switches] == ["stick"]
    assert abs(a.switches[0].t - b.switches[0].t) <= 1e-3 * b.switches[0].t
    assert abs(a.beta[-1] - b.beta[-1]) <= 1e-3 * b.beta[-1]


def newton_euler_inertial(eps, t_end, rtol=1e-12, delta=0.0, rs=0.0):
    """The sliding tippe top under regularised Coulomb friction, written independently: inertial
    frame, rotation matrix and inertial ω as states, the ball's centre held at height r, N solved
    from M z̈ = N − M g by its linearity (two evaluations), with the moments of rolling resistance
    −δN ω_t/|ω_t| and spin friction −μN r_s σ ẑ when δ, r_s are given. Returns SciPy's solution
    (stopped where β first reaches π/2: its ``t_events[0]``)."""
    from scipy.integrate import solve_ivp

    I = np.diag([8e-7, 8e-7, 7e-7])
    M, g, r, s, mu = 0.006, 9.81, 0.015, 0.003, 0.3
    zhat = np.array([0.0, 0.0, 1.0])

    def forces(R, w, v):
        e3 = R[:, 2]
        Iin = R @ I @ R.T
        a = s * e3 - r * zhat
        vz = -s * np.cross(w, e3)[2]
        vel = np.array([v[0], v[1], vz])
        u = vel + np.cross(w, a)
        ut = np.array([u[0], u[1], 0.0])
        phi = -mu * ut / np.sqrt(ut @ ut + eps**2)
        wt, x = np.array([w[0], w[1], 0.0]), rs * w[2]
        m = (-delta * wt / np.linalg.norm(wt) if delta else 0.0) - mu * rs * x / np.sqrt(x * x + eps**2) * zhat

        def wdot(N):
            return np.linalg.solve(Iin, np.cross(a, N * (zhat + phi)) + N * m - np.cross(w, Iin @ w))

        def residual(N):  # M z̈ − (N − M g), z = r − s e3_z
            e3dd = np.cross(wdot(N), e3) + np.cross(w, np.cross(w, e3))
            return -M * s * e3dd[2] - (N - M * g)
        c0, c1 = residual(0.0), residual(1.0)
        N = -c0 / (c1 - c0)
        return N * (zhat + phi), wdot(N)

    def rhs(t, y):
        R, w, v = y[:9].reshape(3, 3), y[9:12], y[12:14]
        F, wd = forces(R, w, v)
        W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        return np.concatenate([(W @ R).ravel(), wd, F[:2] / M])

    R0 = np.array([[np.cos(0.1), 0, np.sin(0.1)], [0, 1, 0], [-np.sin(0.1), 0, np.cos(0.1)]])
    w0 = R0 @ np.array([0.0, 0.0, 180.0])
    ev = lambda t, y: y[8]  # R33 = cos β
    ev.terminal, ev.direction = True, -1
    return solve_ivp(rhs, (0, t_end), np.concatenate([R0.ravel(), w0, [0.0, 0.0]]), method="DOP853",
                     rtol=rtol, atol=rtol * 1e-3, events=ev)


@pytest.mark.slow
def test_regularised_coulomb_tippe_top_passes_ninety_degrees_when_an_independent_integration_does():
    from scipy.interpolate import CubicSpline

    eps = 1e-2
    r = run_scene(_scene(TIPPE, contact={"regularization": eps},
                         simulate={"t_end": 1.2, "samples": 24001, "rtol": 1e-12, "atol": 1e-14}))
    i = int(np.argmax(r.beta > np.pi / 2))
    sl = slice(i - 4, i + 4)
    t90 = float(CubicSpline(r.t[sl], np.cos(r.beta[sl])).solve(0.0, extrapolate=False)[0])
    reference = float(newton_euler_inertial(eps, 1.2).t_events[0][0])
    assert abs(t90 - reference) <= 1e-4 * reference
    J = r.integrals["jellett"]
    assert np.max(np.abs(J - J[0])) <= 1e-10 * abs(J[0])


def _frictionless_reference(b0=0.5, spin=100.0, I1=1e-4, I3=5e-5, M=0.1, g=9.81, l=0.04):
    """The pointed top on a frictionless plane by quadrature, released at rest in β and α: the
    centre of mass on a vertical line, E = ½ (I₁ + M l² sin²β) β̇² + V_eff(β). Returns the
    largest tilt and the nutation period."""
    from scipy.integrate import quad
    from scipy.optimize import brentq

    pa, pg = I3 * spin * np.cos(b0), I3 * spin
    V = lambda b: (pa - pg * np.cos(b)) ** 2 / (2 * I1 * np.sin(b) ** 2) + M * g * l * np.cos(b)
    f = lambda b: V(b0) - V(b)
    bmax = brentq(f, b0 + 1e-6, 2.5, xtol=1e-16)
    c, h = (b0 + bmax) / 2, (bmax - b0) / 2
    rate = lambda b: np.sqrt(2 * f(b) / (I1 + M * l * l * np.sin(b) ** 2))
    T = 2 * quad(lambda ph: h * np.cos(ph) / rate(c + h * np.sin(ph)), -np.pi / 2, np.pi / 2,
                 epsabs=1e-15, epsrel=1e-13, limit=200)[0]
    return bmax, T


def test_the_frictionless_tilt_range_and_nutation_period_equal_an_independent_quadrature():
    from scipy.interpolate import make_interp_spline
    from scipy.optimize import brentq

    r = run_scene(read_example("frictionless_top"), t_end=1.0, samples=20001)
    beta = make_interp_spline(r.t, r.beta, k=5)
    rate = beta.derivative()
    db = rate(r.t)
    turns = np.array([brentq(rate, r.t[i], r.t[i + 1], xtol=1e-15)
                      for i in np.where(np.sign(db[:-1]) != np.sign(db[1:]))[0]])
    bmax, period = _frictionless_reference()
    tops = turns[beta(turns) > 0.6]
    assert np.max(np.abs(beta(tops) - bmax)) <= 1e-9 * bmax
    assert abs((tops[-1] - tops[0]) / (len(tops) - 1) - period) <= 1e-9 * period


@pytest.mark.slow
def test_the_tippe_top_with_regularised_coulomb_friction_inverts_to_jelletts_spin():
    r = run_scene(_scene(TIPPE, contact={"regularization": 1e-2}, simulate={"t_end": 13.0, "samples": 6501}))
    near = np.where(r.beta > np.pi - 0.02)[0]
    assert len(near) > 0
    expected = 180.0 * (0.2 - np.cos(0.1)) / 1.2
    assert abs(r.omega[near[0], 2] - expected) <= 1e-3 * abs(expected)
    J = r.integrals["jellett"]
    assert np.max(np.abs(J - J[0])) <= 1e-10 * abs(J[0])


@pytest.mark.slow
def test_a_frictionless_top_keeps_its_integrals_over_a_hundred_nutations():
    r = run_scene(read_example("frictionless_top"), t_end=100 * _frictionless_reference()[1], samples=2001)
    for v in (r.energy, r.p_alpha, r.p_gamma):
        assert np.max(np.abs(v - v[0])) <= 1e-12 * abs(v[0])


def _extrema(t, b):
    from scipy.interpolate import make_interp_spline
    from scipy.optimize import brentq

    spline = make_interp_spline(t, b, k=5)
    rate = spline.derivative()
    db = rate(t)
    return spline(np.array([brentq(rate, t[i], t[i + 1], xtol=1e-15)
                            for i in np.where(np.sign(db[:-1]) != np.sign(db[1:]))[0]]))


def _routh_sphere_reference(t):
    """Routh's sphere written independently: inertial frame, the ball's centre rolling with
    v_c = ω × r ẑ, the contact force eliminated into (I⁰ − M [a]ₓ²) ω̇ = −ω × I⁰ω
    + M a × (g ẑ − s ω × (ω × ê₃)). Returns β at the times t."""
    from scipy.integrate import solve_ivp

    I = np.diag([1e-3, 1e-3, 0.9e-3])
    M, g, r, s = 1.0, 9.81, 0.05, 0.01
    zhat = np.array([0.0, 0.0, 1.0])

    def rhs(_, y):
        R, w = y[:9].reshape(3, 3), y[9:12]
        e3 = R[:, 2]
        Iin = R @ I @ R.T
        a = s * e3 - r * zhat
        ax = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
        wd = np.linalg.solve(Iin - M * ax @ ax, -np.cross(w, Iin @ w)
                             + M * np.cross(a, g * zhat - s * np.cross(w, np.cross(w, e3))))
        W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        return np.concatenate([(W @ R).ravel(), wd])

    R0 = np.array([[np.cos(1.0), 0, np.sin(1.0)], [0, 1, 0], [-np.sin(1.0), 0, np.cos(1.0)]])
    sol = solve_ivp(rhs, (0, t[-1]), np.concatenate([R0.ravel(), 3.0 * zhat + 5.0 * R0[:, 2]]),
                    method="DOP853", rtol=1e-13, atol=1e-15, t_eval=t)
    return np.arccos(np.clip(sol.y[8], -1, 1))


def test_rouths_sphere_tilt_range_equals_an_independent_derivation():
    r = run_scene(read_example("rolling_sphere"), t_end=1.0, samples=10001)
    ours = _extrema(r.t, r.beta)
    ref = _extrema(r.t, reference("routh-sphere", r.t.tobytes(), lambda: _routh_sphere_reference(r.t)))
    assert len(ref) >= 3
    for pick in (lambda e: e[e > 0.5], lambda e: e[e < 0.5]):
        assert np.max(np.abs(pick(ours)[:, None] - pick(ref)[None, :]).min(axis=0)) <= 1e-9


def test_the_compiled_phase_loop_takes_the_steps_scipys_dop853_takes():
    d = _scene(TIPPE, simulate={"t_end": 0.3, "samples": 301})
    c, s = run_scene(d), run_scene(d, method="scipy-dop853")
    assert (c.method, s.method) == ("dop853", "scipy-dop853")
    assert [x.event for x in c.switches] == [x.event for x in s.switches] == ["stick"]
    # a slip below rtol (|v| + |ω||a|) ≈ 2e-10 m/s sticks at the step's end; it falls at ~6 m/s²,
    # so either loop may stick up to ~4e-11 s before the slip's zero
    assert abs(c.switches[0].t - s.switches[0].t) <= 1e-10
    assert np.max(np.abs(c.omega - s.omega)) <= 1e-9 * 180.0
    assert np.max(np.abs(c.beta - s.beta)) <= 1e-10


def test_a_spent_step_budget_is_a_numerical_failure_saying_where():
    from derive.errors import IntegrationError

    with pytest.raises(IntegrationError, match=r"t = .*step budget"):
        run_scene(_scene(TIPPE, simulate={"t_end": 1.0, "max_steps": 20}))


@pytest.mark.slow
def test_a_frictionless_top_keeps_its_integrals_over_a_thousand_nutations_at_the_tightest_tolerance():
    r = run_scene(read_example("frictionless_top"), t_end=1000 * _frictionless_reference()[1], samples=2001,
                  rtol=2.2e-14, atol=1e-17, max_steps=10_000_000)
    for v in (r.energy, r.p_alpha, r.p_gamma):
        assert np.max(np.abs(v - v[0])) <= 1e-12 * abs(v[0])


@pytest.mark.slow
def test_a_frictionless_top_keeps_its_integrals_over_ten_thousand_nutations():
    r = run_scene(read_example("frictionless_top"), t_end=10_000 * _frictionless_reference()[1], samples=2001,
                  rtol=2.2e-14, atol=1e-17, max_steps=100_000_000)
    assert r.formulation == "contact-reduced"
    for v in (r.energy, r.p_alpha, r.p_gamma):
        assert np.max(np.abs(v - v[0])) <= 1e-12 * abs(v[0])


def test_the_reduced_frictionless_plane_moves_as_the_full_formulation_does():
    d = read_example("frictionless_top")
    d["initial"].update(vx=0.02, vy=-0.01, alpha=0.3, gamma=0.2, alpha_dot=3.0)
    red, full = (run_scene(d, t_end=0.3, samples=301, rtol=1e-12, atol=1e-14, method=m)
                 for m in ("auto", "scipy-dop853"))
    assert (red.formulation, full.formulation) == ("contact-reduced", "contact")
    for name in ("beta", "alpha", "gamma"):
        assert np.max(np.abs(getattr(red, name) - getattr(full, name))) <= 1e-9, name
    assert np.max(np.abs(red.omega - full.omega)) <= 1e-9 * 100
    assert np.max(np.abs(red.com - full.com)) <= 1e-11
    assert np.max(np.abs(red.normal_force - full.normal_force)) <= 1e-9 * full.normal_force.max()


def test_the_full_formulation_runs_a_frictionless_top_near_its_pole_or_leaving_the_table():
    d = read_example("frictionless_top")
    d["initial"]["beta"] = 1e-3  # sin β below the reduced chart's bound
    assert run_scene(d, t_end=0.05, samples=51).formulation == "contact"
    d["initial"].update(beta=0.5, beta_dot=12.0)  # a knock: N > 0 at the start, later zero
    r = run_scene(d, t_end=0.2, samples=51)
    assert r.normal_force[0] > 0 and r.formulation == "contact"
    assert [s.event for s in r.switches][:1] == ["lift-off"]


def _euler_disk_reference(t):
    """A thin disc rolling on its rim, written independently: inertial frame, the contact
    a = −r p/|p| with p = ẑ − (ê₃·ẑ) ê₃ and its rate by hand, the centre of mass's velocity
    −ω × a, the force eliminated into (I⁰ − M [a]ₓ²) ω̇ = −ω × I⁰ω + M a × (g ẑ − ω × ȧ).
    Returns β at the times t."""
    from scipy.integrate import solve_ivp

    I = np.diag([1.6e-4, 1.6e-4, 3.2e-4])
    M, g, r = 0.4, 9.81, 0.04
    zhat = np.array([0.0, 0.0, 1.0])

    def rhs(_, y):
        R, w = y[:9].reshape(3, 3), y[9:12]
        e3 = R[:, 2]
        e3d = np.cross(w, e3)
        c, cd = e3[2], e3d[2]
        p, pn = zhat - c * e3, np.sqrt(1 - c * c)
        pd, pnd = -cd * e3 - c * e3d, -c * cd / pn
        a, ad = -r * p / pn, -r * (pd / pn - p * pnd / pn**2)
        Iin = R @ I @ R.T
        ax = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
        wd = np.linalg.solve(Iin - M * ax @ ax, -np.cross(w, Iin @ w) + M * np.cross(a, g * zhat - np.cross(w, ad)))
        W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        return np.concatenate([(W @ R).ravel(), wd])

    R0 = np.array([[np.cos(1.2), 0, np.sin(1.2)], [0, 1, 0], [-np.sin(1.2), 0, np.cos(1.2)]])
    sol = solve_ivp(rhs, (0, t[-1]), np.concatenate([R0.ravel(), 15.0 * zhat]), method="DOP853",
                    rtol=1e-13, atol=1e-15, t_eval=t)
    return np.arccos(np.clip(sol.y[8], -1, 1))


def test_eulers_disk_rolls_as_an_independent_derivation_says():
    r = run_scene(read_example("euler_disk"), t_end=0.5, samples=501, rtol=1e-13, atol=1e-15)
    ref = reference("euler-disk", r.t.tobytes(), lambda: _euler_disk_reference(r.t))
    assert np.max(np.abs(r.beta - ref)) <= 1e-9
    assert np.ptp(r.energy) <= 1e-11 * abs(r.energy[0])


def test_the_reduced_potential_on_a_frictionless_plane_is_the_pivoted_tops_form_with_z_of_the_contact():
    from derive.contact.equations import I1, I3, MASS, GRAV
    from derive.contact.geometry import OFFSET, RADIUS
    from derive.symbolic.lagrangian import p_alpha, p_gamma
    from derive.symbolic.rotations import beta

    expected = ((p_alpha - p_gamma * sp.cos(beta)) ** 2 / (2 * I1 * sp.sin(beta) ** 2) + p_gamma**2 / (2 * I3)
                + MASS * GRAV * (RADIUS - OFFSET * sp.cos(beta)))
    assert sp.simplify(analysis.reduced_potential("sphere") - expected) == 0


def test_a_round_peg_with_little_friction_sticks_and_slips_each_nutation_keeping_jellett():
    d = read_example("round_peg_top")
    d["contact"]["mu"] = 0.1
    r = run_scene(d, t_end=0.62, samples=621)  # three nutations: sticks from 0.38 s, one each 0.07 s
    events = [s.event for s in r.switches]
    assert events.count("slip") >= 3 and events.count("stick") >= 4
    assert len(r.switches) < 60  # the cycles, not a cascade
    J = r.integrals["jellett"]
    assert np.max(np.abs(J - J[0])) <= 1e-10 * abs(J[0])
    for s in r.switches:  # nothing gains energy at a switch beyond round-off
        assert s.energy_after <= s.energy_before * (1 + 1e-12)


@pytest.mark.slow
def test_a_round_peg_with_little_friction_rises():
    d = read_example("round_peg_top")
    d["contact"]["mu"] = 0.02
    r = run_scene(d, t_end=10.0, samples=1001)
    assert r.beta[-1] < 0.15 and r.beta[0] == pytest.approx(0.5)


STEM = {"radius": 0.005, "offset": 0.016}


def _ends_on_its_stem(r):
    """The run turned over, switched to the stem at located events and stands on it at the end:
    the stem's gap closed, the ball's open, the stem's Jellett integral kept since the last switch."""
    events = [s.event for s in r.switches]
    assert events[0] == "stem" and events[-1] == "stem" and set(events) <= {"stem", "ball"}
    for s in r.switches:  # an inelastic impact at each touch: no energy gained
        assert s.energy_after <= s.energy_before * (1 + 1e-12)
    after = r.t > r.switches[-1].t
    cb = np.cos(r.beta[after])
    assert np.max(np.abs(r.com[after, 2] - (STEM["radius"] - STEM["offset"] * cb))) <= 1e-12
    assert np.all(r.com[after, 2] + 0.003 * cb - 0.015 > 0)  # the ball off the table
    J = r.integrals["jellett"][after]
    assert np.max(np.abs(J - J[0])) <= 1e-10 * abs(J[0])
    assert r.beta[-1] > np.pi - 0.1


def test_the_tippe_top_with_viscous_friction_turns_over_and_ends_on_its_stem():
    r = run_scene(read_example("tippe_top_stem"), t_end=2.0, samples=2001)
    _ends_on_its_stem(r)
    assert 0.5 < r.switches[0].t < 0.7


@pytest.mark.slow
def test_the_tippe_top_with_regularised_coulomb_friction_turns_over_and_ends_on_its_stem():
    r = run_scene(_scene(TIPPE, contact={"regularization": 1e-2, "stem": STEM},
                         simulate={"t_end": 13.0, "samples": 6501}))
    _ends_on_its_stem(r)


def test_the_stem_touches_when_scipys_dop853_says_it_does():
    d = read_example("tippe_top_stem")
    c, s = (run_scene(d, t_end=0.65, samples=66, method=m) for m in ("dop853", "scipy-dop853"))
    assert [x.event for x in c.switches] == [x.event for x in s.switches] == ["stem"]
    assert abs(c.switches[0].t - s.switches[0].t) <= 1e-9


def test_a_spent_switch_budget_is_a_numerical_failure_naming_the_time_and_the_last_switch():
    sc = read(read_example("tippe_top_stem"), "<dict>", t_end=0.7, samples=8)
    with pytest.raises(IntegrationError, match=r"more than 2 phase switches by t = 0\.68.* \(last: stem\)"):
        driver.run(sc.shape, sc.law, params(sc), sc.stem, initial_state(sc), np.linspace(0.0, 0.7, 8),
                   restitution=sc.restitution, rtol=sc.rtol, atol=sc.atol, max_steps=sc.max_steps,
                   max_switches=2)


def test_a_top_started_upside_down_stands_on_its_stem():
    d = _scene(TIPPE, contact={"friction": "viscous", "stem": STEM}, initial={"beta": np.pi - 0.05},
               simulate={"t_end": 0.05, "samples": 51})
    r = run_scene(d)
    assert r.com[0, 2] == pytest.approx(STEM["radius"] - STEM["offset"] * np.cos(np.pi - 0.05), rel=1e-14)
    assert not r.switches and np.all(r.gap >= -1e-15)


@pytest.mark.parametrize("contact,key", [
    ({"stem": {"radius": -0.005, "offset": 0.016}}, "contact.stem.radius"),
    ({"stem": {"offset": 0.016}}, "contact.stem"),
    ({"stem": {"radius": 0.005, "length": 0.016}}, "contact.stem"),
    ({"stem": 0.005}, "contact.stem"),
    ({"shape": "point", "radius": None, "stem": {"radius": 0.005}}, "contact.stem"),
])
def test_a_bad_stem_names_its_key(contact, key):
    d = _scene(TIPPE, contact=contact)
    d["contact"] = {k: v for k, v in d["contact"].items() if v is not None}
    with pytest.raises(SceneError, match=rf": {key}: "):
        read(d, "top.toml")


def test_the_stem_touches_at_the_tilt_the_analysis_derives():
    from scipy.interpolate import make_interp_spline

    d = read_example("tippe_top_stem")
    tilt = analysis.analyze(read(d))["stem"]["tilt"]
    assert np.cos(tilt) == pytest.approx((0.005 - 0.015) / (0.016 - 0.003), rel=1e-15)
    r = run_scene(d, t_end=0.65, samples=6501)
    t_s = r.switches[0].t
    assert r.switches[0].event == "stem"
    before = slice(int(np.searchsorted(r.t, t_s)) - 40, int(np.searchsorted(r.t, t_s)))  # the impact kinks β
    assert abs(float(make_interp_spline(r.t[before], r.beta[before], k=5)(t_s)) - tilt) <= 1e-9


def test_the_contact_run_path_imports_neither_sympy_nor_scipy():
    import subprocess
    import sys

    code = ("import sys, derive.contact.simulate, derive.contact.prepared, derive.export.contact, "
            "derive.export.contact_fmu, derive.sweeps.contact; "
            "print('sympy' in sys.modules, 'scipy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["False", "False"]


def test_the_run_side_names_are_the_derivation_s_symbols():
    from derive.contact import kernel as ck, reduced, scene, sources
    from derive.contact.geometry import SHAPES

    assert ck.PARAM_NAMES == tuple(str(p) for p in sources.PARAMS)
    assert reduced.PARAM_NAMES == tuple(str(p) for p in sources.REDUCED_PARAMS)
    assert scene.SHAPES == tuple(SHAPES)
    assert scene.SPHERICAL == tuple(name for name, s in SHAPES.items() if s.spherical)


def test_a_contact_model_missing_from_generated_is_derived_on_demand(tmp_path, monkeypatch):
    from derive.codegen.render import GENERATED
    from derive.contact import kernel as ck

    name = "contact_point_none.c"
    monkeypatch.setattr(ck, "GENERATED", tmp_path)
    assert ck.text(name) == (GENERATED / "contact" / name).read_text(encoding="utf-8")
