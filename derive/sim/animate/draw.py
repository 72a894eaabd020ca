"""Frames as pictures (matplotlib's Agg renderer, headless) and the GIF and MP4 files made of them.

The scene is seen from a fixed camera (orthographic, :data:`AZIMUTH`, :data:`ELEVATION`): the
unit sphere's equator and a meridian, the path of ê₃ on it up to the frame (the far side of the
sphere fainter), the vertical z, the angular momentum L (its length |L(t)|/max|L|), the body's
faces turned away from the camera left out and the rest painted far to near, lit from the
upper left. The readout gives t and the three angles; the caption the time scale and how the
spin is drawn (:mod:`derive.sim.animate.motion`). The same picture is drawn in the browser by
the HTML player (:mod:`derive.sim.animate.page`).

GIF: Pillow, each frame reduced to a palette of :data:`GIF_COLORS` colours without dithering
(flat colours compress well), looping. MP4: H.264 by an ``ffmpeg`` found on PATH
(:func:`ffmpeg_path`), fed raw RGB frames.
"""
from __future__ import annotations

import math
import os
import shutil
import subprocess
import tempfile
import textwrap

import numpy as np

from derive.errors import SceneError
from derive.sim.animate.motion import Frames, Mesh

AZIMUTH = math.radians(-60.0)
ELEVATION = math.radians(25.0)
#: Picture size in pixels (width, height): small enough for a GIF of a few seconds to stay small.
PIXELS = (320, 360)
GIF_COLORS = 32
#: A longer title is cut (the HTML page shows it whole).
TITLE_CHARS = 52
LIGHT = np.array([-0.4, 0.5, 0.77])  # in camera axes (right, up, toward the viewer)
LIGHT = LIGHT / np.linalg.norm(LIGHT)
TRACE = "#c0392b"
L_COLOR = "#16a085"


def view_matrix(azimuth: float = AZIMUTH, elevation: float = ELEVATION) -> np.ndarray:
    """Rows: the screen's right, its up, and the direction toward the viewer, in inertial axes."""
    ca, sa, ce, se = math.cos(azimuth), math.sin(azimuth), math.cos(elevation), math.sin(elevation)
    return np.array([[-sa, ca, 0.0], [-se * ca, -se * sa, ce], [ce * ca, ce * sa, se]])


def shade(color, normal_cam: np.ndarray) -> tuple:
    """Lambert shading of a face whose normal (camera axes) faces the viewer."""
    k = 0.45 + 0.55 * max(0.0, float(normal_cam @ LIGHT))
    return tuple(min(1.0, c * k) for c in color)


def faces_at(mesh: Mesh, normals: np.ndarray, R: np.ndarray, V: np.ndarray):
    """The faces seen at orientation R: (2-D polygons, colours), far to near
    (:meth:`~derive.sim.animate.motion.Mesh.order`)."""
    VR = V @ R
    P = mesh.verts @ VR.T  # camera coordinates (x, y, depth toward the viewer)
    N = normals @ VR.T
    depth = np.array([P[f, 2].mean() for f in mesh.faces])
    polys, colors = [], []
    for i in mesh.order(depth, float(VR[2, 2])):
        if N[i, 2] <= 1e-9:
            continue  # turned away (every part of the body is a closed convex solid)
        polys.append(P[mesh.faces[i], :2])
        colors.append(shade(mesh.colors[i], N[i]))
    return polys, colors


def _split(points: np.ndarray, V: np.ndarray):
    """2-D x, y of a path of 3-D points in two copies, the far (depth < 0) and the near part,
    each with NaN where the other part runs."""
    P = points @ V.T
    far = P[:, 2] < 0
    near = ~far
    # extend each part by one point so that the two meet
    near_x = np.where(near | np.roll(near, 1) | np.roll(near, -1), P[:, 0], np.nan)
    near_y = np.where(near | np.roll(near, 1) | np.roll(near, -1), P[:, 1], np.nan)
    far_x = np.where(far, P[:, 0], np.nan)
    far_y = np.where(far, P[:, 1], np.nan)
    return (far_x, far_y), (near_x, near_y)


