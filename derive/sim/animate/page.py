"""The HTML player, the object Jupyter shows inline, and a Result's summary table.

The page is one file with no network access: the motion is embedded as data (the rotation
matrix, the angles and L at each frame, the path of ê₃ at the result's samples, the body's
faces) and drawn on a canvas by a short inline script (``player.html`` beside this module),
the same picture :mod:`derive.sim.animate.draw` paints for a GIF. Data rather than pictures:
a few tens of kB instead of megabytes of images, sharp at any size and on high-density screens,
and the view can be turned by dragging. Controls: play/pause, a slider to scrub, the playback
speed (¼× to 4× of the animation's time scale); ``page.html#frame=N`` opens paused at frame N.
"""
from __future__ import annotations

import html
import json
from importlib import resources

import numpy as np

from derive.sim.animate.draw import AZIMUTH, ELEVATION
from derive.sim.animate.motion import Frames, Mesh
from derive.symbolic import effects as fx

#: The most samples of ê₃'s path embedded in a page (a longer result is thinned evenly).
TRACE_POINTS = 2000


def _numbers(a, digits: int = 5) -> list:
    return np.round(np.asarray(a, dtype=float), digits).ravel().tolist()


def page_html(frames: Frames, mesh: Mesh) -> str:
    """The self-contained HTML page of an animation (see the module docstring)."""
    step = max(1, int(np.ceil(len(frames.trace_t) / TRACE_POINTS)))
    data = {
        "title": frames.title, "notes": frames.notes + [f"The body: {mesh.shape}."], "fps": frames.fps, "speed": frames.speed,
        "strobe": frames.strobe,
        "view": {"az": AZIMUTH, "el": ELEVATION},
        "t": _numbers(frames.t, 6), "R": _numbers(frames.R), "ang": _numbers(np.degrees(frames.angles), 2),
        "L": _numbers(frames.L, 4),
        "trace_t": _numbers(frames.trace_t[::step], 6), "trace": _numbers(frames.trace[::step], 4),
        "mesh": {"v": _numbers(mesh.verts, 4), "f": [list(map(int, f)) for f in mesh.faces],
                 "c": [list(c) for c in mesh.colors], "n": _numbers(mesh.normals(), 4),
                 "layer": [int(x) for x in mesh.layers]},
        "com": None if mesh.com is None else _numbers(mesh.com, 4),
    }
    # "</" inside the script element would end it: JSON allows "<\/" for it
    text = json.dumps(data, separators=(",", ":"), ensure_ascii=False).replace("</", "<\\/")
    template = resources.files(__package__).joinpath("player.html").read_text(encoding="utf-8")
    return template.replace("__TITLE__", html.escape(frames.title or "derive animate")).replace("__DATA__", text)


class Animation:
    """An animation Jupyter shows inline (``_repr_html_``: the player in an iframe of its own, so
    that several in one notebook do not share names); ``html`` is the page, ``save(path)`` writes
    it, ``frames`` holds the numbers drawn."""

    def __init__(self, page: str, frames: Frames):
        self.html = page
        self.frames = frames

    def _repr_html_(self) -> str:
        return (f'<iframe srcdoc="{html.escape(self.html, quote=True)}" width="560" height="760" '
                f'style="border:none" title="{html.escape(self.frames.title or "animation")}"></iframe>')

    def save(self, path) -> None:
        """Write the page to ``path`` (any name: this is the HTML player)."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.html)

    def __repr__(self) -> str:
        return f"<Animation: {len(self.frames.t)} frames at {self.frames.fps} fps; {self.frames.notes[0]}>"


def energy_row(res) -> tuple[str, str]:
    """(label, value) of the energy line: the drift max |E − E(0)| / |E(0)| when every effect is
    conservative, else the change E(end) − E(0) (work done by damping or a drive, not error)."""
    e = np.asarray(res.energy, dtype=float)
    e0 = float(e[0])
    working = [eff for eff in fx.lookup(res.effects) if not eff.conservative]
    if not working:
        dev = float(np.max(np.abs(e - e0)))
        return ("energy drift", f"{dev / abs(e0):.2e} (relative)" if e0 else f"{dev:.3g} J")
    # (a term written in the scene has a registry name made from its text: say what it is)
    named = sorted({f"the scene's {eff.table}" if eff.table in fx.USER_TABLES else eff.name for eff in working})
    return ("energy change", f"{float(e[-1]) - e0:+.4g} J (work done by {', '.join(named)})")


def summary_html(res) -> str:
    """A short table of a Result for Jupyter: scene, model and method, time span, samples,
    right-hand-side evaluations, energy drift (or change), the integrals' drift."""
    scene = res.scene
    rows = []
    if scene is not None:
        rows.append(("scene", scene.title or scene.source))
    rows += [("method", f"{res.method} / {res.formulation}"), ("model", res.model or "-"),
             ("t", f"{float(res.t[0]):g} … {float(res.t[-1]):g} s"), ("samples", str(len(res.t))),
             ("rhs evaluations", str(res.nfev)), energy_row(res)]
    for name, values in res.integrals.items():
        v = np.asarray(values, dtype=float)
        scale = abs(float(v[0])) or 1.0
        rows.append((f"drift of {name}", f"{float(np.max(np.abs(v - v[0]))) / scale:.2e}"))
    body = "".join(f"<tr><th style='text-align:left'>{html.escape(k)}</th><td style='text-align:left'>"
                   f"{html.escape(v)}</td></tr>" for k, v in rows)
    return f"<table><caption style='text-align:left'>derive Result</caption>{body}</table>"
