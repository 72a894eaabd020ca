"""The targets, each a ratio measured side by side in one run of `derive bench`.

* **Reference scene** (:data:`REFERENCE`: symmetric heavy top I₁ = I₂ = 1, I₃ = 0.5,
  M = g = l = 1; α₀ = 0, β₀ = 0.8, γ₀ = 0, α̇₀ = −0.4, β̇₀ = 0.3, γ̇₀ = 6; t ∈ [0, 10], 1001
  samples, rtol 1e-10): ``derive.simulate`` against ``solve_ivp(DOP853)`` with the hand-written
  plain-Python rhs (goal ≥ 100×) and CasADi cvodes-Adams (goal ≥ 10×), each at the loosest rtol
  (halved or doubled from 1e-10) whose error against the exact solution is no larger than ours. Also,
  labelled as such, SciPy on derive's generated NumPy rhs, and PyDy when installed. Derive's
  time split into derivation, code generation, compilation (fresh processes, cold and warm
  cache), the Python around the one C call, and the output map's share of that call.
* **Fixed cost** of one prepared call, ``derive.prepare(scene).run()`` (t_end = 1e-3, 2
  samples), over ``solve_ivp``'s on the same problem (goal ≤ 0.5×); ``derive.simulate(dict)``,
  which reads, checks and plans the scene on every call, is context.
* **Batch**: ``simulate_batch`` over 1000 variants of the reference scene against SciPy per
  trajectory (goal ≥ 150×); ``derive.prepare(...).run_batch`` of the same trajectories against
  the C batch call doing the same work (its own C call on prepared arrays: init map,
  integration and the outputs; goal ≥ 70 % of its throughput), ``simulate_batch``'s share of
  that call as context. The
  solve-only C loop (``Kernel.solve_batch``, states only, no outputs) is reported as context:
  with the outputs a large share of the C work, 70 % of a loop that skips them is out of reach
  of any Python around the same C.
* **Ceilings**, as context: each SciPy time over derive's C call alone (no Python at all), the
  largest ratio any Python around that C could reach; where it is below a goal, the goal needs
  fewer rhs evaluations, not less overhead.
* **Processes**: warm ``python -m derive simulate scenes/looping_top.toml -o out.npz`` over
  ``python -c "import numpy"`` (goal ≤ 3×); a cold one (fresh ``DERIVE_CACHE``) minus a warm
  one (goal ≤ 1 s).
* **Verify speed** (`derive.bench.verify_speed`): `derive verify` on each corpus text, user CPU
  seconds per 100 displays (goal ≤ 10), from a checkout.
* **NumPy batch rhs** at N = 10⁵: the generated ``heavy_top.rhs`` over ``sympy.lambdify(...,
  cse=True)`` of the same expressions, its rows stacked into one (6, N) array as ``rhs`` returns
  (goal ≤ 1×); the raw list of rows lambdify returns is timed too, and, as context, lambdify
  run in the generated module's cache-sized blocks (what the generated code gains by them).

Everything goes through public entry points except what `derive.bench.internals` isolates; a
part that fails is reported as such, with why, and the rest of the bench goes on.
"""
from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
import warnings

import numpy as np
from tqdm import tqdm

from derive.bench import runner as B
from derive.bench import timing
from derive.bench import contenders as bc
from derive.bench import peers as bench_peers
from derive.bench import tippe_race
from derive.bench.reference import reference_data
import derive
from derive.bench import internals as bi
from derive.bench.autochoice import LEVELS, SCENES, bench_auto_choice
from derive.bench.own_body import bench_own_body
from derive.bench.throughput import bench_throughput
from derive.bench import verify_speed


