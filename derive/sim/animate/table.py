"""A top on a table, animated: the body at its place on the plane z = 0, the contact's track on it.

Takes a contact run's result (duck-typed: ``t``, the z-y-z angles, ``omega``, ``axis``, ``com``,
``contact``, ``phase``, ``normal_force`` and its scene's moments, mass, shape, radius and
offset). The camera (the fixed direction of :mod:`~derive.sim.animate.draw`, orthographic)
follows the centre of mass across the table: the table's grid lines, fixed on the plane, move
under it; the contact point's track up to the frame is drawn on the plane in the colour of the
phase it was made in (slide, roll; none in flight), the centre of mass's track fainter. The
body, drawn at its true size in body axes from its centre of mass (:func:`body_mesh`):

* a ball on a stem (the tippe top: the sphere's centre at s = αr > 0 along ê₃, the stem beyond
  it along +ê₃);
* a disc at the centre of mass on a spindle down to a ball (a round peg, s < 0) or to a point
  (a pointed top): the disc a uniform one of the moments, radius √(2 I₃/M) and thickness
  from I₁ as in :mod:`~derive.sim.animate.motion`;
* a thin disc of radius r (Euler's disk), its thickness from I₁ = M (r²/4 + H²/12).

The motion at a frame is :func:`derive.sim.animate.motion.rotation_at` (the body turned by its
angular velocity between the samples) and the centre of mass and contact point linear between
the samples. GIF and MP4 are drawn frame by frame (:mod:`~derive.sim.animate.draw`'s encoders);
the HTML page embeds the GIF with the caption (self-contained, no network).
"""
from __future__ import annotations

import base64
import html
import io
import math
from dataclasses import dataclass

import numpy as np

from derive.sim.animate import draw, motion
from derive.sim.animate.motion import BODY, SPINDLE, STRIPE, Mesh

#: The window's half-width around the centre of mass, in body reaches.
WINDOW = 2.6
#: Colours of the contact's track by phase.
PHASE_COLORS = {"slide": "#c0392b", "roll": "#27ae60", "flight": "#2980b9"}
GRID = "#d0d0d0"


@dataclass
class TableFrames:
    """The motion at the frames: ``t``, ``R`` (k, 3, 3) body → inertial, ``com`` and ``contact``
    (k, 3, inertial), ``phase`` (k,) and ``beta`` (k,); the result's samples for the tracks
    (``track_t``, ``track`` the contact point, ``com_track``, ``track_phase``); ``fps``,
    ``speed``, ``spin_turns`` (the largest turn about ê₃ between frames), ``title`` and
    ``notes``."""

    t: np.ndarray
    R: np.ndarray
    com: np.ndarray
    contact: np.ndarray
    phase: np.ndarray
    beta: np.ndarray
    normal_force: np.ndarray
    track_t: np.ndarray
    track: np.ndarray
    com_track: np.ndarray
    track_phase: np.ndarray
    fps: int
    speed: float
    spin_turns: float
    title: str
    notes: list

    @property
    def strobe(self) -> bool:
        return self.spin_turns > motion.STROBE_TURN


def _sphere(verts, faces, colors, centre, r, nlat=9, nlon=16):
    """A closed UV sphere; two sectors of longitude striped (the spin shows)."""
    k0 = len(verts)
    lats = np.linspace(0, np.pi, nlat + 1)[1:-1]
    lons = 2 * np.pi * (np.arange(nlon) + 0.5) / nlon
    for th in lats:
        verts.extend(list(np.asarray(centre) + r * np.array([math.sin(th) * math.cos(p),
                                                               math.sin(th) * math.sin(p), math.cos(th)]))
                     for p in lons)
    south, north = len(verts), len(verts) + 1
    verts.extend([list(np.asarray(centre) + [0, 0, -r]), list(np.asarray(centre) + [0, 0, r])])
    color = lambda i: STRIPE if i < 2 else BODY  # noqa: E731
    for j in range(nlat - 2):
        for i in range(nlon):
            a, b = k0 + j * nlon + i, k0 + j * nlon + (i + 1) % nlon
            faces.append([a + nlon, b + nlon, b, a])
            colors.append(color(i))
    last = k0 + (nlat - 2) * nlon
    for i in range(nlon):
        a, b = k0 + i, k0 + (i + 1) % nlon
        faces.append([north, a, b])
        colors.append(color(i))
        a, b = last + i, last + (i + 1) % nlon
        faces.append([south, b, a])
        colors.append(color(i))


def _cyl(verts, faces, colors, r, z0, z1, color, stripe, sides=motion.SIDES):
    motion._cylinder(verts, faces, colors, r, z0, z1, sides, color, stripe)


