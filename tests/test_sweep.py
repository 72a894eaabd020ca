"""Parameter sweeps (derive.sweeps) and the measures computed in the compiled loop (derive.sweeps.measures)."""
from __future__ import annotations

import math
import shutil

import numpy as np
import pytest

import compile_once
import derive
from derive.runtime import catalogue
from derive.errors import SceneError
from derive.reference.exact import heavy_top
from derive.sweeps.measures import REGISTRY, MeasureKernel, c_sources
from derive.sweeps.spec import load

REF = {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
       "initial": {"alpha": 0.0, "beta": 0.8, "gamma": 0.0, "alpha_dot": -0.4, "beta_dot": 0.3,
                   "gamma_dot": 6.0},
       "simulate": {"t_end": 3.0, "rtol": 1e-8, "atol": 1e-12}}


def _spec(**over):
    spec = {"scene": REF, "vary": {"initial": {"beta": {"from": 0.3, "to": 1.2, "num": 4},
                                               "gamma_dot": {"values": [5.0, 6.0, 7.0]}}}}
    spec.update(over)
    return spec


def test_grid_points_c_order():
    sp = load(_spec())
    assert sp.keys == ("initial.beta", "initial.gamma_dot") and sp.shape == (4, 3)
    b, g = np.meshgrid(np.linspace(0.3, 1.2, 4), [5.0, 6.0, 7.0], indexing="ij")
    assert np.array_equal(sp.columns["initial.beta"], b.ravel())
    assert np.array_equal(sp.columns["initial.gamma_dot"], g.ravel())
    assert sp.columns["initial.beta"][:3].tolist() == [0.3] * 3  # first key slowest


def test_random_points_follow_the_seed():
    spec = {"scene": REF, "random": {"n": 50, "seed": 7, "initial": {
        "beta": {"low": 0.2, "high": 1.0}, "gamma_dot": {"low": 4.0, "high": 8.0}}}}
    a, b = load(spec), load(spec)
    rng = np.random.default_rng(7)
    assert np.array_equal(a.columns["initial.beta"], rng.uniform(0.2, 1.0, 50))
    assert np.array_equal(a.columns["initial.gamma_dot"], rng.uniform(4.0, 8.0, 50))
    assert all(np.array_equal(a.columns[k], b.columns[k]) for k in a.keys)
    spec["random"]["seed"] = 8
    assert not np.array_equal(load(spec).columns["initial.beta"], a.columns["initial.beta"])


def test_inputs_and_final_state_match_simulate_bit_for_bit():
    """The arrays built without a scene per point give what derive.simulate gives: the outputs at
    t_end of the measured run equal the plain run's last sample (measuring does not change the
    steps), run with the formulation the sweep ran the point with."""
    spec = _spec(measures=["final_state", "nfev"])
    res = derive.sweep(spec, processes=1)
    for i in (0, 5, 11):
        scene = {**REF, "initial": {**REF["initial"], "beta": float(res.params["initial.beta"][i]),
                                    "gamma_dot": float(res.params["initial.gamma_dot"][i])},
                 "simulate": {**REF["simulate"], "formulation": str(res.formulation[i]),
                              "samples": 7}}
        sim = derive.simulate(scene)
        assert res.measures["final_beta"][i] == sim.beta[-1]
        for name in ("alpha", "gamma"):  # the same angle; unwrapped from fewer samples
            d = res.measures[f"final_{name}"][i] - getattr(sim, name)[-1]
            assert abs(math.remainder(d, 2 * math.pi)) < 1e-12
        for k in range(3):
            assert res.measures[f"final_omega{k + 1}"][i] == sim.omega[-1, k]