GOALS = {
    "vs_scipy": ("≥", 100.0), "vs_casadi": ("≥", 10.0), "fixed_cost": ("≤", 0.5),
    "batch_vs_own": ("≥", 0.70), "batch_vs_scipy": ("≥", 150.0), "warm_process": ("≤", 3.0),
    "cold_minus_warm": ("≤", 1.0), "numpy_vs_lambdify": ("≤", 1.0),
    # sweeps
    "sweep_vs_scipy": ("≥", 200.0), "dask_vs_local": ("≤", 1.1), "dask_scaling": ("≥", 0.8),
    # derive.bench.peers: derive's time over the peer's, at equal error
    # (the prepared call is the fast path: derive.simulate(dict) validates and plans each call
    # and its rows are context, not goals)
    "vs_heyoka": ("≤", 0.5), "vs_numbalsoda": ("≤", 0.5), "long_vs_heyoka": ("≤", 0.7),
    "batch_vs_heyoka": ("≤", 0.7), "fixed_prepared_vs_heyoka": ("≤", 2.5),
    # user terms (derive.bench.own_body)
    "own_first_run": ("≤", 3.0), "own_gravity_vs_gravity": ("≤", 1.1),
    "own_warm_vs_shipped": ("≤", 1.2),
    # derive.bench.tippe_race: the tippe top against MuJoCo
    tippe_race.JELLETT_GOAL: ("≥", 1000.0), tippe_race.SPIN_GOAL: ("≤", 1.0),
    # derive.bench.verify_speed: user CPU seconds per 100 displays of each corpus text
    verify_speed.GOAL_KEY: ("≤", 10.0),
}


def met(key: str, value) -> bool | None:
    if key not in GOALS or value is None or not np.isfinite(value):
        return None
    op, goal = GOALS[key]
    return value >= goal if op == "≥" else value <= goal


def _guard(name: str, fn, *args):
    """Run one part; a failure becomes {"error": ...} in the report instead of ending the bench."""
    try:
        return fn(*args)
    except Exception as exc:  # noqa: BLE001 - report what broke, keep benchmarking
        tqdm.write(f"bench target {name}: {type(exc).__name__}: {exc}")
        return {"error": f"{type(exc).__name__}: {(str(exc).splitlines() or [''])[0][:200]}"}


# ---------------------------------------------------------------------------------------------
# reference scene


