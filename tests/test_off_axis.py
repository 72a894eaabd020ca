"""The off-axis heavy asymmetric top (no integrable case) against an independent 30-digit
Taylor integration of Newton–Euler with a centre of mass anywhere (mpmath, tests/test_exact.py's
integrator): the simulated ω̃ and axis, in every formulation without a singular set."""
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest

import derive
from derive.codegen.render import ROOT
from derive.sim.scene import load_scene

import test_exact
from kept_results import kept
from test_exact import taylor_solve

SCENE = ROOT / "scenes" / "off_axis_top.toml"


def heavy_body_rhs(I, Mg, com):
    """ω̃' from I ω̃' = (I ω̃) × ω̃ + M g n × r_c, n = R[2, :] (the inertial vertical in body
    axes), and R' = R [ω̃]ₓ; state (ω̃, rows of R). Written from the physics, not from derive."""
    I1, I2, I3 = (mp.mpf(x) for x in I)
    Mg = mp.mpf(Mg)
    cx, cy, cz = (mp.mpf(x) for x in com)

    def rhs(Y):
        w1, w2, w3 = Y[:3]
        R = [Y[3:6], Y[6:9], Y[9:12]]
        n1, n2, n3 = R[2]
        tau = [Mg * (n2 * cz - n3 * cy), Mg * (n3 * cx - n1 * cz), Mg * (n1 * cy - n2 * cx)]
        out = [((I2 - I3) * (w2 * w3) + tau[0]) / I1,
               ((I3 - I1) * (w3 * w1) + tau[1]) / I2,
               ((I1 - I2) * (w1 * w2) + tau[2]) / I3]
        for r in R:
            out += [r[1] * w3 - r[2] * w2, r[2] * w1 - r[0] * w3, r[0] * w2 - r[1] * w1]
        return out

    return rhs


@pytest.fixture(scope="module")
def reference():
    """The 30-digit integration from the scene's numbers, kept between test runs
    (tests/kept_results.py) under those numbers and the bytes of this file and of test_exact.py
    (the integrator's): the simulations are held to it on every run."""
    sc = load_scene(SCENE)
    t = np.linspace(0.0, 0.6, 7)
    a, b, g = sc.initial.alpha, sc.initial.beta, sc.initial.gamma
    gr = sc.gravity
    numbers = (tuple(map(float, sc.body.moments)), float(gr.M * gr.g), tuple(map(float, gr.com)),
               tuple(map(float, sc.initial.omega)), (float(a), float(b), float(g)), tuple(t.tolist()))

    def integrate():
        with mp.workdps(30):
            ca, sa, cb, sb, cg, sg = (f(mp.mpf(x)) for x, f in
                                      ((a, mp.cos), (a, mp.sin), (b, mp.cos), (b, mp.sin),
                                       (g, mp.cos), (g, mp.sin)))
            Rz = lambda c, s: mp.matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])  # noqa: E731
            R = Rz(ca, sa) * mp.matrix([[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]]) * Rz(cg, sg)
            state0 = [mp.mpf(w) for w in sc.initial.omega] + [R[i, j] for i in range(3) for j in range(3)]
            return taylor_solve(heavy_body_rhs(sc.body.moments, gr.M * gr.g, gr.com), state0, t)

    ref = kept("off-axis-reference", numbers, integrate, [Path(__file__), Path(test_exact.__file__)])
    return t, ref[:, :3], ref[:, 3:].reshape(-1, 3, 3)[:, :, 2]


@pytest.mark.parametrize("formulation", ["auto", "euler-poisson", "quaternion"])
def test_off_axis_top_matches_a_30_digit_taylor_integration(reference, formulation):
    t, omega, axis = reference
    res = derive.simulate(SCENE, t_end=float(t[-1]), samples=len(t), rtol=1e-12, atol=1e-14,
                          formulation=formulation)
    assert res.formulation in ("euler-poisson", "quaternion")  # no Routh reduction here
    scale = float(np.max(np.abs(omega)))
    assert np.max(np.abs(res.omega - omega)) <= 1e-10 * scale
    assert np.max(np.abs(res.axis - axis)) <= 1e-10
    # and its invariants: energy and L·n (= p_α) to round-off level
    assert np.ptp(res.energy) <= 1e-11 * np.max(np.abs(res.energy))
    assert np.ptp(res.p_alpha) <= 1e-11 * np.max(np.abs(res.L))
