"""`derive animate` and Result.animate: frames sampled from the motion, the body drawn, the
stroboscopic rule for fast spins, the three formats, the command line's rules."""
import shutil
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import derive
from derive import cli
from derive.errors import SceneError
from derive.reference.rotation import euler_matrix
from derive.sim import animate, examples
from derive.sim.animate import draw, motion, page

ROOT = Path(__file__).resolve().parents[1]
#: The looping top over a fifth of a second: 51 samples, 4 ms apart; spin about 147 rad/s.
SHORT = {"t_end": 0.2, "samples": 51}


@pytest.fixture(scope="module")
def top():
    return derive.simulate("looping_top", **SHORT)


@pytest.fixture(scope="module")
def racket():
    return derive.simulate("tennis_racket", t_end=1.0, samples=51)


def test_frames_are_spaced_by_speed_over_fps_up_to_the_end(top):
    fr = motion.frames(top, fps=10, speed=0.05)
    assert len(fr.t) == 41  # 0.2 s * 10 frames/s / 0.05
    assert np.allclose(np.diff(fr.t), 0.005)
    assert fr.t[0] == top.t[0] and fr.t[-1] == pytest.approx(top.t[-1])


def test_gif_frame_count_size_and_delay_follow_fps_and_speed(top, tmp_path):
    out = tmp_path / "top.gif"
    fr = animate.write(top, out, fps=10, speed=0.1)
    im = Image.open(out)
    assert im.n_frames == len(fr.t) == 21
    assert im.info["duration"] == 100  # ms: 10 frames per second
    assert im.size == draw.PIXELS
    assert out.stat().st_size < 21 * 12_000  # one shared palette: frames store what changed


def test_a_frame_at_a_sample_time_is_the_samples_rotation(top):
    fr = motion.frames(top, fps=10, speed=0.2)  # a frame every 0.02 s: every fifth sample
    R = euler_matrix(top.alpha, top.beta, top.gamma)
    assert np.array_equal(fr.R, R[::5])
    assert np.allclose(fr.axis, top.axis[::5], atol=1e-12)


def test_a_frame_between_samples_follows_the_motion(top):
    fine = derive.simulate("looping_top", t_end=0.2, samples=501)  # 0.4 ms apart
    fr = motion.frames(top, fps=10, speed=0.06)  # 6 ms per frame: between the coarse samples
    j = np.rint(fr.t / 4e-4).astype(int)
    assert np.allclose(fine.t[j], fr.t, atol=1e-12)
    Rf = euler_matrix(fine.alpha[j], fine.beta[j], fine.gamma[j])
    # the whole rotation, spin included (the body turns ~0.6 rad about ê3 between samples):
    # third order in the sample spacing, far below a pixel (1/120 of the sphere's radius)
    assert np.max(np.abs(fr.R - Rf)) < 2e-4
    assert np.max(np.abs(fr.axis - fine.axis[j])) < 2e-4


def test_the_drawn_axis_is_the_results_axis_projected(top):
    fr, mesh = animate.prepare(top, fps=10, speed=0.2)
    painter = draw.Painter(fr, mesh)
    painter.draw(3)  # t = 0.06 s, sample 15
    V = draw.view_matrix()
    tip = V @ top.axis[15]
    xs, ys = (painter.near if tip[2] >= 0 else painter.far).get_data()
    assert (xs[-1], ys[-1]) == pytest.approx((tip[0], tip[1]), abs=1e-12)
    # and the spindle's tip, drawn with the body, is there too
    spindle_tip = (V @ fr.R[3] @ np.array([0.0, 0.0, 1.0]))[:2]
    assert spindle_tip == pytest.approx(tip[:2], abs=1e-12)


def test_the_spin_is_drawn_stroboscopically_above_a_quarter_turn_per_frame_and_said(top):
    rate = float(np.max(np.abs(top.omega[:, 2])))
    below = motion.STROBE_TURN * 0.9 * 2 * np.pi * 20 / rate  # speed for 0.9 of the threshold
    slow = motion.frames(top, fps=20, speed=below)
    fast = motion.frames(top, fps=20, speed=below * 2)
    assert slow.spin_turns == pytest.approx(0.9 * motion.STROBE_TURN)
    assert not slow.strobe and "stroboscopic" not in " ".join(slow.notes)
    assert fast.strobe and "stroboscopic" in fast.notes[1] and "turns/s" in fast.notes[1]
    assert "1 s on screen is" in fast.notes[0]