def reference_scene(cfg, fams) -> dict:
    data = reference_data(cfg.ref_t_end)
    rtol = data["simulate"]["rtol"]
    t = np.linspace(0.0, data["simulate"]["t_end"], data["simulate"]["samples"])
    ref = B.exact_axis(data, t)
    ours_call = lambda: derive.simulate(data)  # noqa: E731
    res = ours_call()  # derive, compile (or load) once: the timing is of a warm call
    # The same call's C alone (init, solve, outputs; inputs prepared): the ratio's ceiling; and
    # the output map alone, its share of that C. Timed in turns with the whole call, so that
    # their differences mean something.
    parts, errors = {}, {}
    for key, make, arg in (("own_call", bi.own_batch_call, [data]), ("output_map", bi.output_map_call, data)):
        try:
            parts[key] = make(arg)
        except Exception as exc:  # noqa: BLE001
            errors[f"{key}_error"] = f"{type(exc).__name__}: {exc}"
    own_call = parts.get("own_call")
    k = max(1, int(0.02 / timing.timed(ours_call, 3)[0]))
    t_ours, *t_parts = timing.interleaved([ours_call, *parts.values()], 0, blocks=max(3, cfg.ref_repeats),
                                     counts=[k] * (1 + len(parts)))
    ours = {"time": t_ours, "error": B.axis_error(res.axis, ref), "nfev": int(res.nfev),
            "method": res.method, "formulation": res.formulation, "rtol": rtol,
            **dict(zip(parts, t_parts)), **errors}
    if "own_call" in ours:  # the Python around the C call
        ours["overhead"] = t_ours - ours["own_call"]

    rows = []
    prob = bc.problem(data, "euler-angles", "reference")
    contenders = [("scipy", "scipy-dop853", "`solve_ivp` DOP853, hand-written plain-Python rhs (Euler angles)"),
                  ("scipy", "scipy-odeint", "`odeint` (LSODA, Fortran loop), the same plain-Python rhs + Jacobian")]
    if "casadi" in fams:
        contenders.append(("casadi", "casadi-cvodes-adams", "CasADi cvodes (Adams), same equations as SX"))
    if "pydy" in fams:
        contenders.append(("pydy", "pydy-odeint", "PyDy Cython rhs + `odeint`, same equations"))
    for fam, method, label in contenders:
        t0 = time.perf_counter()  # one-off: build the integrator / generate and compile the rhs
        bc.CONTENDERS[fam].setup(prob, method, rtol, B.ATOL_RATIO * rtol)
        first_setup = time.perf_counter() - t0
        m = B.match_tolerance(lambda r: B.contender_error(fam, method, prob, ref, r), ours["error"], rtol)
        m["setup"] = bc.PYDY_BUILD_TIME.get(prob.formulation, first_setup) if fam == "pydy" else first_setup
        if not m["reached"]:  # no tolerance of it reaches derive's error (odeint fails below ~1e-13)
            rows.append({"family": fam, "method": method, "label": label, **m, "time": None, "ratio": None})
            continue
        # Timed in turns with ours (one contender call, then as many of ours as take about as
        # long), so that a change of machine load hits both sides of the ratio alike.
        theirs = B.contender_call(fam, method, prob, m["rtol"])
        t0 = time.perf_counter()
        theirs()
        k = max(1, min(1000, int((time.perf_counter() - t0) / t_ours)))
        fns, counts = [theirs, ours_call], [1, k]
        if own_call is not None and method == "scipy-dop853":
            fns, counts = fns + [own_call], counts + [k]
        m["time"], m["ours_paired"], *own = timing.interleaved(fns, 0, blocks=max(3, cfg.ref_repeats), counts=counts)
        if own:
            m["own_call_paired"] = own[0]
        rows.append({"family": fam, "method": method, "label": label, **m,
                     "ratio": m["time"] / m["ours_paired"]})
    # Labelled apart: SciPy on derive's generated NumPy rhs (one state per call through NumPy).
    scipy_rtol = rows[0]["rtol"]
    odeint = next(r for r in rows if r["method"] == "scipy-odeint")
    t_np, res_np = timing.timed(lambda: derive.simulate(data, method="scipy-dop853", rtol=scipy_rtol,
                                                   atol=B.ATOL_RATIO * scipy_rtol), 1)
    rows.append({"family": "scipy-numpy", "method": "scipy-dop853",
                 "label": "`solve_ivp` DOP853 on derive's generated NumPy rhs (`method = \"scipy-dop853\"`)",
                 "rtol": scipy_rtol, "error": B.axis_error(res_np.axis, ref), "nfev": int(res_np.nfev),
                 "reached": None, "time": t_np, "ratio": t_np / t_ours, "tried": []})
    return {"scene": data, "ours": ours, "rows": rows,
            "vs_scipy": rows[0]["ratio"] if rows[0]["reached"] else None,
            "ceiling_vs_scipy": (rows[0]["time"] / rows[0]["own_call_paired"]
                                 if rows[0]["reached"] and rows[0].get("own_call_paired") else None),
            "vs_odeint": odeint["ratio"] if odeint["reached"] else None,
            "vs_casadi": next((r["ratio"] for r in rows if r["method"] == "casadi-cvodes-adams" and r["reached"]),
                              None)}


def phases(cfg) -> dict:
    """Where a first call's time goes, in fresh processes (reference scene): the first and
    second ``simulate`` with an empty ``DERIVE_CACHE`` (cold) and with a filled one (warm);
    compilation = cold first call − warm first call; and, apart, the SymPy derivation and code
    generation of the model (`derive.bench.internals.DERIVE_SCRIPT`)."""
    arg = json.dumps(reference_data(cfg.ref_t_end))
    out = {}
    with tempfile.TemporaryDirectory(prefix="derive-bench-cache-") as tmp:
        cold_env = dict(os.environ, DERIVE_CACHE=tmp)
        out["cold"] = timing.fresh(timing.FIRST_CALL_SCRIPT, arg, cold_env, tmp)
        out["warm"] = timing.fresh(timing.FIRST_CALL_SCRIPT, arg, cold_env, tmp)  # the same cache, now filled
        out["derive"] = timing.fresh(bi.DERIVE_SCRIPT, arg, dict(os.environ, DERIVE_CACHE=tmp), tmp)
    c, w = out["cold"], out["warm"]
    if "error" not in c and "error" not in w:
        out["compilation"] = c["first_simulate"] - w["first_simulate"]
    return out


