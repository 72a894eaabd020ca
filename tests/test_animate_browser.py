"""The HTML player in a real browser: headless Chromium loads the page from disk (no network) and
its screenshot shows the body, which moves between two scrub positions (``#frame=N``)."""
import shutil
import subprocess

import numpy as np
import pytest
from PIL import Image

import derive
from derive.sim import animate

BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable", "headless_shell")
BROWSER = next((found for found in map(shutil.which, BROWSERS) if found), None)

pytestmark = pytest.mark.skipif(BROWSER is None, reason="no Chromium on PATH (.ci/run installs the "
                                                        "distribution's chromium package)")


def _screenshots(page, frames, tmp_path) -> list:
    """Screenshots of the page opened at each of ``frames`` (browsers started side by side)."""
    runs = []
    for k in frames:
        out = tmp_path / f"frame{k}.png"
        cmd = [BROWSER, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
               "--no-first-run", "--disable-extensions", f"--user-data-dir={tmp_path / f'profile{k}'}",
               "--window-size=560,760", f"--screenshot={out}", f"{page.as_uri()}#frame={k}"]
        runs.append((out, subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)))
    shots = []
    for out, proc in runs:
        _, err = proc.communicate(timeout=120)
        assert proc.returncode == 0 and out.exists(), err[-2000:]
        shots.append(np.asarray(Image.open(out).convert("RGB")).astype(int))
    return shots


def _body_pixels(shot: np.ndarray) -> np.ndarray:
    """Where the shot shows the body's orange (shaded: R > 80, R/G within 1.4..2.6, G > 2 B):
    neither the red path (R/G ≈ 3.4), the green L, the grey spindle nor the page's text."""
    r, g, b = shot[..., 0], shot[..., 1], shot[..., 2]
    return (r > 80) & (r > 1.4 * g) & (r < 2.6 * g) & (g > 2 * b)


def test_the_page_shows_the_body_turning_in_headless_chromium(tmp_path):
    res = derive.simulate("looping_top", t_end=0.2, samples=51)
    page = tmp_path / "top.html"
    fr = animate.write(res, page, fps=20, speed=0.05)
    last = len(fr.t) - 1
    first, later = map(_body_pixels, _screenshots(page, (0, last), tmp_path))
    # the canvas is the square under the title: the body is drawn there, a few thousand pixels
    ys, xs = np.nonzero(first)
    assert first.sum() > 2000 and later.sum() > 2000, (first.sum(), later.sum())
    assert 40 < ys.min() and ys.max() < 600 and xs.max() < 560
    # scrubbing to the end moves it: the tilted top has precessed and nutated
    assert (first ^ later).sum() > 0.1 * first.sum()
