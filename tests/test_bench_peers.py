"""heyoka and numbalsoda as contenders of `derive bench`: they integrate the baselines'
equations, land on the exact solution, and the races report finite ratios. Skipped where the
peer is not installed (``pip install -e '.[peers]'``; numbalsoda needs a Fortran compiler).

No timed assertions: the bench reports the ratios, the tests check what they are made of."""
import dataclasses
import math

import numpy as np
import pytest

from derive.bench import contenders as bc
from derive.bench import peers
from derive.bench import runner as bench

CONSTS = {"euler-angles": [1.3, 0.6, 0.7], "quaternion": [1.3, 1.7, 0.6, 0.7]}


def _states(formulation, n, seed=31):
    rng = np.random.default_rng(seed)
    for _ in range(n):
        if formulation == "euler-angles":
            yield np.array([rng.uniform(-3, 3), rng.uniform(0.2, math.pi - 0.2), rng.uniform(-3, 3),
                            *rng.uniform(-8, 8, 3)])
        else:
            q = rng.normal(size=4)
            yield np.array([*(q / np.linalg.norm(q)), *rng.uniform(-8, 8, 3)])


def _baseline_rhs(formulation):
    b = bc.baselines()
    c = CONSTS[formulation]
    return b.euler_top_rhs(*c) if formulation == "euler-angles" else b.quaternion_rhs(*c)


def test_lanes_pad_the_last_chunk_with_its_last_trajectory():
    Y0 = np.arange(30.0).reshape(5, 6)
    P = np.arange(15.0).reshape(5, 3)
    chunks = peers._lanes(Y0, P, 4)
    assert [real for _, _, real in chunks] == [4, 1]
    y, p, _ = chunks[1]
    assert y.shape == (6, 4) and p.shape == (3, 4)
    assert (y.T == Y0[4]).all() and (p.T == P[4]).all()
    assert (chunks[0][0].T == Y0[:4]).all()


def test_without_peers_the_races_are_skipped_and_say_why():
    out = peers.run(bench.SMOKE, ["scipy"], lambda n, t: [])
    assert "skipped" in out and "heyoka" in out["skipped"]


@pytest.mark.parametrize("formulation", ["euler-angles", "quaternion"])
def test_heyoka_equations_are_the_baselines(formulation):
    hy = pytest.importorskip("heyoka")
    system = bc.heyoka_system(formulation)
    f = hy.cfunc([e for _, e in system], [v for v, _ in system])
    rhs = _baseline_rhs(formulation)
    for y in _states(formulation, 5):
        assert np.allclose(f(y, pars=np.array(CONSTS[formulation])), rhs(0.0, y), rtol=1e-13, atol=1e-13)


@pytest.mark.parametrize("formulation", ["euler-angles", "quaternion"])
def test_heyoka_reaches_the_exact_solution_and_resets_between_calls(formulation):
    pytest.importorskip("heyoka")
    data = bc.scene_data(bench.SCENES / "looping_top.toml", t_end=0.05, samples=11)
    prob = bc.problem(data, formulation)
    ref = bench.exact_axis(data, prob.t)
    setup = bc.heyoka_setup(prob, "heyoka-taylor", 1e-12, 1e-14)
    Y, steps = bc.solve_heyoka(prob, "heyoka-taylor", 1e-12, 1e-14, setup)
    assert steps > 0 and bench.axis_error(prob.axis(Y), ref) < 1e-10
    Y2, _ = bc.solve_heyoka(prob, "heyoka-taylor", 1e-12, 1e-14, setup)
    assert np.array_equal(Y, Y2)  # the second call starts again from t0, y0


def test_heyoka_batch_lanes_agree_with_the_scalar_integrator():
    pytest.importorskip("heyoka")
    from derive.bench.targets import batch_scenes

    scenes = batch_scenes(5, 0.5)  # 5 trajectories: one padded chunk of lanes at least
    for d in scenes:
        d["simulate"]["samples"] = 11
    probs = [bc.problem(d, "euler-angles") for d in scenes]
    grid_run, final_run, width = peers.heyoka_batch(probs[0], probs, 1e-12)
    Yg, Yf = grid_run(), final_run()
    assert Yg.shape == (5, 11, 6) and Yf.shape == (5, 6) and width >= 1
    setup = bc.heyoka_setup(probs[0], "heyoka-taylor", 1e-12, 1e-14)
    for b, prob in enumerate(probs):
        Y, _ = bc.solve_heyoka(prob, "heyoka-taylor", 1e-12, 1e-14, setup)
        assert np.allclose(Yg[b], Y, rtol=1e-11, atol=1e-11)
        assert np.allclose(Yf[b], Y[-1], rtol=1e-11, atol=1e-11)