# ---------------------------------------------------------------------------------------------
# fixed cost, batch


def fixed_cost(cfg) -> dict:
    """The fixed cost of one short run (t_end = 1e-3, 2 samples) against SciPy's: the prepared
    call (``derive.prepare(scene).run()``, the fast path: validated, planned and compiled once)
    is the goal; ``derive.simulate(dict)``, which validates and plans on every call, is context."""
    data = reference_data()
    data["simulate"].update(t_end=1e-3, samples=2)
    prob = bc.problem(data, "euler-angles", "fixed cost")
    rtol = data["simulate"]["rtol"]
    prepared = derive.prepare(data)
    prepared.run()
    derive.simulate(data)
    t_prepared, t_dict, t_scipy, t_odeint = timing.interleaved(
        [prepared.run, lambda: derive.simulate(data), B.contender_call("scipy", "scipy-dop853", prob, rtol),
         B.contender_call("scipy", "scipy-odeint", prob, rtol)], cfg.fixed_cost_calls)
    return {"prepared": t_prepared, "ours": t_dict, "scipy": t_scipy, "odeint": t_odeint,
            "ratio": t_prepared / t_scipy, "ratio_odeint": t_prepared / t_odeint,
            "ratio_dict": t_dict / t_scipy}


def batch_scenes(n: int, t_end: float, seed: int = 2) -> list[dict]:
    """``n`` variants of the reference scene: β₀ ∈ [0.6, 1.0], α̇₀ ∈ [−0.6, −0.2],
    β̇₀ ∈ [0.1, 0.5], γ̇₀ ∈ [5, 7] (uniform, fixed seed)."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        d = reference_data(t_end)
        d["initial"].update(beta=float(rng.uniform(0.6, 1.0)), alpha_dot=float(rng.uniform(-0.6, -0.2)),
                            beta_dot=float(rng.uniform(0.1, 0.5)), gamma_dot=float(rng.uniform(5.0, 7.0)))
        out.append(d)
    return out


def batch(cfg, rtols: dict) -> dict:
    """``rtols``: SciPy method -> the rtol that matched derive's error on the reference scene."""
    scenes = batch_scenes(cfg.batch_n, cfg.batch_t_end)
    res = derive.simulate_batch(scenes)  # compile once
    # the method auto chose for the batch, named in every scene: the C calls timed beside
    # simulate_batch (its own call, the solve-only loop) then run the same method
    method = res[0].method
    scenes = [dict(s, simulate=dict(s["simulate"], method=method)) for s in scenes]
    out = {"n": len(scenes), "t_end": cfg.batch_t_end, "formulation": res[0].formulation, "method": method}
    # simulate_batch, the raw solve-only C loop and simulate_batch's own C call, timed in turns
    # (best of three rounds each), so that a change of machine load hits all three alike.
    prepared, initial = bench_peers.prepared_batch(scenes)
    every = derive.SaveAt()  # every output at every sample, as simulate_batch keeps by default
    fns = {"time": lambda: derive.simulate_batch(scenes),
           "prepared": lambda: prepared.run_batch(initial=initial, saveat=every)}
    try:
        kernel, y0s, ps, t, rtol, atol = bi.batch_inputs(scenes, res[0].formulation)
        raw = lambda: kernel.solve_batch(method, y0s, ps, t, rtol=rtol, atol=atol, check=False)  # noqa: E731
        raw()  # (the model kernel's solve-only loops are the Runge-Kutta methods': a Taylor batch has none)
        fns["raw"] = raw
    except Exception as exc:  # noqa: BLE001
        out["raw_error"] = f"{type(exc).__name__}: {exc}"
    try:  # informational: simulate_batch's own C call (outputs included) without its Python
        fns["own_call"] = bi.own_batch_call(scenes)
    except Exception as exc:  # noqa: BLE001
        out["own_call_error"] = f"{type(exc).__name__}: {exc}"
    for fn in fns.values():
        fn()
    best = timing.best_in_turns(fns, 3 if cfg.batch_n >= 500 else 5)
    out.update(best, per_scene=best["time"] / len(scenes))
    if "raw" in best:
        out["vs_raw"] = best["raw"] / best["time"]
    bc.solve_scipy(bc.problem(scenes[0], "euler-angles"), "scipy-dop853", 1e-6, 1e-8)  # imports, untimed
    for peer, key in (("scipy-dop853", "scipy"), ("scipy-odeint", "odeint")):
        if rtols and peer not in rtols:  # it reached derive's error at no tolerance
            continue
        r = rtols.get(peer) or scenes[0]["simulate"]["rtol"]
        times = []
        for d in scenes[:cfg.batch_scipy_n]:
            run = B.contender_call("scipy", peer, bc.problem(d, "euler-angles"), r)
            times.append(min(timing.timed(run, 1)[0] for _ in range(2)))  # the better of two: load spikes
        per = statistics.median(times)
        out.update({f"{key}_rtol": r, f"{key}_n": len(times), f"{key}_per_trajectory": per,
                    f"vs_{key}": per / out["per_scene"]})
    if "own_call" in best:
        out["prepared_vs_own"] = best["own_call"] / best["prepared"]
        out["ceiling_vs_scipy"] = out["scipy_per_trajectory"] / (best["own_call"] / len(scenes))
    return out