def test_beta_extrema_against_exact_turning_points():
    """beta_max / beta_min located on the dense output agree with the turning points of the
    closed-form heavy top (y = sin^2(beta/2) roots) to 1e-7 at rtol 1e-11."""
    scene = {**REF, "simulate": {"t_end": 10.0, "rtol": 1e-11, "atol": 1e-14}}
    spec = {"scene": scene, "random": {"n": 6, "seed": 3, "initial": {
        "beta": {"low": 0.3, "high": 1.4}, "beta_dot": {"low": -0.5, "high": 0.5}}},
        "measures": ["beta_max", "beta_min", "nutation"]}
    res = derive.sweep(spec, processes=1)
    assert (res.status == "ok").all()
    worst = 0.0
    for i in range(6):
        b0, bd0 = res.params["initial.beta"][i], res.params["initial.beta_dot"][i]
        ex = heavy_top(1.0, 0.5, 1.0, 1.0, 1.0, 0.0, b0, 0.0, -0.4, bd0, 6.0, np.array([0.0, 1.0]))
        assert not ex.info["mirrored"]
        turning = [2 * math.asin(math.sqrt(y)) for y in ex.info["y_roots"][:2]]
        worst = max(worst, abs(res.measures["beta_max"][i] - max(turning)),
                    abs(res.measures["beta_min"][i] - min(turning)),
                    abs(res.measures["nutation"][i] - (max(turning) - min(turning))) / 2)
        # the largest *sample* of a 1001-point output is visibly worse: the search matters
    assert worst < 1e-7


def test_time_to_tilt_and_flip_are_located_on_the_dense_output():
    spec = {"scene": REF, "vary": {"initial": {"gamma_dot": {"values": [4.0, 6.0]}}},
            "measure": {"names": ["time_to_tilt", "beta_max"], "time_to_tilt": {"angle": 1.0}}}
    res = derive.sweep(spec, processes=1)
    for i, tt in enumerate(res.measures["time_to_tilt"]):
        if res.measures["beta_max"][i] <= 1.0:
            assert math.isnan(tt)
            continue
        scene = {**REF, "initial": {**REF["initial"], "gamma_dot": float(res.params["initial.gamma_dot"][i])},
                 "simulate": {**REF["simulate"], "t_end": float(tt), "formulation": "euler-poisson"}}
        assert abs(derive.simulate(scene).beta[-1] - 1.0) < 1e-8
    racket = {"body": {"I1": 1e-3, "I2": 2e-3, "I3": 2.5e-3},
              "initial": {"alpha": 0.0, "beta": 1.5707963267948966, "gamma": 1.5707963267948966,
                          "omega": [1e-3, 10.0, 0.0]},
              "simulate": {"t_end": 6.0}}
    res = derive.sweep({"scene": racket, "vary": {"initial": {"omega": {"0": {"values": [1e-6, 1e-4]}}}},
                        "measures": ["time_to_flip", "flips"]}, processes=1)
    for i, tf in enumerate(res.measures["time_to_flip"]):
        w0 = float(res.params["initial.omega.0"][i])
        sim = derive.simulate({**racket, "initial": {**racket["initial"], "omega": [w0, 10.0, 0.0]},
                               "simulate": {"t_end": float(tf), "formulation": "euler-poisson"}})
        assert abs(sim.omega[-1, 1]) < 1e-8 * 10.0
        assert res.measures["flips"][i] >= 1
    # ln(100) / lambda apart (linearised growth, lambda = 10 sqrt(1e-3 * 0.5e-3 / 2.5e-6))
    lam = 10.0 * math.sqrt(1e-3 * 0.5e-3 / (1e-3 * 2.5e-3))
    assert abs(np.diff(res.measures["time_to_flip"])[0] + math.log(100) / lam) < 0.01


def test_failing_and_invalid_points_are_recorded_not_fatal():
    scene = {**REF, "simulate": {**REF["simulate"], "max_steps": 60}}
    spec = {"scene": scene, "vary": {"body": {"I3": {"values": [0.5, 2.5]}},
                                     "initial": {"gamma_dot": {"values": [1.0, 60.0]}}},
            "measures": ["beta_max", "nfev"]}
    res = derive.sweep(spec, processes=1)
    st = res.status.reshape(2, 2)
    assert st[0, 0] == "ok"
    assert "step" in st[0, 1] and "t = " in st[0, 1]  # budget spent: the spin is fast
    assert st[1, 0].startswith("invalid: body") and st[1, 1].startswith("invalid: body")
    bm = res.measures["beta_max"].reshape(2, 2)
    assert np.isfinite(bm[0, 0]) and np.isnan(bm[0, 1]) and np.isnan(bm[1]).all()
    df = res.to_pandas()
    assert list(df.columns) == ["body.I3", "initial.gamma_dot", "beta_max", "nfev", "status"]


