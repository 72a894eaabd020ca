"""The measures' integral drift (the extra integral of the integrable cases, in C from the
formulas of derive.symbolic.integrable) and the dense output formed only where a search reads it."""
from __future__ import annotations

import copy
import functools
import platform
import tomllib

import numpy as np
import pytest
from cli_in_process import derive_main

import derive
from derive.codegen import sources
from derive.symbolic import integrable
from derive.sweeps import measures as ms
from derive.runtime.cbuild import DEFAULT_FLAGS, compile_library
from derive.errors import SceneError
from derive.codegen.render import CHECKOUT, GENERATED
from derive.sweeps.spec import load
from derive.sweeps.tasks import run_chunk

TOP = {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
       "initial": {"alpha": 0.0, "beta": 0.8, "gamma": 0.0, "alpha_dot": -0.4, "beta_dot": 0.3,
                   "gamma_dot": 6.0},
       "simulate": {"t_end": 3.0, "rtol": 1e-8, "atol": 1e-12}}
TOP_SWEEP = {"scene": TOP, "vary": {"initial": {"beta": {"values": [0.3, 0.75, 1.2]},
                                                "gamma_dot": {"values": [2.0, 7.0]}}},
             "measure": {"names": ["beta_max", "beta_min", "energy_drift", "p_alpha_drift",
                                   "p_gamma_drift", "time_to_tilt", "flips", "time_to_flip",
                                   "integral_drift", "final_state", "nfev"],
                         "time_to_tilt": {"angle": 1.0}}}
RACKET_SWEEP = {"scene": {"body": {"I1": 1e-3, "I2": 2e-3, "I3": 2.5e-3},
                          "initial": {"alpha": 0.0, "beta": 1.5707963267948966,
                                      "gamma": 1.5707963267948966, "omega": [1e-3, 10.0, 0.0]},
                          "simulate": {"t_end": 15.0, "rtol": 1e-10}},
                "vary": {"initial": {"omega": {"0": {"values": [1e-6, 1e-3, 0.3]}}}},
                "measures": ["time_to_flip", "flips", "beta_max", "beta_min", "energy_drift",
                             "integral_drift", "nfev"]}


def _scene(name: str) -> dict:
    with open(CHECKOUT / "scenes" / name, "rb") as f:
        return tomllib.load(f)


def _chunk(spec, dense_always: bool):
    """One compiled call for all the points of a sweep, the dense output formed lazily or on
    every step."""
    sp = load(spec)
    config = ms.config_of(sp.measures, sp.options)
    config[ms.CONFIG["dense_always"]] = float(dense_always)
    s = sp.scene.simulate
    rows = ms.integral_rows(sp.general, sp.damping)
    return run_chunk(sp.key, sp.method, sp.inputs, sp.ps, np.array([0.0, s.t_end]),
                     (s.rtol, s.atol, 0.0, s.max_steps), config, rows)


def test_a_sweep_without_beta_measures_runs_no_extremum_search():
    """energy_drift alone costs what the plain loop costs (no dense output for beta's turning
    points, whose search nothing reads), and reads the same values as beside beta_max."""
    def run(names):
        spec = copy.deepcopy(TOP_SWEEP)
        spec["measure"] = {"names": names}
        sp = load(spec)
        s = sp.scene.simulate
        return run_chunk(sp.key, sp.method, sp.inputs, sp.ps, np.array([0.0, s.t_end]),
                         (s.rtol, s.atol, 0.0, s.max_steps), ms.config_of(sp.measures, sp.options),
                         ms.integral_rows(sp.general, sp.damping))

    plain, drift, both = run(["nfev"]), run(["energy_drift", "nfev"]), run(["beta_max", "energy_drift", "nfev"])
    assert np.array_equal(drift[2]["nfev"], plain[2]["nfev"])
    assert (both[2]["nfev"] > drift[2]["nfev"]).all()  # the searches form dense outputs
    e = ms.SLOTS.index("energy_drift")
    assert np.array_equal(drift[0][:, e], both[0][:, e])