# ---------------------------------------------------------------------------------------------
# processes


def _wall(cmd, env=None, cwd=None) -> float:
    t0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=cwd)
    dt = time.perf_counter() - t0
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, cmd[:4]))}…: exit {p.returncode}: "
                           f"{(p.stderr.strip().splitlines() or ['?'])[-1]}")
    return dt


def processes(cfg) -> dict:
    scene = str(B.SCENES / "looping_top.toml")
    with tempfile.TemporaryDirectory(prefix="derive-bench-proc-") as tmp:
        sim_cmd = [sys.executable, "-m", "derive", "simulate", scene, "-o", os.path.join(tmp, "out.npz")]
        numpy_cmd = [sys.executable, "-c", "import numpy"]
        _wall(sim_cmd, cwd=tmp)  # warm the cache
        _wall(numpy_cmd, cwd=tmp)
        warm, base = [], []
        for _ in range(cfg.process_repeats):  # interleaved, so a load change hits both alike
            base.append(_wall(numpy_cmd, cwd=tmp))
            warm.append(_wall(sim_cmd, cwd=tmp))
        cold = []
        for _ in range(cfg.cold_runs):
            with tempfile.TemporaryDirectory(prefix="derive-bench-cold-") as cache:
                cold.append(_wall(sim_cmd, env=dict(os.environ, DERIVE_CACHE=cache), cwd=tmp))
    w, b = statistics.median(warm), statistics.median(base)
    out = {"import_numpy": b, "warm": w, "warm_ratio": w / b, "warm_runs": warm, "numpy_runs": base}
    if cold:
        c = statistics.median(cold)
        out.update(cold=c, cold_runs=cold, cold_minus_warm=c - w)
    return out


# ---------------------------------------------------------------------------------------------
# NumPy rhs vs lambdify


def numpy_vs_lambdify(cfg) -> dict:
    import sympy as sp

    states, params, rhs = bi.heavy_top_expressions()
    f = sp.lambdify([states, params], list(rhs), modules="numpy", cse=True)
    mod = B.generated_numpy()
    n = cfg.lambdify_n
    Y = B.random_states(n)
    P = B.HEAVY_TOP_PARAMS
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        a = np.asarray(mod.rhs(0.0, Y, P))
        b = np.array([np.broadcast_to(x, (n,)) for x in f(Y, P)])
        diff = float(np.max(np.abs(a - b)) / np.max(np.abs(a)))
        reps = max(3, cfg.numpy_repeats)
        stacked = lambda: np.stack(np.broadcast_arrays(*f(Y, P)))  # noqa: E731 - one (6, N) array, like rhs

        def blocked():  # context: lambdify in the generated module's cache-sized blocks
            out = np.empty((len(rhs), n))
            for s in range(0, n, mod.BLOCK):
                for i, row in enumerate(f(Y[:, s:s + mod.BLOCK], P)):
                    out[i, s:s + mod.BLOCK] = row
            return out

        # in turns, so that a change of machine load hits all alike
        t_gen, t_lam, t_raw, t_blk = timing.interleaved([lambda: mod.rhs(0.0, Y, P), stacked, lambda: f(Y, P), blocked],
                                                   0, blocks=reps, counts=[3, 3, 3, 3])
    return {"n": n, "generated": t_gen, "lambdify": t_lam, "lambdify_raw": t_raw, "ratio": t_gen / t_lam,
            "ratio_raw": t_gen / t_raw, "max_rel_diff": diff, "generated_ns_per_state": t_gen / n * 1e9,
            "lambdify_ns_per_state": t_lam / n * 1e9, "lambdify_raw_ns_per_state": t_raw / n * 1e9,
            "block": mod.BLOCK, "lambdify_blocked_ns_per_state": t_blk / n * 1e9, "ratio_blocked": t_gen / t_blk}


