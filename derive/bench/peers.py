"""The races against the two peers a user can ``pip install`` that beat derive: heyoka
(LLVM-compiled Taylor method of adaptive order) and numbalsoda (Hairer's DOP853 in C++ on a
numba ``cfunc`` right-hand side), each raced when it imports (:mod:`derive.bench.contenders`).

Every race runs the reference scene (``scenes/reference_top.toml``, Euler angles for the
contenders, the equations of ``derive/bench/baselines/scipy_baselines.py``) and measures the
error as the bench always does: max over the output times of |ê₃ − ê₃,exact| against
`derive.reference.exact`. "At equal error ε": each side at the loosest tolerance (halved or
doubled from ε, :func:`derive.bench.runner.match_tolerance`) whose error is ≤ ε, then the two
calls timed in turns (blocks of calls alternating, median per side), so a change of machine
load hits both alike. Ratios are derive's time over the peer's (the goals are ≤).

* :func:`equal_error` — t ∈ [0, t_end], 1001 samples, at each error level: ``derive.simulate``
  (the public call, validation included) and ``derive.prepare(...).run()`` (the prepared call)
  against heyoka's ``propagate_grid`` (integrator built and JIT-compiled outside the timing,
  reset to t₀, y₀ per call) and numbalsoda's ``dop853`` at the same output times. Used twice:
  the reference run (t_end = 10) and the long run (t_end = 1000).
* :func:`batch` — N variants of the reference scene: ``derive.simulate_batch`` (every output at
  every sample, and ``outputs="final"``: the last sample only) against heyoka's batch mode
  (``taylor_adaptive_batch``, one trajectory per SIMD lane, lanes = heyoka's recommended SIMD
  size): ``propagate_grid`` over the output times (the states at every sample), and
  ``propagate_until`` t_end (the final state only); heyoka at the tolerance that matched
  derive's error on the reference scene. When the scenes' method is not Taylor, the Taylor
  method's ``outputs="final"`` batch too (its lanes driver), against heyoka's final states at
  the error the Taylor method makes there.
* :func:`fixed_cost` — t_end = 1e-3, 2 samples, rtol 1e-10: ``derive.prepare(scene).run()``
  and ``derive.simulate(dict)`` (the same scene again, and a scene with new numbers each call)
  against heyoka's reset + ``propagate_grid`` of the same two times (and numbalsoda's
  ``dop853``).
"""
from __future__ import annotations

import itertools
import warnings

import numpy as np

from derive.bench import contenders as bc
from derive.bench import runner as B
from derive.bench import timing
from derive.bench.reference import reference_data
import derive

#: The peers and the contender method each runs.
PEERS = {"heyoka": "heyoka-taylor", "numbalsoda": "numbalsoda-dop853"}


def _derive_error(data: dict, ref: np.ndarray, rtol: float):
    """(axis error, nfev) of ``derive.simulate`` at ``rtol`` (atol = ATOL_RATIO rtol)."""
    axis, nfev = B.ours(data, rtol=rtol, atol=B.ATOL_RATIO * rtol)
    return B.axis_error(axis, ref), nfev


