"""Benchmarks (`derive bench`): what the generated code costs, and what it buys, against the
strongest baselines a user could pick instead. This module holds the settings, the reference
solutions, the kernel speed, the drift and the machine; the work–precision curves are
:mod:`derive.bench.workprecision`, the timing primitives :mod:`derive.bench.timing`.

Four parts, written to ``out/`` as ``report.md`` and its short version ``summary.md`` (the
README's "Measured" section; both by `derive.bench.report`), one work–precision plot per scene
(``wp_<scene>.png``), every run as ``points.csv`` and everything as ``results.json``:

1. **Kernel speed.** The committed ``generated/c/heavy_top.c`` against
   ``derive/bench/baselines/handwritten_heavy_top.c`` (the same equations typed from the textbook), each in
   its own translation unit, called through a pointer by ``derive/bench/baselines/rhs_loop.c``; the
   generated NumPy ``rhs`` on a batch of states; one call through Python.
2. **Targets** (`derive.bench.targets`), each a ratio measured side by side in one
   run: the reference heavy top against ``solve_ivp(DOP853)`` with a hand-written plain-Python
   rhs and against CasADi, the fixed cost of a call, ``simulate_batch`` against its own raw C
   loop and SciPy, process start-up warm and cold, NumPy rhs against ``sympy.lambdify``; and
   each of derive's times split into derivation, code generation, compilation, per-call
   overhead and the solve.
3. **Work–precision** per scene: ours through ``derive.simulate`` (dop853 over rtol, rk4 /
   gauss4 / gauss6 over h, in every formulation that can run the scene); SciPy's ``solve_ivp``
   DOP853, LSODA and Radau, and ``odeint`` (LSODA with its loop in Fortran; the LSODAs and Radau
   with the analytic Jacobian) on the hand-written plain-Python rhs of
   ``derive/bench/baselines/scipy_baselines.py`` in the formulation(s) most favourable to it; and the peers
   when installed (CasADi cvodes Adams/BDF and idas, PyDy Cython + odeint) on the same
   equations (`derive.bench.contenders`). Error = max over the output times of |ê₃ − ê₃,ref|,
   ref = the exact solution (`derive.reference.exact`). The cost of an error level on a curve is
   interpolated log-log between the runs around it; each contender's best cost is divided by ours.
4. **Drift** of energy and momenta over 10⁶ fixed steps (looping top, quaternion formulation).

Wall times are medians of repeats. Goals are reported, never asserted: timings depend on the
machine and its load, which the report states with the versions of everything.
"""
from __future__ import annotations

import math
import os
import platform
import statistics
import subprocess
import tempfile
import time
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

import derive
from derive.bench import contenders as bc
from derive.bench import internals as bi
from derive.bench.timing import per_call, timed
from derive.codegen.render import CHECKOUT, GENERATED
from derive.errors import IntegrationError
from derive.methods.registry import compiled_methods, tolerance_driven
from derive.reference import exact
from derive.reference.rotation import euler_matrix
from derive.runtime.cbuild import check_compiles, compiler
from derive.sim import examples
from derive.sim.scene import FIXED_STEP_METHODS, FORMULATIONS, MIN_RTOL

SCENES = examples.SCENES

#: Error levels at which the cost of each contender's best method is compared with ours.
ERROR_LEVELS = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)
#: atol = ATOL_RATIO * rtol for every adaptive run (ours and the contenders' alike), as in the
#: scenes' defaults (rtol 1e-10, atol 1e-12).
ATOL_RATIO = 1e-2
#: Errors below this are rounding noise: a fixed-step sweep stops refining there.
ERROR_FLOOR = 1e-13

#: The tolerance-driven methods of ours (the method registry: DOP853 and the Taylor method).
ADAPTIVE = tuple(m for m in compiled_methods() if tolerance_driven(m))
#: The fixed-step methods a scene can name (the method registry: rk4, gauss4/6, the splittings).
FIXED = tuple(FIXED_STEP_METHODS)
#: scene file stem -> the baseline formulations the contenders get: Euler angles for symmetric
#: tops, quaternion + Euler's equations for any body; where the axis passes near a pole (or both
#: are natural), both, and each contender's best counts. Ours run in every formulation the scene
#: accepts (`our_formulations`).
WP_SCENES = {
    "free_symmetric": ("euler-angles", "quaternion"),
    "tennis_racket": ("quaternion",),
    "looping_top": ("euler-angles",),
    "cuspidal_top": ("euler-angles",),
    "sleeping_top": ("euler-angles", "quaternion"),
}


