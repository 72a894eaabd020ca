"""Every point of a sweep as numbers: the init map's inputs and each candidate model's parameters,
(N, …) arrays built from the base scene and the varied columns, without a scene per point. The
initial ω̃ from varied Euler-angle rates is the scene validator's own map
(:func:`derive.sim.scene.body_omega`, the same libm calls elementwise); a point whose moments
violate the triangle inequality is recorded, not run.

Takes: a :class:`derive.sweeps.spec.Spec` with its columns. Gives: the spec's arrays, model and
method (:func:`build`).
"""
from __future__ import annotations

import numpy as np

from derive.errors import SceneError
from derive.methods.registry import DEFAULT_METHOD, compiled_methods, measure_window
from derive.runtime import catalogue
from derive.sim.inputs import AUTO, choose_method, inputs_of
from derive.sim.plan import auto_method
from derive.sim.scene import TRIANGLE_SLACK, body_omega, load_scene
from derive.sweeps.keys import term_key, variable_keys as _variable_keys
from derive.sweeps.plan import measuring_methods, sweep_plan
from derive.symbolic import effects
from derive.symbolic.formulations import REGISTRY as FORMS


def _fail(source, key, what):
    raise SceneError(f"{source}: {key}: {what}")


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
    set_entry(data, _variable_keys()[key], value)


def set_entry(data: dict, where: tuple, value) -> None:
    """Set ``data[table][name]`` (``index`` None) or its component ``index``, where ``where`` is
    a keys registry's ``(table, name, index, ...)``; the table and the list are changed copies."""
    table, name, index = where[:3]
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


def _runnable(n: int, invalid) -> np.ndarray:
    """The indices 0..n-1 not in ``invalid`` (the points that are run), in order."""
    keep = np.ones(n, dtype=bool)
    keep[np.fromiter(invalid, int, len(invalid))] = False
    return np.flatnonzero(keep)


def build(spec) -> None:
    """Fill ``spec`` (a :class:`derive.sweeps.spec.Spec`): inputs (N, NIN), ps (N, NP), the invalid
    points, the model and the method."""
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
    alpha, beta, gamma = (col("initial", k, getattr(base.initial, k)) for k in ("alpha", "beta", "gamma"))
    inputs[:, 0], inputs[:, 1], inputs[:, 2] = alpha, beta, gamma
    if base.initial.has_rates:
        ad, bd, gd = (col("initial", k, getattr(base.initial, k)) for k in ("alpha_dot", "beta_dot", "gamma_dot"))
        inputs[:, 6], inputs[:, 7], inputs[:, 8] = ad, bd, gd
        if any(k in cols for k in ("initial.beta", "initial.gamma", "initial.alpha_dot",
                                   "initial.beta_dot", "initial.gamma_dot")):
            # the scene validator's map, elementwise (the same libm calls, the same numbers)
            inputs[:, 3:6] = np.column_stack(body_omega(beta, gamma, ad, bd, gd))
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


def _params(desc, values: dict, n: int) -> np.ndarray:
    """(N, NP) parameters of the model ``desc`` from the named columns ``values`` (the ones its
    init map derives, such as reduced-u's p_alpha, p_gamma, E', are left 0 for C to fill)."""
    derived = set(desc.derived_params)
    ps = np.zeros((n, len(desc.params)))
    for k, name in enumerate(desc.params):
        if k not in derived:
            ps[:, k] = values[name]
    return ps