def equal_error(cfg, fams: list[str], t_end: float, levels) -> dict:
    """derive against each installed peer at equal error on the reference scene over
    [0, ``t_end``] (1001 samples), at each error level of ``levels``."""
    data = reference_data(t_end)
    t = np.linspace(0.0, t_end, data["simulate"]["samples"])
    ref = B.exact_axis(data, t)
    prob = bc.problem(data, "euler-angles", "reference")
    peers = [f for f in PEERS if f in fams]
    rows = []
    for level in levels:
        ours = B.match_tolerance(lambda r: _derive_error(data, ref, r), level, level)
        row = {"level": level, "derive": ours, "peers": {}}
        if not ours["reached"]:
            rows.append(row)
            continue
        r = ours["rtol"]
        tuned = dict(data, simulate=dict(data["simulate"], rtol=r, atol=B.ATOL_RATIO * r))
        prepared = derive.prepare(tuned)
        ran = prepared.run()
        ours.update(method=ran.method, formulation=ran.formulation)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sim = lambda: derive.simulate(tuned)  # noqa: E731
            run = prepared.run
            for fam in peers:
                m = B.match_tolerance(lambda x, fam=fam: B.contender_error(fam, PEERS[fam], prob, ref, x),
                                      level, level)
                entry = dict(m)
                if m["reached"]:
                    theirs = B.contender_call(fam, PEERS[fam], prob, m["rtol"])
                    # the peer's call and then the axis from its states (NumPy): what its user
                    # computes to get the quantity both sides are judged on (derive's call
                    # returns the axis among its outputs)
                    with_axis = lambda theirs=theirs: prob.axis(theirs()[0])  # noqa: E731
                    fns = [theirs, sim, run, with_axis]
                    (entry["time"], entry["derive_simulate"], entry["derive_prepared"],
                     entry["time_with_axis"]) = timing.interleaved(
                        fns, 0, blocks=max(3, cfg.ref_repeats), counts=timing.block_counts(fns))
                    entry["ratio_simulate"] = entry["derive_simulate"] / entry["time"]
                    entry["ratio_prepared"] = entry["derive_prepared"] / entry["time"]
                    entry["ratio_prepared_with_axis"] = entry["derive_prepared"] / entry["time_with_axis"]
                row["peers"][fam] = entry
        rows.append(row)
    return {"t_end": t_end, "samples": len(t), "rows": rows, "peers": peers}


def _lanes(Y0: np.ndarray, P: np.ndarray, width: int):
    """Chunks of ``width`` trajectories, the last padded with copies of its last one: ((ny,
    width) states, (np, width) constants, how many are real)."""
    out = []
    for s in range(0, len(Y0), width):
        y, p = Y0[s:s + width], P[s:s + width]
        real = len(y)
        if real < width:
            y = np.vstack([y, np.repeat(y[-1:], width - real, axis=0)])
            p = np.vstack([p, np.repeat(p[-1:], width - real, axis=0)])
        out.append((np.ascontiguousarray(y.T), np.ascontiguousarray(p.T), real))
    return out


def heyoka_batch(prob: bc.Problem, probs: list[bc.Problem], tol: float):
    """(grid run, final run, lanes): two callables that integrate every problem of ``probs``
    (same formulation and output times as ``prob``) in heyoka's batch mode, one trajectory per
    SIMD lane: the states at every output time ((N, n, ny)), or the final states only ((N, ny))."""
    import heyoka as hy

    width = int(hy.recommended_simd_size())
    chunks = _lanes(np.array([p.y0 for p in probs]), np.array([p.const_values for p in probs]), width)
    ta = hy.taylor_adaptive_batch(bc.heyoka_system(prob.formulation), chunks[0][0], tol=tol, pars=chunks[0][1])
    grid = np.ascontiguousarray(np.repeat(prob.t[:, None], width, axis=1))
    n, ny, t0, t_end = len(prob.t), len(prob.y0), float(prob.t[0]), float(prob.t[-1])

    def start(y, p):
        ta.set_time(t0)
        ta.state[:] = y
        ta.pars[:] = p

    def grid_run():
        out = np.empty((len(probs), n, ny))
        s = 0
        for y, p, real in chunks:
            start(y, p)
            Y = ta.propagate_grid(grid)[-1]  # (n, ny, lanes)
            out[s:s + real] = Y[:, :, :real].transpose(2, 0, 1)
            s += real
        return out

    def final_run():
        out = np.empty((len(probs), ny))
        s = 0
        for y, p, real in chunks:
            start(y, p)
            ta.propagate_until(t_end)
            out[s:s + real] = ta.state[:, :real].T
            s += real
        return out

    return grid_run, final_run, width


