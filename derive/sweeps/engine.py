"""Parameter sweeps: one scene, many numbers, each trajectory measured while it is integrated.

A sweep (a TOML file or a dict of the same shape)::

    scene = "../sleeping_top.toml"     # relative to the sweep file; or an inline [scene] table
    [vary]                             # dotted scene keys; the Cartesian product, first key slowest
    initial.beta = { from = 0.05, to = 1.0, num = 40 }
    initial.gamma_dot = { values = [100.0, 150.0, 200.0] }
    # or, instead of [vary]:
    # [random]
    # n = 1000
    # seed = 1
    # initial.beta = { low = 0.05, high = 1.0 }
    [measure]
    names = ["beta_max", "time_to_tilt"]   # the registry: derive.sweeps.measures
    time_to_tilt = { angle = 1.0 }         # a measure's options

The points are numbers only: the base scene is validated once, each varied key's values are
checked against the scene contract (every distinct value of a grid, both bounds of a random
range), and the init map's inputs and the model's parameters are built as arrays from the base
scene and the varied columns, without a scene per point. A vector key is varied by component:
``initial.omega.0`` is ω̃₁.

Decisions (documented here once):

* Body moments varied jointly may violate the triangle inequality at some points only: those
  points are not run and their ``status`` says why; everything else wrong is a bad sweep file
  (SceneError, exit 2, ``<file>: <key>: <what>``).
* If any point has I2 != I1 the whole sweep runs the asymmetric model (it represents the
  symmetric points too; a symmetric one would not).
* Formulation "auto" runs, per point, the formulations auto would try for a single run,
  cheapest first (:func:`sweep_plan`): a start that a candidate's compiled pole check refuses
  (status RANGE, decided from the start by the Routh polynomial before any step) runs again
  with the next candidate, in the same chunk, down to the cheapest one without a singular set,
  which takes every point. The heavy symmetric top runs reduced-u clear of the poles
  (|sin beta| >= 0.1 all along) and euler-poisson elsewhere. Every point's outcome depends on
  its own numbers only, never on its chunk. ``SweepResult.formulation`` says which
  formulation ran each point. A singular formulation named in the scene is refused. The
  method must have a dense output that follows the tolerance (its family's measure window,
  :func:`derive.methods.registry.measure_window`): dop853 (its dense polynomial) or taylor (the
  step's series); ``auto`` takes the cost model's choice for the first candidate's model at
  the sweep's tolerance, t_end and rates (the representative point's), and dop853 if a
  candidate has no Taylor kernel.
* The scene's ``samples`` is not used: a sweep keeps the outputs at t_end only (final_state).
* The random points are drawn in the calling process (``numpy.random.default_rng(seed)``, one
  ``uniform`` per key, in the file's order), so a seed gives the same points whatever runs them.

Engines: local (default; chunks of at most ``CHUNK`` points, one process per core, each process
loading the compiled library once), a dask ``LocalCluster`` (``workers``) or an existing Dask
cluster (``scheduler``). Every trajectory is computed by the same compiled loop on its own, so
the results are bit-for-bit the same whatever the engine, chunking and worker count. A point
whose integration fails is recorded in ``status``; Ctrl-C cancels the outstanding chunks.
"""
from __future__ import annotations

import copy
import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from derive.sweeps import measures as ms
from derive.errors import EngineError, SceneError
from derive.sim import examples
from derive.sweeps.keys import term_key, unit_of, variable_keys as _variable_keys  # noqa: F401 - unit_of: its old home

#: Largest number of trajectories in one task (one C call).
CHUNK = 10_000
#: Below this many points the local engine runs in the calling process (no pool to start).
IN_PROCESS = 200
#: Seconds to reach a ``scheduler`` (connect, Dask handshake) and then for its first worker.
DEFAULT_SCHEDULER_TIMEOUT = 5.0
#: Available memory the cap on ``workers`` leaves to each LocalCluster worker: a worker measured
#: about 75 MB resident after its chunks (Python, Dask, NumPy, the library), a chunk's arrays
#: and the transfers come on top.
WORKER_MEMORY = 256 * 2**20
#: LocalCluster workers per core at most (more only queue: each chunk is one C call on one core).
WORKERS_PER_CORE = 4
_SPEC_KEYS = ("scene", "vary", "random", "measure", "measures", "title")


# ---------------------------------------------------------------------------------------------
# the spec


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


def _fail(source, key, what):
    raise SceneError(f"{source}: {key}: {what}")


def _real(x) -> float | None:
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        return None
    x = float(x)
    return x if math.isfinite(x) else None


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


def _set(data: dict, key: str, value) -> None:
    """Set the dotted scene key ``key`` in ``data``. The tables and lists on its path are
    replaced by changed copies, never changed in place: ``data`` may be a shallow copy of the
    base scene (``dict(raw)``) that shares every other table with it."""
    term = term_key(key)
    if term is not None:  # a user term's param: the entry of [[kind]] with that name
        kind, name, param = term
        entries = list(data[kind])
        k = next(i for i, e in enumerate(entries) if e.get("name") == name)
        entries[k] = {**entries[k], "params": {**entries[k].get("params", {}), param: value}}
        data[kind] = entries
        return
    table, name, index, _ = _variable_keys()[key]
    t = dict(data.get(table, {}))
    if index is None:
        t[name] = value
    else:
        vec = list(t[name])
        vec[index] = value
        t[name] = vec
    data[table] = t


def _scene_error(source, exc: SceneError, prefix: str) -> SceneError:
    text = str(exc)
    if text.startswith("<dict>: "):
        text = f"{source}: {prefix}{text[len('<dict>: '):]}"
    return SceneError(text)


def _scene_path(source: str, folder: Path, sc: str) -> str:
    """The scene file a sweep names (``sc``, relative to the sweep file's ``folder``)."""
    path = folder / sc
    if "\0" in sc or not path.exists():
        _fail(source, "scene", f"no scene file {sc!r} (a path relative to the sweep file)")
    return str(path)


def input_files(spec) -> tuple:
    """The files a sweep reads (the sweep file, and the scene file it names), to compare the
    outputs with before any work (``outputs.check_paths``); () for a dict. Reads the sweep file
    with the checks of :func:`load` (SceneError as it would raise)."""
    from derive.sim.scene import read_toml

    if isinstance(spec, Mapping) or not isinstance(spec, (str, os.PathLike)):
        return ()
    source = examples.resolve(os.fspath(spec), "sweep")  # a bare name: a shipped example, as in load
    sc = read_toml(source, "sweep").get("scene")
    if not isinstance(sc, str):
        return (source,)
    return (source, _scene_path(source, Path(source).resolve().parent, sc))