def test_engines_give_identical_results():
    """In-process, a local process pool and a real dask LocalCluster (2 worker processes) give
    the same numbers bit for bit."""
    pytest.importorskip("dask.distributed")
    spec = {"scene": {**REF, "simulate": {**REF["simulate"], "t_end": 1.0}},
            "random": {"n": 240, "seed": 11, "initial": {"beta": {"low": 0.3, "high": 1.2}}},
            "measures": ["beta_max", "beta_min", "energy_drift", "nfev", "flips", "integral_drift"]}
    one = derive.sweep(spec, processes=1)
    assert (one.measures["integral_drift"] < 1e-6).all()  # the Lagrange top's L3: its rows travel too
    pool = derive.sweep(spec, processes=2)
    cluster = derive.sweep(spec, workers=2)
    for other in (pool, cluster):
        assert np.array_equal(other.status, one.status)
        for k in one.measures:
            assert np.array_equal(other.measures[k], one.measures[k], equal_nan=True), k


BAD = [
    ({"vary": {"initial": {"beta": {"from": 0.1, "to": 0.2}}}}, "vary.initial.beta"),
    ({"vary": {"initial": {"bta": {"values": [0.1]}}}}, "vary.initial.bta"),
    ({"vary": {"simulate": {"rtol": {"values": [1e-6]}}}}, "vary.simulate.rtol"),
    ({"vary": {"body": {"I1": {"values": [1.0, -1.0]}}}}, "vary.body.I1"),
    ({"vary": {"gravity": {"g": {"values": [-9.81]}}}}, "vary.gravity.g"),
    ({"vary": {"damping": {"c": {"values": [0.1]}}}}, "vary.damping.c"),
    ({"vary": {"initial": {"omega": {"0": {"values": [0.1]}}}}}, "vary.initial.omega.0"),
    ({"vary": {"initial": {"beta": {"values": []}}}}, "vary.initial.beta"),
    ({"vary": {"initial": {"beta": {"values": [10**400]}}}}, "vary.initial.beta"),  # beyond a double
    ({"vary": {"initial": {"beta": {"from": 0.1, "to": 10**400, "num": 3}}}}, "vary.initial.beta"),
    ({"random": {"n": 5, "seed": 1, "initial": {"beta": {"low": 0.1, "high": 10**400}}}, "vary": None},
     "random.initial.beta"),
    ({"random": {"n": 0, "seed": 1, "initial": {"beta": {"low": 0.1, "high": 0.2}}}, "vary": None}, "random.n"),
    ({"random": {"n": 5, "seed": 1, "initial": {"beta": {"low": 0.3, "high": 0.2}}}, "vary": None},
     "random.initial.beta"),
    ({"measures": ["beta_maximum"]}, "measures"),
    ({"measure": {"names": ["time_to_tilt"], "time_to_tilt": {"angel": 1.0}}}, "measure.time_to_tilt.angel"),
    ({"scene": {**REF, "body": {"I1": 1.0}}}, "scene.body.I3"),
    ({"scene": {**REF, "simulate": {"t_end": 1.0, "method": "rk4", "h": 0.01}}}, "scene.simulate.method"),
    ({"scene": {**REF, "simulate": {"t_end": 1.0, "formulation": "euler-angles"}}}, "scene.simulate.formulation"),
    ({"colour": 1}, "colour"),
]


@pytest.mark.parametrize("change,key", BAD)
def test_bad_sweeps_name_the_key(change, key):
    spec = {"scene": REF, "vary": {"initial": {"beta": {"values": [0.5]}}}}
    spec.update(change)
    spec = {k: v for k, v in spec.items() if v is not None}
    with pytest.raises(SceneError) as info:
        load(spec)
    msg = str(info.value)
    assert msg.startswith(f"<sweep>: {key}: "), msg
    assert "\n" not in msg