def batch(cfg, scenes: list[dict], fams: list[str]) -> dict:
    """``derive.simulate_batch`` over ``scenes`` (variants of the reference scene) against
    heyoka's batch mode, per trajectory, timed in turns (best of a few rounds each)."""
    if "heyoka" not in fams:
        return {"skipped": "heyoka not installed"}
    data = dict(scenes[0])
    t = np.linspace(0.0, float(data["simulate"]["t_end"]), int(data["simulate"]["samples"]))
    ref = B.exact_axis(data, t)
    rtol = float(data["simulate"]["rtol"])
    target, _ = _derive_error(data, ref, rtol)
    prob = bc.problem(data, "euler-angles", "batch")
    m = B.match_tolerance(lambda x: B.contender_error("heyoka", PEERS["heyoka"], prob, ref, x), target, rtol)
    probs = [bc.problem(d, "euler-angles") for d in scenes]
    grid_run, final_run, width = heyoka_batch(prob, probs, m["rtol"])
    prepared, initial = prepared_batch(scenes)
    ny = len(prob.y0)
    fns = {"derive_full": lambda: derive.simulate_batch(scenes),
           "heyoka_grid": grid_run, "heyoka_final": final_run,
           "derive_final": lambda: derive.simulate_batch(scenes, outputs="final"),
           "derive_prepared_final": lambda: prepared.run_batch(initial=initial),
           # every sample of the quantity both sides are judged on: derive's axis, asked for by
           # name, against heyoka's states (its user computes the axis from them after: timed apart)
           "derive_prepared_axis": lambda: prepared.run_batch(initial=initial, outputs=("axis",)),
           # like for like: the states at every sample, derive's (its formulation's: 4 for
           # reduced-u) against heyoka's (its Euler-angle equations': 6)
           "derive_prepared_state": lambda: prepared.run_batch(initial=initial, outputs=("state",)),
           "heyoka_grid_axis": lambda: prob.axis(grid_run().reshape(-1, ny))}
    results = {k: fn() for k, fn in fns.items()}  # warm: compile, JIT, first touch
    best = timing.best_in_turns(fns, 3 if len(scenes) >= 500 else 5)
    n = len(scenes)
    out = {"n": n, "t_end": float(t[-1]), "samples": len(t), "rtol": rtol, "derive_error": target,
           "heyoka_tol": m["rtol"], "heyoka_error": m["error"], "heyoka_reached": m["reached"], "lanes": width,
           **{f"{k}_per_trajectory": v / n for k, v in best.items()}}
    # The two sides integrate the same motions: their final axes agree to about the tolerance.
    full = results["derive_full"]
    axes = np.array([r.axis[-1] for r in full])
    out["final_axis_difference"] = float(np.max(np.linalg.norm(prob.axis(results["heyoka_final"]) - axes, axis=1)))
    out.update(ratio_full_vs_grid=best["derive_full"] / best["heyoka_grid"],
               ratio_final_vs_final=best["derive_final"] / best["heyoka_final"],
               ratio_prepared_final_vs_final=best["derive_prepared_final"] / best["heyoka_final"],
               ratio_prepared_axis_vs_grid=best["derive_prepared_axis"] / best["heyoka_grid"],
               ratio_prepared_axis_vs_grid_axis=best["derive_prepared_axis"] / best["heyoka_grid_axis"],
               ratio_prepared_state_vs_grid=best["derive_prepared_state"] / best["heyoka_grid"])
    if data["simulate"].get("method") != "taylor":
        out.update(_lanes_race(scenes, prob, probs, ref, rtol))
    return out


def _lanes_race(scenes: list[dict], prob, probs, ref, rtol: float) -> dict:
    """The Taylor method's final-only batch (its lanes driver, W trajectories at once) against
    heyoka's final-only batch at the error the Taylor method makes on the reference scene (a
    tighter one than the scenes' own method's: heyoka is matched to it anew), timed in turns."""
    taylor = [dict(d, simulate=dict(d["simulate"], method="taylor")) for d in scenes]
    target, _ = _derive_error(taylor[0], ref, rtol)
    m = B.match_tolerance(lambda x: B.contender_error("heyoka", PEERS["heyoka"], prob, ref, x), target, rtol)
    _, final_run, _ = heyoka_batch(prob, probs, m["rtol"])
    ran = derive.simulate_batch(taylor, outputs="final")  # warm: compile, load
    prepared, initial = prepared_batch(taylor)
    prepared.run_batch(initial=initial)
    fns = {"derive": lambda: derive.simulate_batch(taylor, outputs="final"),
           "derive_prepared": lambda: prepared.run_batch(initial=initial), "heyoka": final_run}
    final_run()
    best = timing.best_in_turns(fns, 3 if len(scenes) >= 500 else 5)
    n = len(scenes)
    return {"lanes_driver": ran.driver, "lanes_derive_error": target, "lanes_heyoka_tol": m["rtol"],
            "lanes_heyoka_error": m["error"], "derive_lanes_per_trajectory": best["derive"] / n,
            "heyoka_final_lanes_per_trajectory": best["heyoka"] / n,
            "ratio_lanes_vs_final": best["derive"] / best["heyoka"],
            "derive_prepared_lanes_per_trajectory": best["derive_prepared"] / n,
            "ratio_prepared_lanes_vs_final": best["derive_prepared"] / best["heyoka"]}