def test_the_asymmetric_body_is_the_box_of_its_moments(racket):
    mesh = motion.body_mesh(racket.scene)
    assert mesh.kind == "box"
    half = mesh.verts[:8].max(axis=0)  # the eight corners first, centred on the centre of mass
    I1, I2, I3 = racket.scene.body.moments
    expected = np.sqrt([I2 + I3 - I1, I1 + I3 - I2, I1 + I2 - I3])
    assert half / half[0] == pytest.approx(expected / expected[0])


def test_the_symmetric_top_is_a_disc_whose_moments_are_the_scenes(top):
    mesh = motion.body_mesh(top.scene)
    assert mesh.kind == "top"
    disc = mesh.verts[: (motion.SIDES * 2)]
    r = np.hypot(disc[:, 0], disc[:, 1]).max()
    centre = disc[:, 2].mean()
    g = top.scene.tables["gravity"]
    # radius and height in the drawing keep the scene's ratio r / l = sqrt(2 I3 / M) / l
    assert r / centre == pytest.approx(np.sqrt(2 * top.scene.body.I3 / g["M"]) / g["l"], rel=1e-3)
    assert mesh.verts[:, 2].max() == pytest.approx(1.0)  # the spindle's tip on the unit sphere


def test_the_html_page_is_self_contained(top, tmp_path):
    out = tmp_path / "top.html"
    animate.write(top, out, fps=5, speed=0.1)
    text = out.read_text(encoding="utf-8")
    assert "http://" not in text and "https://" not in text
    assert "<script src" not in text and "<link" not in text and "@import" not in text
    assert '<canvas id="view"' in text and '"R":[' in text
    assert len(text) < 60_000


def test_a_title_from_the_scene_is_data_in_the_page():
    scene = {"title": "</script><b>x</b>", "body": {"I1": 1.0, "I3": 0.5},
             "initial": {"alpha": 0.0, "beta": 0.3, "gamma": 0.0, "alpha_dot": 1.0, "beta_dot": 0.0,
                         "gamma_dot": 2.0}, "simulate": {"t_end": 0.1, "samples": 5}}
    text = derive.simulate(scene).animate(fps=5, speed=0.05).html
    assert "</script><b>" not in text and "&lt;/script&gt;&lt;b&gt;" in text


def test_result_animate_without_a_path_gives_an_inline_player(top):
    shown = top.animate(fps=5, speed=0.1)
    html = shown._repr_html_()
    assert html.startswith("<iframe srcdoc=") and "canvas" in html
    assert len(shown.frames.t) == 11


def test_result_repr_html_is_a_short_summary_table(top):
    table = top._repr_html_()
    assert table.startswith("<table>") and table.count("<tr>") <= 10
    for word in ("Looping top", top.method, "samples", "51", "energy drift", "drift of L_3"):
        assert word in table


def test_a_damped_result_names_the_energy_change_not_drift():
    res = derive.simulate("damped_top", t_end=0.1, samples=11)
    label, value = page.energy_row(res)
    assert label == "energy change" and "damping" in value


def _main(argv, capsys):
    code = cli.main([str(a) for a in argv])
    return code, capsys.readouterr()