@pytest.mark.parametrize("spec", [TOP_SWEEP, RACKET_SWEEP], ids=["heavy-top", "tennis-racket"])
def test_lazy_dense_output_changes_no_value(spec):
    """Forming the dense output only on the steps a search reads gives every measure bit for bit
    what forming it on every step gives (the turning-point, tilt and flip searches included);
    only nfev drops, by DOP853's three dense stages per step skipped."""
    res_lazy, final_lazy, st_lazy = _chunk(spec, False)
    res_all, final_all, st_all = _chunk(spec, True)
    assert (st_lazy["status"] == 0).all()
    assert np.array_equal(res_lazy, res_all, equal_nan=True)
    assert np.array_equal(final_lazy, final_all)
    assert np.array_equal(st_lazy["naccept"], st_all["naccept"])
    saved = st_all["nfev"] - st_lazy["nfev"]
    assert (saved % 3 == 0).all() and (saved > 0).all()
    # most steps skip it: beta turns a few times, the first tilt and flip happen once
    assert (saved > 3 * 0.5 * st_all["naccept"]).all()


@pytest.mark.skipif(platform.system() != "Linux" or platform.machine() != "x86_64",
                    reason="values recorded with glibc's libm on x86-64")
def test_values_recorded_before_the_lazy_dense_output():
    """The heavy-top points' values as the code that formed the dense output on every step gave
    them (recorded at commit 9fa0855, float.hex, when auto ran every sweep on euler-poisson:
    named here, now that auto runs reduced-u where it can)."""
    ep = {**TOP, "simulate": {**TOP["simulate"], "formulation": "euler-poisson"}}
    res = derive.sweep({**TOP_SWEEP, "scene": ep}, processes=1)
    recorded = {
        "beta_max": ["0x1.2d8d6b3f454ddp+1", "0x1.0fbd079002379p-1", "0x1.3c86838c02a12p+1",
                     "0x1.1b15eedc315b5p+0", "0x1.5121d161d6d72p+1", "0x1.9abe2463115dbp+0"],
        "beta_min": ["0x1.3333333333333p-2", "0x1.08b0f450f1a29p-2", "0x1.8000000000000p-1",
                     "0x1.738a7e6ec73a6p-1", "0x1.3333333333333p+0", "0x1.2e6075e4b2618p+0"],
        "time_to_tilt": ["0x1.38ced01efa90ep+0", "nan", "0x1.e7c8b21e80c3cp-2",
                         "0x1.f95210e2f8e40p-2", "0x0.0p+0", "0x0.0p+0"],
        "time_to_flip": ["0x1.49b0eca582d27p+0", "0x1.5ff6db4b92e4fp-2", "0x1.1d913050cd741p+0",
                         "0x1.16b56458075e8p-2", "0x1.03074dcfea415p+0", "0x1.ec7003ce8c2f6p-3"],
        "energy_drift": ["0x1.72281582f774dp-32", "0x1.712255fe8419ep-38", "0x1.67c603df57167p-32",
                         "0x1.49111336ec121p-36", "0x1.720e9aa0c9ea2p-32", "0x1.7787afc31a4ffp-36"],
        "final_beta": ["0x1.0683d13c31845p+1", "0x1.07f2b42569e25p-1", "0x1.568e7810e7197p+0",
                       "0x1.1a4085f27f11cp+0", "0x1.4241f4c189d17p+0", "0x1.761dd7eb86243p+0"],
    }
    before_nfev = [301, 572, 320, 587, 298, 632]
    for name, values in recorded.items():
        assert np.array_equal(res.measures[name], [float.fromhex(v) for v in values], equal_nan=True), name
    assert (res.measures["nfev"] < before_nfev).all()


# ---------------------------------------------------------------------------------------------
# the integrals in C


def test_generated_header_is_the_formulas_printed():
    """generated/c/derive_integrals.h is what derive.symbolic.integrable renders now (one source)."""
    assert (GENERATED / "c" / "derive_integrals.h").read_text() == sources.integrals_header()