# ---------------------------------------------------------------------------------------------


def run(cfg, fams) -> dict:
    """All targets; each part guarded (a failure is reported, not raised)."""
    out = {}

    def rtols():  # the SciPy methods' rtols that matched derive's error on the reference scene
        return {r["method"]: r["rtol"] for r in out["reference"].get("rows", [])
                if r["family"] == "scipy" and r["reached"] is not False}

    parts = [("reference", "reference scene", lambda: reference_scene(cfg, fams)),
             ("phases", "phases", lambda: phases(cfg) if cfg.process_repeats else {}),
             ("fixed_cost", "fixed cost", lambda: fixed_cost(cfg)),
             ("batch", "batch", lambda: batch(cfg, rtols())),
             ("processes", "processes", lambda: processes(cfg) if cfg.process_repeats else {}),
             ("lambdify", "lambdify", lambda: numpy_vs_lambdify(cfg)),
             ("sweeps", "sweeps", lambda: sweeps(cfg)),
             ("peers", "peers", lambda: bench_peers.run(cfg, fams, batch_scenes)),
             ("own_body", "own body", bench_own_body),
             ("auto_choice", "auto choice", lambda: auto_choice(cfg)),
             ("tippe_top", "tippe top vs MuJoCo", lambda: tippe_race.run(cfg)),
             ("verify_speed", "verify speed", lambda: {"skipped": "not in a smoke run"} if cfg.name == "smoke"
              else verify_speed.bench_verify_speed())]
    with tqdm(total=len(parts), desc="targets", unit="part", file=sys.stderr) as bar:
        for key, name, part in parts:
            out[key] = _guard(name, part)
            bar.update()
    return out


def auto_choice(cfg) -> dict:
    """Does ``method = "auto"`` pick the faster of dop853 and taylor
    (:mod:`derive.bench.autochoice`)?"""
    if cfg.name == "smoke":
        return bench_auto_choice(levels=LEVELS[:1], scenes=SCENES[:1], blocks=1)
    return bench_auto_choice(levels=LEVELS if cfg.name == "full" else LEVELS[1::2], blocks=5)


def sweeps(cfg) -> dict:
    """The sweep targets (:func:`derive.bench.throughput.bench_throughput`): the measured sweep loop per
    trajectory against ``solve_ivp(DOP853)`` on a plain-Python rhs at rtol 1e-8, t ∈ [0, 10];
    with ``cfg.sweep_big`` points, a 2-worker Dask LocalCluster against the local engine with 2
    processes, and the scaling from 1 to 2 workers."""
    return bench_throughput(n=cfg.sweep_n, scipy_n=cfg.sweep_scipy_n, engines=cfg.sweep_big > 0,
                            big=max(cfg.sweep_big, 1))


#: Rows that are context, not targets: what the row's goal column says instead.
CONTEXT = {"batch_vs_raw": "(solve only, no outputs)", "ceiling_vs_scipy": "(ceiling: C alone)",
           "batch_ceiling_vs_scipy": "(ceiling: C alone)", "fixed_prepared_vs_numbalsoda": "(context)",
           "dict_call": "(context: validated and planned per call)"}