def our_formulations() -> tuple[str, ...]:
    """Every formulation a scene can ask for (the scene format's registry), "auto" excluded."""
    return tuple(f for f in FORMULATIONS if f != "auto")


HEAVY_TOP_PARAMS = np.array([1.8e-4, 4.0e-5, 0.1, 9.81, 0.04])  # (I1, I3, M, g, l) of the scenes' top

GOAL_KERNEL_RATIO = 1.2


@dataclass(frozen=True)
class Settings:
    """How much to measure. FULL is `derive bench`, QUICK `--quick`, SMOKE the test suite's."""
    name: str
    rtols: tuple[float, ...]              # adaptive sweeps, loose to tight
    max_refinements: int                  # fixed-step sweeps: h = dt_out / 2**k, k < this
    repeats: int                          # timing repeats per run of ours (median)
    other_repeats: int                    # the same for the contenders' runs
    long_run: float                       # s: a run slower than this is timed once
    cap: float                            # s: a sweep stops after a run slower than this
    scenes: tuple[str, ...]
    min_total: float = 0.05               # s: fast runs are repeated until they add up to this
    families: tuple[str, ...] = ("scipy", "casadi", "pydy", "heyoka", "numbalsoda")  # (peers if installed)
    all_baseline_forms: bool = True       # contenders in every baseline formulation (else the first)
    other_formulations: bool = True       # ours also in the formulations `auto` does not pick
    all_formulations_fixed: bool = True   # ... fixed-step methods too (else dop853 only there)
    scene_overrides: dict = field(default_factory=dict)
    c_flags: tuple[tuple[str, ...], ...] = (("-std=c99", "-O2"), ("-std=c99", "-O3"))
    loop_calls: int = 2_000_000
    loop_repeats: int = 15
    numpy_sizes: tuple[int, ...] = (10_000, 100_000)
    numpy_repeats: int = 15
    python_calls: int = 20_000
    drift_steps: int = 1_000_000
    # targets (derive.bench.targets)
    ref_t_end: float = 10.0
    ref_repeats: int = 7
    fixed_cost_calls: int = 1500
    # the races against heyoka and numbalsoda (derive.bench.peers): the error levels on the
    # reference scene, and the long run's span and levels
    peer_levels: tuple[float, ...] = (1e-8, 1e-10, 1e-12)
    long_t_end: float = 1000.0
    long_levels: tuple[float, ...] = (1e-8, 1e-9, 1e-10, 1e-11)
    batch_n: int = 1000
    batch_t_end: float = 10.0
    batch_scipy_n: int = 5
    process_repeats: int = 5
    cold_runs: int = 2
    # Lie-Poisson splitting against DOP853 and Gauss-Legendre (derive.bench.splitting.bench_energy):
    # (case, measure) pairs, the periods each run spans, the error target, a time budget per scan
    splitting_cases: tuple[tuple[str, str], ...] = (("fast-top", "energy"), ("fast-top", "axis"),
                                                    ("lagrange", "axis"), ("asymmetric", "energy"))
    splitting_periods: float = 1e4
    splitting_target: float = 1e-8
    splitting_budget: float = 30.0
    lambdify_n: int = 100_000
    # the sweep targets (derive.bench.throughput.bench_throughput): trajectories per process,
    # SciPy runs, and the 2-process / Dask comparison's points (0: not run)
    sweep_n: int = 2000
    sweep_scipy_n: int = 20
    sweep_big: int = 100_000


def _decades(lo: int, hi: int, half: bool) -> tuple[float, ...]:
    step = 0.5 if half else 1.0
    return tuple(float(f"{10.0 ** -(lo + step * i):.3g}") for i in range(int((hi - lo) / step) + 1))


FULL = Settings("full", rtols=_decades(4, 13, half=True), max_refinements=12, repeats=3, other_repeats=3,
                long_run=1.0, cap=4.0, scenes=tuple(WP_SCENES), all_formulations_fixed=False)
