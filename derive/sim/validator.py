"""The validator: a raw scene dict (as TOML gives it, or from Python) to a :class:`Scene`, the first
problem in document order raised as one line ``<file>: <key>: <what is wrong>`` (the rules:
:mod:`derive.sim.scene`).

Takes: a dict and the ``[simulate]`` overrides. Gives: a :class:`~derive.sim.scene_types.Scene`.
"""
from __future__ import annotations

import dataclasses
import difflib
import math
import numbers
from collections.abc import Mapping

import numpy as np

from derive.errors import scene_error
from derive.methods import registry as solvers
from derive.reference.rotation import body_omega
from derive.sim.scene_types import (FIXED_STEP_METHODS, FORMULATIONS, MAX_SAMPLES, MAX_STEPS_LIMIT, METHODS,
                                    MIN_RTOL, SIMULATE_DEFAULTS, TRIANGLE_SLACK, Body, Initial, Scene,
                                    Simulate, TableValues)
from derive.symbolic import effects
from derive.symbolic import formulations
from derive.symbolic import terms as user_terms
from derive.symbolic.expressions import ExpressionError, parse as parse_expression


_RATES = ("alpha_dot", "beta_dot", "gamma_dot")


_FIXED_KEYS = {  # table -> its keys, in the order they are documented
    "body": ("I1", "I2", "I3"),
    "initial": ("alpha", "beta", "gamma", *_RATES, "omega"),
    "simulate": ("t_end", "samples", "method", "rtol", "atol", "formulation", "h", "max_steps"),
}


def _table_keys() -> dict[str, tuple[str, ...]]:
    """Every table's keys in documented order: body, the effects' tables (from the registry),
    initial, simulate."""
    keys = {"body": _FIXED_KEYS["body"]}
    keys.update({name: tuple(k.name for k in t.keys) for name, t in effects.TABLES.items()})
    keys.update(initial=_FIXED_KEYS["initial"], simulate=_FIXED_KEYS["simulate"])
    return keys


_TOP_KEYS = ("title",)


#: Longest value shown in an error line (a huge string or list is cut, so the line stays short).
SHOW_LIMIT = 80


def _show(value) -> str:
    """A value as the user wrote it (TOML spelling for booleans, tables and strings), at most
    about ``SHOW_LIMIT`` characters."""
    text = _show_full(value)
    return text if len(text) <= SHOW_LIMIT else text[:SHOW_LIMIT - 20] + f"... ({len(text)} characters)"


def _show_full(value, depth: int = 0) -> str:
    if depth > 8:  # a list nested a thousand deep (a dict from Python) would exhaust the stack
        return "..."
    if isinstance(value, np.ndarray):
        if value.ndim == 0:
            return f"a 0-d array ({_show_full(value.item(), depth + 1)})"
        if value.ndim == 1 and value.size <= 8:
            return _show_full(value.tolist(), depth + 1)
        return f"an array of shape {value.shape}"
    if value is None:  # a masked array item, or None from Python
        return "None"
    if isinstance(value, (bool, np.bool_)):
        return f"{str(bool(value)).lower()} (a boolean)"
    if isinstance(value, str):
        if len(value) > SHOW_LIMIT:
            return f"{value[:SHOW_LIMIT // 2]!r}... (a string of {len(value)} characters)"
        return f"{value!r} (a string)"
    if isinstance(value, Mapping):
        return "a table"
    if isinstance(value, float):
        return repr(float(value))
    if isinstance(value, numbers.Real):
        text = str(value)
        return text if len(text) <= 24 else f"{text[:8]}... (an integer of {len(text)} digits)"
    if isinstance(value, (list, tuple)):
        if len(value) > 8:
            return f"a list of {len(value)} items"
        return "[" + ", ".join(_show_full(v, depth + 1) for v in value) + "]"
    name = type(value).__name__
    return f"{'an' if name[:1].lower() in 'aeiou' else 'a'} {name}"


def _real(value) -> float | None:
    """value as a finite float, or None. Booleans are not numbers; ints are welcome."""
    if type(value) is float:
        return value if math.isfinite(value) else None
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        return None
    try:
        x = float(value)
    except OverflowError:  # an integer beyond the float range
        return None
    return x if math.isfinite(x) else None


