"""Timing primitives of the bench: the median of repeats, the cost per call, and calls of
several functions interleaved in blocks (so that a machine's drifting load falls on all alike), and
a script timed in a fresh process.

Takes: callables, or a script. Gives: seconds.
"""
from __future__ import annotations

import json
import math
import statistics
import subprocess
import sys
import time


def timed(fn, repeats: int, long_run: float = math.inf, min_total: float = 0.0):
    """(median wall time, last result) of at least ``repeats`` calls, more (up to 100) until
    they add up to ``min_total`` seconds; a single call if the first took over ``long_run``."""
    times, out = [], None
    while len(times) < max(1, repeats) or (sum(times) < min_total and len(times) < 100):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
        if times[0] > long_run:
            break
    return statistics.median(times), out


def per_call(fn, calls: int, blocks: int = 7) -> float:
    """Median over ``blocks`` blocks of the mean time of one call (s)."""
    return interleaved([fn], calls, blocks)[0]


def best_in_turns(fns: dict, rounds: int) -> dict:
    """{name: the best of ``rounds`` timings of one call of ``fns[name]``}, the functions called
    in turns each round (a change of machine load hits them alike): for calls long enough to
    time one at a time (a whole batch)."""
    best = {k: math.inf for k in fns}
    for _ in range(rounds):
        for key, fn in fns.items():
            t0 = time.perf_counter()
            fn()
            best[key] = min(best[key], time.perf_counter() - t0)
    return best


def interleaved(fns, calls: int, blocks: int = 15, counts=None) -> list[float]:
    """Per-call time of each function (s): blocks of ``calls // blocks`` calls (or ``counts[i]``
    calls of function i: a fast one many times, a slow one once), the functions taking turns
    block by block (so a change of machine load hits all alike), median per function."""
    ns = list(counts) if counts is not None else [max(1, calls // blocks)] * len(fns)
    for fn in fns:
        fn()
    out = [[] for _ in fns]
    for _ in range(blocks):
        for i, fn in enumerate(fns):
            t0 = time.perf_counter()
            for _ in range(ns[i]):
                fn()
            out[i].append((time.perf_counter() - t0) / ns[i])
    return [statistics.median(x) for x in out]


def block_counts(fns, budget: float = 0.02, most: int = 10_000) -> list[int]:
    """Calls per block for each function of :func:`interleaved`, so that each block takes about
    ``budget`` seconds (one warm call, then one timed)."""
    out = []
    for fn in fns:
        fn()
        t0 = time.perf_counter()
        fn()
        out.append(max(1, min(most, int(budget / max(time.perf_counter() - t0, 1e-7)))))
    return out


#: A fresh process's first and second ``derive.simulate`` (``import derive`` timed apart).
FIRST_CALL_SCRIPT = r"""
import json, sys, time
t0 = time.perf_counter()
import derive
t1 = time.perf_counter()
arg = sys.argv[1]
scene = json.loads(arg) if arg.startswith("{") else arg
derive.simulate(scene)
t2 = time.perf_counter()
derive.simulate(scene)
t3 = time.perf_counter()
print(json.dumps({"import": t1 - t0, "first_simulate": t2 - t1, "second_simulate": t3 - t2}))
"""


def fresh(script: str, arg: str, env: dict, cwd: str) -> dict:
    """The JSON line ``python -c script arg`` prints last (in ``cwd`` with ``env``), or
    ``{"error": its last line of stderr}``."""
    out = subprocess.run([sys.executable, "-c", script, arg], capture_output=True, text=True, env=env, cwd=cwd)
    if out.returncode != 0:
        return {"error": (out.stderr.strip().splitlines() or ["?"])[-1][:200]}
    return json.loads(out.stdout.strip().splitlines()[-1])
