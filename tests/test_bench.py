"""`derive bench` end to end on a tiny budget, and the work–precision bookkeeping it rests on.

No timed assertions: the speed targets are reported by the bench, never asserted here."""
import json
import math

import numpy as np

from derive import bench


def _point(time, error):
    return bench.Point("s", "ours", "m", "f", "", time, 1, error)


def test_cost_at_interpolates_log_log_between_the_runs_around_the_level():
    pts = [_point(1.0, 1e-4), _point(10.0, 1e-8)]
    t, bound = bench.cost_at(pts, 1e-6)
    assert not bound and math.isclose(t, math.sqrt(10.0), rel_tol=1e-12)


def test_cost_at_ignores_runs_that_are_slower_and_no_more_accurate():
    pts = [_point(1.0, 1e-4), _point(5.0, 1e-3), _point(10.0, 1e-8), _point(20.0, 1e-8)]
    assert math.isclose(bench.cost_at(pts, 1e-6)[0], math.sqrt(10.0), rel_tol=1e-12)


def test_cost_at_marks_an_upper_bound_and_an_unreached_level():
    pts = [_point(2.0, 1e-9), _point(4.0, 1e-11)]
    assert bench.cost_at(pts, 1e-6) == (2.0, True)
    assert bench.cost_at(pts, 1e-13) == (None, False)
    assert bench.cost_at([_point(math.nan, math.nan)], 1.0) == (None, False)


def test_smoke_run_writes_report_plots_and_finite_numbers(tmp_path):
    res = bench.main(out=tmp_path, quick=True, smoke=True)
    report = (tmp_path / "report.md").read_text()
    for heading in ("Kernel speed", "Whole trajectory", "Work–precision", "Drift"):
        assert heading in report
    for wp in res["work_precision"]:
        png = tmp_path / wp["plot"]
        assert png.stat().st_size > 1000 and png.read_bytes()[:4] == b"\x89PNG"
        ok = [p for c in wp["curves"] for p in c.points if p.ok]
        assert ok and all(np.isfinite([p.time, p.error]).all() and p.nfev > 0 for p in ok)
        assert {c.family for c in wp["curves"]} == {"ours", "scipy"}
    for row in res["c_loop"]:
        assert all(np.isfinite(row[k]) and row[k] > 0 for k in ("generated_ns", "handwritten_ns", "ratio"))
        assert row["max_rel_diff"] < 1e-10  # the hand-written rhs computes the same equations
    assert all(np.isfinite(r["ns_per_state"]) for r in res["numpy_batch"])
    tr = res["trajectory"]
    assert np.isfinite(tr["speedup"]) and tr["speedup"] > 0
    assert tr["scipy"]["error"] <= tr["ours"]["error"] or tr["scipy"]["rtol"] <= bench.MIN_RTOL
    assert all(np.isfinite(r["energy"]) for r in res["drift"]["rows"])
    data = json.loads((tmp_path / "results.json").read_text())
    assert data["settings"]["name"] == "smoke"
    assert (tmp_path / "points.csv").read_text().count("\n") > 4