def body_mesh(scene) -> Mesh:
    """The body in body axes from its centre of mass, true size (see the module docstring)."""
    I1, I3, M = scene.I1, scene.I3, scene.M
    r, s, shape = scene.radius, scene.offset, scene.shape
    verts, faces, colors = [], [], []
    if shape == "disc":
        H = max(math.sqrt(max(12.0 * (I1 / M - r * r / 4), 0.0)), 0.05 * r)
        _cyl(verts, faces, colors, r, s - H / 2, s + H / 2, BODY, True)
        what = f"a thin disc of radius r = {r:g} m (thickness from I1 = M (r²/4 + H²/12))"
    elif shape == "sphere" and s > 0:
        _sphere(verts, faces, colors, (0.0, 0.0, s), r)
        stem = getattr(scene, "stem", None)  # a second sphere (radius, offset) the stem ends in
        end = s + 1.7 * r if stem is None else stem[1]
        _cyl(verts, faces, colors, 0.16 * r, s + 0.8 * r, end, SPINDLE, False, 8)
        if stem is not None:
            _sphere(verts, faces, colors, (0.0, 0.0, stem[1]), stem[0], 6, 10)
        what = (f"a ball of radius r = {r:g} m centred s = {s:g} m from the centre of mass along ê₃, "
                f"its stem beyond" + ("" if stem is None else f", ending in a sphere of radius {stem[0]:g} m"))
    else:
        rd = math.sqrt(2.0 * I3 / M)
        # no thicker than keeps its lower face above the peg's centre (or the point): a body
        # drawn through the table would mislead more than a thinner disc
        room = max(-s - (0.5 * r if shape == "sphere" else 0.0), 0.0)
        H = max(min(rd * math.sqrt(max(6.0 * (I1 / I3 - 0.5), 0.0)), 2 * room), motion.MIN_THICKNESS * rd)
        _cyl(verts, faces, colors, rd, -H / 2, H / 2, BODY, True)
        top = H / 2 + 0.6 * rd
        low = s if shape == "point" else s + 0.5 * r
        _cyl(verts, faces, colors, 0.05 * rd, min(low, -H / 2), top, SPINDLE, False, 8)
        if shape == "sphere":
            _sphere(verts, faces, colors, (0.0, 0.0, s), r, 6, 10)
        what = (f"a disc of the moments (radius sqrt(2 I3/M) = {rd:.3g} m) at the centre of mass on a "
                f"spindle down to its {'peg, a ball of radius ' + format(r, 'g') + ' m' if shape == 'sphere' else 'point'}")
    n = len(faces)
    return Mesh(np.array(verts, dtype=float), faces, colors, [0] * n, None, "table", what)


def frames(res, fps=None, speed=None, title: str = "") -> TableFrames:
    """The motion of a contact result at the frames (spacing speed/fps, up to t_end)."""
    fps, speed, ts, t = motion.frame_times(res, fps, speed)
    R = motion.rotation_at(res, t)
    com, contact = (motion._interp(ts, np.asarray(a, dtype=float), t) for a in (res.com, res.contact))
    at = np.clip(np.searchsorted(ts, t, side="right") - 1, 0, len(ts) - 1)
    phase = np.asarray(res.phase).astype(str)
    rate = float(np.max(np.abs(res.omega[:, 2])))
    fr = TableFrames(t, R, com, contact, phase[at], np.arccos(np.clip(R[:, 2, 2], -1, 1)),
                     np.interp(t, ts, res.normal_force), ts, np.asarray(res.contact, dtype=float),
                     np.asarray(res.com, dtype=float), phase, fps, speed,
                     rate * speed / fps / (2 * np.pi), title, [])
    fr.notes = [motion.time_note(fr), motion.spin_note(fr, rate, True),
                "the camera follows the centre of mass across the table"]
    return fr


