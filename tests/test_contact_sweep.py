"""Sweeps over tops on a table, and the prepared contact scene: small grids on short runs.

The tippe top's inversion map (spin × the ball's offset s = αr) and the round peg's rise map
(μ × peg radius) as 3 × 3 grids; each point's measures equal a single run of that scene; the
contact measures are refused for a pivoted scene and the pivoted ones for a contact sweep.
"""
from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import derive
from derive.cli import main

ROOT = Path(__file__).resolve().parent.parent
CONTACT = ROOT / "scenes" / "contact"


def _scene(name: str, t_end: float, samples: int) -> dict:
    with open(CONTACT / f"{name}.toml", "rb") as f:
        data = tomllib.load(f)
    data["simulate"] = {"t_end": t_end, "samples": samples}
    return data


@pytest.fixture(scope="module")
def tippe_map():
    scene = _scene("tippe_top", 0.6, 121)
    spec = {"scene": scene,
            "vary": {"contact.offset": {"values": [0.001, 0.003, 0.005]},
                     "initial.omega.2": {"values": [60.0, 120.0, 180.0]}},
            "measure": {"names": ["inverted", "time_to_invert", "final_tilt", "final_spin",
                                  "switches", "jellett_drift", "nfev"]}}
    return scene, derive.sweep(spec)


def test_tippe_inversion_map_has_a_row_per_point_and_keeps_jellett(tippe_map):
    _, res = tippe_map
    assert res.shape == (3, 3) and list(res.keys) == ["contact.offset", "initial.omega.2"]
    assert (res.status == "ok").all()
    assert np.all(res.measures["jellett_drift"] < 1e-9)  # J = L·a under any contact force
    assert res.measures["switches"].dtype == np.int64
    inv = res.measures["inverted"].reshape(3, 3)
    t = res.measures["time_to_invert"].reshape(3, 3)
    # the fastest spin turns over within 0.6 s at every offset, the slowest at none
    assert inv[:, 2].tolist() == [1.0, 1.0, 1.0] and inv[:, 0].tolist() == [0.0, 0.0, 0.0]
    assert np.isnan(t[:, 0]).all() and np.all((t[:, 2] > 0) & (t[:, 2] < 0.6))
    # a faster spin turns it over sooner
    assert np.all(t[1:, 2] < t[1:, 1])


def test_tippe_map_point_equals_a_single_run(tippe_map):
    scene, res = tippe_map
    k = 5  # offset 0.003, spin 180: the shipped scene's numbers
    assert res.params["contact.offset"][k] == 0.003 and res.params["initial.omega.2"][k] == 180.0
    one = derive.simulate(scene)
    assert res.measures["final_tilt"][k] == one.beta[-1]
    assert res.measures["final_spin"][k] == one.omega[-1, 2]
    assert res.measures["nfev"][k] == one.nfev
    # θ first passes 90° between the two samples around it, on the cubic through β and β̇
    i = int(np.flatnonzero(one.beta >= math.pi / 2)[0])
    assert one.t[i - 1] < res.measures["time_to_invert"][k] <= one.t[i]


def test_time_to_invert_is_located_between_the_samples():
    # the cubic through β and β̇ at the samples: ten times more samples move it by < 1e-6 s
    from derive.sweeps.measures import REGISTRY

    m = REGISTRY["time_to_invert"].contact
    coarse = m(derive.simulate(_scene("tippe_top", 0.5, 101)))
    fine = m(derive.simulate(_scene("tippe_top", 0.5, 1001)))
    assert 0.3 < fine < 0.35 and abs(coarse - fine) < 1e-6


def test_round_peg_rise_map_over_mu_and_radius():
    spec = {"scene": _scene("round_peg_top", 0.3, 61),
            "vary": {"contact.mu": {"from": 0.2, "to": 0.5, "num": 3},
                     "contact.radius": {"values": [0.003, 0.005, 0.008]}},
            "measure": {"names": ["min_tilt", "final_tilt", "switches"]}}
    res = derive.sweep(spec)
    assert (res.status == "ok").all() and len(res.status) == 9
    rise = res.measures["min_tilt"].reshape(3, 3)
    assert np.all(rise < 0.5)                # every top rises from its start at 0.5 rad
    assert np.all(rise[:, 2] < rise[:, 0])   # a wider peg rises further
    assert np.all(res.measures["switches"] >= 1)  # captured into rolling: a located stick