def load(spec) -> Spec:
    """Read and validate a sweep (path or dict); raises SceneError ``<file>: <key>: <what>``.

    A sweep file is read by the scene files' reader (``scene.read_toml``: regular files of at
    most ``scene.MAX_SCENE_BYTES``, nothing special such as /dev/zero or a FIFO); a key named
    twice in any spelling (quoted or dotted) is refused, as is a table that names no key.
    """
    from derive.sim.scene import load_scene, read_toml

    if isinstance(spec, Mapping):
        source, data, folder = "<sweep>", spec, Path.cwd()
    elif isinstance(spec, (str, os.PathLike)):
        source = examples.resolve(os.fspath(spec), "sweep")  # a bare name: a shipped example
        data = read_toml(source, "sweep")
        folder = Path(source).resolve().parent
    else:
        raise SceneError(f"<sweep>: sweep: must be a path to a TOML file or a dict, not {type(spec).__name__}")
    for k in data:
        if k not in _SPEC_KEYS:
            _fail(source, k, f"unknown key (the keys of a sweep: {', '.join(_SPEC_KEYS)})")

    # the base scene
    if "scene" not in data:
        _fail(source, "scene", "missing (a path relative to the sweep file, or an inline [scene] table)")
    sc = data["scene"]
    files = (source,) if source != "<sweep>" else ()
    if isinstance(sc, str):
        path = _scene_path(source, folder, sc)
        files += (path,)
        raw = read_toml(path)  # read once, with the scene files' checks
        try:
            base = load_scene(raw)
        except SceneError as exc:
            raise _scene_error(path, exc, "") from None  # its errors name the scene file
    elif isinstance(sc, Mapping):
        raw = copy.deepcopy(dict(sc))
        try:
            base = load_scene(raw)
        except SceneError as exc:
            raise _scene_error(source, exc, "scene.") from None
    else:
        _fail(source, "scene", f"must be a path or a table, got {sc!r}")
    if "title" in data and "title" not in raw and isinstance(data["title"], str):
        raw["title"] = data["title"]

    keys, shape, columns = _points(source, data, raw, base)
    names, options = _measures(source, data)
    out = Spec(source, base, raw, keys, shape, columns, names, options, files=files)
    _build(out)
    return out


def _points(source, data, raw, base):
    variable = _variable_keys()
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
            _check_key(source, f"vary.{key}", key, variable, raw)
            columns[key] = _grid_values(source, f"vary.{key}", rule)
        keys = tuple(columns)
        shape = tuple(len(v) for v in columns.values())
        grids = np.meshgrid(*columns.values(), indexing="ij")
        cols = {k: g.ravel(order="C").copy() for k, g in zip(keys, grids)}
        distinct = columns
    else:
        table = data["random"]
        if not isinstance(table, Mapping):
            _fail(source, "random", "must be a table")
        n, seed = table.get("n"), table.get("seed")
        if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= 10**9:
            _fail(source, "random.n", f"must be an integer from 1 to 1e9, got {n!r}")
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
            _check_key(source, where, key, variable, raw)
            if not isinstance(rule, Mapping) or set(rule) != {"low", "high"}:
                _fail(source, where, "must be { low = a, high = b }")
            lo, hi = _real(rule["low"]), _real(rule["high"])
            if lo is None or hi is None or not lo <= hi:
                _fail(source, where, f"low and high must be finite numbers with low <= high, got {dict(rule)}")
            cols[key] = rng.uniform(lo, hi, n)
            distinct[key] = np.array([lo, hi])
        keys, shape = tuple(cols), None
    _check_values(source, "vary" if shape is not None else "random", raw, distinct)
    return keys, shape, cols


def _check_key(source, where, key, variable, raw):
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
        _fail(source, where, "not a scene key that takes a number (e.g. initial.beta, body.I3, "
                             "gravity.l, initial.omega.0)")
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
    from derive.sim.scene import load_scene

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


def _measures(source, data):
    names, options = list(ms.DEFAULT), {}
    if "measure" in data and "measures" in data:
        _fail(source, "measure", "give [measure] or measures, not both")
    if "measures" in data:
        names = data["measures"]
        where = "measures"
        extra = {}
    elif "measure" in data:
        table = data["measure"]
        if not isinstance(table, Mapping):
            _fail(source, "measure", "must be a table with names = [...]")
        names = table.get("names", list(ms.DEFAULT))
        where = "measure.names"
        extra = {k: v for k, v in table.items() if k != "names"}
    else:
        extra = {}
        where = "measure.names"
    if isinstance(names, str):
        names = [names]
    if not isinstance(names, (list, tuple)) or not names or not all(isinstance(n, str) for n in names):
        _fail(source, where, f"must be a non-empty list of measure names, got {names!r}")
    for n in names:
        if n not in ms.REGISTRY:
            _fail(source, where, f"unknown measure {n!r} (one of {', '.join(ms.REGISTRY)})")
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


# ---------------------------------------------------------------------------------------------
# numbers of every point


def _libm(fn, x) -> np.ndarray:
    """``fn`` (a function of the math module) of every element: the scalar libm call load_scene
    makes, bit for bit (NumPy's own vectorised sin and cos may differ in the last bit); once for
    a column that is one number (bit for bit: -0.0 is not 0.0), a key the sweep does not vary."""
    x = np.asarray(x, dtype=float)
    bits = x.reshape(-1).view(np.int64)
    if bits.size > 1 and (bits == bits[0]).all():
        return np.full(x.shape, fn(float(x.reshape(-1)[0])))
    return np.fromiter(map(fn, x.tolist()), dtype=float, count=x.size)


def _runnable(n: int, invalid) -> np.ndarray:
    """The indices 0..n-1 not in ``invalid`` (the points that are run), in order."""
    keep = np.ones(n, dtype=bool)
    keep[np.fromiter(invalid, int, len(invalid))] = False
    return np.flatnonzero(keep)


