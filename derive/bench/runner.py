"""Benchmarks (`derive bench`): what the generated code costs, and what it buys, against the
strongest baselines a user could pick instead.

Four parts, written to ``out/`` as ``report.md`` and its short version ``summary.md`` (the
README's "Measured" section; both by `derive.bench.report`), one work–precision plot per scene
(``wp_<scene>.png``), every run as ``points.csv`` and everything as ``results.json``:

1. **Kernel speed.** The committed ``generated/c/heavy_top.c`` against
   ``derive/bench/baselines/handwritten_heavy_top.c`` (the same equations typed from the textbook), each in
   its own translation unit, called through a pointer by ``derive/bench/baselines/rhs_loop.c``; the
   generated NumPy ``rhs`` on a batch of states; one call through Python.
2. **Targets** of issue 8 (`derive.bench.targets`), each a ratio measured side by side in one
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

import csv
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
import warnings
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np
from tqdm import tqdm

from derive.bench import contenders as bc
from derive.codegen.render import CHECKOUT
from derive.errors import IntegrationError
from derive.methods.registry import compiled_methods, tolerance_driven
from derive.sim import examples
from derive.sim.scene import FIXED_STEP_METHODS, MIN_RTOL
from derive.sim.scene import FORMULATIONS
import derive
from derive.reference import exact
from derive.codegen.render import GENERATED
from derive.runtime.cbuild import check_compiles
from derive.bench import internals as bi
from derive.runtime.cbuild import compiler

#: The source checkout (for the commit the report names), or None when installed.
REPO = CHECKOUT
BENCH_SOURCES = bc.BENCH_SOURCES
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
    try:

        return tuple(f for f in FORMULATIONS if f != "auto")
    except ImportError:
        return ("reduced", "euler-angles", "quaternion")


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
    # issue 20's races against heyoka and numbalsoda (derive.bench.peers): the error levels on the
    # reference scene, and the long run's span and levels
    peer_levels: tuple[float, ...] = (1e-8, 1e-10, 1e-12)
    long_t_end: float = 1000.0
    long_levels: tuple[float, ...] = (1e-8, 1e-9, 1e-10, 1e-11)
    batch_n: int = 1000
    batch_t_end: float = 10.0
    batch_scipy_n: int = 5
    process_repeats: int = 5
    cold_runs: int = 2
    # Lie-Poisson splitting against DOP853 and Gauss-Legendre (derive.methods.splitting.bench_energy):
    # (case, measure) pairs, the periods each run spans, the error target, a time budget per scan
    splitting_cases: tuple[tuple[str, str], ...] = (("fast-top", "energy"), ("fast-top", "axis"),
                                                    ("lagrange", "axis"), ("asymmetric", "energy"))
    splitting_periods: float = 1e4
    splitting_target: float = 1e-8
    splitting_budget: float = 30.0
    lambdify_n: int = 100_000
    # issue 11's sweep targets (derive.bench.throughput.bench_throughput): trajectories per process,
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


# ---------------------------------------------------------------------------------------------
# timing


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
    n = max(1, calls // blocks)
    fn()
    out = []
    for _ in range(blocks):
        t0 = time.perf_counter()
        for _ in range(n):
            fn()
        out.append((time.perf_counter() - t0) / n)
    return statistics.median(out)


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


# ---------------------------------------------------------------------------------------------
# reference solutions


def _rotation(a: float, b: float, c: float) -> np.ndarray:
    """R = Rz(α) Ry(β) Rz(γ): body components -> inertial components."""
    def rz(x):
        return np.array([[np.cos(x), -np.sin(x), 0.0], [np.sin(x), np.cos(x), 0.0], [0.0, 0.0, 1.0]])
    ry = np.array([[np.cos(b), 0.0, np.sin(b)], [0.0, 1.0, 0.0], [-np.sin(b), 0.0, np.cos(b)]])
    return rz(a) @ ry @ rz(c)


def exact_axis(data: dict, t: np.ndarray) -> np.ndarray | None:
    """ê₃(t) from `derive.reference.exact` for scene data (`bench_contenders.scene_data`), or None when
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
        R0 = _rotation(a, be, ga)
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
        sources[name] = (BENCH_SOURCES / name).read_text()
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
    import importlib.util


    spec = importlib.util.spec_from_file_location(f"derive_bench_generated_{name}", GENERATED / "numpy" / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


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
# 3. work–precision


@dataclass
class Point:
    scene: str
    family: str          # "ours" | "scipy" | "casadi" | "pydy"
    method: str
    formulation: str
    setting: str         # "rtol=1e-08" or "h=0.001"
    time: float          # s, median
    nfev: int
    error: float         # max axis error over the output times (nan: the run failed)
    note: str = ""

    @property
    def ok(self) -> bool:
        return np.isfinite(self.error) and np.isfinite(self.time)


@dataclass
class Curve:
    family: str
    method: str
    formulation: str
    points: list[Point]

    @property
    def label(self) -> str:
        return f"{self.method} / {self.formulation}"


def _point(name, family, method, formulation, setting, run, post, ref: Reference, repeats, cfg) -> Point:
    """Time ``run()`` (-> (raw, nfev)); error of ``post(raw)`` (the axis) against the reference."""
    try:
        t_run, (raw, nfev) = timed(run, repeats, cfg.long_run, cfg.min_total)
        err = axis_error(post(raw), ref.axis)
        note = ""
    except (IntegrationError, ValueError, RuntimeError) as exc:
        t_run, nfev, err, note = math.nan, 0, math.nan, (str(exc).splitlines() or ["?"])[0][:160]
    return Point(name, family, method, formulation, setting, t_run, int(nfev), err, note)


def _ours_point(name, method, formulation, setting, path, over: dict, ref: Reference, cfg) -> Point:
    """A run of ours timed as the contenders' are, the solve call alone: the scene read,
    validated, planned and its kernel loaded by ``derive.prepare`` outside the timing, then
    ``.run()`` timed (what a user who runs a scene again calls; ``derive.simulate``'s own cost
    per call is the fixed cost of the targets section)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            prepared = derive.prepare(path, **over)
        except (IntegrationError, ValueError, RuntimeError) as exc:
            return Point(name, "ours", method, formulation, setting, math.nan, 0, math.nan,
                         (str(exc).splitlines() or ["?"])[0][:160])

        def run():
            res = prepared.run()
            return np.asarray(res.axis), int(res.nfev)

        return _point(name, "ours", method, formulation, setting, run, lambda a: a, ref, cfg.repeats, cfg)


def sweep_ours(name: str, path: Path, ref: Reference, formulation: str, method: str,
               cfg: Settings) -> Curve | None:
    """One method of ours in one formulation over its tolerances (adaptive) or steps (fixed);
    None when the scene refuses the method in this formulation (e.g. a splitting needs
    Euler–Poisson variables and conservative effects)."""
    over = dict(cfg.scene_overrides, formulation=formulation, method=method)
    t_end = float(cfg.scene_overrides.get("t_end", 0) or _scene_simulate(path)["t_end"])
    samples = int(cfg.scene_overrides.get("samples", 0) or _scene_simulate(path).get("samples", 1001))
    dt_out = t_end / (samples - 1)
    try:  # derive and compile this formulation's model and method outside the timing
        if method in FIXED:
            ours(path, **over, h=dt_out * (1 + 1e-9))
        else:
            ours(path, **over, rtol=1e-4, atol=1e-6)
    except IntegrationError:
        pass
    except ValueError as exc:
        tqdm.write(f"{name}: {method} / {formulation}: skipped ({(str(exc).splitlines() or ['?'])[0][:120]})")
        return None
    points = []
    if method in FIXED:
        prev, worse = math.inf, 0
        for k in range(cfg.max_refinements):
            h = dt_out / 2**k * (1 + 1e-9)  # a hair above dt_out / 2**k: exactly 2**k steps per interval
            pt = _ours_point(name, method, formulation, f"h={h:.4g}", path, dict(over, h=h), ref, cfg)
            points.append(pt)
            worse = worse + 1 if pt.ok and pt.error > prev else 0
            if pt.ok and (pt.error < ERROR_FLOOR or pt.time > cfg.cap
                          or (pt.error < 1e-10 and pt.error > 0.5 * prev)  # rounding-limited
                          or worse >= 2):  # round-off growing with the step count: smaller h only costs
                break
            prev = pt.error if pt.ok else math.inf
    else:
        for rtol in cfg.rtols:
            pt = _ours_point(name, method, formulation, f"rtol={rtol:.3g}", path,
                             dict(over, rtol=rtol, atol=ATOL_RATIO * rtol), ref, cfg)
            points.append(pt)
            if pt.ok and pt.time > cfg.cap:
                break
    return Curve("ours", method, formulation, points)


def sweep_contender(name: str, prob: bc.Problem, ref: Reference, family: str, method: str, cfg: Settings) -> Curve:
    """One contender method on one baseline problem over the tolerances."""
    c = bc.CONTENDERS[family]
    points = []
    setup = None
    for rtol in cfg.rtols:
        atol = ATOL_RATIO * rtol
        try:
            if setup is None or c.per_tolerance_setup:
                setup = c.setup(prob, method, rtol, atol)
        except Exception as exc:  # noqa: BLE001 - a peer refusing a setting is one failed point
            points.append(Point(name, family, method, prob.formulation, f"rtol={rtol:.3g}", math.nan, 0, math.nan,
                                f"setup: {type(exc).__name__}: {exc}"[:160]))
            continue
        pt = _point(name, family, method, prob.formulation, f"rtol={rtol:.3g}",
                    lambda: c.solve(prob, method, rtol, atol, setup), prob.axis, ref, cfg.other_repeats, cfg)
        points.append(pt)
        if pt.ok and pt.time > cfg.cap:
            break
    return Curve(family, method, prob.formulation, points)


def _scene_simulate(path: Path) -> dict:
    return bc.scene_data(path)["simulate"]


def cost_at(points: list[Point], level: float):
    """Wall time to reach error ≤ level on one curve: ``(time, bound)``.

    The curve is first reduced to its Pareto front (runs more accurate than every cheaper run);
    the time is interpolated log-log between the last run above the level and the first at or
    below it. When the cheapest run is already below the level, its time is returned with
    bound=True (an upper bound on the cost); when no run reaches the level, ``(None, False)``.
    """
    front = []
    for p in sorted((p for p in points if p.ok), key=lambda p: p.time):
        e = max(p.error, 1e-17)
        if not front or e < front[-1][1]:
            front.append((p.time, e))
    for i, (t, e) in enumerate(front):
        if e <= level:
            if i == 0:
                return t, True
            t0, e0 = front[i - 1]
            w = (math.log(level) - math.log(e0)) / (math.log(e) - math.log(e0))
            return math.exp(math.log(t0) + w * (math.log(t) - math.log(t0))), False
    return None, False


def best_at(curves: list[Curve], family: str, level: float, formulation: str | None = None):
    """(time, bound, curve label) of the cheapest curve of a family at an error level (among
    the curves of one formulation, if given)."""
    best = (None, False, "")
    for c in curves:
        if c.family != family or (formulation is not None and c.formulation != formulation):
            continue
        t, bound = cost_at(c.points, level)
        if t is not None and (best[0] is None or t < best[0]):
            best = (t, bound, c.label)
    return best


def compare(curves: list[Curve], level: float, family: str = "scipy", formulation: str | None = None) -> dict:
    """A contender family's best cost over ours at one error level; ``formulation`` restricts
    ours to one formulation (the one `auto` picks: what `derive simulate` runs by default)."""
    to, bo, lo = best_at(curves, "ours", level, formulation)
    ts, bs, ls = best_at(curves, family, level)
    row = {"level": level, "family": family, "ours": lo, "ours_time": to, "ours_bound": bo,
           "other": ls, "other_time": ts, "other_bound": bs, "ratio": None, "kind": ""}
    if to is None:
        row["kind"] = "ours n/a"
    elif ts is None:
        slowest = max((p.time for c in curves if c.family == family for p in c.points if p.ok), default=None)
        if slowest is not None:
            row.update(ratio=slowest / to, kind=">")  # the contender did not get there within its sweep
        else:
            row["kind"] = f"{family} n/a"
    else:
        row.update(ratio=ts / to, kind="*" if (bo or bs) else "")
    return row


def work_precision(cfg: Settings, name: str, fams: list[str]) -> dict:
    """Every method × formulation of ours and of each contender family on one scene."""
    path = SCENES / f"{name}.toml"
    data = bc.scene_data(path, **cfg.scene_overrides)
    ref = reference(path, data, **cfg.scene_overrides)

    auto = derive.simulate(path, **cfg.scene_overrides, rtol=1e-4, atol=1e-6).formulation
    base_forms = WP_SCENES[name] if cfg.all_baseline_forms else WP_SCENES[name][:1]
    forms = [auto]
    for form in (our_formulations() if cfg.other_formulations else ()):
        if form == auto:
            continue
        try:  # a formulation the scene refuses (asymmetric body for "reduced", ...) is left out
            ours(path, **cfg.scene_overrides, formulation=form, method="dop853", rtol=1e-4, atol=1e-6)
        except ValueError as exc:
            tqdm.write(f"{name}: {form}: skipped ({(str(exc).splitlines() or ['?'])[0][:120]})")
            continue
        except IntegrationError:
            pass  # it runs, if not at this tolerance: its sweep says where
        forms.append(form)
    plan = []
    for form in forms:
        methods = list(ADAPTIVE) + (list(FIXED) if (form == auto or cfg.all_formulations_fixed) else [])
        plan += [("ours", form, m) for m in methods]
    probs = {}
    for bf in base_forms:
        try:
            probs[bf] = bc.problem(data, bf, name)
        except ValueError as exc:
            tqdm.write(f"{name}: baseline {bf}: skipped ({exc})")
            continue
        plan += [(fam, bf, m) for fam in fams for m in bc.CONTENDERS[fam].methods]
    curves = []
    with tqdm(plan, desc=f"work-precision {name}", unit="curve", file=sys.stderr) as bar:
        for fam, form, method in bar:
            bar.set_postfix_str(f"{method} / {form}")
            if fam == "ours":
                curve = sweep_ours(name, path, ref, form, method, cfg)
                if curve is not None:
                    curves.append(curve)
            else:
                curves.append(sweep_contender(name, probs[form], ref, fam, method, cfg))
    return {"scene": name, "title": data.get("title", name), "auto": auto, "reference": ref.label,
            "reference_check": ref.check, "reference_note": ref.note, "curves": curves,
            "baseline_formulations": list(probs), "families": fams,
            "ratios": {fam: [compare(curves, lv, fam) for lv in ERROR_LEVELS] for fam in fams},
            "ratios_auto": {fam: [compare(curves, lv, fam, auto) for lv in ERROR_LEVELS] for fam in fams},
            "t_end": float(data["simulate"]["t_end"]), "samples": int(data["simulate"].get("samples", 1001))}


# Work-precision plots: a series is (family, method, formulation), up to about twenty of them.
# Colour names the method (no two methods share one, across all families), the marker the
# formulation; derive's series are filled and solid, the contenders' hollow and dashed; the
# legend lists them grouped by family. Dash style alone could not tell twenty series apart.
_COLORS = {  # Kelly's colours of maximum contrast, black for the one PyDy series
    "dop853": "#0067A5", "rk4": "#F38400", "gauss4": "#008856", "gauss6": "#BE0032",
    "splitting2": "#8DB600", "splitting4": "#882D17", "splitting6": "#E68FAC", "taylor": "#A1CAF1",
    "scipy-dop853": "#875692", "scipy-lsoda": "#654522", "scipy-radau": "#B3446C",
    "scipy-odeint": "#2B3D26", "scipy-rk45": "#604E97",
    "casadi-cvodes-adams": "#848482", "casadi-cvodes-bdf": "#C2B280", "casadi-idas": "#008080",
    "pydy-odeint": "k", "heyoka-taylor": "#F6A600", "numbalsoda-dop853": "#DCD300"}
_MARKERS = {"reduced": "o", "euler-angles": "s", "quaternion": "^", "euler-poisson": "D"}
_FAMILY_NAMES = {"ours": "derive (filled, solid)", "scipy": "SciPy (hollow, dashed)",
                 "casadi": "CasADi (hollow, dashed)", "pydy": "PyDy (hollow, dashed)",
                 "heyoka": "heyoka (hollow, dashed)", "numbalsoda": "numbalsoda (hollow, dashed)"}


def _series_style(c) -> dict:
    ours = c.family == "ours"
    colour = _COLORS.get(c.method, "0.3")
    return dict(color=colour, ls="-" if ours else "--", marker=_MARKERS.get(c.formulation, "x"),
                ms=5 if ours else 6, lw=1.3, mfc=colour if ours else "none", mew=1.2)


def work_precision_figure(wp: dict):
    """The work–precision figure of one scene (matplotlib Figure, not saved): error against wall
    time (left axes, label ``"time"``) and against rhs evaluations (right, ``"nfev"``).

    Each series (family, method, formulation) has its own colour + marker pair: colour = the
    method, marker = the formulation (○ reduced, □ Euler angles, △ quaternion, ◇ Euler–Poisson);
    derive filled and solid, contenders hollow and dashed. The legend groups the series by
    family. A run that failed or gave no error is not dropped silently: it is an ``x`` on the
    top edge at its cost (gid ``"failed"``), and its series' legend entry counts them.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    fig, axes = plt.subplots(1, 2, figsize=(16, 6.4), constrained_layout=True)
    axes[0].set_label("time")
    axes[1].set_label("nfev")
    fig.suptitle(f"{wp['title'] or wp['scene']} — work–precision, t ∈ [0, {wp['t_end']:g}] s, "
                 f"error vs {wp['reference']}")
    floor = 1e-16
    groups: dict[str, list] = {}
    for c in wp["curves"]:
        style = _series_style(c)
        pts = [p for p in c.points if p.ok]  # in sweep order: loose to tight
        bad = [p for p in c.points if not p.ok]
        label = c.label + (f" ({len(bad)} failed, x on the top edge)" if bad else "")
        if pts:
            err = [max(p.error, floor) for p in pts]
            axes[0].loglog([p.time for p in pts], err, label=label, **style)
            axes[1].loglog([max(p.nfev, 1) for p in pts], err, **style)
        for ax, cost in zip(axes, ([p.time for p in bad], [max(p.nfev, 1) for p in bad])):
            cost = [x for x in cost if np.isfinite(x)]
            if cost:
                ax.plot(cost, [0.98] * len(cost), ls="none", marker="x", color=style["color"],
                        ms=7, mew=1.5, clip_on=False, transform=ax.get_xaxis_transform(),
                        gid="failed")
        if not pts and not bad:
            continue
        handle = Line2D([], [], **style)
        groups.setdefault(c.family, []).append((handle, label))
    for ax, xlabel in zip(axes, ("wall time per solve [s] (median)", "right-hand-side evaluations")):
        for level in ERROR_LEVELS:
            ax.axhline(level, color="0.85", lw=0.8, zorder=0)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(f"max |ê₃ − ê₃,ref| over the output times (floor {floor:g})")
        ax.grid(True, which="major", color="0.9")
    axes[0].set_title("error vs time (colour = method, marker = formulation)")
    axes[1].set_title("error vs rhs evaluations")
    # One legend, grouped: a bold header line per family, then its series.
    handles, labels = [], []
    order = list(_FAMILY_NAMES)
    for family in sorted(groups, key=lambda f: (order.index(f) if f in order else len(order), f)):
        handles.append(Line2D([], [], ls="none"))
        labels.append(_FAMILY_NAMES.get(family, family))
        for handle, label in groups[family]:
            handles.append(handle)
            labels.append(label)
    if handles:
        legend = fig.legend(handles, labels, fontsize=7, loc="outside right center",
                            handlelength=3.0)
        headers = {_FAMILY_NAMES.get(f, f) for f in groups}
        for text in legend.get_texts():
            if text.get_text() in headers:
                text.set_fontweight("bold")
    return fig


def plot_work_precision(wp: dict, path: Path) -> None:
    """Write :func:`work_precision_figure` to ``path`` (PNG, 100 dpi)."""
    import matplotlib.pyplot as plt

    fig = work_precision_figure(wp)
    try:
        fig.savefig(path, dpi=100)
    finally:
        plt.close(fig)


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
    versions.update({k: v for k, v in bc.peers_available().items()})
    try:
        from importlib.metadata import version

        versions["derive"] = version("derive")
    except Exception:  # noqa: BLE001
        versions["derive"] = "?"
    try:
        commit = "?" if REPO is None else subprocess.run(
            ["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True, cwd=REPO).stdout.strip() or "?"
    except OSError:
        commit = "?"
    return {"cpu": cpu, "cores": os.cpu_count(), "compiler": cc, "platform": platform.platform(),
            "versions": versions, "commit": commit,
            "load_average": list(os.getloadavg()) if hasattr(os, "getloadavg") else None}


# ---------------------------------------------------------------------------------------------
# entry point


def _jsonable(x):
    if isinstance(x, dict):
        return {k: _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, Curve):
        return {"family": x.family, "method": x.method, "formulation": x.formulation,
                "points": [_jsonable(asdict(p)) for p in x.points]}
    if isinstance(x, (np.floating, float)):
        return float(x) if np.isfinite(x) else None
    if isinstance(x, np.integer):
        return int(x)
    if isinstance(x, np.ndarray):
        return _jsonable(x.tolist())
    return x


def write_points(results: dict, out: Path) -> None:
    with open(out / "points.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["scene", "family", "method", "formulation", "setting", "time_s", "nfev", "error", "note"])
        for wp in results["work_precision"]:
            for c in wp["curves"]:
                for p in c.points:
                    w.writerow([p.scene, p.family, p.method, p.formulation, p.setting, f"{p.time:.6g}",
                                p.nfev, f"{p.error:.6g}", p.note])