def test_cli_writes_parquet_and_map_and_refuses_bad_files(tmp_path, capsys):
    from derive.cli import main

    pd = pytest.importorskip("pandas")
    scene = tmp_path / "top.toml"
    scene.write_text('[body]\nI1 = 1.0\nI3 = 0.5\n[gravity]\nM = 1.0\ng = 1.0\nl = 1.0\n'
                     '[initial]\nalpha = 0.0\nbeta = 0.8\ngamma = 0.0\nalpha_dot = 0.0\n'
                     'beta_dot = 0.0\ngamma_dot = 6.0\n[simulate]\nt_end = 1.0\nrtol = 1e-8\n')
    sweep = tmp_path / "s.toml"
    sweep.write_text('scene = "top.toml"\n[vary]\ninitial.beta = { from = 0.1, to = 0.5, num = 3 }\n'
                     'initial.gamma_dot = { values = [3.0, 6.0] }\n[measure]\nnames = ["beta_max", "nfev"]\n')
    out, png = tmp_path / "r.parquet", tmp_path / "m.png"
    rc = main(["sweep", str(sweep), "-o", str(out), "--plot", str(png)])
    assert rc == 0, capsys.readouterr().err
    df = pd.read_parquet(out)
    assert list(df.columns) == ["initial.beta", "initial.gamma_dot", "beta_max", "nfev", "status"]
    assert len(df) == 6 and (df.status == "ok").all() and png.stat().st_size > 10_000
    bad = tmp_path / "bad.toml"
    bad.write_text('scene = "top.toml"\n[vary]\ninitial.beta = { from = 0.1, to = 0.5 }\n')
    out2 = tmp_path / "r2.parquet"
    capsys.readouterr()
    rc = main(["sweep", str(bad), "-o", str(out2)])
    err = capsys.readouterr().err
    assert rc == 2 and not out2.exists()
    assert err.strip().splitlines() == [err.strip()]
    assert err.startswith(f"error: {bad}: vary.initial.beta: ")


def test_measure_registry_and_strict_c():
    """The registry holds the documented measures; the measures unit compiles cleanly under the
    project's strict flags."""
    assert set(REGISTRY) >= {"beta_max", "beta_min", "energy_drift", "nfev", "final_state", "flips",
                             "time_to_tilt"}
    gcc = shutil.which("gcc")
    if gcc is None:
        pytest.skip("no gcc")
    desc = catalogue.describe(("euler-poisson", True, ("gravity",)))
    files = dict(c_sources(desc, "dop853"))
    files["unit.c"] = "".join(f'#include "{n}"\n' for n in (f"{desc.name}.c", f"{desc.name}_solvers.c",
                                                            f"{desc.name}_measures.c"))
    flags = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O0", "-DDERIVE_MEASURES"]
    compile_once.compiles_once(files, "unit.c", flags)  # kept for these exact sources and flags
    assert MeasureKernel.load(desc, "dop853") is MeasureKernel.load(desc, "dop853")


def test_plot_measure_is_one_column_and_the_api_is_callable():
    spec = _spec(measures=["nfev"])
    with pytest.raises(SceneError, match="final_state has several columns"):
        derive.sweep(spec, add_measure="final_state", processes=1)
    res = derive.sweep(spec, add_measure="final_beta", processes=1)
    assert res.measure_names == ("nfev", "final_state") and "final_beta" in res.measures
    from derive.sweeps import engine as sweeps  # the package (sweeps) does not shadow the function (sweep)

    again = derive.sweep(spec, processes=1)
    assert np.array_equal(again.measures["nfev"], res.measures["nfev"])
    assert callable(derive.sweep) and callable(sweeps.sweep)