def summary(t: dict) -> list[tuple[str, str, float | None, bool | None]]:
    """(target, goal, measured ratio, met) rows for the report's table."""
    ref, fc, ba, pr, la, sw, ob = (t.get(k) or {} for k in ("reference", "fixed_cost", "batch",
                                                            "processes", "lambdify", "sweeps",
                                                            "own_body"))

    def g(key):
        if key in CONTEXT:
            return CONTEXT[key]
        if key not in GOALS:
            return "(stronger baseline)"
        op, goal = GOALS[key]
        return f"{op} {goal:g}" + ("" if key in ("cold_minus_warm", "dask_scaling", "own_first_run",
                                                 verify_speed.GOAL_KEY) else "×")

    rows = [
        ("reference scene: `derive.simulate` vs `solve_ivp` DOP853 plain-Python rhs, equal or smaller error",
         "vs_scipy", ref.get("vs_scipy")),
        ("reference scene: vs `odeint` (LSODA in Fortran) on the same plain-Python rhs, equal or smaller error",
         "vs_odeint", ref.get("vs_odeint")),
        ("reference scene: vs CasADi cvodes (Adams), equal or smaller error", "vs_casadi", ref.get("vs_casadi")),
        ("fixed cost of one call (t_end = 1e-3, 2 samples): `derive.prepare(...).run()` / `solve_ivp`", "fixed_cost",
         fc.get("ratio")),
        ("fixed cost of one call: `derive.prepare(...).run()` / `odeint`", "fixed_cost_odeint", fc.get("ratio_odeint")),
        ("fixed cost of one call: `derive.simulate(dict)` / `solve_ivp`", "dict_call", fc.get("ratio_dict")),
        ("reference scene: `solve_ivp` DOP853 / derive's C call alone (init, solve, outputs; no Python)",
         "ceiling_vs_scipy", ref.get("ceiling_vs_scipy")),
        (f"`derive.prepare(...).run_batch` ({ba.get('n', '?')} trajectories, every output at every sample) "
         "throughput / its own C call (init, solve and outputs; no Python)", "batch_vs_own", ba.get("prepared_vs_own")),
        (f"`simulate_batch` ({ba.get('n', '?')} scenes) throughput / its own C call", "dict_call",
         ba["own_call"] / ba["time"] if ba.get("own_call") and ba.get("time") else None),
        ("`simulate_batch` throughput / the solve-only C batch loop (`Kernel.solve_batch`, states only)",
         "batch_vs_raw", ba.get("vs_raw")),
        ("`simulate_batch` per trajectory vs SciPy (`solve_ivp` DOP853) per trajectory", "batch_vs_scipy",
         ba.get("vs_scipy")),
        ("SciPy per trajectory / the batch's C call per trajectory (no Python)", "batch_ceiling_vs_scipy",
         ba.get("ceiling_vs_scipy")),
        ("`simulate_batch` per trajectory vs `odeint` per trajectory", "batch_vs_odeint", ba.get("vs_odeint")),
        ("warm `derive simulate scenes/looping_top.toml -o out.npz` / `python -c \"import numpy\"`", "warm_process",
         pr.get("warm_ratio")),
        ("cold compile (fresh `DERIVE_CACHE`) − warm run [s]", "cold_minus_warm", pr.get("cold_minus_warm")),
        (f"NumPy batch rhs (N = {la.get('n', 0):,}) / `sympy.lambdify(cse=True)`", "numpy_vs_lambdify", la.get("ratio")),
        ("sweep (measures on, rtol 1e-8, t ∈ [0, 10]) per trajectory vs `solve_ivp` DOP853 "
         "plain-Python rhs", "sweep_vs_scipy", sw.get("speedup")),
        ("10⁵ points, Dask LocalCluster 2 workers / local engine 2 processes", "dask_vs_local",
         sw.get("dask2_over_local2")),
        ("Dask scaling from 1 to 2 workers", "dask_scaling", sw.get("scaling_1_to_2")),
        ("first `derive.simulate` of a new user body (derive, generate, compile, run) [s]",
         "own_first_run", ob.get("first_run")),
        ("potential restating gravity / `[gravity]`, prepared run, same formulation",
         "own_gravity_vs_gravity", ob.get("gravity_ratio")),
        ("warm `derive.simulate`: user body (compile cache) / the shipped heavy top",
         "own_warm_vs_shipped", ob.get("warm_ratio")),
    ]
    rows += peer_rows(t.get("peers") or {})
    rows += tippe_race.rows(t.get("tippe_top") or {})
    rows += verify_speed.rows(t.get("verify_speed") or {})
    return [(what, g(key), value, met(key, value)) for what, key, value in rows]