def _vector3(value) -> list[float] | None:
    """``value`` as three finite floats, or None.

    Accepted: a list or tuple of three reals (what TOML gives) or a NumPy array of shape (3,)
    whose items are reals. Everything else is None, never an exception: a 0-d array or a NumPy
    scalar (``len()`` of either raises TypeError), an array of another shape ((1, 3), (3, 1),
    (3, 3)), a ragged list ([[1, 2], 3, 4]), a string (a sequence, but of characters), booleans
    or non-finite items, a masked item (``tolist()`` makes it None).
    """
    if isinstance(value, np.ndarray):
        if value.shape != (3,):
            return None
        value = value.tolist()  # Python scalars; a masked item becomes None
    elif not isinstance(value, (list, tuple)) or len(value) != 3:
        return None
    vec = [_real(w) for w in value]
    return None if None in vec else vec


def _unknown(key: str, valid: tuple[str, ...], where: str, expected: str = "") -> str:
    """The text in 'unknown key (...)': a likely fix (the table the key belongs in, or a close
    spelling of a valid key), then what was expected."""
    hint = ""
    home = [t for t, keys in _table_keys().items() if key in keys and t != where]
    close = [k for k in valid if k.lower() == str(key).lower()]
    close = close or difflib.get_close_matches(str(key), valid, n=1, cutoff=0.6)
    if home:
        hint = f"{key} belongs in [{home[0]}]; "
    elif close:
        hint = f"did you mean {close[0]}? "
    return hint + (expected or f"expected one of {', '.join(valid)}")


def _positive(x) -> bool:
    return x > 0


def _below_one(x) -> bool:
    return 0 < x < 1


_POSITIVE = "a positive finite number"


#: The triangle inequalities of the principal moments, (a, b, c): Ia + Ib >= Ic, checked (and
#: reported) for c = I3, I1, I2 in this order.
_TRIANGLE = ((0, 1, 2), (1, 2, 0), (0, 2, 1))


