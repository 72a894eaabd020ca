"""Views of a motion: a Result and its scene's body in, an animation (GIF, MP4, HTML) out.

Takes: a :class:`~derive.sim.simulation.Result` (the arrays ``t``, ``alpha``/``beta``/``gamma``,
``omega``, ``axis``, ``L``) and its scene's body, or a top on a table's result (its body drawn
on the plane with the contact's track, :mod:`~derive.sim.animate.table`). Gives: the body's shape and the motion at the
frames (:mod:`~derive.sim.animate.motion`), the frames painted and written as GIF or MP4
(:mod:`~derive.sim.animate.draw`), the self-contained HTML player, the object Jupyter shows
inline and a Result's summary table (:mod:`~derive.sim.animate.page`). :func:`write` writes an
animation all or nothing, in the format the file's suffix names (:data:`FORMATS`).

matplotlib and Pillow load only when a picture is drawn; importing this package costs NumPy.

May import: :mod:`derive.sim.outputs`, :mod:`derive.symbolic`, :mod:`derive.reference`,
:mod:`derive.errors`.
"""
from __future__ import annotations

import os

from derive.errors import SceneError
from derive.sim.animate import draw, motion, page, table
from derive.sim.outputs import check_paths, output_format, write_all

#: Suffix -> format of ``derive animate -o``.
FORMATS = {".gif": "gif", ".mp4": "mp4", ".html": "html"}


def check_output(path, inputs=()) -> str:
    """The format of ``path`` (SceneError naming ``-o`` for another suffix, a path that cannot
    be written or would overwrite an input, and for .mp4 with no ffmpeg on PATH)."""
    fmt = output_format(path, "-o", FORMATS)
    if fmt == "mp4":
        draw.ffmpeg_path()
    check_paths([path], inputs=inputs)
    return fmt


def on_table(res) -> bool:
    """Whether ``res`` is a top on a table's run (it has the contact point's track)."""
    return hasattr(res, "contact") and hasattr(res, "com")


def _title(res) -> str:
    scene = res.scene
    return (scene.title or os.path.basename(str(scene.source))) if scene is not None else ""


def prepare(res, fps=None, speed=None):
    """(frames, mesh) of a Result: the motion at the frames and the body drawn."""
    scene = res.scene
    if scene is None:
        raise SceneError("animate: the result carries no scene, so no body to draw")
    fr = motion.frames(res, fps, speed, title=scene.title or os.path.basename(str(scene.source)))
    return fr, motion.body_mesh(scene)


def write(res, path, fps=None, speed=None):
    """Write the animation of ``res`` to ``path``.

    Parameters
    ----------
    res : derive.sim.simulation.Result
        The motion (with its scene).
    path : str or os.PathLike
        ``.gif`` (Pillow), ``.mp4`` (ffmpeg on PATH) or ``.html`` (the self-contained player):
        the suffix decides. Written to a temporary file beside it and renamed when complete.
    fps : int, optional
        Frames per second (default 20).
    speed : float, optional
        Simulated seconds per wall second (default: from the motion, see
        :func:`derive.sim.animate.motion.default_speed`).

    Returns
    -------
    derive.sim.animate.motion.Frames
        What was drawn (times, rotations, the caption's notes).

    Raises
    ------
    SceneError
        An unknown suffix, a path that cannot be written or is the scene file, bad ``fps`` or
        ``speed``, no ffmpeg for .mp4.
    """
    source = res.scene.source if res.scene is not None else None
    inputs = [source] if source and source != "<dict>" else []
    fmt = check_output(path, inputs)
    motion.check_settings(fps, speed)
    if on_table(res):  # a top on a table: the body at its place on the plane, the track on it
        fr, writer = table.writer(res, fmt, fps, speed, _title(res))
    else:
        fr, mesh = prepare(res, fps, speed)
        text = page.page_html(fr, mesh).encode("utf-8") if fmt == "html" else None
        writer = {"html": lambda fh: fh.write(text), "gif": lambda fh: draw.write_gif(fh, fr, mesh),
                  "mp4": lambda fh: draw.write_mp4(fh, fr, mesh)}[fmt]
    write_all({path: writer}, inputs=inputs)
    return fr


def animate(res, path=None, fps=None, speed=None):
    """``Result.animate``: with a path, write the file (:func:`write`) and return the path;
    without, an :class:`~derive.sim.animate.page.Animation` Jupyter shows inline."""
    if path is not None:
        write(res, path, fps, speed)
        return path
    if on_table(res):
        fr = table.frames(res, fps, speed, _title(res))
        return page.Animation(table.page_html(fr, table.body_mesh(res.scene)), fr)
    fr, mesh = prepare(res, fps, speed)
    return page.Animation(page.page_html(fr, mesh), fr)


summary_html = page.summary_html
