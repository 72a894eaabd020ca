"""A sweep read and validated: the base scene, the varied keys and their columns (a grid or
random points), the measures and their options.

Takes: a sweep file, an example's name or a dict. Gives: a :class:`Spec` with every point's
numbers (:func:`derive.sweeps.points.build`).
"""
from __future__ import annotations

import copy
import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from derive.errors import SceneError
from derive.sim import examples
from derive.sim.scene import load_scene, read_toml
from derive.sim.validator import _real
from derive.sweeps import measures as ms
from derive.sweeps.keys import term_key, variable_keys as _variable_keys
from derive.sweeps.points import _fail, _scene_error, _set, build


_SPEC_KEYS = ("scene", "vary", "random", "measure", "measures", "title")


@dataclass
class Spec:
    """A validated sweep: the base scene, the varied columns, the measures and the model."""
    source: str
    scene: object  # the representative Scene (a valid point; asymmetric if any point is)
    raw: dict  # the base scene as a dict
    keys: tuple
    shape: tuple | None  # grid shape (None: random points)
    columns: dict  # key -> (N,) float array
    measures: tuple
    options: dict
    inputs: np.ndarray = field(repr=False, default=None)
    ps: np.ndarray = field(repr=False, default=None)
    invalid: dict = field(default_factory=dict)  # point index -> why it is not run
    general: np.ndarray = field(repr=False, default=None)  # (N, 8) I1..I3, M, g, cx, cy, cz
    damping: np.ndarray = field(repr=False, default=None)  # (N,) the damping coefficient c
    key: tuple = ()  # the first candidate's model (formulation, symmetric, effects)
    method: str = ""
    pole_check: int = 0  # the first candidate's pole check (0: none, it takes every point)
    fallback: tuple = ()  # the next candidates, in order: (model key, pole check, ps (N, NP))
    terms: tuple = ()  # the user's terms (derive.symbolic.terms.Term), registered in each worker
    files: tuple = ()  # the files read: the sweep file and the scene file it names

    @property
    def n(self) -> int:
        return len(next(iter(self.columns.values())))


def _flatten(table: Mapping, prefix: str, leaf, source: str = "<sweep>", where: str = "") -> dict:
    """Dotted keys of nested tables down to the leaves (``leaf(value)`` says when to stop; an
    empty table is a leaf, so that its key is reported, not dropped).

    TOML keeps ``"initial.beta"`` (one quoted key) and ``initial.beta`` (a table ``initial``
    with a key ``beta``) apart; dotted here they are the same key, and the one given later
    would silently win: a key reached twice is a SceneError ``<source>: <where>.<key>``.
    """
    out = {}

    def put(name, value):
        if name in out:
            _fail(source, f"{where}.{name}" if where else name,
                  "given twice (a quoted \"a.b\" and a dotted a.b name the same key)")
        out[name] = value

    for k, v in table.items():
        name = f"{prefix}{k}"
        if isinstance(v, Mapping) and v and not leaf(v):
            for sub, value in _flatten(v, name + ".", leaf, source, where).items():
                put(sub, value)
        else:
            put(name, v)
    return out


def _scene_path(source: str, folder: Path, sc: str) -> str:
    """The scene file a sweep names (``sc``, relative to the sweep file's ``folder``)."""
    path = folder / sc
    if "\0" in sc or not path.exists():
        _fail(source, "scene", f"no scene file {sc!r} (a path relative to the sweep file)")
    return str(path)


def _read(spec) -> tuple[dict, str, Path]:
    """(the sweep's data, its source, its folder) of a path, an example's name or a dict;
    SceneError for anything else or a file the scene files' reader refuses."""
    if isinstance(spec, Mapping):
        return spec, "<sweep>", Path.cwd()
    if not isinstance(spec, (str, os.PathLike)):
        raise SceneError(f"<sweep>: sweep: must be a path to a TOML file or a dict, not {type(spec).__name__}")
    source = examples.resolve(os.fspath(spec), "sweep")  # a bare name: a shipped example
    return read_toml(source, "sweep"), source, Path(source).resolve().parent