def canvas(pixels, xlim, ylim):
    """(figure, its Agg canvas, axes filling it without frame, equal aspect, these limits): the
    Agg canvas itself, not pyplot, so that a Jupyter user's backend is left alone."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(pixels[0] / 100, pixels[1] / 100), dpi=100, facecolor="white")
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_aspect("equal")
    ax.axis("off")
    return fig, FigureCanvasAgg(fig), ax


def short(title: str) -> str:
    """A title cut to :data:`TITLE_CHARS` (the HTML page shows it whole)."""
    return title if len(title) <= TITLE_CHARS else title[:TITLE_CHARS - 1] + "…"


class Painter:
    """One matplotlib figure redrawn per frame (artists updated in place)."""

    def __init__(self, frames: Frames, mesh: Mesh, pixels: int = PIXELS):
        from matplotlib.collections import PolyCollection

        self.fr, self.mesh, self.V = frames, mesh, view_matrix()
        self.normals = mesh.normals()
        self.fig, self.canvas, ax = canvas(pixels, (-1.3, 1.3), (-1.3 - 2.6 * (pixels[1] / pixels[0] - 1) - 0.1, 1.4))
        self.ax = ax
        s = np.linspace(0, 2 * np.pi, 121)
        for circle in (np.stack([np.cos(s), np.sin(s), 0 * s], 1), np.stack([np.cos(s), 0 * s, np.sin(s)], 1),
                       np.stack([0 * s, np.cos(s), np.sin(s)], 1)):
            (fx, fy), (nx, ny) = _split(circle, self.V)
            ax.plot(fx, fy, color="#cccccc", lw=0.6, ls=(0, (2, 2)), zorder=1)
            ax.plot(nx, ny, color="#bbbbbb", lw=0.7, zorder=4)
        up = np.array([[0, 0, 0], [0, 0, 1.12]]) @ self.V.T  # (short of the readout)
        ax.plot(up[:, 0], up[:, 1], color="#555555", lw=0.9, ls=(0, (4, 2)), zorder=1)
        ax.text(up[1, 0] + 0.03, up[1, 1], "z", fontsize=7, color="#555555")
        self.far, = ax.plot([], [], color=TRACE, lw=0.8, alpha=0.35, zorder=1)
        self.near, = ax.plot([], [], color=TRACE, lw=1.1, zorder=5)
        self.body = PolyCollection([], linewidths=0.4, zorder=3, antialiased=True)
        ax.add_collection(self.body)
        self.com, = ax.plot([], [], "o", color="black", ms=3, zorder=6)
        self.Lline, = ax.plot([], [], color=L_COLOR, lw=1.6, zorder=6)
        self.Lhead, = ax.plot([], [], marker="o", color=L_COLOR, ms=3.5, zorder=6)
        self.Ltext = ax.text(0, 0, "L", color=L_COLOR, fontsize=8, zorder=6)
        self.clock = ax.text(-1.27, 1.24, "", fontsize=7, va="top")
        # what changes per frame is drawn over a copy of the rest (blitting)
        self.moving = [self.far, self.body, self.near, self.com, self.Lline, self.Lhead, self.Ltext, self.clock]
        for artist in self.moving:
            artist.set_animated(True)
        self.background = None
        ax.text(-1.27, -1.17, "\n".join(_wrap(n, 70) for n in frames.notes), fontsize=5.2, va="top",
                color="#333333", linespacing=1.25)
        ax.text(-1.27, 1.37, short(frames.title), fontsize=7, va="top", color="#222222", weight="bold")

    def draw(self, k: int) -> np.ndarray:
        """Frame k as an RGB array (height, width, 3)."""
        fr, V = self.fr, self.V
        R = fr.R[k]
        polys, colors = faces_at(self.mesh, self.normals, R, V)
        self.body.set_verts(polys)
        self.body.set_facecolor(colors)
        self.body.set_edgecolor(colors)  # (edges in the face's colour close the seams between faces)
        upto = fr.trace[fr.trace_t <= fr.t[k]]
        path = np.vstack([upto, fr.axis[k][None]]) if len(upto) else fr.axis[k][None]
        (fx, fy), (nx, ny) = _split(path, V)
        self.far.set_data(fx, fy)
        self.near.set_data(nx, ny)
        if self.mesh.com is not None:
            c = (R @ self.mesh.com) @ V.T
            self.com.set_data([c[0]], [c[1]])
        tip = (1.15 * fr.L[k]) @ V.T
        self.Lline.set_data([0, tip[0]], [0, tip[1]])
        self.Lhead.set_data([tip[0]], [tip[1]])
        self.Ltext.set_position((tip[0] + 0.04, tip[1]))
        a, b, g = np.degrees(fr.angles[k])
        self.clock.set_text(f"t = {fr.t[k]:.3f} s\nα = {a:6.1f}°  β = {b:5.1f}°  γ = {g:6.1f}°"
                            + ("\nspin: stroboscopic" if fr.strobe else ""))
        if self.background is None:
            self.canvas.draw()
            self.background = self.canvas.copy_from_bbox(self.fig.bbox)
        self.canvas.restore_region(self.background)
        for artist in self.moving:
            self.ax.draw_artist(artist)
        return np.asarray(self.canvas.buffer_rgba())[:, :, :3].copy()


def _wrap(text: str, width: int) -> str:
    return "\n".join(textwrap.wrap(text, width))


def pictures(frames: Frames, mesh: Mesh):
    """Every frame as an RGB array, one at a time."""
    painter = Painter(frames, mesh)
    for k in range(len(frames.t)):
        yield painter.draw(k)


def encode_gif(fh, picture, n: int, fps: int, keep=()) -> None:
    """A looping GIF of the ``n`` frames ``picture(k)`` (RGB arrays) into the binary file ``fh``
    (Pillow): one palette of :data:`GIF_COLORS` colours for every frame, from a few frames spread
    over the animation (a GIF whose frames share it stores only what changed), no dithering
    (flat colours compress well). ``keep``: RGB colours (0-255) the palette must hold, such as
    thin lines' that the palette of a few frames would merge into their neighbours."""
    from PIL import Image

    picks = np.unique(np.linspace(0, n - 1, min(6, n)).round().astype(int))
    # the picked frames are kept for the encoding below: each frame is drawn once
    drawn = {int(k): picture(int(k)) for k in picks}
    strip = np.vstack(list(drawn.values()))
    if len(keep):
        width = strip.shape[1]
        swatches = np.repeat(np.asarray(keep, dtype=strip.dtype)[:, None, :], width, axis=1)
        strip = np.vstack([strip, np.repeat(swatches, strip.shape[0] // (4 * len(keep)) + 1, axis=0)])
    pal = Image.fromarray(strip).quantize(GIF_COLORS, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    images = (Image.fromarray(drawn.pop(k) if k in drawn else picture(k)).quantize(palette=pal, dither=Image.Dither.NONE)
              for k in range(n))
    first = next(images)
    first.save(fh, format="GIF", save_all=True, append_images=images, loop=0,
               duration=1000 / fps, disposal=1)


def write_gif(fh, frames: Frames, mesh: Mesh) -> None:
    """The animation as a looping GIF into the binary file ``fh`` (:func:`encode_gif`)."""
    encode_gif(fh, Painter(frames, mesh).draw, len(frames.t), frames.fps)


def ffmpeg_path() -> str:
    """The ``ffmpeg`` on PATH, else SceneError (exit 2) saying MP4 needs it."""
    found = shutil.which("ffmpeg")
    if found is None:
        raise SceneError("animate: -o: an .mp4 is written by ffmpeg, and no ffmpeg is on PATH "
                         "(install it, or write .gif or .html)")
    return found


def encode_mp4(fh, pictures_, fps: int) -> None:
    """H.264 MP4 of the RGB arrays ``pictures_`` (an iterable) into the binary file ``fh``,
    encoded by ffmpeg (to a temporary file first: MP4's index goes at its start, which needs a
    seekable file)."""
    exe = ffmpeg_path()
    with tempfile.TemporaryDirectory(prefix="derive-animate-") as tmp:
        out = os.path.join(tmp, "out.mp4")
        cmd = [exe, "-nostdin", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24",
               "-s", f"{PIXELS[0]}x{PIXELS[1]}", "-r", str(fps), "-i", "-", "-an", "-c:v", "libx264",
               "-pix_fmt", "yuv420p", "-movflags", "+faststart", out]
        proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stderr=subprocess.PIPE)
        try:
            try:
                for a in pictures_:
                    proc.stdin.write(a.tobytes())
                proc.stdin.close()
            except BrokenPipeError:
                pass  # ffmpeg stopped reading: its message follows
            err = proc.stderr.read().decode(errors="replace")
            if proc.wait() != 0:
                raise SceneError(f"animate: -o: ffmpeg failed ({' '.join(err.split())[:200] or proc.returncode})")
        finally:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
        with open(out, "rb") as f:
            shutil.copyfileobj(f, fh)


def write_mp4(fh, frames: Frames, mesh: Mesh) -> None:
    """The animation as H.264 MP4 into the binary file ``fh`` (:func:`encode_mp4`)."""
    encode_mp4(fh, pictures(frames, mesh), frames.fps)