def prepared_batch(scenes: list[dict]):
    """(the first scene prepared, {initial key: array over the scenes}) for the keys of
    ``[initial]`` that differ among them: ``Prepared.run_batch``'s arguments for the same
    trajectories (the scenes differ only there: :func:`derive.bench.targets.batch_scenes`)."""
    first = scenes[0]["initial"]
    varying = [k for k in first if any(d["initial"][k] != first[k] for d in scenes)]
    return (derive.prepare(scenes[0]),
            {k: np.array([float(d["initial"][k]) for d in scenes]) for k in varying})


def fixed_cost(cfg, fams: list[str]) -> dict:
    """The cost of one short call (t_end = 1e-3, 2 samples, rtol 1e-10): derive's prepared run,
    ``derive.simulate(dict)`` of the same scene again (``derive_simulate``) and of a scene with
    new numbers every call (``derive_simulate_new``), each validated and planned, against the
    peers' calls, timed in turns."""
    data = reference_data()
    data["simulate"].update(t_end=1e-3, samples=2)
    prob = bc.problem(data, "euler-angles", "fixed cost")
    rtol = float(data["simulate"]["rtol"])
    prepared = derive.prepare(data)
    # the same motion each time but for a start rate that differs in its last digits
    fresh = itertools.cycle([dict(data, initial=dict(data["initial"], gamma_dot=data["initial"]["gamma_dot"] + 1e-9 * k))
                             for k in range(256)])
    names = ["derive_prepared", "derive_simulate", "derive_simulate_new"]
    fns = [prepared.run, lambda: derive.simulate(data), lambda: derive.simulate(next(fresh))]
    for fam in PEERS:
        if fam in fams:
            names.append(fam)
            fns.append(B.contender_call(fam, PEERS[fam], prob, rtol))
    times = dict(zip(names, timing.interleaved(fns, max(cfg.fixed_cost_calls, 15))))
    out = {"rtol": rtol, **times}
    for fam in PEERS:
        if fam in times:
            out[f"prepared_vs_{fam}"] = times["derive_prepared"] / times[fam]
            out[f"simulate_vs_{fam}"] = times["derive_simulate"] / times[fam]
            out[f"simulate_new_vs_{fam}"] = times["derive_simulate_new"] / times[fam]
    return out


def run(cfg, fams: list[str], batch_scenes) -> dict:
    """Every race that an installed peer can run; ``batch_scenes(n, t_end)`` gives
    the batch's scenes (:func:`derive.bench.targets.batch_scenes`). Each part is guarded by the
    caller; without heyoka and numbalsoda: ``{"skipped": ...}``."""
    peers = [f for f in PEERS if f in fams]
    if not peers:
        return {"skipped": "neither heyoka nor numbalsoda is installed (pip install -e '.[peers]')"}
    parts = {"reference": lambda: equal_error(cfg, fams, cfg.ref_t_end, cfg.peer_levels),
             "long": lambda: equal_error(cfg, fams, cfg.long_t_end, cfg.long_levels),
             "batch": lambda: batch(cfg, batch_scenes(cfg.batch_n, cfg.batch_t_end), fams),
             "fixed_cost": lambda: fixed_cost(cfg, fams)}
    out = {"peers": peers}
    for key, part in parts.items():
        try:
            out[key] = part()
        except Exception as exc:  # noqa: BLE001 - report what broke, keep benchmarking
            out[key] = {"error": f"{type(exc).__name__}: {(str(exc).splitlines() or [''])[0][:200]}"}
    return out