def input_files(spec) -> tuple:
    """The files a sweep reads (the sweep file, and the scene file it names), to compare the
    outputs with before any work (``outputs.check_paths``); () for a dict. Reads the sweep file
    with the checks of :func:`load` (SceneError as it would raise)."""
    if isinstance(spec, Mapping) or not isinstance(spec, (str, os.PathLike)):
        return ()
    data, source, folder = _read(spec)
    sc = data.get("scene")
    return (source,) if not isinstance(sc, str) else (source, _scene_path(source, folder, sc))


def contact_sweep(spec) -> tuple[dict, str, Path] | None:
    """(the sweep's data, its source, its folder) when the sweep ``spec`` (path, example name or
    dict) names a scene with a ``[contact]`` table, else None (an unreadable sweep too: the
    general reader reports it)."""
    try:
        data, source, folder = _read(spec)
    except SceneError:
        return None
    sc = data.get("scene")
    if isinstance(sc, str):
        path = folder / sc
        if "\0" in sc or not path.is_file():
            return None
        try:
            return (data, source, folder) if "contact" in read_toml(str(path)) else None
        except SceneError:
            return None
    return (data, source, folder) if isinstance(sc, Mapping) and "contact" in sc else None


def load(spec) -> Spec:
    """Read and validate a sweep (path or dict); raises SceneError ``<file>: <key>: <what>``.

    A sweep file is read by the scene files' reader (``scene.read_toml``: regular files of at
    most ``scene.MAX_SCENE_BYTES``, nothing special such as /dev/zero or a FIFO); a key named
    twice in any spelling (quoted or dotted) is refused, as is a table that names no key.
    """
    data, source, folder = _read(spec)

    def read(raw, where):  # a scene file's errors name it; an inline scene's, scene.<key>
        try:
            return load_scene(raw)
        except SceneError as exc:
            raise _scene_error(where, exc, "" if where != source else "scene.") from None

    raw, base, files = base_scene(data, source, folder, read)
    variable = _variable_keys()
    keys, shape, columns, distinct = grid_or_random(
        source, data, lambda where, key: _check_key(source, where, key, variable, raw))
    _check_values(source, "vary" if shape is not None else "random", raw, distinct)
    names, options = _measures(source, data)
    out = Spec(source, base, raw, keys, shape, columns, names, options, files=files)
    build(out)
    return out


def base_scene(data, source: str, folder: Path, read):
    """(the base scene as a dict, ``read(raw, where)`` of it, the files read) of a sweep's
    ``data``: its keys checked, its ``scene`` a path relative to ``folder`` (read once, with the
    scene files' checks; ``where`` the path) or an inline table (``where`` the sweep's
    ``source``); the sweep's title given to a scene without one."""
    for k in data:
        if k not in _SPEC_KEYS:
            _fail(source, k, f"unknown key (the keys of a sweep: {', '.join(_SPEC_KEYS)})")
    if "scene" not in data:
        _fail(source, "scene", "missing (a path relative to the sweep file, or an inline [scene] table)")
    sc = data["scene"]
    files = (source,) if source != "<sweep>" else ()
    if isinstance(sc, str):
        where = _scene_path(source, folder, sc)
        files, raw = files + (where,), read_toml(where)
    elif isinstance(sc, Mapping):
        where, raw = source, copy.deepcopy(dict(sc))
    else:
        _fail(source, "scene", f"must be a path or a table, got {sc!r}")
    base = read(raw, where)
    if "title" in data and "title" not in raw and isinstance(data["title"], str):
        raw["title"] = data["title"]
    return raw, base, files