class _Validator:
    """Turns the raw dict into a Scene, raising SceneError at the first problem.

    The keys come from the registries (:func:`_table_keys`); messages are built only when
    something fails.
    """

    def __init__(self, source: str):
        self.source = source
        self.overridden: set[str] = set()  # dotted keys whose value came from an override

    def fail(self, key: str, what: str):
        if key in self.overridden:
            what += " (given as an override)"
        raise scene_error(self.source, key, what)

    # ---- generic readers ----

    def table(self, data: Mapping, name: str) -> Mapping:
        """The table ``name`` after checking it has only known keys; the first unknown one in
        document order is reported."""
        keys = _table_keys()[name]
        for key in data:
            if key not in keys:
                self.fail(f"{name}.{key}", "unknown key (" + _unknown(key, keys, name) + ")")
        return data

    def number(self, data, table, key, test=None, must="a finite number", default=...):
        """A finite real (int or float, not bool) satisfying ``test``, or ``default`` if absent
        (``...`` = required)."""
        if key not in data:
            if default is ...:
                self.fail(f"{table}.{key}", "missing required key")
            return default
        value = data[key]
        x = _real(value)
        if x is None or (test is not None and not test(x)):
            self.fail(f"{table}.{key}", f"must be {must}, got {_show(value)}")
        return x

    def choice(self, data, table, key, choices):
        """A string among ``choices`` (a dict or tuple of names; messages list them in order)."""
        value = data[key]
        if type(value) is str and value in choices:
            return value
        dotted = f"{table}.{key}"
        if not isinstance(value, str):
            self.fail(dotted, f"must be a string, one of {', '.join(choices)}; got {_show(value)}")
        if value not in choices:
            close = difflib.get_close_matches(value, list(choices), n=1, cutoff=0.6)
            hint = f"did you mean {close[0]}? " if close else ""
            self.fail(dotted, f"unknown {key} {value!r} ({hint}expected one of {', '.join(choices)})")
        return value

    # ---- the tables ----

    def scene(self, data: Mapping, overrides: dict) -> Scene:
        tables = _table_keys()
        for key, value in data.items():
            if key in _TOP_KEYS or key in user_terms.KINDS:
                continue
            if key not in tables:
                if isinstance(value, Mapping):
                    self.fail(str(key), "unknown table (" + _unknown(key, tuple(tables), "")
                              + ")")
                self.fail(str(key), "unknown key (" + _unknown(
                    key, _TOP_KEYS, "", "the only top-level key is title") + ")")
            if type(value) is not dict and not isinstance(value, Mapping):  # dict: no ABC check
                self.fail(key, f"must be a table [{key}], got {_show(value)}")
        title = data.get("title")
        if title is not None and not isinstance(title, str):
            self.fail("title", f"must be a string, got {_show(title)}")
        # Tables in document order, so the first problem reported is the first one in the file.
        if "body" not in data:
            self.fail("body", "missing required table")
        body = self.body(self.table(data["body"], "body"))
        tables = {name: self.effect_table(self.table(data[name], name), table)
                  for name, table in effects.TABLES.items() if name in data}
        terms = self.terms(data)
        if "initial" not in data:
            self.fail("initial", "missing required table")
        initial = self.initial(self.table(data["initial"], "initial"))

        if overrides:
            for key in overrides:
                if key not in _FIXED_KEYS["simulate"]:
                    self.overridden.add(f"simulate.{key}")
                    self.fail(f"simulate.{key}", "unknown key (" + _unknown(
                        key, _FIXED_KEYS["simulate"], "simulate") + ")")
        if "simulate" not in data and "t_end" not in overrides:
            self.fail("simulate", "missing required table (simulate.t_end has no default)")
        simulate = self.table(data.get("simulate", {}), "simulate")
        if overrides:
            self.overridden.update(f"simulate.{key}" for key in overrides)
            simulate = {**simulate, **overrides}
        simulate = self.simulate(simulate)

        scene = Scene(title=title, body=body, tables=tables, initial=initial, simulate=simulate,
                      source=self.source, terms=terms)
        self.formulation_fits(scene)
        return scene

    def with_initial(self, data: Mapping, like: Scene) -> Scene:
        """The scene of ``data``, a dict whose model part is that of the dict ``like`` was
        validated from (:func:`same_model_part`): its ``[initial]`` table read, everything else
        ``like``'s (valid: the first problem of ``data`` can only be in its initial state)."""
        if "initial" not in data:
            self.fail("initial", "missing required table")
        initial = self.initial(self.table(data["initial"], "initial"))
        scene = dataclasses.replace(like, initial=initial, source=self.source)
        scene.__dict__["effects"] = like.effects  # (its tables and terms are like's)
        self.formulation_fits(scene)
        return scene

    def body(self, t) -> Body:
        I1 = self.number(t, "body", "I1", _positive, _POSITIVE)
        I2 = self.number(t, "body", "I2", _positive, _POSITIVE, I1)  # symmetric unless told
        I3 = self.number(t, "body", "I3", _positive, _POSITIVE)
        # Principal moments of any mass distribution obey Ia + Ib >= Ic (equality: a flat plate).
        moments, slack = (I1, I2, I3), 1 - TRIANGLE_SLACK
        for a, b, c in _TRIANGLE:
            if moments[a] + moments[b] < moments[c] * slack:
                names = ("I1", "I2", "I3")
                values = ", ".join(f"{k} = {v:g}" for k, v in zip(names, moments))
                self.fail("body", f"moments violate the triangle inequality {names[a]} + "
                                  f"{names[b]} >= {names[c]} ({values}); no rigid body has these "
                                  f"principal moments")
        return Body(I1=I1, I2=I2, I3=I3)

    def effect_table(self, t, table: effects.Table) -> TableValues:
        """An effect's table, read by its declaration: each key a finite real (or a list of 3)
        passing its check; of each ``one_of`` group exactly one key given."""
        for group in table.one_of:
            given = [k for k in group if k in t]
            if len(given) > 1:
                self.fail(f"{table.name}.{given[1]}",
                          f"give {' or '.join(group)}, not both ({', '.join(given)} given)")
            if not given:
                self.fail(f"{table.name}.{group[0]}",
                          f"missing required key (give {' or '.join(group)})")
        values = {}
        for key in table.keys:
            if key.kind == "vector3":
                values[key.name] = self.vector3(t, table.name, key)
            else:
                default = ... if key.default is effects.REQUIRED else key.default
                values[key.name] = self.number(t, table.name, key.name, key.check, key.must, default)
        values = table.complete(values)
        out = TableValues(table.name, values, effects.for_table(table.name, values).name)
        given = set(t)
        for group in table.one_of:
            # One spelling per meaning: of a one-of group the first key the completed values
            # fill is the one the scene keeps (gravity's com = [0, 0, l] is written back as l).
            given.difference_update(group)
            given.add(next((k for k in group if values.get(k) is not None), group[0]))
        out.__dict__["_given"] = given
        return out

    def terms(self, data: Mapping) -> tuple:
        """The user's ``[[potential]]`` and ``[[torque]]`` terms (:mod:`derive.symbolic.terms`),
        each registered as an effect keyed by its content. Keys are reported as
        ``potential.<name>.V``, ``torque.<name>.tau.<i>``, ``potential.<name>.params.<p>``
        (``potential[<i>]`` before a name is known)."""
        out = []
        seen_content: dict = {}
        for kind in user_terms.KINDS:
            if kind not in data:
                continue
            entries = data[kind]
            if isinstance(entries, Mapping):
                self.fail(kind, f"must be an array of tables [[{kind}]] (one per term), "
                                f"got a single table [{kind}]")
            if not isinstance(entries, (list, tuple)):
                self.fail(kind, f"must be an array of tables [[{kind}]], got {_show(entries)}")
            if len(entries) > user_terms.MAX_TERMS:
                self.fail(kind, f"at most {user_terms.MAX_TERMS} terms, got {len(entries)}")
            names = set()
            for i, entry in enumerate(entries):
                term = self.term(kind, i, entry, names)
                content = term.content
                k = seen_content.get(content, 0)
                seen_content[content] = k + 1
                if k:
                    term = dataclasses.replace(term, occurrence=k)
                try:
                    user_terms.register(term)
                except ExpressionError as exc:  # pragma: no cover - parse() checked it already
                    self.fail(f"{kind}.{term.name}", str(exc))
                out.append(term)
        return tuple(out)

    def term(self, kind: str, i: int, t, names: set):
        """One user term: its table's keys, name, expressions (whitelisted) and params."""
        where = f"{kind}[{i}]"
        if not isinstance(t, Mapping):
            self.fail(where, f"must be a table (name = ..., {'V' if kind == 'potential' else 'tau'}"
                             f" = ..., params = {{...}}), got {_show(t)}")
        keys = ("name", "V", "params") if kind == "potential" else ("name", "frame", "tau", "params")
        name = t.get("name")
        if "name" not in t:
            self.fail(f"{where}.name", "missing required key (letters, digits and _)")
        if not isinstance(name, str) or not user_terms.NAME_PATTERN.fullmatch(name):
            self.fail(f"{where}.name", f"must be a name of letters, digits and _ (starting with a "
                                       f"letter, at most 32 characters), got {_show(name)}")
        if name in names:
            self.fail(f"{kind}.{name}", f"name given twice: each [[{kind}]] needs its own name")
        names.add(name)
        where = f"{kind}.{name}"
        for key in t:
            if key not in keys:
                self.fail(f"{where}.{key}", "unknown key (" + _unknown(
                    key, keys, "", f"the keys of [[{kind}]]: {', '.join(keys)}") + ")")
        raw_params = t.get("params", {})
        if not isinstance(raw_params, Mapping):
            self.fail(f"{where}.params", f"must be a table {{ name = number, ... }}, "
                                         f"got {_show(raw_params)}")
        if len(raw_params) > user_terms.MAX_PARAMS:
            self.fail(f"{where}.params", f"at most {user_terms.MAX_PARAMS} params, "
                                         f"got {len(raw_params)}")
        params = []
        for p, v in raw_params.items():
            if not isinstance(p, str) or not user_terms.NAME_PATTERN.fullmatch(p):
                self.fail(f"{where}.params", f"{_show(p)} is not a param name (letters, digits "
                                             f"and _, starting with a letter)")
            if p in user_terms.RESERVED:
                self.fail(f"{where}.params.{p}", f"{p!r} is a name expressions use already "
                                                 f"(R11 ... R33, alpha, beta, gamma, omega1..3, "
                                                 f"t, pi, the functions); choose another")
            x = _real(v)
            if x is None:
                self.fail(f"{where}.params.{p}", f"must be a finite number, got {_show(v)}")
            params.append((p, x))
        allowed = user_terms.names_for(kind, [p for p, _ in params])
        if kind == "potential":
            if "V" not in t:
                self.fail(f"{where}.V", "missing required key (the potential, J, an expression)")
            exprs = ((f"{where}.V", t["V"]),)
            frame = ""
        else:
            frame = t.get("frame", "body")
            if frame not in user_terms.FRAMES:
                self.fail(f"{where}.frame", f"must be \"body\" or \"inertial\", got {_show(frame)}")
            if "tau" not in t:
                self.fail(f"{where}.tau", "missing required key (three expressions, N m)")
            tau = t["tau"]
            if not isinstance(tau, (list, tuple)) or len(tau) != 3:
                self.fail(f"{where}.tau", f"must be a list of 3 expressions (strings), "
                                          f"got {_show(tau)}")
            exprs = tuple((f"{where}.tau.{k}", e) for k, e in enumerate(tau))
        for key, text in exprs:
            try:
                parse_expression(text, allowed)
            except ExpressionError as exc:
                self.fail(key, str(exc))
        return user_terms.Term(kind, name, tuple(e for _, e in exprs), frame, tuple(params))

    def vector3(self, t, table: str, key: effects.Key):
        if key.name not in t:
            if key.default is effects.REQUIRED:
                self.fail(f"{table}.{key.name}", "missing required key")
            return key.default
        value = t[key.name]
        vec = _vector3(value)
        if vec is None or (key.check is not None and not key.check(tuple(vec))):
            self.fail(f"{table}.{key.name}", f"must be {key.must}, got {_show(value)}")
        return tuple(vec)

    def initial(self, t) -> Initial:
        alpha, beta, gamma = (self.number(t, "initial", k, None, "a finite number (rad)")
                              for k in ("alpha", "beta", "gamma"))
        rates_given = any(k in t for k in _RATES)
        both = "give either the Euler-angle rates (alpha_dot, beta_dot, gamma_dot) or omega"
        if rates_given and "omega" in t:
            self.fail("initial", both + ", not both")
        if rates_given:
            # Missing rates are 0: a scene released at a turning point need not say beta_dot = 0.
            ad, bd, gd = (self.number(t, "initial", k, None, "a finite number (rad/s)", 0.0) for k in _RATES)
            return Initial(alpha=alpha, beta=beta, gamma=gamma, alpha_dot=ad, beta_dot=bd,
                        gamma_dot=gd, omega=body_omega(beta, gamma, ad, bd, gd))
        if "omega" not in t:
            self.fail("initial", both + " = [w1, w2, w3] (body frame, rad/s); got neither")
        value = t["omega"]
        omega = _vector3(value)
        if omega is None:
            self.fail("initial.omega", f"must be a list of 3 finite numbers [w1, w2, w3] "
                                       f"(body frame, rad/s), got {_show(value)}")
        return Initial(alpha=alpha, beta=beta, gamma=gamma, alpha_dot=None, beta_dot=None,
                    gamma_dot=None, omega=tuple(omega))

    def simulate(self, t) -> Simulate:
        s = {**SIMULATE_DEFAULTS, **t}
        t_end = self.number(t, "simulate", "t_end", _positive, "a positive finite number (s)")
        samples = self.integer(s, "samples", 2, MAX_SAMPLES, f"{MAX_SAMPLES}")
        method = self.choice(s, "simulate", "method", METHODS)
        rtol = self.number(s, "simulate", "rtol", _below_one, "a number in (0, 1)")
        if rtol < MIN_RTOL:
            self.fail("simulate.rtol", f"must be at least 100 machine epsilons ({MIN_RTOL:.1e}): "
                                       f"no double-precision integrator can meet {rtol:g}")
        atol = self.number(s, "simulate", "atol", _positive, _POSITIVE)
        formulation = self.choice(s, "simulate", "formulation", FORMULATIONS)
        max_steps = self.integer(s, "max_steps", 1, MAX_STEPS_LIMIT, f"{MAX_STEPS_LIMIT:.0e}")
        h = None
        if s["h"] is not None:
            h = self.number(s, "simulate", "h", _positive, "a positive finite number (s)")
            if method not in FIXED_STEP_METHODS:
                self.fail("simulate.h", f"is the step of a fixed-step method "
                                        f"({', '.join(FIXED_STEP_METHODS)}), but method is "
                                        f"{method!r}; remove h or name a fixed-step method")
        return Simulate(t_end=t_end, samples=samples, method=method, rtol=rtol,
                    atol=atol, formulation=formulation, h=h, max_steps=max_steps)

    def integer(self, s, key, lo, hi, shown) -> int:
        """``simulate.<key>``: an integer (not a boolean) from ``lo`` to ``hi``."""
        value = s[key]
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral) \
                or not lo <= value <= hi:
            self.fail(f"simulate.{key}", f"must be an integer from {lo} to {shown}, got {_show(value)}")
        return int(value)

    def formulation_fits(self, scene: Scene) -> None:
        """Reject a formulation that cannot represent this scene (the registry says why)."""
        form = scene.simulate.formulation
        if form != "auto":
            reason = formulations.REGISTRY[form].applicable(scene)
            if reason:
                self.fail("simulate.formulation", reason)
        reason = solvers.method_reason(scene.simulate.method, form, scene.effects)
        if reason:
            self.fail("simulate.method", reason)


def same_model_part(a, b) -> bool:
    """Whether two scene dicts are equal but for their ``[initial]`` table: each other table
    the same object, or the same text (``repr`` tells ``1``, ``1.0`` and ``True`` apart, and
    ``-0.0`` from ``0.0``). Then the scene validated from one has the other's body, effect
    tables, terms, settings and title, and so its model and plan (:meth:`_Validator.with_initial`)."""
    if type(a) is not dict or type(b) is not dict or a.keys() != b.keys():
        return False
    return all(k == "initial" or a[k] is b[k] or repr(a[k]) == repr(b[k]) for k in a)