def test_contact_sweep_gives_the_same_numbers_in_worker_processes():
    spec = {"scene": _scene("round_peg_top", 0.1, 11),
            "vary": {"contact.mu": {"values": [0.2, 0.4]}, "contact.radius": {"values": [0.003, 0.006]}},
            "measure": {"names": ["min_tilt", "final_spin", "switches", "nfev"]}}
    here, there = derive.sweep(spec), derive.sweep(spec, workers=2)
    for name in here.measures:
        assert np.array_equal(here.measures[name], there.measures[name]), name
    assert list(there.status) == ["ok"] * 4
    with pytest.raises(derive.SceneError, match="--scheduler"):
        derive.sweep(spec, scheduler="tcp://127.0.0.1:1")


def test_contact_sweep_refuses_a_pivoted_measure(capsys, tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text(f'scene = "{CONTACT / "round_peg_top.toml"}"\n[vary]\ncontact.mu = '
                    '{ values = [0.1] }\n[measure]\nnames = ["beta_max"]\n', encoding="utf-8")
    assert main(["sweep", str(spec), "-o", str(tmp_path / "o.csv")]) == 2
    err = capsys.readouterr().err
    assert "measure.names" in err and "beta_max" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "o.csv").exists()


def test_contact_sweep_refuses_a_value_the_scene_refuses(capsys, tmp_path):
    spec = {"scene": _scene("round_peg_top", 0.1, 11), "vary": {"contact.mu": {"values": [0.1, -0.2]}}}
    with pytest.raises(derive.SceneError, match="vary.contact.mu"):
        derive.sweep(spec)
    spec["vary"] = {"gravity.l": {"values": [0.1]}}
    with pytest.raises(derive.SceneError, match="vary.gravity.l"):
        derive.sweep(spec)


def test_pivoted_sweep_refuses_a_contact_measure():
    spec = {"scene": "scenes/sleeping_top.toml", "vary": {"initial.beta": {"values": [0.1]}},
            "measures": ["inverted"]}
    spec["scene"] = str(ROOT / "scenes" / "sleeping_top.toml")
    with pytest.raises(derive.SceneError, match="top on a table"):
        derive.sweep(spec)


def test_contact_sweep_cli_writes_the_table_and_the_map(capsys, tmp_path):
    spec = tmp_path / "tippe.toml"
    scene = tmp_path / "tippe_scene.toml"
    text = (CONTACT / "tippe_top.toml").read_text(encoding="utf-8")
    scene.write_text(text.split("[simulate]")[0] + "[simulate]\nt_end = 0.2\nsamples = 21\n",
                     encoding="utf-8")
    spec.write_text('scene = "tippe_scene.toml"\n[vary]\ncontact.offset = { values = [0.001, 0.004] }\n'
                    'initial.omega.2 = { values = [100.0, 180.0] }\n[measure]\n'
                    'names = ["final_tilt", "inverted"]\n', encoding="utf-8")
    out, png = tmp_path / "t.csv", tmp_path / "t.png"
    assert main(["sweep", str(spec), "-o", str(out), "--plot", str(png)]) == 0
    assert "4 points (0 failed)" in capsys.readouterr().out
    import pandas as pd

    table = pd.read_csv(out)
    assert list(table.columns) == ["contact.offset", "initial.omega.2", "final_tilt", "inverted",
                                   "status"]
    assert png.stat().st_size > 0


# ---------------------------------------------------------------------------------------------
# the prepared contact scene