class TablePainter:
    """One matplotlib figure redrawn per frame (the Agg canvas, headless)."""

    def __init__(self, fr: TableFrames, mesh: Mesh, pixels=draw.PIXELS):
        from matplotlib.collections import LineCollection, PolyCollection
        from matplotlib.lines import Line2D

        self.fr, self.mesh, self.V = fr, mesh, draw.view_matrix()
        self.normals = mesh.normals()
        self.half = WINDOW * float(np.max(np.linalg.norm(mesh.verts, axis=1)))
        aspect = pixels[1] / pixels[0]
        self.fig, self.canvas, ax = draw.canvas(pixels, (-1.0, 1.0), (0.25 - aspect, aspect))
        self.ax = ax
        self.grid = LineCollection([], colors=GRID, linewidths=0.6, zorder=1)
        ax.add_collection(self.grid)
        self.com_track, = ax.plot([], [], color="0.55", lw=0.7, zorder=2)
        self.tracks = {p: ax.plot([], [], color=c, lw=1.2, zorder=2)[0] for p, c in PHASE_COLORS.items()}
        self.body = PolyCollection([], linewidths=0.3, zorder=4)
        ax.add_collection(self.body)
        self.point, = ax.plot([], [], "o", ms=3, color="black", zorder=5)
        # the legend (it also puts the phases' colours into every frame's palette)
        handles = [Line2D([], [], color=c, lw=2, label=f"contact, {p}") for p, c in PHASE_COLORS.items()
                   if p != "flight"] + [Line2D([], [], color="0.55", lw=1, label="centre of mass")]
        ax.legend(handles=handles, loc="upper right", fontsize=5.5, frameon=False,
                  bbox_to_anchor=(1.0, 0.9))
        self.clock = ax.text(-0.97, ax.get_ylim()[1] - 0.12, "", fontsize=7, va="top")
        ax.text(-0.97, ax.get_ylim()[0] + 0.02, "\n".join(draw._wrap(n, 70) for n in fr.notes),
                fontsize=5.2, va="bottom", color="#333333", linespacing=1.25)
        ax.text(-0.97, ax.get_ylim()[1] - 0.02, draw.short(fr.title), fontsize=7, va="top", weight="bold")

    def _screen(self, X: np.ndarray, centre: np.ndarray) -> np.ndarray:
        return ((X - centre) @ self.V.T)[..., :2] / self.half

    def draw(self, k: int) -> np.ndarray:
        """Frame k as an RGB array (height, width, 3)."""
        fr = self.fr
        centre = np.array([fr.com[k, 0], fr.com[k, 1], 0.0])
        step = 10 ** math.floor(math.log10(self.half))
        lines = []
        for axis in (0, 1):
            lo = math.floor((centre[axis] - 2 * self.half) / step)
            for j in range(lo, lo + int(4 * self.half / step) + 2):
                a = np.array(centre)
                b = np.array(centre)
                a[axis] = b[axis] = j * step
                a[1 - axis] -= 2 * self.half
                b[1 - axis] += 2 * self.half
                lines.append(self._screen(np.array([a, b]), centre))
        self.grid.set_segments(lines)
        upto = fr.track_t <= fr.t[k]
        c = self._screen(fr.com_track[upto] * [1, 1, 0], centre)
        self.com_track.set_data(c[:, 0], c[:, 1])
        for p, line in self.tracks.items():
            pts = self._screen(np.vstack([fr.track[upto], fr.contact[k][None]]), centre)
            mask = np.append(fr.track_phase[upto] == p, fr.phase[k] == p) & (p != "flight")
            line.set_data(np.where(mask, pts[:, 0], np.nan), np.where(mask, pts[:, 1], np.nan))
        polys, colors = draw.faces_at(self.mesh, self.normals, fr.R[k], self.V)
        shift = self._screen(fr.com[k][None], centre)[0]
        self.body.set_verts([poly / self.half + shift for poly in polys])
        self.body.set_facecolor(colors)
        self.body.set_edgecolor(colors)
        p = self._screen(fr.contact[k][None], centre)[0]
        self.point.set_data([p[0]], [p[1]])
        self.clock.set_text(f"t = {fr.t[k]:.3f} s   β = {math.degrees(fr.beta[k]):5.1f}°   "
                            f"{fr.phase[k]}\nN = {fr.normal_force[k]:.3g} N")
        self.canvas.draw()
        return np.asarray(self.canvas.buffer_rgba())[:, :, :3].copy()


def _keep() -> list:
    """The tracks' colours as RGB 0-255 (kept in the GIF's palette)."""
    return [tuple(int(c[i:i + 2], 16) for i in (1, 3, 5)) for c in PHASE_COLORS.values()]


def page_html(fr: TableFrames, mesh: Mesh) -> str:
    """A self-contained page: the animation (an embedded GIF), its title and caption."""
    buf = io.BytesIO()
    draw.encode_gif(buf, TablePainter(fr, mesh).draw, len(fr.t), fr.fps, _keep())
    data = base64.b64encode(buf.getvalue()).decode("ascii")
    notes = "".join(f"<p>{html.escape(n)}</p>" for n in fr.notes + [f"The body: {mesh.shape}."])
    title = html.escape(fr.title or "derive animate")
    return (f'<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n<title>{title}</title>\n'
            f"<!-- Made by derive animate: self-contained (no network); the animation is the GIF below. -->\n"
            f"</head>\n<body style=\"font: 14px/1.4 system-ui, sans-serif; margin: 12px\">\n"
            f"<h3>{title}</h3>\n<img alt=\"{title}\" src=\"data:image/gif;base64,{data}\">\n"
            f"<div style=\"font-size: 12px; color: #444\">{notes}</div>\n</body>\n</html>\n")


def writer(res, fmt: str, fps=None, speed=None, title: str = ""):
    """(frames, a function writing the animation into a binary file) for ``fmt``."""
    fr = frames(res, fps, speed, title)
    mesh = body_mesh(res.scene)
    if fmt == "html":
        text = page_html(fr, mesh).encode("utf-8")
        return fr, lambda fh: fh.write(text)
    if fmt == "gif":
        return fr, lambda fh: draw.encode_gif(fh, TablePainter(fr, mesh).draw, len(fr.t), fr.fps, _keep())
    painter = TablePainter(fr, mesh)
    return fr, lambda fh: draw.encode_mp4(fh, (painter.draw(k) for k in range(len(fr.t))), fr.fps)