def test_extrema_inside_the_first_and_the_last_step():
    """A turning point inside the first step (released just past it) or the last one (t_end
    just past it) has no discrete neighbour on one side; it is still found."""
    exact = heavy_top(1.0, 0.5, 1.0, 1.0, 1.0, 0.0, 0.8, 0.0, -0.4, 0.3, 6.0, np.array([0.0, 1.0]))
    bmax = 2 * math.asin(math.sqrt(exact.info["y_roots"][1]))  # first reached at t = 1.046
    base = {**REF, "simulate": {"t_end": 1.0, "rtol": 1e-11, "atol": 1e-14}}
    spec = {"scene": base, "vary": {"initial": {"beta": {"values": [0.8]}}}, "measures": ["beta_max"]}
    for t_end in np.linspace(1.048, 1.09, 8):
        spec["scene"] = {**base, "simulate": {**base["simulate"], "t_end": float(t_end)}}
        assert abs(derive.sweep(spec, processes=1).measures["beta_max"][0] - bmax) < 1e-9
    for bd in (-1e-3, -1e-2):  # the minimum just after the release
        ex = heavy_top(1.0, 0.5, 1.0, 1.0, 1.0, 0.0, 0.8, 0.0, -0.4, bd, 6.0, np.array([0.0, 1.0]))
        spec["scene"] = {**base, "initial": {**base["initial"], "beta_dot": bd}}
        spec["measures"] = ["beta_min"]
        bmin = 2 * math.asin(math.sqrt(ex.info["y_roots"][0]))
        assert abs(derive.sweep(spec, processes=1).measures["beta_min"][0] - bmin) < 1e-9


def test_bench_throughput_runs():
    """The throughput report's function (figures in docs/sweeps.md; no speed asserted here)."""
    from derive.bench.throughput import bench_throughput

    out = bench_throughput(n=20, scipy_n=2)
    assert out["per_traj_sweep"] > 0 and out["per_traj_scipy"] > 0 and out["nfev_mean"] > 100


def test_threads_sharing_a_library_get_their_own_trajectories():
    """The compiled accumulators are per library; concurrent calls from threads (a Dask worker
    with several threads) are serialised and give the single-threaded numbers."""
    from concurrent.futures import ThreadPoolExecutor

    from derive.sweeps.tasks import run_chunk

    sp = load({"scene": REF, "random": {"n": 40, "seed": 5, "initial": {"beta": {"low": 0.3, "high": 1.2}}}})
    from derive.sweeps.measures import config_of

    args = (sp.key, sp.method, sp.inputs, sp.ps, np.array([0.0, 3.0]), (1e-8, 1e-12, 0.0, 10**6),
            config_of(["beta_max", "beta_min"]))
    ref = run_chunk(*args)[0]
    with ThreadPoolExecutor(4) as pool:
        for res, _, _ in pool.map(lambda _: run_chunk(*args), range(8)):
            assert np.array_equal(res, ref, equal_nan=True)


def test_kovalevskaya_ratio_example_dips_where_the_classification_says():
    """scenes/sweeps/kovalevskaya_ratio.toml: K's drift is at the tolerance's level only at the
    ratio the classification names (I3 = I1/2), orders of magnitude larger 0.1 % away; the 1-D
    plot is on a log scale with that ratio marked."""
    from pathlib import Path

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from derive.sweeps import maps as sweep_maps

    path = Path(__file__).resolve().parents[1] / "scenes" / "sweeps" / "kovalevskaya_ratio.toml"
    res = derive.sweep(str(path), processes=1)
    assert res.ok.all()
    i3, drift = res.params["body.I3"], res.measures["integral_drift"]
    at = drift[i3 == 1.0][0]
    near = drift[np.isclose(i3, 0.999) | np.isclose(i3, 1.001)]
    assert at < 1e-10 and near.min() > 1e4 * at
    assert (res.measures["energy_drift"] < 1e-10).all()  # energy: conserved for every I3
    fig, ax = plt.subplots()
    sweep_maps._integrable_moments(ax, res.scene, "body.I3", i3)
    lines = [ln for ln in ax.get_lines()]
    plt.close(fig)
    assert [ln.get_xdata()[0] for ln in lines] == [1.0]
    assert lines[0].get_label().startswith("kovalevskaya case")