def _build(spec: Spec) -> None:
    """inputs (N, NIN), ps (N, NP), the invalid points, the model and the method."""
    from derive.runtime import catalogue
    from derive.symbolic import effects
    from derive.symbolic.formulations import REGISTRY as FORMS
    from derive.sim.scene import TRIANGLE_SLACK, load_scene
    from derive.sim.simulation import choose_method, inputs_of
    from derive.sim.inputs import AUTO
    from derive.sim.plan import auto_method
    from derive.methods.registry import DEFAULT_METHOD, compiled_methods, measure_window

    base, n, cols = spec.scene, spec.n, spec.columns
    src = spec.source

    def col(table, name, default):
        key = f"{table}.{name}"
        return cols[key] if key in cols else np.full(n, float(default))

    # body moments (I2 follows I1 when the scene does not give it)
    I1 = col("body", "I1", base.body.I1)
    I2 = cols["body.I2"] if "body.I2" in cols else (I1 if "I2" not in spec.raw.get("body", {})
                                                    else np.full(n, base.body.I2))
    I3 = col("body", "I3", base.body.I3)
    moments = {"I1": I1, "I2": I2, "I3": I3}
    for c in ("I3", "I1", "I2"):
        a, b = (k for k in moments if k != c)
        bad = np.flatnonzero(moments[a] + moments[b] < moments[c] * (1 - TRIANGLE_SLACK))
        for i in bad:
            spec.invalid.setdefault(int(i), f"invalid: body: moments violate the triangle "
                                            f"inequality {a} + {b} >= {c}")
    symmetric = bool(np.all(I1 == I2))

    # parameters: the moments and each effect's values (per distinct row of its varied keys),
    # and where each effect acts (an effect whose values make it vanish is not in the model
    # unless it acts at some point: a sweep of c from 0 runs the damped model at every point)
    values = {"I1": I1, "I2": I2, "I3": I3}
    acts = {}
    for tname, tv in base.tables.items():
        varied = [k for k in spec.keys if k.startswith(tname + ".")]
        effect = effects.REGISTRY[tv.effect]
        table = effects.TABLES[tname]
        if not varied:
            vals = effect.values(tv)
            values.update({k: np.full(n, float(v)) for k, v in vals.items()})
            acts[tv.effect] = np.full(n, not effect.vanishes(vals))
            continue
        rows = np.stack([cols[k] for k in varied], axis=1)
        uniq, inverse = np.unique(rows, axis=0, return_inverse=True)
        per = []
        for row in uniq:
            given = {k: tv[k] for k in tv.given()}
            given.update({k.split(".", 1)[1]: float(v) for k, v in zip(varied, row)})
            full = {key.name: given.get(key.name, None if key.default is effects.REQUIRED else key.default)
                    for key in table.keys}
            per.append(effect.values(table.complete(full)))
        for name in per[0]:
            values[name] = np.array([p[name] for p in per], dtype=float)[np.ravel(inverse)]
        acts[tv.effect] = np.array([not effect.vanishes(p) for p in per])[np.ravel(inverse)]

    # the user's terms: each param a column (varied) or the scene's value
    for term in base.terms:
        for param, value in term.params:
            key = f"{term.kind}.{term.name}.{param}"
            values[term.model_param(param)] = cols[key] if key in cols else np.full(n, value)
        acts[term.effect] = np.full(n, True)
    spec.terms = base.terms

    # the representative scene: a valid point, asymmetric if any point is, and where it can be
    # one at which every effect of the model acts
    valid = _runnable(n, spec.invalid)
    if valid.size == 0:
        _fail(src, "body", "every point violates the triangle inequality of the moments")
    needed = tuple(e.name for e in effects.lookup([e for e, a in acts.items() if a[valid].any()]))
    fits = valid if symmetric else valid[I1[valid] != I2[valid]]
    full = fits[np.all([acts[e][fits] for e in needed], axis=0)] if needed else fits
    pick = int(full[0] if full.size else fits[0])
    data = dict(spec.raw)  # _set copies what it changes
    for key in spec.keys:
        _set(data, key, float(cols[key][pick]))
    if "I2" not in data["body"]:
        data["body"] = {**data["body"], "I2": float(I2[pick])}
    try:
        spec.scene = rep = load_scene(data)
    except SceneError as exc:
        raise _scene_error(src, exc, "scene.") from None

    method = choose_method(rep)
    if method not in compiled_methods() or measure_window(method) is None:
        _fail(src, "scene.simulate.method", f"a sweep measures on the dense output of a "
                                            f"tolerance-driven method ({', '.join(measuring_methods())}"
                                            f" or auto), not {method}")
    form = rep.simulate.formulation
    if form == "auto":
        plan = sweep_plan(symmetric, needed, method)
    elif FORMS[form].singular:
        _fail(src, "scene.simulate.formulation", f"{form} is singular at sin(beta) = 0; a sweep "
                                                 f"runs a formulation without a singular set (or auto)")
    else:
        plan = ((form, 0),)
    descs = [catalogue.describe((f, symmetric, needed)) for f, _ in plan]
    desc = descs[0]
    if rep.simulate.method == AUTO:
        # the cost model's method for the first candidate's model, at the sweep's tolerance and
        # span (the representative point's), for every point and every fallback candidate: one
        # method per sweep, as a batch takes one
        method = auto_method(rep, desc, samples=2)  # a sweep keeps t = 0 and t_end
        if any(d.jet_weight <= 0 for d in descs):  # a candidate without a Taylor kernel
            method = DEFAULT_METHOD
    spec.key, spec.method, spec.pole_check = (plan[0][0], symmetric, needed), method, plan[0][1]

    # inputs
    inputs = np.tile(inputs_of(base), (n, 1))
    alpha = col("initial", "alpha", base.initial.alpha)
    beta = col("initial", "beta", base.initial.beta)
    gamma = col("initial", "gamma", base.initial.gamma)
    inputs[:, 0], inputs[:, 1], inputs[:, 2] = alpha, beta, gamma
    if base.initial.has_rates:
        ad = col("initial", "alpha_dot", base.initial.alpha_dot)
        bd = col("initial", "beta_dot", base.initial.beta_dot)
        gd = col("initial", "gamma_dot", base.initial.gamma_dot)
        inputs[:, 6], inputs[:, 7], inputs[:, 8] = ad, bd, gd
        if any(k in cols for k in ("initial.beta", "initial.gamma", "initial.alpha_dot",
                                   "initial.beta_dot", "initial.gamma_dot")):
            # the scene validator's formula and libm calls, each product and sum the one it makes
            # in its order (NumPy's elementwise operations round as Python's floats do)
            sb, cb = _libm(math.sin, beta), _libm(math.cos, beta)
            sg, cg = _libm(math.sin, gamma), _libm(math.cos, gamma)
            ad, bd, gd = (np.broadcast_to(np.asarray(v, dtype=float), (n,)) for v in (ad, bd, gd))
            inputs[:, 3] = -ad * sb * cg + bd * sg
            inputs[:, 4] = ad * sb * sg + bd * cg
            inputs[:, 5] = ad * cb + gd
    else:
        for i in range(3):
            if f"initial.omega.{i}" in cols:
                inputs[:, 3 + i] = cols[f"initial.omega.{i}"]

    spec.inputs, spec.ps = inputs, _params(desc, values, n)
    spec.fallback = tuple(((f, symmetric, needed), mode, _params(d, values, n))
                          for (f, mode), d in zip(plan[1:], descs[1:]))
    # the general parameters of every point (derive.symbolic.integrable.parameters' convention: no
    # gravity is M = g = 0; gravity's l is the centre of mass on axis 3), for integral_drift
    zero = np.zeros(n)
    com = [values.get(c, zero) for c in ("cx", "cy")] + [values.get("cz", values.get("l", zero))]
    spec.general = np.column_stack([I1, I2, I3, values.get("M", zero), values.get("g", zero), *com])
    spec.damping = np.asarray(values.get("c", zero), dtype=float)


def measuring_methods() -> tuple[str, ...]:
    """The methods a sweep can run: those with a measure window
    (:func:`derive.methods.registry.measure_window`), scene-visible ones only.

    Returns
    -------
    tuple of str
        Their names, in the registry's order (``("dop853", "taylor")``).
    """
    from derive.methods.registry import INTERNAL_METHODS, compiled_methods, measure_window

    return tuple(m for m in compiled_methods() if m not in INTERNAL_METHODS and measure_window(m))


def _params(desc, values: dict, n: int) -> np.ndarray:
    """(N, NP) parameters of the model ``desc`` from the named columns ``values`` (the ones its
    init map derives, such as reduced-u's p_alpha, p_gamma, E', are left 0 for C to fill)."""
    derived = set(desc.derived_params)
    ps = np.zeros((n, len(desc.params)))
    for k, name in enumerate(desc.params):
        if k not in derived:
            ps[:, k] = values[name]
    return ps


def sweep_plan(symmetric: bool, effects: tuple, method: str) -> tuple:
    """The formulations a sweep of formulation "auto" tries per point, cheapest first, each
    with the pole check its C driver runs on the start: ((formulation, pole check), ...), the
    last one without a singular set (check 0: it takes every point).

    They are the candidates of :func:`derive.sim.auto.plan` for the model's structure (body
    symmetry, effects, method; a point's start is judged by the compiled check, per point),
    except:

    * a formulation whose accuracy near a pole is judged after the run from the sampled beta
      (``pole_loss``: euler-angles) is left out: a sweep keeps no samples to judge it on, so a
      point refused by the first candidate runs the universal one instead;
    * a singular formulation is tried only when its model exists (generated or cached): the
      plan must not cost a derivation in SymPy;
    * the check of mode 2 (the reduced equations may meet a pole where they stay regular) is
      made mode 1 (clear of both poles): a start at a pole, which ``derive.simulate`` refuses
      for those formulations up front, cannot then reach their integration.
    """
    from derive.runtime import catalogue
    from derive.sim import auto
    from derive.symbolic.formulations import REGISTRY as FORMS

    out = []
    for name, mode in auto.structural(symmetric, effects, method):
        if not mode:
            out.append((name, 0))
            break
        if FORMS[name].pole_loss or catalogue.available((name, symmetric, effects)) is None:
            continue
        out.append((name, 1))
    return tuple(out)


