"""The targets for user terms (``[[potential]]``, ``[[torque]]``), measured in `derive bench`.

* ``own_first_run``: seconds of the first ``derive.simulate`` of a new user body (derive with
  SymPy, generate, compile, run) in a fresh process with an empty ``DERIVE_CACHE``; goal ≤ 3 s.
* ``own_gravity_vs_gravity``: a potential restating gravity (``V = "M*g*l*R33"``) against
  ``[gravity]``, the same formulation and method: time per prepared run (``derive.prepare``),
  restated / built-in; goal ≤ 1.1. The largest difference of the axes is reported beside it.
* ``own_warm_vs_shipped``: warm ``derive.simulate`` of the restated body (a model from the
  compile cache) / of the shipped heavy top (``generated/``); goal ≤ 1.2.
"""
from __future__ import annotations

import json
import os
import tempfile
import timeit

import numpy as np
import derive
from derive.bench import timing

#: The body of the measurements: a symmetric top at 1 rad, spinning, for 20 s.
BASE = {
    "body": {"I1": 1.0, "I3": 0.5},
    "initial": {"alpha": 0.0, "beta": 1.0, "gamma": 0.0, "alpha_dot": 0.3, "beta_dot": 0.0,
                "gamma_dot": 4.0},
    "simulate": {"t_end": 20.0, "samples": 1001},
}
GRAVITY = {"M": 1.0, "g": 9.81, "l": 0.1}


def scenes() -> tuple[dict, dict, dict]:
    """(the [gravity] top, the same top with gravity restated as a potential, a new user body:
    a dipole in a horizontal field with a drive torque)."""
    gravity = {**BASE, "gravity": dict(GRAVITY)}
    restated = {**BASE, "potential": [{"name": "gravity", "V": "M*g*l*R33",
                                       "params": dict(GRAVITY)}]}
    new = {**BASE, "potential": [{"name": "magnet", "V": "-mu*B*R13 + k*R33**2",
                                  "params": {"mu": 0.2, "B": 1.5, "k": 0.05}}],
           "torque": [{"name": "drive", "tau": ["0", "0", "A*cos(w*t)"],
                       "params": {"A": 0.01, "w": 3.0}}]}
    return gravity, restated, new


def bench_own_body(repeats: int = 5, number: int = 20) -> dict:
    """The three measurements of the module docstring."""
    gravity, restated, new = scenes()
    out = {}
    with tempfile.TemporaryDirectory(prefix="derive-bench-own-") as tmp:
        run = timing.fresh(timing.FIRST_CALL_SCRIPT, json.dumps(new), dict(os.environ, DERIVE_CACHE=tmp), tmp)
        if "error" in run:
            out["first_run_error"] = run["error"]
        else:
            out["first_run"] = run["first_simulate"]
    pg, pr = derive.prepare(gravity), derive.prepare(restated)
    a, b = pg.run(), pr.run()
    out["formulation"] = a.formulation
    out["same_formulation"] = a.formulation == b.formulation
    out["max_axis_difference"] = float(np.max(np.abs(a.axis - b.axis)))

    def per_call(fn):  # the best of ``repeats`` means over ``number`` calls
        return min(timeit.repeat(fn, number=number, repeat=repeats)) / number

    t_g, t_r = per_call(pg.run), per_call(pr.run)
    out["prepared_gravity_s"], out["prepared_restated_s"] = t_g, t_r
    out["gravity_ratio"] = t_r / t_g
    s_g, s_r = per_call(lambda: derive.simulate(gravity)), per_call(lambda: derive.simulate(restated))
    out["simulate_shipped_s"], out["simulate_restated_s"] = s_g, s_r
    out["warm_ratio"] = s_r / s_g
    return out