def test_races_against_heyoka_report_finite_ratios_at_reached_levels():
    pytest.importorskip("heyoka")
    from derive.bench.targets import batch_scenes, peer_rows

    cfg = dataclasses.replace(bench.SMOKE, families=("scipy", "heyoka"))
    out = peers.run(cfg, ["scipy", "heyoka"], batch_scenes)
    for part in ("reference", "long", "batch", "fixed_cost"):
        assert "error" not in out[part], (part, out[part])
    for part in ("reference", "long"):
        for row in out[part]["rows"]:
            e = row["peers"]["heyoka"]
            assert row["derive"]["reached"] and e["reached"]
            assert row["derive"]["error"] <= row["level"] and e["error"] <= row["level"]
            assert e["time"] > 0 and e["ratio_simulate"] > 0 and e["ratio_prepared"] > 0
    ba = out["batch"]
    assert ba["final_axis_difference"] < 1e-8  # both sides integrated the same motions
    assert ba["ratio_full_vs_grid"] > 0 and ba["ratio_final_vs_final"] > 0
    assert ba["lanes_driver"] == "lanes" and ba["ratio_lanes_vs_final"] > 0
    assert ba["ratio_prepared_axis_vs_grid"] > 0
    assert ba["ratio_prepared_axis_vs_grid_axis"] > 0 and ba["heyoka_grid_axis_per_trajectory"] > 0
    from derive.bench.report import peers_section

    text = "\n".join(peers_section({"targets": {"peers": out}}))
    assert "the axis alone at every sample" in text and "propagate_grid" in text
    fc = out["fixed_cost"]
    assert fc["prepared_vs_heyoka"] > 0 and fc["simulate_vs_heyoka"] > 0
    keys = {key for _, key, value in peer_rows(out) if value is not None}
    assert {"vs_heyoka", "long_vs_heyoka", "batch_vs_heyoka", "fixed_prepared_vs_heyoka",
            "dict_call"} <= keys


@pytest.mark.parametrize("formulation", ["euler-angles", "quaternion"])
def test_numbalsoda_equations_are_the_baselines_and_reach_the_exact_solution(formulation):
    pytest.importorskip("numbalsoda")
    pytest.importorskip("numba")
    import ctypes

    address = bc._numba_rhs(formulation)
    f = ctypes.CFUNCTYPE(None, ctypes.c_double, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p)(address)
    rhs = _baseline_rhs(formulation)
    p = np.array(CONSTS[formulation])
    for y in _states(formulation, 5):
        du = np.empty_like(y)
        f(0.0, y.ctypes.data, du.ctypes.data, p.ctypes.data)
        assert np.allclose(du, rhs(0.0, y), rtol=1e-13, atol=1e-13)
    data = bc.scene_data(bench.SCENES / "looping_top.toml", t_end=0.05, samples=11)
    prob = bc.problem(data, formulation)
    Y, _ = bc.solve_numbalsoda(prob, "numbalsoda-dop853", 1e-10, 1e-12)
    assert bench.axis_error(prob.axis(Y), bench.exact_axis(data, prob.t)) < 1e-7


def test_the_fixed_cost_race_times_a_repeat_and_new_numbers_and_reports_both():
    from derive.bench import peers, report
    from derive.bench.runner import SMOKE

    out = peers.fixed_cost(SMOKE, [])
    assert out["derive_prepared"] > 0 and out["derive_simulate"] > 0 and out["derive_simulate_new"] > 0
    fake = dict(out, heyoka=1e-5, prepared_vs_heyoka=1.0, simulate_vs_heyoka=2.0, simulate_new_vs_heyoka=3.0)
    text = "\n".join(report.peers_section({"targets": {"peers": {"peers": ["heyoka"], "fixed_cost": fake}}}))
    assert "new numbers" in text and "**3×**" in text and "**2×**" in text