# ---------------------------------------------------------------------------------------------
# engines


def run_chunk(key, method, inputs, ps, t, args, config, integral=None, terms=(), pole_check=0,
              fallback=(), which=False):
    """One task: measured simulations of a block of points (the libraries are compiled or
    loaded once per process).

    Parameters
    ----------
    key, method : tuple, str
        The first candidate's model and the method.
    inputs, ps : ndarray
        The init map's inputs (N, NIN) and the first candidate's parameters (N, NP).
    t, args, config, integral
        As :meth:`derive.sweeps.measures.MeasureKernel.run` takes them.
    terms : tuple
        The user's terms of the model, registered here first (a worker started afresh knows
        only the built-in effects).
    pole_check : int
        The first candidate's check of each start (0: none).
    fallback : tuple
        The next candidates, ``(key, pole check, ps (N, NP))``: the points the previous
        candidate's check refused (status RANGE) run again with the next, in one C call each.
    which : bool
        Also return ``ran`` (the engines' tasks do; every argument is positional there, so
        that a stand-in for this function in the tests takes ``*args``).

    Returns
    -------
    tuple
        (res (N, len(SLOTS)), final outputs (N, NOBS), stats (N,)), and with ``which`` ``ran``
        (N,) int8: the index of the candidate whose run gave each point's numbers (0 the
        first).
    """
    from derive.methods.status import Status
    from derive.runtime import catalogue
    from derive.symbolic import terms as user_terms

    for term in terms:
        user_terms.register(term)

    desc = catalogue.describe(key)
    kernel = ms.MeasureKernel.load(desc, method)
    res, out, st = kernel.run(inputs, ps, t, args, config, integral, pole_check)
    final = np.ascontiguousarray(out[:, :, -1])
    ran = np.zeros(len(st), dtype=np.int8)
    todo = np.flatnonzero(st["status"] == Status.RANGE) if pole_check else np.zeros(0, int)
    for j, (fkey, fcheck, fps) in enumerate(fallback, start=1):
        if todo.size == 0:
            break
        fdesc = catalogue.describe(fkey)
        if fdesc.outputs != desc.outputs:  # the rows below mix the two models' outputs
            raise AssertionError(f"{fdesc.name} and {desc.name} have different outputs")
        sub = None if integral is None else np.asarray(integral)[todo]
        r, o, s = ms.MeasureKernel.load(fdesc, method).run(inputs[todo], fps[todo], t, args,
                                                          config, sub, fcheck)
        res[todo], final[todo], st[todo], ran[todo] = r, o[:, :, -1], s, j
        todo = todo[s["status"] == Status.RANGE] if fcheck else todo[:0]
    return (res, final, st, ran) if which else (res, final, st)


def _chunks(idx: np.ndarray, parallel: int) -> list:
    """The points ``idx`` in chunks of at most CHUNK, about four per worker of ``parallel``
    (0: no workers, the calling process runs them: chunks of CHUNK)."""
    size = max(1, min(CHUNK, math.ceil(idx.size / max(1, 4 * parallel))))
    return [idx[i:i + size] for i in range(0, idx.size, size)]


def _in_process(points: int, processes: int) -> bool:
    """Does the local engine run ``points`` in the calling process (no pool to start)?"""
    return processes <= 1 or points < IN_PROCESS


def _progress_bar(total, progress):
    import sys

    from tqdm import tqdm

    if progress is None:
        progress = sys.stderr.isatty()
    return tqdm(total=total, unit="pt", disable=not progress, desc="sweep", leave=False)


def _die_with_parent(parent: int) -> None:
    """Ask the kernel to kill this process when its parent dies (Linux ``PR_SET_PDEATHSIG``), so
    that a parent killed outright (SIGKILL, the OOM killer) leaves no worker computing for no
    one and printing BrokenPipeError; elsewhere a worker ends when its pipe closes."""
    import ctypes
    import signal

    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, int(signal.SIGKILL), 0, 0, 0)  # 1: PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        return
    if os.getppid() != parent:  # the parent died before the request: nothing will send it
        os._exit(1)