@functools.lru_cache(maxsize=None)
def _monomials(name: str):
    """[(degree in L, degree in n, coefficient(p))] of an integral's expanded formula (SymPy)."""
    import sympy as sp

    integral = next(i for i in integrable.C_INTEGRALS if i.name == name)
    Ls, ns = sp.symbols("L1:4"), sp.symbols("n1:4")
    ps = sp.symbols(integrable.C_PARAMS)
    poly = sp.Poly(sp.expand(integral.formula(Ls, ns, dict(zip(integrable.C_PARAMS, ps)))), *Ls, *ns)
    return [(sum(m[:3]), sum(m[3:]), sp.lambdify(ps, c)) for m, c in poly.terms()]


def _scale(integral, L, n, p) -> float:
    """The documented size S, computed here from the definition (an independent check of the
    printed C): the sum over the monomials c L^a n^b of |c| |L|^|a| |n|^|b|."""
    Ln, nn = np.linalg.norm(L), np.linalg.norm(n)
    q = [p[k] for k in integrable.C_PARAMS]
    return float(sum(abs(c(*q)) * Ln ** a * nn ** b for a, b, c in _monomials(integral.name)))


def test_c_integrals_equal_the_numpy_formulas():
    """derive_integral in C against each Integral.formula on NumPy numbers, at random states
    and parameters, and its size S against the definition; |I| <= S for any L, n of those
    lengths."""
    import ctypes

    harness = ('#include "derive_integrals.h"\n'
               "double derive_test_integral(int which, const double *L, const double *n,\n"
               "        const double *q, double *scale)\n"
               "{\n    return derive_integral(which, L, n, q, scale);\n}\n")
    lib = compile_library("derive_test_integrals", {
        "derive_integrals.h": (GENERATED / "c" / "derive_integrals.h").read_text(),
        "harness.c": harness}, "harness.c", list(DEFAULT_FLAGS))
    fn = lib.derive_test_integral
    fn.restype = ctypes.c_double
    fn.argtypes = [ctypes.c_int] + [ctypes.c_void_p] * 4
    rng = np.random.default_rng(11)
    for code, integral in enumerate(integrable.C_INTEGRALS, start=1):
        for _ in range(5):
            L, n = rng.normal(size=3), rng.normal(size=3)
            q = np.concatenate([rng.uniform(0.5, 2.0, 5), rng.normal(size=3)])
            p = dict(zip(integrable.C_PARAMS, q.tolist()))
            s = np.zeros(1)
            value = fn(code, L.ctypes.data, n.ctypes.data, q.ctypes.data, s.ctypes.data)
            S = _scale(integral, L, n, p)
            assert abs(value - integral.formula(L, n, p)) <= 1e-14 * S, integral.name
            assert abs(s[0] - S) <= 1e-13 * S, integral.name
            for _ in range(5):  # another state of the same lengths
                L2 = rng.normal(size=3)
                L2 *= np.linalg.norm(L) / np.linalg.norm(L2)
                n2 = rng.normal(size=3)
                n2 *= np.linalg.norm(n) / np.linalg.norm(n2)
                assert abs(integral.formula(L2, n2, p)) <= S * (1 + 1e-12)
    s = np.zeros(1)
    z = np.zeros(8)
    assert np.isnan(fn(0, z.ctypes.data, z.ctypes.data, z.ctypes.data, s.ctypes.data)) and np.isnan(s[0])


# ---------------------------------------------------------------------------------------------
# integral_drift along trajectories


def _numpy_drift(integral, scene: dict, axes=(0, 1, 2)) -> float:
    """max |I - I0| / S over a densely sampled derive.simulate run, I from the NumPy formula on
    the outputs L and n (the formulas' axes = body axes ``axes``)."""
    res = derive.simulate(scene)
    p = integrable.relabel_params(integrable.parameters(derive.sim.scene.load_scene(scene)), axes)
    L, n = res.L[:, list(axes)].T, res.n[:, list(axes)].T
    values = np.asarray(integral.formula(L, n, p), dtype=float)
    return float(np.max(np.abs(values - values[0])) / _scale(integral, L[:, 0], n[:, 0], p))


