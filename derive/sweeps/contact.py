"""Sweeps over a top on a table: one ``[contact]`` scene, many numbers, each run measured.

The sweep file is the one every sweep has (``scene``, ``[vary]`` or ``[random]``,
``[measure]``); its scene has a ``[contact]`` table. The keys a point may vary are
:func:`derive.sweeps.keys.contact_keys` (``initial.omega.2``, ``contact.offset``,
``contact.mu``, ``contact.radius``, …); the measures are the registry's entries with a
``contact`` function (:data:`derive.sweeps.measures.CONTACT_MEASURES` and ``nfev``).

Each point is the base scene with its numbers, validated by the scene's own rules and run by
:func:`derive.contact.simulate.simulate` (the compiled phase loop, the shape and law's kernel
loaded once per process). Every distinct value of a grid (both bounds of a random range) is
checked first, substituted alone into the base scene: a value the scene refuses is a bad sweep
(SceneError naming ``vary.<key>``). A point whose combination is refused (the moments' triangle
inequality) or whose run fails is not a bad sweep: its ``status`` says why and its measures are
NaN. The points run in this process, or with ``workers`` in that many worker processes (the
same numbers: each point's run depends on its own numbers only); a Dask scheduler is not used
for these sweeps.
"""
from __future__ import annotations

import functools
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from derive.contact.scene import read as read_scene
from derive.contact.simulate import simulate
from derive.errors import IntegrationError, SceneError
from derive.sweeps import measures as ms
from derive.sweeps.keys import contact_keys
from derive.sweeps.points import _fail, set_entry
from derive.sweeps.result import SweepResult
from derive.sweeps.spec import _check_key, _measures, base_scene, grid_or_random


def _set(data: dict, key: str, value: float) -> dict:
    """A copy of the scene ``data`` with the dotted key set (``initial.omega.2``: a component)."""
    out = dict(data)
    set_entry(out, contact_keys()[key], value)
    return out


_WHAT = ("a key of a top on a table that takes a number (e.g. initial.omega.2, initial.beta, contact.offset, "
         "contact.mu)")


def _points(source: str, data: dict, raw: dict):
    """(keys, grid shape or None, {key: (N,) column}), every distinct value checked."""
    keys, shape, cols, distinct = grid_or_random(
        source, data, lambda where, key: _check_key(source, where, key, contact_keys(), raw, _WHAT), n_max=10**6)
    where = "vary" if shape is not None else "random"
    for key, values in distinct.items():
        for v in np.unique(values):
            try:
                read_scene(_set(raw, key, float(v)))
            except SceneError as exc:
                inner = str(exc).split(": ", 2)[-1]
                _fail(source, f"{where}.{key}", f"{float(v)!r} makes the scene invalid ({inner})")
    return keys, shape, cols


def _run_point(raw: dict, keys: tuple, names: tuple, row: list) -> tuple[str, list]:
    """(status, [value per measure column]) of one point: the values ``row`` of the ``keys``."""
    data = raw
    for key, v in zip(keys, row):
        data = _set(data, key, v)
    try:
        res = simulate(read_scene(data))
    except SceneError as exc:
        return str(exc).split(": ", 1)[-1], [np.nan] * len(names)
    except IntegrationError as exc:
        return str(exc), [np.nan] * len(names)
    return "ok", [float(ms.REGISTRY[n].contact(res)) for n in names]


def sweep(found: tuple[dict, str, Path], workers: int | None = None,
          scheduler: str | None = None, add_measure: str | None = None) -> SweepResult:
    """Run a sweep over a ``[contact]`` scene (``found``: :func:`derive.sweeps.spec.contact_sweep`'s answer).

    Parameters
    ----------
    found : (dict, str, Path)
        The sweep's data, its source and its folder
        (:func:`derive.sweeps.spec.contact_sweep`).
    workers : int, optional
        Run the points in that many worker processes (default: in this process).
    scheduler : str, optional
        Refused: a Dask cluster does not run these sweeps.
    add_measure : str, optional
        A measure added to the file's list (the column to plot).

    Returns
    -------
    SweepResult
        A row per point (grid points in C order, the first key slowest), a column per varied
        key and per measure, ``status`` "ok" or why the point has no values.

    Raises
    ------
    SceneError
        A bad sweep (``<file>: <key>: <what>``).
    """
    data, source, folder = found
    if scheduler is not None:
        raise SceneError(f"{source}: --scheduler: a sweep over a top on a table runs on this "
                         f"machine (--workers N for processes)")

    def read(raw, where):  # a scene file's errors name it; an inline scene's, scene.<key>
        try:
            return read_scene(raw, where)
        except SceneError as exc:
            raise SceneError(str(exc) if where != source else
                             f"{source}: scene.{str(exc).split(': ', 1)[-1]}") from None

    raw, base, files = base_scene(data, source, folder, read)
    keys, shape, cols = _points(source, data, raw)
    names, _ = _measures(source, data, contact=True)
    if add_measure is not None:
        if add_measure not in ms.REGISTRY or ms.REGISTRY[add_measure].contact is None:
            raise SceneError(f"{source}: --measure: {add_measure!r} is not a measure of a top on a table")
        names = tuple(dict.fromkeys((*names, add_measure)))
    n = len(cols[keys[0]])
    rows = np.column_stack([cols[k] for k in keys]).tolist()
    run = functools.partial(_run_point, raw, keys, names)
    if workers is None or workers <= 1 or n == 1:
        out = [run(row) for row in rows]
    else:  # a chunk of about n / workers points per task, as each worker takes one
        with ProcessPoolExecutor(max_workers=workers) as pool:
            out = list(pool.map(run, rows, chunksize=-(-n // workers)))
    values = np.array([v for _, v in out], dtype=float).reshape(n, len(names))
    measures = {}
    for j, name in enumerate(names):
        col = values[:, j]
        integer = name in ("switches", "nfev") and np.isfinite(col).all()
        measures[name] = col.astype(np.int64) if integer else col
    status = np.array([s for s, _ in out], dtype=str)
    return SweepResult(params=cols, measures=measures, status=status, keys=keys, shape=shape,
                       measure_names=names, title=raw.get("title", "") or "", source=source,
                       model=f"contact_{base.shape}_{base.law}", scene=base, files=files,
                       formulation=np.where(status == "ok", "contact", "").astype(str))