def _worker_init(parent: int) -> None:
    """Set up a local worker process: Ctrl-C and SIGTERM are the parent's to handle.

    SIGINT stays blocked (it was blocked when the worker was forked): Ctrl-C reaches the whole
    process group, and a worker that took it would print a traceback while the parent is
    already stopping the workers; the compiled loop's interrupt guard installs its own SIGINT
    handler, which a blocked signal never reaches. SIGTERM gets its default action (the end),
    not the parent's handlers the fork copied, and the worker dies with its parent."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGTERM})
    _die_with_parent(parent)


class _held:
    """Ctrl-C and SIGTERM wait until the end of the ``with`` body, then act as they would have.

    For the steps that must not stop half-way: starting a pool or a cluster (stopped half-way,
    its processes are left to Dask's exit hook or nobody) and their clean-up. In the main thread
    SIGINT and SIGTERM get a handler that notes them, and the first one noted is raised again on
    exit under the handlers restored (KeyboardInterrupt, :class:`Terminated`, or SIGTERM's
    default action). ``masked`` signals are also blocked in the calling thread, so that the
    processes forked and the threads started in the body begin with them blocked.
    """

    def __init__(self, *masked):
        self.masked = set(masked)

    def __enter__(self):
        import signal
        import threading

        self.pending, self.old, self.mask = [], {}, None
        if threading.current_thread() is threading.main_thread():
            for sig in (signal.SIGINT, signal.SIGTERM):
                self.old[sig] = signal.signal(sig, self._note)
        if self.masked:
            self.mask = signal.pthread_sigmask(signal.SIG_BLOCK, self.masked)
        return self

    def _note(self, signum, frame):
        self.pending.append(signum)

    def __exit__(self, *exc):
        import signal

        if self.mask is not None:  # a signal blocked meanwhile is noted now, before the restore
            signal.pthread_sigmask(signal.SIG_SETMASK, self.mask)
        for sig, old in self.old.items():
            signal.signal(sig, old)
        if self.pending:
            signal.raise_signal(self.pending[0])


def _signal_name(number: int) -> str:
    import signal

    try:
        return signal.Signals(number).name
    except ValueError:
        return f"signal {number}"


def _worker_main(conn, parent: int) -> None:
    """A local pool worker: run the chunks the parent sends, ``(k, args)``, and send back
    ``(k, True, result)`` or ``(k, False, exception)``, until None or the pipe closes."""
    _worker_init(parent)
    while True:
        try:
            task = conn.recv()
        except (EOFError, OSError):
            return
        if task is None:
            return
        k, args = task
        try:
            reply = (k, True, run_chunk(*args))
        except Exception as exc:  # raised again in the parent
            reply = (k, False, exc)
        try:
            conn.send(reply)
        except (OSError, ValueError):  # the parent is gone
            return
        except Exception as exc:  # e.g. an exception that does not pickle
            try:
                conn.send((k, False, RuntimeError(f"{type(exc).__name__}: {exc}")))
            except Exception:
                return  # the parent sees a dead worker


def _receive(conn):
    """One reply from a worker (a function of its own: the tests make it fail)."""
    return conn.recv()


def _exit_reason(code: int | None) -> str:
    if code is not None and code < 0:
        hint = " (out of memory?)" if code == -9 else ""
        return f"was killed by {_signal_name(-code)}{hint}"
    return f"exited with status {code}"


def _local(tasks, submit_args, progress, processes, source="<sweep>"):
    """In this process when the sweep is small, else ``processes`` worker processes (fork where
    the system has it: they inherit the loaded library), each sent one chunk at a time.

    A worker that dies (the OOM killer, a signal) or a result that cannot be received (out of
    memory) ends the sweep at once with :class:`EngineError` ``<source>: sweep: ...``: every
    worker has its own pipe and the parent watches both the pipes and the processes, so nothing
    waits for a chunk that will not come (``multiprocessing.Pool`` would: a dead worker's chunk
    is lost, a dead result thread stops every reply, and its terminate can wait on a lock a
    killed worker held). Ctrl-C and SIGTERM (:class:`Terminated`) stop the workers; they ignore
    both themselves and die with this process (:func:`_worker_init`)."""
    import multiprocessing as mp
    import signal
    from multiprocessing.connection import wait

    results = {}
    with _progress_bar(sum(len(i) for i in tasks), progress) as bar:
        if len(tasks) == 1 or _in_process(sum(len(i) for i in tasks), processes):
            for k, idx in enumerate(tasks):
                results[k] = run_chunk(*submit_args(idx))
                bar.update(len(idx))
            return results
        ctx = mp.get_context("fork" if "fork" in mp.get_all_start_methods() else "spawn")
        workers = []  # (process, connection)
        try:
            # Forked with SIGINT and SIGTERM blocked (and a signal meanwhile held back): a
            # worker must not take either before its initializer has set them.
            with _held(signal.SIGINT, signal.SIGTERM):
                for _ in range(min(processes, len(tasks))):
                    mine, theirs = ctx.Pipe()
                    proc = ctx.Process(target=_worker_main, args=(theirs, os.getpid()), daemon=True)
                    proc.start()
                    theirs.close()
                    workers.append((proc, mine))
            todo = list(range(len(tasks)))[::-1]  # popped from the end: chunk 0 first
            busy = {}  # connection -> (process, chunk)

            def dead(proc, k):
                what = f"running chunk {k + 1} of {len(tasks)}" if k is not None else "idle"
                return EngineError(f"{source}: sweep: worker process {proc.pid} "
                                   f"{_exit_reason(proc.exitcode)} ({what}); "
                                   f"{len(tasks) - len(results)} of {len(tasks)} chunks unfinished")

            def send(proc, conn):
                k = todo.pop()
                try:
                    conn.send((k, submit_args(tasks[k])))
                except (BrokenPipeError, ConnectionError):
                    proc.join(1)
                    raise dead(proc, k) from None
                busy[conn] = (proc, k)

            for proc, conn in workers:
                if todo:
                    send(proc, conn)
            while len(results) < len(tasks):
                ready = wait([*busy, *(p.sentinel for p, _ in workers)], timeout=1.0)
                for conn in [r for r in ready if r in busy]:
                    proc, k = busy.pop(conn)
                    try:
                        got, ok, value = _receive(conn)
                    except (EOFError, OSError):
                        proc.join(1)
                        raise dead(proc, k) from None
                    except MemoryError:
                        raise EngineError(f"{source}: sweep: out of memory receiving the results "
                                          f"of chunk {k + 1} of {len(tasks)} ({len(tasks[k])} "
                                          f"points)") from None
                    if not ok:
                        if isinstance(value, MemoryError):
                            raise EngineError(f"{source}: sweep: worker process {proc.pid} ran "
                                              f"out of memory in chunk {k + 1} of {len(tasks)}")
                        raise value
                    results[got] = value
                    bar.update(len(tasks[got]))
                    if todo:
                        send(proc, conn)
                for proc, conn in workers:  # a worker gone while idle or busy: never expected
                    if proc.exitcode is not None:
                        raise dead(proc, busy.get(conn, (None, None))[1])
        finally:
            with _held():  # a second Ctrl-C waits for this (bounded) clean-up
                _stop_local(workers, clean=len(results) == len(tasks))
    return results


def _stop_local(workers, clean: bool) -> None:
    """End the local workers: asked to (None) after a complete sweep, else SIGKILL at once
    (a chunk in a C loop is not worth finishing); every process is reaped."""
    for proc, conn in workers:
        if clean:
            try:
                conn.send(None)
            except OSError:
                pass
        elif proc.exitcode is None:
            proc.kill()
    for proc, conn in workers:
        proc.join(5)
        if proc.exitcode is None:
            proc.kill()
            proc.join(5)
        conn.close()


def _dask(run, submit_args, progress, workers, scheduler, *, source="<sweep>", timeout=None,
          dashboard=False, security=None):
    """The chunks through a Dask cluster (a closed LocalCluster of ``workers`` processes, see
    :func:`local_cluster`, or the one at ``scheduler``, probed first and joined within
    ``timeout`` seconds), cut for its worker count. Returns (tasks, results)."""
    import contextlib
    import logging
    import signal

    from dask.distributed import Client, as_completed
    from distributed.scheduler import KilledWorker

    timeout = DEFAULT_SCHEDULER_TIMEOUT if timeout is None else timeout
    logging.getLogger("distributed").setLevel(logging.CRITICAL)  # failures are our one line
    cluster = client = None
    futures = []
    try:
        if scheduler is None:
            # The workers are spawned (exec'd) by threads the cluster starts, which inherit
            # SIGINT blocked from here, and so do the workers (Python does not unblock it): Ctrl-C
            # to the process group reaches only this process, which stops them (a worker taking
            # it while importing would print a traceback, and fail the cluster's start). The
            # resource tracker is started first: starting it unblocks SIGINT in the thread that
            # does, which would then spawn the workers with it unblocked.
            from multiprocessing import resource_tracker

            resource_tracker.ensure_running()
            with _held(signal.SIGINT):
                cluster = local_cluster(workers, dashboard=dashboard)
            if dashboard:
                import sys

                print(f"note: dashboard at {cluster.dashboard_link}", file=sys.stderr, flush=True)
            client = Client(cluster, timeout=timeout)
        else:
            client = _connect(scheduler, source, timeout, security)
        tasks = _chunks(run, max(1, sum(client.nthreads().values())))
        futures = [client.submit(run_chunk, *submit_args(idx), pure=False) for idx in tasks]
        index = {f.key: k for k, f in enumerate(futures)}
        results = {}
        with _progress_bar(sum(len(i) for i in tasks), progress) as bar:
            for fut in as_completed(futures):
                k = index[fut.key]
                try:
                    results[k] = fut.result()
                except KilledWorker as exc:  # its workers died in it (Dask retried it)
                    raise EngineError(f"{source}: sweep: chunk {k + 1} of {len(tasks)} killed "
                                      f"the Dask workers that ran it (out of memory?): "
                                      f"{' '.join(str(exc).split())[:200]}") from None
                bar.update(len(tasks[k]))
        return tasks, results
    except BaseException:
        if futures and client is not None:
            with contextlib.suppress(Exception):
                client.cancel(futures, force=True)
        if cluster is not None:  # ours: stop its workers now, mid-chunk
            _stop_workers(cluster)
        raise
    finally:
        # (after Ctrl-C the futures are cancelled; a worker of another cluster busy in a chunk
        # finishes that C call). Signals wait for the close: a cluster closed half-way is closed
        # again by Dask's exit hook, which prints a traceback.
        with _held():
            with contextlib.suppress(Exception):
                if client is not None:
                    client.close()
            if cluster is not None:
                with contextlib.suppress(Exception):
                    cluster.close()


def _stop_workers(cluster) -> None:
    """Terminate the worker processes of a LocalCluster at once (SIGTERM), mid-chunk."""
    import contextlib

    with contextlib.suppress(Exception):
        for w in list(cluster.workers.values()):
            proc = getattr(getattr(w, "process", None), "process", None)
            if proc is not None:
                proc.terminate()


def local_cluster(workers: int, dashboard: bool = False):
    """Start the Dask ``LocalCluster`` of ``derive sweep --workers``: closed to everyone else.

    Parameters
    ----------
    workers : int
        Worker processes, one thread each (a process runs one measured C call at a time).
    dashboard : bool
        Serve Dask's dashboard (``/status``) on 127.0.0.1 (a free port: ``dashboard_link``).
        Without it the scheduler's HTTP server answers only ``/health``.

    Returns
    -------
    distributed.LocalCluster
        Its scheduler and workers speak TLS with credentials made for this cluster only
        (``Security.temporary()``: a fresh CA and key, in memory, required of both ends), so a
        client without them (another local user) is refused; everything it starts (scheduler,
        nannies, workers, HTTP servers) listens on 127.0.0.1 only. The caller closes it.
    """
    import logging

    import dask
    from dask.distributed import LocalCluster
    from distributed.security import Security

    routes = (dask.config.get("distributed.scheduler.http.routes") if dashboard
              else ["distributed.http.health"])
    # dashboard_address ":0" would bind 0.0.0.0; a scheduler always serves HTTP, so its
    # address is given even without the dashboard (loopback, any free port, never 8787's clash)
    with dask.config.set({"distributed.scheduler.http.routes": routes}):
        return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                            host="127.0.0.1", security=Security.temporary(),
                            dashboard_address=None, worker_dashboard_address=None,
                            scheduler_kwargs={"dashboard": dashboard,
                                              "dashboard_address": "127.0.0.1:0"},
                            silence_logs=logging.CRITICAL)


def worker_cap() -> tuple[int, str]:
    """The most LocalCluster workers this machine can hold, and why.

    Returns
    -------
    (int, str)
        ``min(WORKERS_PER_CORE * cores, available memory // WORKER_MEMORY)``, at least 1, and a
        phrase naming the figures, for the message that refuses more.
    """
    cores = _cpus()
    by_cores = WORKERS_PER_CORE * cores
    try:
        import psutil

        available = int(psutil.virtual_memory().available)
    except Exception:  # psutil comes with dask; without it the cores alone cap
        return by_cores, f"{WORKERS_PER_CORE} per core on {cores} cores"
    by_memory = max(1, available // WORKER_MEMORY)
    why = (f"{WORKERS_PER_CORE} per core on {cores} cores, and {WORKER_MEMORY >> 20} MB of the "
           f"{available / 2**30:.1f} GB available memory each")
    return max(1, min(by_cores, by_memory)), why


_FLAG_NAMES = {"workers": "--workers", "scheduler": "--scheduler",
               "scheduler_timeout": "--scheduler-timeout", "dashboard": "--dashboard"}


def check_engine(source, workers=None, scheduler=None, scheduler_timeout=None, dashboard=False,
                 flags=False) -> str | None:
    """Validate a sweep's engine arguments before any work; returns the scheduler address.

    Parameters
    ----------
    source : str
        The sweep file (or ``<sweep>``), first in the message.
    workers, scheduler, scheduler_timeout, dashboard
        As :func:`sweep` takes them.
    flags : bool
        Name them as the command line does (``--workers``) rather than as the API does.

    Returns
    -------
    str or None
        The scheduler address, ``tcp://`` added when no scheme is given.

    Raises
    ------
    SceneError
        ``<source>: <name>: <what>`` for a bad value, both engines, more workers than
        :func:`worker_cap` allows, a malformed address, a dashboard without ``workers`` or
        without bokeh (which Dask's dashboard needs).
    """
    name = (lambda k: _FLAG_NAMES[k]) if flags else (lambda k: k)

    def bad(key, what):
        raise SceneError(f"{source}: {name(key)}: {what}")

    if workers is not None and scheduler is not None:
        bad("workers", f"give {name('workers')} or {name('scheduler')}, not both")
    if workers is not None:
        if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
            bad("workers", f"must be a positive integer, got {workers!r}")
        cap, why = worker_cap()
        if workers > cap:
            bad("workers", f"{workers} worker processes is more than this machine holds (at most "
                           f"{cap}: {why}); a bigger sweep goes to a cluster ({name('scheduler')})")
    if not isinstance(dashboard, bool):
        bad("dashboard", f"must be true or false, got {dashboard!r}")
    if dashboard and workers is None:
        bad("dashboard", f"only with {name('workers')} (the cluster derive starts; a scheduler "
                         f"serves its own)")
    if dashboard:
        import importlib.util

        if importlib.util.find_spec("bokeh") is None:
            bad("dashboard", "Dask's dashboard needs bokeh, which is not installed "
                             "(pip install 'bokeh>=3.1')")
    if scheduler_timeout is not None:
        t = _real(scheduler_timeout)
        if t is None or not 0 < t <= 3600:
            bad("scheduler_timeout", f"must be a number of seconds in (0, 3600], got "
                                     f"{scheduler_timeout!r}")
        if scheduler is None:
            bad("scheduler_timeout", f"only with {name('scheduler')}")
    if scheduler is None:
        return None
    if not isinstance(scheduler, str):
        bad("scheduler", f"must be an address such as tcp://host:8786, got {scheduler!r}")
    try:
        return _parse_address(scheduler)
    except ValueError as exc:
        bad("scheduler", f"{exc} (an address such as tcp://host:8786)")


def _parse_address(address: str) -> str:
    """``[tcp:// | tls://]host:port`` -> ``scheme://host:port``; ValueError saying what is wrong."""
    text = address.strip()
    scheme, sep, loc = text.partition("://")
    if not sep:
        scheme, loc = "tcp", text
    if scheme not in ("tcp", "tls"):
        raise ValueError(f"{address!r}: the scheme must be tcp:// or tls://")
    host, colon, port = loc.rpartition(":")
    if not colon or not host:
        raise ValueError(f"{address!r} is not host:port")
    bare = host[1:-1] if host.startswith("[") and host.endswith("]") else host
    if not bare or any(c.isspace() or c in "/?#@[]" for c in bare) or (":" in bare and bare == host):
        raise ValueError(f"{address!r}: bad host {host!r}")
    if not port.isdigit() or not 1 <= int(port) <= 65535:
        raise ValueError(f"{address!r}: the port must be a number from 1 to 65535")
    return f"{scheme}://{host}:{int(port)}"


def _probe(address: str, source: str, timeout: float) -> None:
    """Reach the scheduler at ``address`` within ``timeout`` seconds and, for tcp://, read its
    Dask handshake (the server speaks first: an 8-byte length, then a small msgpack dict), so
    that a closed port, a silent listener or another protocol is one clear EngineError instead
    of Dask's retries, a wait for ever or a gigabyte-sized allocation from an HTTP reply."""
    import socket
    import struct
    import time

    scheme, loc = address.split("://", 1)
    host, port = loc.rsplit(":", 1)
    host = host.strip("[]")
    where = f"{source}: scheduler {address}"
    deadline = time.monotonic() + timeout

    def left():
        return max(0.01, deadline - time.monotonic())

    try:
        sock = socket.create_connection((host, int(port)), timeout=left())
    except socket.gaierror as exc:
        raise EngineError(f"{where}: unknown host ({exc.strerror or exc})") from None
    except ConnectionRefusedError:
        raise EngineError(f"{where}: connection refused (nothing listens there)") from None
    except (TimeoutError, socket.timeout):
        raise EngineError(f"{where}: no answer within {timeout:g} s") from None
    except OSError as exc:
        raise EngineError(f"{where}: cannot connect ({exc.strerror or exc})") from None
    if scheme != "tcp":  # TLS: the client speaks first; Dask's own timeout covers the rest
        sock.close()
        return

    def read(n):
        data = bytearray()
        while len(data) < n:
            sock.settimeout(left())
            chunk = sock.recv(n - len(data))
            if not chunk:
                raise EngineError(f"{where}: closed the connection without a Dask handshake")
            data += chunk
        return bytes(data)

    try:
        with sock:
            (size,) = struct.unpack("Q", read(8))
            if not 8 <= size <= 1 << 16:  # a handshake is ~60 bytes; "HTTP/1.1" reads as 10^18
                raise EngineError(f"{where}: answered, but not as a Dask scheduler (is it one?)")
            body = read(size)
    except (TimeoutError, socket.timeout):
        raise EngineError(f"{where}: accepted the connection but sent no Dask handshake within "
                          f"{timeout:g} s (is it a Dask scheduler?)") from None
    except ConnectionError as exc:
        raise EngineError(f"{where}: the connection failed ({exc.strerror or exc})") from None
    try:
        from distributed.protocol import loads
        from distributed.protocol.utils import unpack_frames

        hello = loads(unpack_frames(body), deserialize=False)
    except Exception:
        hello = None
    if not isinstance(hello, dict) or "python" not in hello:
        raise EngineError(f"{where}: answered, but not as a Dask scheduler (is it one?)")


def _connect(address: str, source: str, timeout: float, security=None):
    """A Client of the scheduler at ``address`` with a worker, within ``timeout`` seconds for
    the connection and as much again for the first worker; EngineError otherwise."""
    from dask.distributed import Client

    _probe(address, source, timeout)
    where = f"{source}: scheduler {address}"
    try:
        client = Client(address, timeout=timeout, security=security)
    except (OSError, TimeoutError, TypeError, ValueError) as exc:
        if address.startswith("tls://") and security is None:  # Dask: "TLS expects a ssl_context"
            why = ("a tls:// scheduler needs credentials: security= in the API, or Dask's "
                   "distributed.comm.tls configuration")
        else:
            why = " ".join(str(exc).split())[:200]
        raise EngineError(f"{where}: cannot connect ({why})") from None
    try:
        client.wait_for_workers(1, timeout=timeout)
    except (TimeoutError, OSError):
        client.close()
        raise EngineError(f"{where}: has no workers (none joined within {timeout:g} s; start "
                          f"some with `dask worker {address} --nthreads 1`)") from None
    except BaseException:
        client.close()
        raise
    return client


def _cpus() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


# ---------------------------------------------------------------------------------------------
# results


@dataclass
class SweepResult:
    """``params`` and ``measures``: {name: (N,) array}, one entry per point (grid points in C
    order, the first varied key slowest); ``status``: (N,) str, "ok" or why the point failed;
    ``formulation``: (N,) str, the formulation whose run gave the point's numbers ("" for a
    point not run: invalid); ``model``: the models that ran any point, in the order tried."""

    params: dict
    measures: dict
    status: np.ndarray
    keys: tuple
    shape: tuple | None
    measure_names: tuple
    title: str = ""
    source: str = ""
    model: str = ""
    scene: object = field(default=None, repr=False)
    files: tuple = ()  # the files the sweep read (outputs may not replace them: ``write``)
    formulation: np.ndarray = field(default=None, repr=False)

    @property
    def ok(self) -> np.ndarray:
        return self.status == "ok"

    def to_pandas(self):
        """The sweep as a ``pandas.DataFrame``: a column per varied key, per measure column, and
        ``status``; one row per point."""
        import pandas as pd

        cols = {**self.params, **self.measures, "status": self.status.astype(str)}
        return pd.DataFrame(cols)


def sweep(spec, *, workers=None, scheduler=None, progress=None, processes=None,
          add_measure=None, scheduler_timeout=None, dashboard=False, security=None,
          saveat=None) -> SweepResult:
    """Run a sweep (a file path or a dict shaped like one).

    Parameters
    ----------
    spec : str, os.PathLike or dict
        The sweep file, or a dict of the same shape.
    workers : int, optional
        Start a Dask LocalCluster of that many worker processes for this sweep, closed to
        everyone else (:func:`local_cluster`), at most :func:`worker_cap`.
    scheduler : str, optional
        The address of a running Dask scheduler (``tcp://host:8786``, ``tls://...``).
    progress : bool, optional
        A tqdm bar on stderr (None: when stderr is a TTY).
    processes : int, optional
        The local engine's pool size (neither ``workers`` nor ``scheduler``; default one per core).
    add_measure : str, optional
        A measure (or one of its columns) added to the file's list.
    scheduler_timeout : float, optional
        Seconds to reach ``scheduler`` and, again, for its first worker
        (default ``DEFAULT_SCHEDULER_TIMEOUT``).
    dashboard : bool
        With ``workers``: serve Dask's dashboard on 127.0.0.1 (its address is printed on
        stderr; needs bokeh).
    security : distributed.security.Security, optional
        The credentials for a ``tls://`` scheduler.
    saveat : derive.SaveAt, optional
        What to keep besides the measures: a sweep keeps t_end only (``t="final"``); its
        outputs there (:func:`final_measures`: ``alpha``, ``beta``, ``gamma``, ``omega``) add
        the ``final_state`` measure's columns.

    Returns
    -------
    SweepResult

    Raises
    ------
    SceneError
        A bad sweep or engine argument (``<file>: <key>: <what>``).
    EngineError
        The engine could not finish: a broken local pool, an unreachable or silent scheduler,
        a scheduler without workers.
    """
    from derive.runtime import catalogue
    from derive.sim.simulation import _explain

    source = os.fspath(spec) if isinstance(spec, (str, os.PathLike)) else "<sweep>"
    scheduler = check_engine(source, workers, scheduler, scheduler_timeout, dashboard)
    sp = load(spec)
    extra = final_measures(saveat, sp.source)
    if extra:
        sp.measures = tuple(dict.fromkeys((*sp.measures, *extra)))
    if add_measure is not None:  # the column to plot: a measure's (final_beta) or a measure
        name = ms.owner(add_measure)
        if name is None:
            raise SceneError(f"{sp.source}: --measure: unknown measure {add_measure!r} "
                             f"(one of {', '.join(ms.REGISTRY)})")
        if len(ms.REGISTRY[name].columns) > 1 and add_measure == name:
            raise SceneError(f"{sp.source}: --measure: {name} has several columns; plot one of "
                             f"{', '.join(ms.REGISTRY[name].columns)}")
        sp.measures = tuple(dict.fromkeys((*sp.measures, name)))
    descs = [catalogue.describe(k) for k in (sp.key, *(f[0] for f in sp.fallback))]
    desc = descs[0]
    for d in descs:  # compile here, once, before any worker needs them
        ms.MeasureKernel.load(d, sp.method)
    s = sp.scene.simulate
    t = np.array([0.0, s.t_end])
    args = ms.driver_args(sp.method, s.rtol, s.atol, s.max_steps)
    config = ms.config_of(sp.measures, sp.options)
    run = _runnable(sp.n, sp.invalid)
    processes = processes or _cpus()
    integral = None
    if "integral_drift" in sp.measures:
        choice = sp.options.get("integral_drift", {}).get("integral", "case")
        integral = ms.integral_rows(sp.general, sp.damping, choice)

    def submit_args(idx):
        return (sp.key, sp.method, sp.inputs[idx], sp.ps[idx], t, args, config,
                None if integral is None else integral[idx], sp.terms, sp.pole_check,
                tuple((k, c, p[idx]) for k, c, p in sp.fallback), True)

    if workers is None and scheduler is None:
        # in this process: chunks of CHUNK points (one C call each, no pool to feed)
        tasks = _chunks(run, 0 if _in_process(run.size, processes) else processes)
        results = _local(tasks, submit_args, progress, processes, sp.source)
    else:
        timeout = None if scheduler_timeout is None else float(scheduler_timeout)
        tasks, results = _dask(run, submit_args, progress, workers, scheduler, source=sp.source,
                               timeout=timeout, dashboard=dashboard, security=security)

    n = sp.n
    res = np.full((n, len(ms.SLOTS)), np.nan)
    final = np.full((n, len(desc.outputs)), np.nan)
    from derive.runtime.integrate import STATS_DTYPE

    stats = np.zeros(n, dtype=STATS_DTYPE)
    status = np.full(n, "ok", dtype=object)
    ran = np.full(n, -1, dtype=np.int8)  # the candidate that ran each point (-1: not run)
    for i, why in sp.invalid.items():
        status[i] = why
    for k, idx in enumerate(tasks):
        r, f, st, which = results[k]
        res[idx], final[idx], stats[idx], ran[idx] = r, f, st, which
    for i in np.flatnonzero(stats["status"] != 0):
        status[i] = _explain(descs[ran[i]], stats[i], s.max_steps)
    for i in run[~np.isfinite(final[run]).all(axis=1)]:
        if status[i] == "ok":
            status[i] = f"t = {s.t_end:.8g}: non-finite outputs (overflow)"
            res[i] = np.nan
    values = ms.read(sp.measures, desc, res, stats, final)
    names = np.array(["", *(d.formulation for d in descs)], dtype=object)
    used = [d.name for j, d in enumerate(descs) if (ran == j).any()] or [desc.name]
    return SweepResult(params={k: sp.columns[k] for k in sp.keys}, measures=values,
                       status=status.astype(str), keys=sp.keys, shape=sp.shape,
                       measure_names=sp.measures, title=sp.scene.title or "", source=sp.source,
                       model=", ".join(used), scene=sp.scene, files=sp.files,
                       formulation=names[ran.astype(int) + 1].astype(str))


def final_measures(saveat, source: str = "<sweep>") -> tuple[str, ...]:
    """The measures a sweep adds for ``saveat`` (a :class:`derive.SaveAt` or None): a sweep
    keeps no samples, only t_end, where the ``final_state`` measure gives α, β, γ and ω̃; ()
    for None. SceneError for the grid or another output."""
    if saveat is None:
        return ()
    if not saveat.final:
        raise SceneError(f"{source}: saveat: a sweep keeps t_end only (SaveAt(t=\"final\")), not the grid")
    allowed = ("alpha", "beta", "gamma", "omega")
    for name in saveat.outputs or ():
        if name not in allowed:
            raise SceneError(f"{source}: saveat: a sweep keeps {', '.join(allowed)} at t_end, not {name!r}")
    return ("final_state",)


def write(result: SweepResult, parquet: str | None, png: str | None = None,
          measure: str | None = None) -> None:
    """The table (one row per point: .parquet, or .csv with one header row) and the plot (.png,
    .pdf or .svg), each in the format its extension names, all or nothing; neither may be a
    file the sweep read (``result.files``: SceneError naming both)."""
    from derive.sim.outputs import PLOT_FORMATS, TABLE_FORMATS, check_paths, output_format, write_all

    check_paths([parquet, png], inputs=result.files)  # a clash with an input first
    table_format = output_format(parquet, "-o", TABLE_FORMATS) if parquet else None
    plot_format = output_format(png, "--plot", PLOT_FORMATS) if png else None
    writers = {}
    if table_format == "parquet":
        writers[parquet] = lambda f: result.to_pandas().to_parquet(f, engine="pyarrow", index=False)
    elif table_format == "csv":
        # repr: the shortest text that reads back to the same double
        writers[parquet] = lambda f: result.to_pandas().to_csv(
            f, index=False, float_format=lambda x: repr(float(x)), na_rep="nan")
    if png:
        def plot(f):
            from derive.sweeps.maps import plot_sweep

            plot_sweep(result, f, measure, plot_format)

        writers[png] = plot
    write_all(writers, inputs=result.files)


def cli(args) -> int:
    """``derive sweep``: run, write, print a one-line summary. SIGTERM is handled as Ctrl-C is
    (workers stopped, no temporary left), raised as :class:`Terminated` (exit 143)."""
    import sys
    import time

    from derive.sim.outputs import PLOT_FORMATS, TABLE_FORMATS, check_paths, output_format

    timeout = getattr(args, "scheduler_timeout", None)
    dashboard = bool(getattr(args, "dashboard", False))
    check_engine(args.sweep, args.workers, args.scheduler, timeout, dashboard, flags=True)
    # before the work: an output that would replace the sweep file or its scene is known now
    check_paths([args.output, args.plot], inputs=input_files(args.sweep))
    output_format(args.output, "-o", TABLE_FORMATS)
    output_format(args.plot, "--plot", PLOT_FORMATS)
    with _sigterm_raises():
        t0 = time.perf_counter()
        res = sweep(args.sweep, workers=args.workers, scheduler=args.scheduler, progress=None,
                    add_measure=args.measure, scheduler_timeout=timeout, dashboard=dashboard)
        write(res, args.output, args.plot, args.measure)
    failed = int((~res.ok).sum())
    print(f"{res.source}: {len(res.status)} points ({failed} failed), model {res.model}, "
          f"{time.perf_counter() - t0:.2f} s -> {args.output}", file=sys.stdout)
    return 0


class _sigterm_raises:
    """Within the ``with`` body (main thread only), SIGTERM raises :class:`Terminated` where
    Ctrl-C would raise KeyboardInterrupt, once: a second SIGTERM during the clean-up is ignored
    (the workers die with this process in any case). The previous handler is restored after."""

    def __enter__(self):
        import signal
        import threading

        self.old = None
        if (threading.current_thread() is threading.main_thread()
                and signal.getsignal(signal.SIGTERM) is not signal.SIG_IGN):  # kept ignored
            self.old = signal.signal(signal.SIGTERM, self._raise)
        return self

    @staticmethod
    def _raise(signum, frame):
        import signal

        from derive.errors import Terminated

        signal.signal(signal.SIGTERM, signal.SIG_IGN)
        raise Terminated()

    def __exit__(self, *exc):
        import signal

        if self.old is not None:
            signal.signal(signal.SIGTERM, self.old)