QUICK = Settings("quick", rtols=_decades(4, 13, half=False), max_refinements=9, repeats=3, other_repeats=1,
                 long_run=0.2, cap=0.5, scenes=tuple(WP_SCENES), all_formulations_fixed=False,
                 all_baseline_forms=False, other_formulations=False,
                 loop_calls=1_000_000, loop_repeats=9, numpy_repeats=7, python_calls=5_000, drift_steps=200_000,
                 ref_repeats=3, fixed_cost_calls=300, batch_n=200, long_levels=(1e-8, 1e-10),
                 batch_scipy_n=2, process_repeats=3, cold_runs=1,
                 splitting_periods=1e3, splitting_budget=10.0, sweep_n=500, sweep_scipy_n=5, sweep_big=20_000)
SMOKE = Settings("smoke", rtols=(1e-4, 1e-8), max_refinements=2, repeats=1, other_repeats=1, long_run=0.0,
                 cap=1.0, scenes=("looping_top",), families=("scipy",), all_baseline_forms=False,
                 other_formulations=False, all_formulations_fixed=False,
                 scene_overrides={"t_end": 0.2, "samples": 101}, c_flags=(("-std=c99", "-O2"),),
                 loop_calls=20_000, loop_repeats=3,
                 numpy_sizes=(1_000,), numpy_repeats=3, python_calls=200, min_total=0.0, drift_steps=2_000,
                 ref_t_end=0.5, ref_repeats=1, fixed_cost_calls=3, peer_levels=(1e-8,), long_t_end=2.0,
                 long_levels=(1e-8,), batch_n=4, batch_t_end=0.2, batch_scipy_n=1,
                 process_repeats=0, cold_runs=0, lambdify_n=1_000,
                 splitting_cases=(("fast-top", "axis"),), splitting_periods=20.0, splitting_budget=5.0,
                 sweep_n=20, sweep_scipy_n=2, sweep_big=0)


def axis_error(axis: np.ndarray, ref: np.ndarray) -> float:
    """max over the output times of the Euclidean distance between the two axes."""
    return float(np.max(np.linalg.norm(np.asarray(axis) - ref, axis=1)))


def ours(scene, **overrides):
    """``derive.simulate`` (the public entry point): (axis at the output times, rhs evaluations)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = derive.simulate(scene, **overrides)
    return np.asarray(res.axis), int(res.nfev)


def match_tolerance(solve, target: float, rtol0: float = 1e-10) -> dict:
    """The loosest rtol at which ``solve(rtol) -> (axis error, nfev)`` is no larger than
    ``target``: halved from ``rtol0`` (down to MIN_RTOL) until it is, or, if ``rtol0`` already
    is, doubled up to 1e-4, keeping the loosest that is — the cheapest setting of the contender
    that is at least as accurate as ours. Every doubling is tried, not only up to the first miss:
    a contender whose error is not monotonic in rtol (derive's ``auto`` changes method with the
    tolerance, and the Taylor method is far more accurate than its rtol) gets its loosest
    setting too. Returns that try and the list of tries."""
    tried = []

    def attempt(r):
        try:
            err, nfev = solve(r)
        except Exception as exc:  # noqa: BLE001 - a failed tolerance: another may work, or not
            tried.append({"rtol": r, "error": None, "nfev": 0, "failure": str(exc)[:120]})
            return False
        tried.append({"rtol": r, "error": err, "nfev": nfev})
        return bool(np.isfinite(err) and err <= target)

    r = rtol0
    ok = attempt(r)
    best = tried[-1] if ok else None
    if ok:
        while r * 2 <= 1e-4:
            r *= 2
            if attempt(r):
                best = tried[-1]
    else:
        while r > MIN_RTOL:
            r = max(MIN_RTOL, r / 2)
            if attempt(r):
                best = tried[-1]
                break
    last = best or tried[-1]
    return {"rtol": last["rtol"], "error": last["error"], "nfev": last["nfev"], "reached": best is not None,
            "tried": tried}


def contender_call(family: str, method: str, prob, rtol: float):
    """A contender's solve of ``prob`` at ``rtol`` (atol = ATOL_RATIO rtol) as a callable, its
    setup (the integrator built, the rhs compiled) done now, outside whatever times the call."""
    c = bc.CONTENDERS[family]
    setup = c.setup(prob, method, rtol, ATOL_RATIO * rtol)
    return lambda: c.solve(prob, method, rtol, ATOL_RATIO * rtol, setup)


def contender_error(family: str, method: str, prob, ref: np.ndarray, rtol: float):
    """(axis error against ``ref``, nfev) of a contender's solve of ``prob`` at ``rtol``."""
    Y, nfev = contender_call(family, method, prob, rtol)()
    return axis_error(prob.axis(Y), ref), nfev