def test_prepare_a_contact_scene_runs_as_simulate():
    p = derive.prepare(CONTACT / "round_peg_top.toml", t_end=0.2, samples=21)
    a = p.run()
    b = derive.simulate(CONTACT / "round_peg_top.toml", t_end=0.2, samples=21)
    assert np.array_equal(a.beta, b.beta) and a.nfev == b.nfev
    c = p.run(initial={"beta": 0.4}, params={"mu": 0.2, "radius": 0.004})
    data = _scene("round_peg_top", 0.2, 21)
    data["initial"]["beta"] = 0.4
    data["contact"].update(mu=0.2, radius=0.004)
    d = derive.simulate(data)
    assert np.array_equal(c.beta, d.beta) and abs(c.beta[0] - 0.4) < 1e-15
    assert np.array_equal(p.run().beta, a.beta)  # the prepared scene itself is unchanged


def test_prepared_contact_refuses_keys_it_does_not_take():
    p = derive.prepare(CONTACT / "tippe_top.toml", t_end=0.1, samples=11)
    with pytest.raises(derive.SceneError, match="initial.gamma_dot"):
        p.run(initial={"gamma_dot": 3.0})  # the scene gives omega
    with pytest.raises(derive.SceneError, match="params: unknown parameter 'l'"):
        p.run(params={"l": 0.1})
    with pytest.raises(derive.SceneError, match="contact.mu"):
        p.run(params={"mu": -1.0})


# ---------------------------------------------------------------------------------------------
# derive animate of a top on a table


@pytest.fixture(scope="module")
def tippe_run():
    return derive.simulate(_scene("tippe_top", 0.4, 81))


def test_table_frames_follow_the_run_at_its_samples(tippe_run):
    from derive.sim.animate import table

    fr = table.frames(tippe_run, fps=5, speed=0.1)
    assert len(fr.t) == 21 and np.allclose(fr.t, np.arange(21) * 0.02)
    k = np.searchsorted(tippe_run.t, fr.t[10])  # t = 0.2, a sample time
    assert np.allclose(fr.com[10], tippe_run.com[k], atol=1e-15)
    assert np.allclose(fr.contact[10], tippe_run.contact[k], atol=1e-15)
    assert np.allclose(fr.R[10][:, 2], tippe_run.axis[k], atol=1e-12)
    assert fr.phase[10] == tippe_run.phase[k]


def test_the_tippe_tops_ball_touches_the_table_in_every_frame(tippe_run):
    from derive.sim.animate import table

    fr = table.frames(tippe_run, fps=5, speed=0.1)
    mesh = table.body_mesh(tippe_run.scene)
    sc = tippe_run.scene
    ball = np.linalg.norm(mesh.verts - [0, 0, sc.offset], axis=1) <= sc.radius * (1 + 1e-12)
    for k in range(len(fr.t)):
        z = fr.com[k, 2] + mesh.verts[ball] @ fr.R[k][2]
        # the vertices lie on the ball, which touches z = 0: none below it, the lowest within
        # the mesh's spacing (20 degrees: r (1 - cos 20°) = 0.06 r) of it
        assert z.min() >= -1e-12 and z.min() < (1 - math.cos(math.radians(20))) * sc.radius


def test_cli_animates_a_top_on_a_table_as_gif_and_html(tmp_path, capsys):
    from PIL import Image

    from derive.sim.animate import draw

    scene = tmp_path / "peg.toml"
    text = (CONTACT / "round_peg_top.toml").read_text(encoding="utf-8")
    scene.write_text(text.split("[simulate]")[0] + "[simulate]\nt_end = 0.3\nsamples = 31\n",
                     encoding="utf-8")
    gif, page = tmp_path / "peg.gif", tmp_path / "peg.html"
    assert main(["animate", str(scene), "-o", str(gif), "--fps", "5", "--speed", "0.25"]) == 0
    assert "7 frames at 5 frames/s" in capsys.readouterr().out  # 0.3 s at 0.25 s per second, 5 a second
    im = Image.open(gif)
    assert im.format == "GIF" and im.n_frames == 7 and im.size == draw.PIXELS
    assert main(["animate", str(scene), "-o", str(page), "--fps", "5", "--speed", "0.3"]) == 0
    text = page.read_text(encoding="utf-8")
    assert "data:image/gif;base64," in text and "http" not in text.lower().replace("http-equiv", "")
    assert "round peg" not in text or "<script" not in text  # data, no script