def peer_rows(pe: dict) -> list[tuple[str, str, float | None]]:
    """The peers' rows (what, goal key, derive's time / the peer's) from :mod:`derive.bench.peers`."""
    rows = []
    names = {"heyoka": "heyoka `taylor_adaptive`", "numbalsoda": "numbalsoda `dop853`"}
    for part, what, key in (("reference", "reference scene", "vs_{}"), ("long", "long run", "long_vs_{}")):
        eq = pe.get(part) or {}
        for row in eq.get("rows", []):
            for fam, entry in row["peers"].items():
                head = f"{what} (t_end = {eq['t_end']:g}) at equal error {row['level']:.0e}: "
                if not entry.get("reached", True) and row["derive"].get("reached"):
                    rows.append((head + f"{names[fam]} does not reach it at any tolerance; derive does",
                                 key.format(fam), None))
                    continue
                # the prepared call is the counterpart of the peer's integrator built once and reset
                rows.append((head + f"`derive.prepare(...).run()` / {names[fam]}", key.format(fam),
                             entry.get("ratio_prepared")))
                rows.append((head + f"`derive.simulate` / {names[fam]}", "dict_call",
                             entry.get("ratio_simulate")))
    ba = pe.get("batch") or {}
    if "ratio_full_vs_grid" in ba:
        rows.append((f"batch of {ba['n']}, per trajectory: `derive.simulate_batch(..., outputs=\"final\")` / "
                     f"heyoka batch mode ({ba['lanes']} lanes) `propagate_until`", "dict_call",
                     ba.get("ratio_final_vs_final")))
        rows.append((f"batch of {ba['n']}, per trajectory: `derive.prepare(...).run_batch(...)` (final states) / "
                     f"heyoka batch mode `propagate_until`", "batch_vs_heyoka", ba["ratio_prepared_final_vs_final"]))
        if "ratio_prepared_lanes_vs_final" in ba:
            rows.append((f"batch of {ba['n']}, per trajectory, Taylor: `derive.prepare(...).run_batch(...)` "
                         f"(final, SIMD lanes) / heyoka batch `propagate_until` at equal error", "batch_vs_heyoka",
                         ba.get("ratio_prepared_lanes_vs_final")))
        rows.append((f"batch of {ba['n']}, per trajectory: `derive.simulate_batch` (every output, {ba['samples']} "
                     f"samples) / heyoka batch `propagate_grid`", "dict_call", ba.get("ratio_full_vs_grid")))
        rows.append((f"batch of {ba['n']}, per trajectory: `derive.prepare(...).run_batch(..., outputs=(\"axis\",))` "
                     f"(the axis at {ba['samples']} samples) / heyoka `propagate_grid` (the states, no axis)",
                     "batch_vs_heyoka", ba["ratio_prepared_axis_vs_grid"]))
        rows.append((f"batch of {ba['n']}, per trajectory: `derive.prepare(...).run_batch(..., outputs=(\"state\",))` "
                     f"(the states at {ba['samples']} samples) / heyoka `propagate_grid` (its states)",
                     "batch_vs_heyoka", ba["ratio_prepared_state_vs_grid"]))
    fc = pe.get("fixed_cost") or {}
    if "prepared_vs_heyoka" in fc:
        rows.append(("fixed cost (t_end = 1e-3, 2 samples): `derive.prepare(...).run()` / heyoka",
                     "fixed_prepared_vs_heyoka", fc["prepared_vs_heyoka"]))
        rows.append(("fixed cost: `derive.simulate(dict)` / heyoka", "dict_call",
                     fc["simulate_vs_heyoka"]))
    if "prepared_vs_numbalsoda" in fc:
        rows.append(("fixed cost: `derive.prepare(...).run()` / numbalsoda `dop853`", "fixed_prepared_vs_numbalsoda",
                     fc["prepared_vs_numbalsoda"]))
    return rows