# ---------------------------------------------------------------------------------------------
# reference solutions


def exact_axis(data: dict, t: np.ndarray) -> np.ndarray | None:
    """ê₃(t) from `derive.reference.exact` for scene data (`derive.bench.contenders.scene_data`), or None when
    the scene has no closed form (damping, or an asymmetric heavy body)."""
    if data.get("damping"):
        return None
    b = bc.baselines()
    body, init, grav = data["body"], data["initial"], data.get("gravity")
    I1, I3 = float(body["I1"]), float(body["I3"])
    I2 = float(body.get("I2", I1))
    a, be, ga = (float(init[k]) for k in ("alpha", "beta", "gamma"))
    rates = None
    if any(k in init for k in ("alpha_dot", "beta_dot", "gamma_dot")):
        rates = [float(init.get(k, 0.0)) for k in ("alpha_dot", "beta_dot", "gamma_dot")]
    w0 = np.array(b.body_rates(be, ga, *rates) if rates is not None else list(map(float, init["omega"])))
    if grav is None:
        R0 = euler_matrix(a, be, ga)
        sol = (exact.free_symmetric(I1, I3, w0, t, R0=R0) if I2 == I1
               else exact.free_asymmetric(I1, I2, I3, w0, t, R0=R0))
    elif I2 == I1:
        rates = rates if rates is not None else b.euler_rates(be, ga, *w0)
        sol = exact.heavy_top(I1, I3, float(grav["M"]), float(grav["g"]), float(grav["l"]), a, be, ga, *rates, t)
    else:
        return None
    return np.asarray(sol.axis, dtype=float)


@dataclass
class Reference:
    axis: np.ndarray
    label: str              # what the errors are measured against
    check: float | None     # max |exact − tight dop853| when both exist
    note: str = ""


#: The tight numerical reference, and how closely the exact solution must match it over the
#: first tenth of the span to be trusted. Only the start is compared: a wrong convention shows
#: at once, while over the whole span an unstable motion (the tennis racket) amplifies even
#: dop853's error at rtol 1e-13 far above this, and the closed form is then the better of the two.
REFERENCE_RTOL = 1e-13
EXACT_TRUST = 1e-9