def grid_or_random(source, data, check_key, n_max: int = 10**9):
    """The points of a sweep file's ``[vary]`` (a grid, C order over its keys as written) or
    ``[random]`` (n uniform draws from a seeded generator): (keys, grid shape or None,
    {key: (N,) column}, {key: the distinct values, or a random key's bounds}).
    ``check_key(where, key)`` refuses a key the scene cannot vary."""
    if ("vary" in data) == ("random" in data):
        _fail(source, "vary", "give [vary] (a grid) or [random] (random points), one of them")
    if "vary" in data:
        table = data["vary"]
        if not isinstance(table, Mapping) or not table:
            _fail(source, "vary", "must be a table of dotted scene keys")
        leaves = _flatten(table, "", lambda v: bool({"from", "to", "num", "values"} & set(v)),
                          source, "vary")
        columns = {}
        for key, rule in leaves.items():
            check_key(f"vary.{key}", key)
            columns[key] = _grid_values(source, f"vary.{key}", rule)
        keys = tuple(columns)
        shape = tuple(len(v) for v in columns.values())
        grids = np.meshgrid(*columns.values(), indexing="ij")
        cols = {k: g.ravel(order="C").copy() for k, g in zip(keys, grids)}
        return keys, shape, cols, columns
    table = data["random"]
    if not isinstance(table, Mapping):
        _fail(source, "random", "must be a table")
    n, seed = table.get("n"), table.get("seed")
    if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= n_max:
        _fail(source, "random.n", f"must be an integer from 1 to {n_max:.0e}, got {n!r}".replace("e+0", "e"))
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        _fail(source, "random.seed", f"must be a non-negative integer, got {seed!r}")
    rest = {k: v for k, v in table.items() if k not in ("n", "seed")}
    leaves = _flatten(rest, "", lambda v: bool({"low", "high"} & set(v)), source, "random")
    if not leaves:
        _fail(source, "random", "names no scene key to vary ({ low = a, high = b } per key)")
    rng = np.random.default_rng(seed)
    cols, distinct = {}, {}
    for key, rule in leaves.items():
        where = f"random.{key}"
        check_key(where, key)
        if not isinstance(rule, Mapping) or set(rule) != {"low", "high"}:
            _fail(source, where, "must be { low = a, high = b }")
        lo, hi = _real(rule["low"]), _real(rule["high"])
        if lo is None or hi is None or not lo <= hi:
            _fail(source, where, f"low and high must be finite numbers with low <= high, got {dict(rule)}")
        cols[key] = rng.uniform(lo, hi, n)
        distinct[key] = np.array([lo, hi])
    return tuple(cols), None, cols, distinct


def _check_key(source, where, key, variable, raw,
               what="a scene key that takes a number (e.g. initial.beta, body.I3, gravity.l, initial.omega.0)"):
    """Refuse a key ``where`` that no point may vary: not in ``variable`` (the keys registry:
    :func:`derive.sweeps.keys.variable_keys` or ``contact_keys``), a table the scene ``raw``
    lacks, a user term's param it lacks, the rates of a scene given ``omega`` or the reverse."""
    if key.startswith("simulate.") or key == "title":
        _fail(source, where, "cannot be varied (the integration settings are shared by every point)")
    term = term_key(key)
    if term is not None:
        kind, name, param = term
        entries = raw.get(kind)
        entry = next((e for e in entries if isinstance(e, Mapping) and e.get("name") == name),
                     None) if isinstance(entries, list) else None
        if entry is None:
            _fail(source, where, f"the scene has no [[{kind}]] named {name!r}")
        if not isinstance(entry.get("params"), Mapping) or param not in entry["params"]:
            _fail(source, where, f"[[{kind}]] {name!r} has no param {param!r} (vary a param "
                                 f"the scene gives a value)")
        return
    if key not in variable:
        _fail(source, where, f"not {what}")
    table, name, index, _ = variable[key]
    if table not in ("body", "initial") and table not in raw:
        _fail(source, where, f"the scene has no [{table}] table")
    if table == "initial":
        init = raw.get("initial", {})
        if index is not None and "omega" not in init:
            _fail(source, where, "the scene gives Euler-angle rates, not omega")
        if name.endswith("_dot") and "omega" in init:
            _fail(source, where, "the scene gives omega, not Euler-angle rates")