def test_cli_writes_html_and_says_how_the_spin_is_drawn(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, io_ = _main(["animate", "looping_top", "-o", "top.html", "--fps", "5", "--speed", "0.5"], capsys)
    assert code == 0, io_.err
    assert (tmp_path / "top.html").exists()
    assert "stroboscopic" in io_.out and "1 s on screen is 500 ms of the motion" in io_.out


@pytest.mark.parametrize("argv, key", [
    (["-o", "x.avi"], "-o"),
    (["-o", "x"], "-o"),
    (["-o", "x.gif", "--fps", "0"], "--fps"),
    (["-o", "x.gif", "--fps", "51"], "--fps"),
    (["-o", "x.gif", "--speed", "-1"], "--speed"),
    (["-o", "x.gif", "--speed", "nan"], "--speed"),
    (["-o", "missing/x.gif"], "missing"),
])
def test_cli_bad_input_is_exit_2_with_one_line_naming_the_key(argv, key, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, io_ = _main(["animate", "looping_top", *argv], capsys)
    assert code == 2
    lines = io_.err.strip().splitlines()
    assert len(lines) == 1 and key in lines[0]
    assert list(tmp_path.iterdir()) == []


def test_cli_without_ffmpeg_refuses_mp4_before_any_work(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("PATH", str(tmp_path))  # no ffmpeg here

    def no_work(*args, **kwargs):
        raise AssertionError("simulated before refusing")

    monkeypatch.setattr("derive.sim.simulation.simulate", no_work)
    code, io_ = _main(["animate", "looping_top", "-o", "top.mp4"], capsys)
    assert code == 2 and "ffmpeg" in io_.err and len(io_.err.strip().splitlines()) == 1
    assert list(tmp_path.iterdir()) == []


def test_an_output_never_overwrites_the_scene(tmp_path, capsys):
    scene = tmp_path / "scene.html"  # a scene file whose name an output could take
    scene.write_text((examples.path("looping_top", "scene")).read_text())
    before = scene.read_bytes()
    code, io_ = _main(["animate", scene, "-o", scene], capsys)
    assert code == 2 and "would overwrite the input" in io_.err
    assert scene.read_bytes() == before


def test_an_interrupted_animation_leaves_no_file(top, tmp_path, monkeypatch):
    drawn = []
    real = draw.Painter.draw

    def interrupted(self, k):
        drawn.append(k)
        if len(drawn) > 3:
            raise KeyboardInterrupt
        return real(self, k)

    monkeypatch.setattr(draw.Painter, "draw", interrupted)
    out = tmp_path / "top.gif"
    with pytest.raises(KeyboardInterrupt):
        animate.write(top, out, fps=10, speed=0.1)
    assert list(tmp_path.iterdir()) == []


def test_python_api_names_the_bad_argument(top, tmp_path):
    with pytest.raises(SceneError, match="animate: fps:"):
        top.animate(tmp_path / "x.gif", fps=2.5)
    with pytest.raises(SceneError, match="-o: extension '.png'"):
        top.animate(tmp_path / "x.png")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(shutil.which("ffmpeg") is None, reason="no ffmpeg on PATH (MP4 is written by ffmpeg)")
def test_mp4_is_written_by_ffmpeg(top, tmp_path):
    out = tmp_path / "top.mp4"
    animate.write(top, out, fps=10, speed=0.2)
    head = out.read_bytes()[:12]
    assert head[4:8] == b"ftyp"
    assert [p.name for p in tmp_path.iterdir()] == ["top.mp4"]


def test_a_frame_is_painted_at_the_picture_size(top):
    fr, mesh = animate.prepare(top, fps=5, speed=0.1)
    picture = draw.Painter(fr, mesh).draw(0)
    assert picture.shape == (draw.PIXELS[1], draw.PIXELS[0], 3) and picture.dtype == np.uint8
    assert len(np.unique(picture.reshape(-1, 3), axis=0)) > 8  # something was drawn


@pytest.mark.parametrize("name", ["looping_top", "sleeping_top", "tennis_racket", "kovalevskaya_top"])
def test_the_docs_show_each_example_animated_in_a_small_gif(name):
    gif = ROOT / "docs" / "animate" / f"{name}.gif"
    im = Image.open(gif)
    assert im.format == "GIF" and im.n_frames >= 40 and im.size == draw.PIXELS
    assert gif.stat().st_size < 400_000
    assert f"animate/{name}.gif" in (ROOT / "docs" / "animate.md").read_text(encoding="utf-8")


def test_more_frames_than_the_limit_are_refused_naming_speed(top):
    with pytest.raises(SceneError, match="animate: speed: .* at most 3000"):
        motion.frames(top, fps=50, speed=0.2 * 50 / 3000 / 2)