def test_kovalevskaya_drift_against_the_numpy_integral_and_a_control():
    """At the Kovalevskaya ratio (I3 = I1/2) K is conserved: the compiled drift is at round-off
    at rtol 1e-12, as the NumPy K on a densely sampled run. Off the ratio (I3 = 0.9, a general
    body: its own integral_drift is NaN) the same K, named, drifts by 1e-2, and the compiled
    maximum over the step ends agrees with the maximum over 8001 samples."""
    scene = _scene("kovalevskaya_top.toml")
    scene["simulate"] = {"t_end": 20.0, "rtol": 1e-12, "atol": 1e-14, "formulation": "euler-poisson",
                         "samples": 8001}
    spec = {"scene": scene, "vary": {"body": {"I3": {"values": [1.0, 0.9]}}},
            "measure": {"names": ["integral_drift"], "integral_drift": {"integral": "kovalevskaya"}}}
    named = derive.sweep(spec, processes=1)
    spec["measure"] = {"names": ["integral_drift"]}
    own = derive.sweep(spec, processes=1)
    assert (named.status == "ok").all() and (own.status == "ok").all()
    K = integrable.EXTRA["kovalevskaya"]
    assert own.measures["integral_drift"][0] == named.measures["integral_drift"][0]
    assert named.measures["integral_drift"][0] < 1e-12
    assert _numpy_drift(K, scene) < 1e-11
    assert np.isnan(own.measures["integral_drift"][1])
    control = copy.deepcopy(scene)
    control["body"]["I3"] = 0.9
    expected = _numpy_drift(K, control)
    measured = named.measures["integral_drift"][1]
    assert expected > 1e-3
    assert expected * (1 - 1e-3) < measured < expected * (1 + 1e-3)


def test_integral_drift_per_case():
    """Euler's free body (|L|^2), a Lagrange top about body axis 1 (relabelled: L1), a
    Goryachev-Chaplygin top on L.n = 0 (G): drifts at the tolerance's level; the Lagrange body
    with another integral named (|L|^2, which its gravity torque changes) drifts; a damped top
    has none (NaN, status ok)."""
    racket = derive.sweep({**RACKET_SWEEP, "measures": ["integral_drift"]}, processes=1)
    assert (racket.measures["integral_drift"] < 1e-9).all()

    axis1 = {"body": {"I1": 0.5, "I2": 1.0, "I3": 1.0}, "gravity": {"M": 1.0, "g": 9.81, "com": [0.2, 0.0, 0.0]},
             "initial": {"alpha": 0.0, "beta": 0.7, "gamma": 0.4, "omega": [5.0, 0.3, -0.2]},
             "simulate": {"t_end": 5.0, "rtol": 1e-11, "atol": 1e-13}}
    spec = {"scene": axis1, "vary": {"initial": {"beta": {"values": [0.7, 1.1]}}},
            "measures": ["integral_drift"]}
    sp = load(spec)
    rows = ms.integral_rows(sp.general, sp.damping)
    lagrange = 1 + integrable.C_INTEGRALS.index(integrable.EXTRA["lagrange"])
    assert rows[0, :4].tolist() == [lagrange, 1, 2, 0]  # formulas' axis 3 = body axis 1
    own = derive.sweep(spec, processes=1).measures["integral_drift"]
    assert (own < 1e-9).all()
    spec["measure"] = {"names": ["integral_drift"], "integral_drift": {"integral": "L_squared"}}
    del spec["measures"]
    assert (derive.sweep(spec, processes=1).measures["integral_drift"] > 1e-2).all()

    gc = _scene("goryachev_chaplygin_top.toml")
    gc["simulate"] = {"t_end": 5.0, "rtol": 1e-11, "atol": 1e-13}
    res = derive.sweep({"scene": gc, "vary": {"initial": {"beta": {"values": [1.0]}}},
                        "measures": ["integral_drift"]}, processes=1)
    assert res.measures["integral_drift"][0] < 1e-9

    damped = _scene("damped_top.toml")
    damped["simulate"] = {"t_end": 0.5}
    res = derive.sweep({"scene": damped, "vary": {"initial": {"beta": {"values": [0.1, 0.2]}}},
                        "measures": ["integral_drift", "energy_drift"]}, processes=1)
    assert (res.status == "ok").all() and np.isnan(res.measures["integral_drift"]).all()
    assert (res.measures["energy_drift"] > 0).all()


