"""The tippe-top race against MuJoCo in `derive bench`: both sides built from the shipped scene's
numbers, the measures they are judged on, how runs are matched, and the line the report gives
without MuJoCo. No timed assertions: the bench reports the times, the tests check the plumbing."""
import math
import sys
from types import SimpleNamespace

import numpy as np
import pytest

from derive.bench import tippe_race as tr


def test_jelletts_final_spin_of_the_shipped_tippe_top():
    n = tr.numbers(tr.tippe_scene())
    assert tr.jellett_spin(n) == pytest.approx(180.0 * (0.2 - math.cos(0.1)) / 1.2, rel=1e-15)
    assert tr.jellett_spin(n) == pytest.approx(-119.2506, abs=1e-4)


def test_matching_takes_the_best_run_no_slower_and_the_fastest_run_no_less_accurate():
    ours = [{"rtol": 1e-6, "time": 0.01, "jellett_drift": 1e-7, "spin_error": 2e-3},
            {"rtol": 1e-9, "time": 0.02, "jellett_drift": 1e-10, "spin_error": 1e-5},
            {"rtol": 1e-12, "time": 0.05, "jellett_drift": 1e-13, "spin_error": 1e-5}]
    m = tr._match({"time": 0.03, "jellett_drift": 1e-2, "spin_error": 1e-3}, ours)
    assert m["equal_time_rtol"] == 1e-9 and m["jellett_ratio"] == pytest.approx(1e8)
    assert m["equal_spin_rtol"] == 1e-9 and m["time_ratio"] == pytest.approx(2 / 3)
    assert tr._match({"time": 0.001, "jellett_drift": 1e-2, "spin_error": 1e-9}, ours) == {}


def test_without_mujoco_the_race_is_skipped_with_one_line(monkeypatch):
    monkeypatch.setitem(sys.modules, "mujoco", None)  # import mujoco raises ImportError
    out = tr.run(SimpleNamespace(name="smoke"))
    assert "MuJoCo is not installed" in out["skipped"] and tr.rows(out) == []
    text = tr.section({"targets": {"tippe_top": out}})
    assert text[-2].startswith("Not raced: MuJoCo is not installed")


def test_the_mujoco_model_has_the_scenes_body_ball_and_friction():
    mujoco = pytest.importorskip("mujoco")
    n = tr.numbers(tr.tippe_scene())
    top = tr.MuJoCoTop(n, 1e-3, t_end=0.05)
    m = top.model
    body = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, "top")
    assert m.body_mass[body] == pytest.approx(n["M"], rel=1e-15)
    assert np.allclose(m.body_inertia[body], [n["I1"], n["I2"], n["I3"]], rtol=1e-15)
    ball = int(np.nonzero(m.geom_bodyid == body)[0][0])
    assert m.geom_size[ball][0] == n["R"] and np.allclose(m.geom_pos[ball], [0, 0, n["s"]])
    assert np.all(m.geom_friction[:, 0] == n["mu"]) and np.all(m.geom_condim == 3)
    rec = top.record()
    assert rec["theta"][0] == pytest.approx(n["theta0"], rel=1e-12)
    assert rec["omega"][0, 2] == n["n0"] and len(rec["t"]) == 51
    # J at the start is I₃ n₀ (s − R cos θ₀); MuJoCo moves it (it is the measure raced)
    assert rec["jellett"][0] == pytest.approx(n["I3"] * n["n0"] * (n["s"] - n["R"] * math.cos(n["theta0"])),
                                              rel=1e-12)


def test_the_smoke_race_reports_both_sides_and_a_row_per_goal():
    pytest.importorskip("mujoco")
    out = tr.run(SimpleNamespace(name="smoke"))
    assert out["derive_law"] == "viscous" and len(out["mujoco_runs"]) == 1
    (m,) = out["mujoco_runs"]
    assert m["dt"] == 1e-3 and m["jellett_drift"] > 0 and m["time"] > 0
    (o,) = out["derive"]
    assert o["jellett_drift"] < m["jellett_drift"]
    assert [key for _, key, _ in tr.rows(out)] == [tr.JELLETT_GOAL, tr.SPIN_GOAL]
    assert any(line.startswith("| MuJoCo | dt 1e-03") for line in tr.section({"targets": {"tippe_top": out}}))