def reference(scene, data: dict, **overrides) -> Reference:
    """The exact solution when `derive.reference.exact` has one (cross-checked against our dop853 at rtol
    1e-13), else that dop853 run itself. ``data``: the scene's TOML data with the overrides."""
    numeric, _ = ours(scene, **overrides, method="dop853", rtol=REFERENCE_RTOL, atol=ATOL_RATIO * REFERENCE_RTOL)
    num_label = f"dop853 rtol {REFERENCE_RTOL:g}"
    t = np.linspace(0.0, float(data["simulate"]["t_end"]), int(data["simulate"].get("samples", 1001)))
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            exact = exact_axis(data, t)
    except (ImportError, AttributeError, NotImplementedError, TypeError, ValueError) as exc:
        return Reference(numeric, num_label, None, f"exact solution unavailable ({type(exc).__name__}: {exc})")
    if exact is None:
        return Reference(numeric, num_label, None, "no closed form for this scene")
    head = max(2, len(t) // 10)
    start = axis_error(exact[:head], numeric[:head])
    check = axis_error(exact, numeric)
    if not np.isfinite(check) or not start <= EXACT_TRUST:
        return Reference(numeric, num_label, check, f"exact solution differs from {num_label} by {start:.2g} "
                                                    f"over the first tenth of the span; not used")
    note = ""
    if check > EXACT_TRUST:
        note = (f"agree to {start:.0e} over the first tenth of the span; the later difference is the "
                "motion amplifying dop853's local errors (an unstable motion), so the closed form is used")
    return Reference(exact, "exact", check, note)


# ---------------------------------------------------------------------------------------------
# 1. kernel speed


def _generated_heavy_top() -> dict[str, str]:
    """The committed contract files generated/c/heavy_top.{h,c} (what `make derive` writes)."""
    return {n: (GENERATED / "c" / n).read_text() for n in ("heavy_top.h", "heavy_top.c")}


def c_loop(cfg: Settings) -> list[dict]:
    """ns/call of generated, hand-written and no-op rhs per flag set (one run each)."""
    sources = _generated_heavy_top()
    for name in ("handwritten_heavy_top.c", "noop_rhs.c", "rhs_loop.c"):
        sources[name] = (bc.BENCH_SOURCES / name).read_text()
    rows = []
    with tempfile.TemporaryDirectory(prefix="derive-bench-") as tmp:
        for flags in cfg.c_flags:
            exe = check_compiles(sources, ["heavy_top.c", "handwritten_heavy_top.c", "noop_rhs.c", "rhs_loop.c"],
                                 flags=flags, executable=Path(tmp) / ("rhs_loop" + "".join(flags).replace("-", "_")))
            out = subprocess.run([str(exe), str(cfg.loop_calls), str(cfg.loop_repeats)],
                                 capture_output=True, text=True, check=True).stdout
            per: dict[str, dict[int, float]] = {}
            check = math.nan
            for line in out.splitlines():
                w = line.split()
                if w[0] == "check":
                    check = float(w[1])
                elif w[0] == "rep":
                    per.setdefault(w[2], {})[int(w[1])] = float(w[3])
            gen, hand, noop = per["generated"], per["handwritten"], per["noop"]
            rows.append({
                "flags": " ".join(flags),
                "generated_ns": statistics.median(gen.values()),
                "handwritten_ns": statistics.median(hand.values()),
                "noop_ns": statistics.median(noop.values()),
                "ratio": statistics.median(gen[r] / hand[r] for r in gen),
                "max_rel_diff": check,
                "calls": cfg.loop_calls, "repeats": cfg.loop_repeats,
            })
    return rows


def random_states(n: int, seed: int = 1) -> np.ndarray:
    """Heavy-top states (6, n): β across (0.1, π − 0.1), rates of both signs, fast spin."""
    rng = np.random.default_rng(seed)
    Y = np.empty((6, n))
    Y[0] = rng.uniform(0, 2 * np.pi, n)
    Y[1] = rng.uniform(0.1, np.pi - 0.1, n)
    Y[2] = rng.uniform(0, 2 * np.pi, n)
    Y[3:5] = rng.uniform(-10, 10, (2, n))
    Y[5] = rng.uniform(100, 200, n)
    return Y


def generated_numpy(name: str = "heavy_top"):
    """The committed generated/numpy/<name>.py as a module."""
    return bc.module_at(GENERATED / "numpy" / f"{name}.py", f"derive_bench_generated_{name}")


def numpy_batch(cfg: Settings) -> list[dict]:
    """ns per state of the generated NumPy rhs on a (6, N) batch, and of its sin + cos alone."""
    mod = generated_numpy()
    rows = []
    for n in cfg.numpy_sizes:
        Y = random_states(n)
        beta = Y[1].copy()
        mod.rhs(0.0, Y, HEAVY_TOP_PARAMS)
        t_rhs, _ = timed(lambda: mod.rhs(0.0, Y, HEAVY_TOP_PARAMS), cfg.numpy_repeats)
        t_trig, _ = timed(lambda: (np.sin(beta), np.cos(beta)), cfg.numpy_repeats)
        rows.append({"n": n, "ns_per_state": t_rhs / n * 1e9, "sin_cos_ns_per_state": t_trig / n * 1e9})
    return rows


def python_calls(cfg: Settings, fams=("scipy",)) -> dict:
    """µs per single-state call through Python: the hand-written plain-Python rhs, the generated
    NumPy rhs and (through the kernel API) the compiled C rhs by ctypes."""
    mod = generated_numpy()
    y = random_states(1)[:, 0].copy()
    I1, I3, M, g, l = HEAVY_TOP_PARAMS
    plain = bc.baselines().euler_top_rhs(I1, I3, M * g * l)
    out = {"plain_python_us": per_call(lambda: plain(0.0, y), cfg.python_calls) * 1e6,
           "numpy_us": per_call(lambda: mod.rhs(0.0, y, HEAVY_TOP_PARAMS), cfg.python_calls) * 1e6,
           "ctypes_us": None}
    try:
        kc = bi.kernel_case(SCENES / "looping_top.toml", "euler-angles")
        out["ctypes_us"] = per_call(lambda: kc.kernel.rhs(0.0, y, HEAVY_TOP_PARAMS), cfg.python_calls) * 1e6
    except Exception as exc:  # noqa: BLE001 - an internal moved: report, don't fail the bench
        out["ctypes_error"] = f"{type(exc).__name__}: {exc}"
    if "pydy" in fams:  # PyDy's Cython function as odeint calls it: f(y, t, constants)
        f = bc._pydy_rhs("euler-angles")
        consts = np.array([I1, I3, M * g * l])
        out["pydy_us"] = per_call(lambda: f(y, 0.0, consts), cfg.python_calls) * 1e6
    return out


# ---------------------------------------------------------------------------------------------
# 4. drift of the invariants


DRIFT_H = 5e-4  # s: 1e6 steps = 500 s of the looping top, ~ 2600 nutations, 84 steps per spin turn


def drift(cfg: Settings, bar=None) -> dict:
    """max |ΔE/E₀|, |Δp_α/p_α₀|, |Δp_γ/p_γ₀| (and ||q| − 1| when the state is exposed) over
    ``drift_steps`` fixed steps (looping top, quaternion formulation: neither momentum is built
    in), and dop853 adaptive over the same span; all through ``derive.simulate``."""
    t_end = cfg.drift_steps * DRIFT_H
    path = SCENES / "looping_top.toml"
    rows = []
    derive.simulate(path, formulation="quaternion", t_end=0.01, samples=2)  # derive and compile untimed
    for method in ("rk4", "gauss4", "gauss6", "dop853"):
        over = dict(t_end=t_end, samples=1001, formulation="quaternion", method=method)
        if method == "dop853":
            over.update(rtol=1e-10, atol=1e-12)
            setting = "rtol=1e-10"
        else:
            over["h"] = DRIFT_H * (1 + 1e-9)
            setting = f"h={DRIFT_H:g}"
        t0 = time.perf_counter()
        try:
            res = derive.simulate(path, **over)
        except (IntegrationError, ValueError) as exc:
            rows.append({"method": method, "error": (str(exc).splitlines() or ["?"])[0]})
            if bar:
                bar.update()
            continue
        elapsed = time.perf_counter() - t0

        def rel(x):
            x = np.asarray(x, dtype=float)
            return float(np.max(np.abs(x - x[0])) / abs(x[0]))

        state = getattr(res, "state", None)
        qnorm = (float(np.max(np.abs(np.linalg.norm(state[:, :4], axis=1) - 1)))
                 if state is not None and np.ndim(state) == 2 and state.shape[1] == 7 else None)
        rows.append({"method": method, "setting": setting,
                     "steps": cfg.drift_steps if method != "dop853" else None, "nfev": int(res.nfev),
                     "time": elapsed, "energy": rel(res.energy),
                     "energy_end": float((res.energy[-1] - res.energy[0]) / abs(res.energy[0])),
                     "p_alpha": rel(res.p_alpha), "p_gamma": rel(res.p_gamma), "qnorm": qnorm})
        if bar:
            bar.update()
    return {"scene": "looping_top", "formulation": "quaternion", "t_end": t_end, "h": DRIFT_H, "rows": rows}


# ---------------------------------------------------------------------------------------------
# machine


def machine() -> dict:
    """CPU, cores, load, compiler and the versions of everything the bench runs."""
    cpu = platform.processor() or ""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    try:
        cc = subprocess.run([*compiler(), "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    except (OSError, IndexError):
        cc = "?"
    import scipy
    import sympy

    versions = {"python": platform.python_version(), "numpy": np.__version__, "scipy": scipy.__version__,
                "sympy": sympy.__version__}
    versions.update(bc.peers_available())
    versions["derive"] = derive.__version__
    try:
        commit = "?" if CHECKOUT is None else subprocess.run(  # the source checkout, else installed
            ["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True, cwd=CHECKOUT).stdout.strip() or "?"
    except OSError:
        commit = "?"
    return {"cpu": cpu, "cores": os.cpu_count(), "compiler": cc, "platform": platform.platform(),
            "versions": versions, "commit": commit,
            "load_average": list(os.getloadavg()) if hasattr(os, "getloadavg") else None}