@pytest.mark.parametrize("measure, key", [
    ({"names": ["integral_drfit"]}, "measure.names"),
    ({"names": ["integral_drift"], "integral_drift": {"integral": "kowalewski"}},
     "measure.integral_drift.integral"),
    ({"names": ["integral_drift"], "integral_drift": {"integral": 3.0}},
     "measure.integral_drift.integral"),
    ({"names": ["integral_drift"], "integral_drift": {"which": "L2"}}, "measure.integral_drift.which"),
])
def test_bad_integral_names_name_the_key(measure, key):
    with pytest.raises(SceneError, match=f"^<sweep>: {key}: "):
        derive.sweep({"scene": TOP, "vary": {"initial": {"beta": {"values": [0.5]}}},
                      "measure": measure}, processes=1)


def test_cli_bad_integral_name_exits_2(tmp_path):
    sweep = tmp_path / "s.toml"
    sweep.write_text('[scene]\nbody = { I1 = 1.0, I3 = 0.5 }\n'
                     'initial = { alpha = 0.0, beta = 0.5, gamma = 0.0, omega = [0.0, 0.0, 3.0] }\n'
                     'simulate = { t_end = 1.0 }\n'
                     '[vary]\ninitial.beta = { values = [0.5] }\n'
                     '[measure]\nnames = ["integral_drift"]\nintegral_drift = { integral = "K" }\n')
    out = tmp_path / "r.parquet"
    p = derive_main("sweep", sweep, "-o", out)
    assert p.returncode == 2 and not out.exists()
    assert p.stderr.strip().splitlines() == [
        f"error: {sweep}: measure.integral_drift.integral: must be one of case, L_squared, L_3, "
        "L_dot_rc, kovalevskaya, goryachev_chaplygin, n_squared, p_alpha, got 'K'"]


def test_named_casimirs():
    """Named, the Casimirs: L.n's drift times its size S = 3|L0||n0| is p_alpha_drift (the same
    quantity from the output map, to rounding); |n|^2 drifts at the tolerance's level. On
    euler-poisson, where both drift (reduced-u, auto's choice here, conserves p_alpha as a
    parameter: its drift is 0)."""
    ep = {**TOP, "simulate": {**TOP["simulate"], "formulation": "euler-poisson"}}
    spec = {"scene": ep, "vary": {"initial": {"beta": {"values": [0.4, 0.9]}}},
            "measure": {"names": ["integral_drift", "p_alpha_drift"],
                        "integral_drift": {"integral": "p_alpha"}}}
    res = derive.sweep(spec, processes=1)
    sp = load(spec)
    L0 = np.array([1.0, 1.0, 0.5]) * sp.inputs[:, 3:6]  # I omega at t = 0, |n0| = 1
    S = 3 * np.linalg.norm(L0, axis=1)
    drift = res.measures["integral_drift"] * S
    assert (res.measures["p_alpha_drift"] > 1e-12).all()
    assert np.allclose(drift, res.measures["p_alpha_drift"], rtol=0, atol=1e-14 * S.max())
    spec["measure"]["integral_drift"] = {"integral": "n_squared"}
    n_squared = derive.sweep(spec, processes=1).measures["integral_drift"]
    assert (n_squared > 0).all() and (n_squared < 1e-7).all()