def _grid_values(source, where, rule) -> np.ndarray:
    if not isinstance(rule, Mapping):
        _fail(source, where, "must be { from = a, to = b, num = n } or { values = [...] }")
    if set(rule) == {"values"}:
        vals = rule["values"]
        if not isinstance(vals, list) or not vals or any(_real(v) is None for v in vals):
            _fail(source, where, f"values must be a non-empty list of finite numbers, got {vals!r}")
        return np.array([float(v) for v in vals])
    if set(rule) == {"from", "to", "num"}:
        a, b, num = _real(rule["from"]), _real(rule["to"]), rule["num"]
        if a is None or b is None:
            _fail(source, where, f"from and to must be finite numbers, got {dict(rule)}")
        if isinstance(num, bool) or not isinstance(num, int) or not 1 <= num <= 10**8:
            _fail(source, where, f"num must be an integer from 1 to 1e8, got {num!r}")
        return np.linspace(a, b, num)
    _fail(source, where, "must be { from = a, to = b, num = n } or { values = [...] }, "
                         f"got keys {sorted(rule)}")


def _check_values(source, where, raw, distinct):
    """Each varied key's distinct values (grid) or bounds (random) against the scene contract,
    substituted one at a time into the base scene. The body moments' positivity is checked
    here and their triangle inequality per point (``_build``)."""
    for key, values in distinct.items():
        if key.startswith("body."):
            bad = values[~(values > 0)]
            if bad.size:
                _fail(source, f"{where}.{key}", f"must be positive (moment of inertia), got {bad[0]!r}")
            continue
        for v in np.unique(values):
            data = dict(raw)  # _set copies what it changes
            _set(data, key, float(v))
            try:
                load_scene(data)
            except SceneError as exc:
                inner = str(exc).split(": ", 2)[-1]
                _fail(source, f"{where}.{key}", f"{float(v)!r} makes the scene invalid ({inner})")


def _measures(source, data, contact: bool = False):
    """The measures' names and options; ``contact``: a sweep over a ``[contact]`` scene, which
    takes the measures with a ``contact`` function only (and the others never take those)."""
    default = ms.CONTACT_DEFAULT if contact else ms.DEFAULT
    options = {}
    if "measure" in data and "measures" in data:
        _fail(source, "measure", "give [measure] or measures, not both")
    table = data.get("measure", {})
    if not isinstance(table, Mapping):
        _fail(source, "measure", "must be a table with names = [...]")
    names = data["measures"] if "measures" in data else table.get("names", list(default))
    where = "measures" if "measures" in data else "measure.names"
    extra = {k: v for k, v in table.items() if k != "names"}
    if isinstance(names, str):
        names = [names]
    if not isinstance(names, (list, tuple)) or not names or not all(isinstance(n, str) for n in names):
        _fail(source, where, f"must be a non-empty list of measure names, got {names!r}")
    for n in names:
        if n not in ms.REGISTRY:
            _fail(source, where, f"unknown measure {n!r} (one of {', '.join(ms.REGISTRY)})")
        if contact and ms.REGISTRY[n].contact is None:
            _fail(source, where, f"{n!r} is not a measure of a top on a table (those: "
                                 f"{', '.join(k for k, m in ms.REGISTRY.items() if m.contact)})")
        if not contact and ms.REGISTRY[n].reads == "contact":
            _fail(source, where, f"{n!r} measures a top on a table (a scene with [contact])")
    for n, opts in extra.items():
        if n not in ms.REGISTRY or not ms.REGISTRY[n].options:
            _fail(source, f"measure.{n}", "unknown key (a measure with options, e.g. time_to_tilt)")
        if not isinstance(opts, Mapping):
            _fail(source, f"measure.{n}", "must be a table of options")
        for k, v in opts.items():
            if k not in ms.REGISTRY[n].options:
                _fail(source, f"measure.{n}.{k}", f"unknown option (one of {', '.join(ms.REGISTRY[n].options)})")
            allowed = ms.REGISTRY[n].choices.get(k)
            if allowed is not None:
                if v not in allowed:
                    _fail(source, f"measure.{n}.{k}", f"must be one of {', '.join(allowed)}, got {v!r}")
            elif _real(v) is None:
                _fail(source, f"measure.{n}.{k}", f"must be a finite number, got {v!r}")
        options[n] = dict(opts)
    return tuple(dict.fromkeys(names)), options
