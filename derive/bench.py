"""Benchmarks (`derive bench`): what the generated code costs, and what it buys.

Four measurements, written to ``out/`` as ``report.md`` (Markdown tables), one work–precision
plot per scene (``wp_<scene>.png``), every run as ``points.csv`` and everything as
``results.json``:

1. **Kernel speed.** The generated ``heavy_top_rhs`` against ``benchmarks/handwritten_heavy_top.c``
   (the same equations typed from the textbook), each in its own translation unit, called
   through a pointer by ``benchmarks/rhs_loop.c`` over a rotating set of states, both built with
   the same flags; one run per flag set times both back to back, repeat after repeat, and the
   ratio is the median of the paired per-repeat ratios. Then the generated NumPy ``rhs`` on a
   batch of states, and the cost of one call through Python (ctypes, NumPy).
2. **Whole trajectory.** ``simulate`` of the looping top over t ∈ [0, 10] against
   ``scipy.integrate.solve_ivp(method="DOP853")`` on the generated NumPy rhs, SciPy's rtol
   tightened until its error is no larger than ours; and what deriving and compiling cost on a
   first call (fresh cache, warm disk cache) against a cached call.
3. **Work–precision** per scene: every method (ours in C: dop853 over rtol, rk4 / gauss4 /
   gauss6 over h; SciPy's RK45, DOP853, Radau, LSODA on the generated NumPy rhs over rtol) and
   formulation, error = max over the output times of |ê₃ − ê₃,ref| (ref = the exact solution,
   `derive.exact`, else a tight dop853 run) against median wall time and rhs evaluations. The
   cost of an error level on a curve is interpolated log-log between the runs around it, and
   SciPy's best cost is divided by ours: with the same equations (ours in the formulation SciPy
   ran) and with each side's best.
4. **Drift** of energy and momenta over 10⁶ fixed steps (looping top, quaternion formulation).

Wall times are medians of repeats (a run slower than ``long_run`` seconds is timed once). Goals
(kernel ≤ 1.2× hand-written, NumPy ≤ 20 ns/state, trajectory ≥ 50× SciPy) are reported, never
asserted: timings depend on the machine and its load.
"""
from __future__ import annotations

import csv
import json
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

from . import simulation as sim
from .errors import IntegrationError
from .render import ROOT
from .scene import MIN_RTOL, Scene, load_scene

BENCH_SOURCES = ROOT / "benchmarks"
SCENES = ROOT / "scenes"

#: Error levels at which the cost of SciPy's best method is compared with ours.
ERROR_LEVELS = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)
#: atol = ATOL_RATIO * rtol for every adaptive run (ours and SciPy's alike), as in the scenes'
#: defaults (rtol 1e-10, atol 1e-12).
ATOL_RATIO = 1e-2
#: Errors below this are rounding noise: a fixed-step sweep stops refining there.
ERROR_FLOOR = 1e-13

ADAPTIVE = ("dop853",)
FIXED = ("rk4", "gauss4", "gauss6")
SCIPY = ("scipy-rk45", "scipy-dop853", "scipy-radau", "scipy-lsoda")
TOPS = ("reduced", "euler-angles", "quaternion")
#: scene file stem -> the formulations of ours that can run it.
WP_SCENES = {
    "free_symmetric": TOPS,
    "tennis_racket": ("euler-angles", "quaternion"),
    "looping_top": TOPS,
    "cuspidal_top": TOPS,
    "sleeping_top": TOPS,
}
#: The heavy top of the generated C contract: heavy_top_rhs (Euler angles, gravity).
HEAVY_TOP_KEY = ("euler-angles", True, ("gravity",))
TOY_TOP = np.array([1.8e-4, 4.0e-5, 0.1, 9.81, 0.04])  # p = (I1, I3, M, g, l) of the scenes' top

GOAL_KERNEL_RATIO = 1.2
GOAL_NUMPY_NS = 20.0
GOAL_TRAJECTORY_SPEEDUP = 50.0


@dataclass(frozen=True)
class Settings:
    """How much to measure. FULL is `derive bench`, QUICK `--quick`, SMOKE the test suite's."""

    name: str
    rtols: tuple[float, ...]              # adaptive sweeps, loose to tight
    max_refinements: int                  # fixed-step sweeps: h = dt_out / 2**k, k < this
    repeats: int                          # timing repeats per run (median)
    scipy_repeats: int                    # the same for SciPy's runs
    long_run: float                       # s: a run slower than this is timed once
    cap: float                            # s: a sweep stops after a run slower than this
    scenes: tuple[str, ...]
    min_total: float = 0.05               # s: fast runs are repeated until they add up to this
    scipy_methods: tuple[str, ...] = SCIPY
    other_formulations: bool = True       # ours also in the formulations `auto` does not pick
    all_formulations_fixed: bool = True   # ... fixed-step methods too (else dop853 only there)
    scene_overrides: dict = field(default_factory=dict)
    c_flags: tuple[tuple[str, ...], ...] = (("-std=c99", "-O2"), ("-std=c99", "-O3"))
    loop_calls: int = 2_000_000
    loop_repeats: int = 15
    numpy_sizes: tuple[int, ...] = (10_000, 100_000)
    numpy_repeats: int = 15
    python_calls: int = 20_000
    trajectory_t_end: float = 10.0
    trajectory_repeats: int = 3
    first_calls: tuple[str, ...] = ("warm", "cold")  # fresh-process conditions timed
    drift_steps: int = 1_000_000


def _decades(lo: int, hi: int, half: bool) -> tuple[float, ...]:
    step = 0.5 if half else 1.0
    return tuple(float(f"{10.0 ** -(lo + step * i):.3g}") for i in range(int((hi - lo) / step) + 1))


FULL = Settings("full", rtols=_decades(4, 13, half=True), max_refinements=12, repeats=3, scipy_repeats=3,
                long_run=1.0, cap=8.0, scenes=tuple(WP_SCENES))
QUICK = Settings("quick", rtols=_decades(4, 13, half=False), max_refinements=9, repeats=3, scipy_repeats=1,
                 long_run=0.2, cap=0.8, scenes=tuple(WP_SCENES), all_formulations_fixed=False,
                 loop_calls=1_000_000, loop_repeats=9, numpy_repeats=7, python_calls=5_000,
                 trajectory_repeats=1)
SMOKE = Settings("smoke", rtols=(1e-4, 1e-8), max_refinements=2, repeats=1, scipy_repeats=1, long_run=0.0,
                 cap=1.0, scenes=("looping_top",), scipy_methods=("scipy-rk45", "scipy-dop853"),
                 other_formulations=False, all_formulations_fixed=False, scene_overrides={"t_end": 0.2, "samples": 101},
                 loop_calls=20_000, loop_repeats=3, numpy_sizes=(1_000,), numpy_repeats=3,
                 python_calls=200, trajectory_t_end=0.5, trajectory_repeats=1, first_calls=(), min_total=0.0,
                 drift_steps=2_000)


# ---------------------------------------------------------------------------------------------
# timing


def _timed(fn, repeats: int, long_run: float, min_total: float = 0.0):
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


def _per_call(fn, calls: int, blocks: int = 7) -> float:
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


# ---------------------------------------------------------------------------------------------
# a scene in one formulation: the inputs every solver of a comparison gets


class Case:
    """One scene in one formulation: state, parameters and output times for every solver, and
    the outputs of the contract computed from whatever state a solver returns."""

    def __init__(self, scene: Scene, formulation: str):
        self.scene = scene
        self.formulation = formulation
        self.key = (formulation, scene.symmetric, sim.effect_names(scene))
        self.model = sim.model_for(*self.key)
        self.p = sim._params(scene, self.model)
        self.y0 = sim._initial_state(scene, self.model)
        self.t = scene.t_out
        # Built here, not on the first (timed) solve: derivation and compilation are measured
        # separately (see `first_calls`).
        self.kernel = sim.kernel_for(*self.key)
        self.module = sim.numpy_module_for(*self.key)

    def solve(self, method: str, rtol: float | None = None, h: float | None = None):
        """(states at the output times, rhs evaluations); raises IntegrationError."""
        if method in sim.SCIPY_METHODS:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                return sim._solve_scipy(self.module, sim.SCIPY_METHODS[method], self.y0, self.p,
                                        self.t, rtol, ATOL_RATIO * rtol)
        if method in FIXED or method == "dop853_fixed":
            sol = self.kernel.solve(method, self.y0, self.p, self.t, h=h)
        else:
            sol = self.kernel.solve(method, self.y0, self.p, self.t, rtol=rtol, atol=ATOL_RATIO * rtol)
        return sol.y, sol.nfev

    def result(self, Y, method: str = "", nfev: int = 0) -> sim.Result:
        return sim._outputs(self.model, self.module, self.t, Y, self.p, self.scene, method, nfev)


def axis_error(axis: np.ndarray, ref: np.ndarray) -> float:
    """max over the output times of the Euclidean distance between the two axes."""
    return float(np.max(np.linalg.norm(axis - ref, axis=1)))


# ---------------------------------------------------------------------------------------------
# reference solutions


def _rotation(a: float, b: float, c: float) -> np.ndarray:
    """R = Rz(α) Ry(β) Rz(γ): body components -> inertial components."""
    def rz(x):
        return np.array([[np.cos(x), -np.sin(x), 0.0], [np.sin(x), np.cos(x), 0.0], [0.0, 0.0, 1.0]])
    ry = np.array([[np.cos(b), 0.0, np.sin(b)], [0.0, 1.0, 0.0], [-np.sin(b), 0.0, np.cos(b)]])
    return rz(a) @ ry @ rz(c)


def _rates(scene: Scene) -> tuple[float, float, float]:
    i = scene.initial
    if i.has_rates:
        return i.alpha_dot, i.beta_dot, i.gamma_dot
    w1, w2, w3 = i.omega
    s, cg, sg = np.sin(i.beta), np.cos(i.gamma), np.sin(i.gamma)
    ad = (-w1 * cg + w2 * sg) / s
    return ad, w1 * sg + w2 * cg, w3 - ad * np.cos(i.beta)


def exact_axis(scene: Scene, t: np.ndarray) -> np.ndarray | None:
    """ê₃(t) from `derive.exact`, or None when the scene has no closed form there."""
    from . import exact

    b, i = scene.body, scene.initial
    if scene.damping is not None:
        return None
    if scene.gravity is None:
        R0 = _rotation(i.alpha, i.beta, i.gamma)
        w0 = np.array(i.omega, dtype=float)
        if scene.symmetric:
            sol = exact.free_symmetric(b.I1, b.I3, w0, t, R0=R0)
        else:
            sol = exact.free_asymmetric(b.I1, b.I2, b.I3, w0, t, R0=R0)
    elif scene.symmetric:
        g = scene.gravity
        sol = exact.heavy_top(b.I1, b.I3, g.M, g.g, g.l, i.alpha, i.beta, i.gamma, *_rates(scene), t)
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
#: first tenth of the span to be trusted. Only the start is compared: a wrong convention (R0,
#: ω, signs) shows at once, while over the whole span an unstable motion (the tennis racket)
#: amplifies even dop853's error at rtol 1e-13 far above this, and the closed form is then the
#: better of the two. The whole-span difference is reported as `check`.
REFERENCE_RTOL = 1e-13
EXACT_TRUST = 1e-9


def reference(scene: Scene) -> Reference:
    """The exact solution when `derive.exact` has one (cross-checked against dop853 at rtol
    1e-13), else that dop853 run itself."""
    case = Case(scene, sim.choose_formulation(scene))
    Y, _ = case.solve("dop853", rtol=REFERENCE_RTOL)
    numeric = case.result(Y).axis
    num_label = f"dop853 rtol {REFERENCE_RTOL:g} ({case.formulation})"
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            exact = exact_axis(scene, case.t)
    except (ImportError, AttributeError, NotImplementedError, TypeError, ValueError) as exc:
        return Reference(numeric, num_label, None, f"exact solution unavailable ({type(exc).__name__}: {exc})")
    if exact is None:
        return Reference(numeric, num_label, None, "no closed form for this scene")
    head = max(2, len(case.t) // 10)
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


def _heavy_top_sources() -> dict[str, str]:
    from .codegen import model_sources

    model = sim.model_for(*HEAVY_TOP_KEY)
    files = model_sources(model)
    src = {f"{model.name}.h": files[f"c/{model.name}.h"], f"{model.name}.c": files[f"c/{model.name}.c"]}
    for name in ("handwritten_heavy_top.c", "noop_rhs.c", "rhs_loop.c"):
        src[name] = (BENCH_SOURCES / name).read_text()
    return src


def c_loop(cfg: Settings) -> list[dict]:
    """ns/call of generated, hand-written and no-op rhs per flag set (one run each)."""
    from .cbuild import check_compiles

    sources = _heavy_top_sources()
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


def _random_states(n: int, seed: int = 1) -> np.ndarray:
    """Heavy-top states (6, n): β across (0.1, π − 0.1), rates of both signs, fast spin."""
    rng = np.random.default_rng(seed)
    Y = np.empty((6, n))
    Y[0] = rng.uniform(0, 2 * np.pi, n)
    Y[1] = rng.uniform(0.1, np.pi - 0.1, n)
    Y[2] = rng.uniform(0, 2 * np.pi, n)
    Y[3:5] = rng.uniform(-10, 10, (2, n))
    Y[5] = rng.uniform(100, 200, n)
    return Y


def numpy_batch(cfg: Settings) -> list[dict]:
    """ns per state of the generated NumPy rhs on a (6, N) batch, and of its sin + cos alone."""
    mod = sim.numpy_module_for(*HEAVY_TOP_KEY)
    rows = []
    for n in cfg.numpy_sizes:
        Y = _random_states(n)
        beta = Y[1].copy()
        mod.rhs(0.0, Y, TOY_TOP)
        t_rhs, _ = _timed(lambda: mod.rhs(0.0, Y, TOY_TOP), cfg.numpy_repeats, math.inf)
        t_trig, _ = _timed(lambda: (np.sin(beta), np.cos(beta)), cfg.numpy_repeats, math.inf)
        rows.append({"n": n, "ns_per_state": t_rhs / n * 1e9, "sin_cos_ns_per_state": t_trig / n * 1e9})
    return rows


def python_calls(cfg: Settings) -> dict:
    """µs per single-state call through Python: ctypes (Kernel.rhs) and NumPy rhs."""
    kernel = sim.kernel_for(*HEAVY_TOP_KEY)
    mod = sim.numpy_module_for(*HEAVY_TOP_KEY)
    y = _random_states(1)[:, 0].copy()
    return {
        "ctypes_us": _per_call(lambda: kernel.rhs(0.0, y, TOY_TOP), cfg.python_calls) * 1e6,
        "numpy_us": _per_call(lambda: mod.rhs(0.0, y, TOY_TOP), cfg.python_calls) * 1e6,
    }


# ---------------------------------------------------------------------------------------------
# 2. whole trajectories


_COLD_START = r"""
import json, sys, time
t0 = time.perf_counter()
from derive import simulation as sim
from derive.scene import load_scene
t1 = time.perf_counter()
path, over = sys.argv[1], json.loads(sys.argv[2])
sc = load_scene(path, **over)
key = (sim.choose_formulation(sc), sc.symmetric, sim.effect_names(sc))
sim.model_for(*key)
t2 = time.perf_counter()
sim.kernel_for(*key)
t3 = time.perf_counter()
sim.numpy_module_for(*key)
t4 = time.perf_counter()
sim.simulate(path, **over)
t5 = time.perf_counter()
sim.simulate(path, **over)
t6 = time.perf_counter()
print(json.dumps({"import": t1 - t0, "derive": t2 - t1, "kernel": t3 - t2, "numpy": t4 - t3,
                  "first_run": t5 - t4, "first_call": t5 - t1, "cached_call": t6 - t5}))
"""


def first_calls(path: Path, over: dict, conditions: tuple[str, ...]) -> list[dict]:
    """Derive + compile cost in fresh processes: "cold" with an empty compile cache, "warm" with
    the disk cache already holding the library (SymPy still derives, the compiler does not run)."""
    rows = []
    for cond in conditions:
        env = dict(os.environ)
        with tempfile.TemporaryDirectory(prefix="derive-bench-cache-") as tmp:
            if cond == "cold":
                env["DERIVE_CACHE"] = tmp
            out = subprocess.run([sys.executable, "-c", _COLD_START, str(path), json.dumps(over)],
                                 capture_output=True, text=True, env=env, cwd=ROOT)
        label = {"cold": "empty compile cache", "warm": "warm disk cache"}[cond]
        if out.returncode != 0:
            rows.append({"condition": label, "error": (out.stderr.strip().splitlines() or ["?"])[-1]})
            continue
        rows.append({"condition": label, **json.loads(out.stdout.strip().splitlines()[-1])})
    return rows


def trajectory(cfg: Settings, bar=None) -> dict:
    """simulate() of the looping top vs solve_ivp DOP853 on the generated NumPy rhs, SciPy's rtol
    tightened (down to MIN_RTOL) until its axis error is no larger than ours."""
    path = SCENES / "looping_top.toml"
    rtol = 1e-10
    over = {"t_end": cfg.trajectory_t_end, "samples": 1001, "rtol": rtol, "atol": ATOL_RATIO * rtol}
    scene = load_scene(path, **over)
    ref = reference(scene)
    sim.simulate(path, **over)  # in-process: derive, compile (or load), run
    t_ours, res = _timed(lambda: sim.simulate(path, **over), max(5, cfg.repeats), math.inf)
    err_ours = axis_error(res.axis, ref.axis)
    case = Case(scene, res.formulation)
    t_kernel, _ = _timed(lambda: case.solve("dop853", rtol=rtol), max(5, cfg.repeats), math.inf)
    if bar:
        bar.update()

    tried = []
    r = rtol
    while True:
        over_s = dict(over, method="scipy-dop853", rtol=r, atol=ATOL_RATIO * r)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            t_s, res_s = _timed(lambda: sim.simulate(path, **over_s), 1, math.inf)
        err = axis_error(res_s.axis, ref.axis)
        tried.append({"rtol": r, "time": t_s, "error": err, "nfev": res_s.nfev})
        if err <= err_ours or r <= MIN_RTOL:
            break
        r = max(MIN_RTOL, r / 2)
    times = [t_s]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for _ in range(cfg.trajectory_repeats - 1):
            times.append(_timed(lambda: sim.simulate(path, **over_s), 1, math.inf)[0])
    t_s = statistics.median(times)
    if bar:
        bar.update()
    starts = first_calls(path, over, cfg.first_calls)
    if bar:
        bar.update()
    return {
        "scene": "looping_top", "t_end": cfg.trajectory_t_end, "samples": 1001, "reference": ref.label,
        "reference_note": ref.note,
        "ours": {"method": res.method, "formulation": res.formulation, "rtol": rtol, "time": t_ours,
                 "kernel_time": t_kernel, "error": err_ours, "nfev": res.nfev},
        "scipy": {"method": "DOP853", "rtol": r, "time": t_s, "error": tried[-1]["error"],
                  "nfev": tried[-1]["nfev"], "tried": tried},
        "speedup": t_s / t_ours,
        "first_calls": starts,
    }


# ---------------------------------------------------------------------------------------------
# 3. work–precision


@dataclass
class Point:
    scene: str
    family: str          # "ours" | "scipy"
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


def _run_point(case: Case, ref: Reference, name: str, family: str, method: str, cfg: Settings,
               rtol=None, h=None) -> Point:
    setting = f"rtol={rtol:.3g}" if h is None else f"h={h:.4g}"
    try:
        repeats = cfg.scipy_repeats if family == "scipy" else cfg.repeats
        t_run, (Y, nfev) = _timed(lambda: case.solve(method, rtol=rtol, h=h), repeats, cfg.long_run,
                                  cfg.min_total)
        err = axis_error(case.result(Y).axis, ref.axis)
        note = ""
    except (IntegrationError, ValueError) as exc:
        t_run, nfev, err, note = math.nan, 0, math.nan, str(exc).splitlines()[0]
    return Point(name, family, method, case.formulation, setting, t_run, int(nfev), err, note)


def sweep(case: Case, ref: Reference, name: str, method: str, cfg: Settings) -> Curve:
    """One method in one formulation over its tolerances (adaptive) or step sizes (fixed)."""
    family = "scipy" if method in SCIPY else "ours"
    points = []
    if method in FIXED:
        dt_out = float(case.t[1] - case.t[0])
        prev = math.inf
        for k in range(cfg.max_refinements):
            # h a hair above dt_out / 2**k, so each output interval takes exactly 2**k steps.
            pt = _run_point(case, ref, name, family, method, cfg, h=dt_out / 2**k * (1 + 1e-9))
            points.append(pt)
            if pt.ok and (pt.error < ERROR_FLOOR or pt.time > cfg.cap
                          or (pt.error < 1e-10 and pt.error > 0.5 * prev)):  # rounding-limited
                break
            prev = pt.error if pt.ok else math.inf
    else:
        for rtol in cfg.rtols:
            pt = _run_point(case, ref, name, family, method, cfg, rtol=rtol)
            points.append(pt)
            if pt.ok and pt.time > cfg.cap:
                break
    return Curve(family, method, case.formulation, points)


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


def compare(curves: list[Curve], level: float, formulation: str | None = None) -> dict:
    """SciPy's best cost over ours at one error level; ``formulation`` restricts ours to the
    formulation SciPy ran (same equations on both sides)."""
    to, bo, lo = best_at(curves, "ours", level, formulation)
    ts, bs, ls = best_at(curves, "scipy", level)
    row = {"level": level, "ours": lo, "ours_time": to, "ours_bound": bo,
           "scipy": ls, "scipy_time": ts, "scipy_bound": bs, "ratio": None, "kind": ""}
    if to is None:
        row["kind"] = "ours n/a"
    elif ts is None:
        slowest = max((p.time for c in curves if c.family == "scipy" for p in c.points if p.ok), default=None)
        if slowest is not None:
            row.update(ratio=slowest / to, kind=">")  # SciPy did not get there within its sweep
        else:
            row["kind"] = "scipy n/a"
    else:
        row.update(ratio=ts / to, kind="*" if (bo or bs) else "")
    return row


def work_precision(cfg: Settings, name: str) -> dict:
    """Every method × formulation on one scene, against its reference; SciPy in the auto
    formulation; ours in every formulation that can run the scene (see Settings)."""
    scene = load_scene(SCENES / f"{name}.toml", **cfg.scene_overrides)
    ref = reference(scene)
    auto = sim.choose_formulation(scene)
    forms = [auto] + ([f for f in WP_SCENES[name] if f != auto] if cfg.other_formulations else [])
    plan = []
    for form in forms:
        try:
            case = Case(scene, form)
        except ValueError as exc:  # a formulation that cannot take this scene (SceneError too)
            tqdm.write(f"{name}: {form}: skipped ({exc})")
            continue
        methods = list(ADAPTIVE) + (list(FIXED) if (form == auto or cfg.all_formulations_fixed) else [])
        methods += list(cfg.scipy_methods) if form == auto else []
        plan += [(case, method) for method in methods]
    curves = []
    with tqdm(plan, desc=f"work-precision {name}", unit="curve", file=sys.stderr) as bar:
        for case, method in bar:
            bar.set_postfix_str(f"{method} / {case.formulation}")
            curves.append(sweep(case, ref, name, method, cfg))
    return {"scene": name, "title": scene.title, "auto": auto, "reference": ref.label,
            "reference_check": ref.check, "reference_note": ref.note, "curves": curves,
            "ratios": [compare(curves, level) for level in ERROR_LEVELS],
            "ratios_same": [compare(curves, level, auto) for level in ERROR_LEVELS],
            "t_end": scene.simulate.t_end, "samples": scene.simulate.samples}


_COLORS = {"dop853": "C0", "rk4": "C1", "gauss4": "C2", "gauss6": "C3",
           "scipy-rk45": "C4", "scipy-dop853": "C5", "scipy-radau": "C6", "scipy-lsoda": "C7"}
_STYLES = {"reduced": "-", "euler-angles": "--", "quaternion": ":"}


def plot_work_precision(wp: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(14, 5.6), constrained_layout=True)
    fig.suptitle(f"{wp['title'] or wp['scene']} — work–precision, t ∈ [0, {wp['t_end']:g}] s, "
                 f"error vs {wp['reference']}")
    for c in wp["curves"]:
        pts = [p for p in c.points if p.ok]  # in sweep order: loose to tight
        if not pts:
            continue
        err = [max(p.error, 1e-17) for p in pts]
        style = dict(color=_COLORS.get(c.method, "k"), ls=_STYLES.get(c.formulation, "-"),
                     marker="s" if c.family == "scipy" else "o", ms=4, lw=1.3,
                     mfc="none" if c.family == "scipy" else None)
        axes[0].loglog([p.time for p in pts], err, label=c.label, **style)
        axes[1].loglog([max(p.nfev, 1) for p in pts], err, **style)
    for ax, xlabel in zip(axes, ("wall time [s] (median)", "right-hand-side evaluations")):
        for level in ERROR_LEVELS:
            ax.axhline(level, color="0.85", lw=0.8, zorder=0)
        ax.set_xlabel(xlabel)
        ax.set_ylabel("max |ê₃ − ê₃,ref| over the output times")
        ax.grid(True, which="major", color="0.9")
    axes[0].set_title("error vs time (ours: filled circles, SciPy: open squares)")
    axes[1].set_title("error vs rhs evaluations")
    axes[0].legend(fontsize=7, ncol=2, loc="best")
    fig.savefig(path, dpi=110)
    plt.close(fig)


# ---------------------------------------------------------------------------------------------
# 4. drift of the invariants


DRIFT_H = 5e-4  # s: 1e6 steps = 500 s of the looping top, ~ 2600 nutations, 84 steps per spin turn


def drift(cfg: Settings, bar=None) -> dict:
    """max |ΔE/E₀|, |Δp_α/p_α₀|, |Δp_γ/p_γ₀| and ||q| − 1| over ``drift_steps`` fixed steps
    (looping top, quaternion formulation: neither momentum is built in), and dop853 adaptive
    over the same span."""
    t_end = cfg.drift_steps * DRIFT_H
    scene = load_scene(SCENES / "looping_top.toml", t_end=t_end, samples=1001, formulation="quaternion")
    case = Case(scene, "quaternion")
    rows = []
    for method in ("rk4", "gauss4", "gauss6", "dop853_fixed", "dop853"):
        t0 = time.perf_counter()
        try:
            if method == "dop853":
                sol = case.kernel.solve(method, case.y0, case.p, case.t, rtol=1e-10, atol=1e-12)
                setting = "rtol=1e-10"
            else:
                sol = case.kernel.solve(method, case.y0, case.p, case.t, h=DRIFT_H * (1 + 1e-9))
                setting = f"h={DRIFT_H:g}"
        except IntegrationError as exc:
            rows.append({"method": method, "error": str(exc)})
            continue
        elapsed = time.perf_counter() - t0
        res = case.result(sol.y)

        def rel(x):
            return float(np.max(np.abs(x - x[0])) / abs(x[0]))

        rows.append({"method": method, "setting": setting, "steps": sol.nstep, "nfev": sol.nfev,
                     "time": elapsed, "energy": rel(res.energy),
                     "energy_end": float((res.energy[-1] - res.energy[0]) / abs(res.energy[0])),
                     "p_alpha": rel(res.p_alpha), "p_gamma": rel(res.p_gamma),
                     "qnorm": float(np.max(np.abs(np.linalg.norm(sol.y[:, :4], axis=1) - 1)))})
        if bar:
            bar.update()
    return {"scene": "looping_top", "formulation": "quaternion", "t_end": t_end, "h": DRIFT_H, "rows": rows}


# ---------------------------------------------------------------------------------------------
# report


def _f(x, fmt="{:.3g}", none="—") -> str:
    if x is None or (isinstance(x, float) and not np.isfinite(x)):
        return none
    return fmt.format(x)


def _t(seconds) -> str:
    """A wall time with a readable unit."""
    if seconds is None or not np.isfinite(seconds):
        return "—"
    if seconds < 1e-3:
        return f"{seconds * 1e6:.0f} µs"
    if seconds < 1:
        return f"{seconds * 1e3:.3g} ms"
    return f"{seconds:.3g} s"


def _verdict(ok: bool) -> str:
    return "met" if ok else "**not met**"


def _machine() -> dict:
    cpu = platform.processor() or ""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    try:
        from .cbuild import compiler

        cc = subprocess.run([*compiler(), "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    except (OSError, IndexError):
        cc = "?"
    import scipy

    return {"cpu": cpu, "cores": os.cpu_count(), "compiler": cc, "python": platform.python_version(),
            "numpy": np.__version__, "scipy": scipy.__version__,
            "load_average": os.getloadavg() if hasattr(os, "getloadavg") else None}


def _ratio_cell(row: dict) -> str:
    if row["ratio"] is None:
        return row["kind"] or "—"
    prefix = "> " if row["kind"] == ">" else ""
    star = "\\*" if row["kind"] == "*" else ""
    return f"{prefix}{row['ratio']:.3g}×{star}"


def goals(results: dict) -> list[tuple[str, str, bool]]:
    """(goal, measured, met) for the targets the bench reports on."""
    out = []
    worst = max(results["c_loop"], key=lambda r: r["ratio"])
    out.append((f"generated C rhs ≤ {GOAL_KERNEL_RATIO:g}× hand-written",
                ", ".join(f"{r['ratio']:.2f}× (`{r['flags']}`)" for r in results["c_loop"]),
                worst["ratio"] <= GOAL_KERNEL_RATIO))
    big = max(results["numpy_batch"], key=lambda r: r["n"])
    out.append((f"NumPy batch rhs ≤ {GOAL_NUMPY_NS:g} ns/state (N = {big['n']:,})",
                f"{big['ns_per_state']:.0f} ns/state (sin + cos alone {big['sin_cos_ns_per_state']:.0f})",
                big["ns_per_state"] <= GOAL_NUMPY_NS))
    tr = results["trajectory"]
    out.append((f"whole trajectory ≥ {GOAL_TRAJECTORY_SPEEDUP:g}× `solve_ivp` DOP853 at equal error",
                f"{tr['speedup']:.0f}×", tr["speedup"] >= GOAL_TRAJECTORY_SPEEDUP))
    return out


def write_report(results: dict, out: Path) -> str:
    m, cfg = results["machine"], results["settings"]
    L = [f"# derive bench ({cfg['name']})", "",
         f"{m['cpu']}, {m['cores']} cores; {m['compiler']}; Python {m['python']}, NumPy {m['numpy']}, "
         f"SciPy {m['scipy']}. Load average at the start: "
         f"{', '.join(f'{x:.2f}' for x in m['load_average']) if m['load_average'] else '?'}. "
         f"Total bench time {results['elapsed']:.0f} s.", ""]
    L += ["| goal | measured | |", "|---|---|---|"] + [f"| {g} | {v} | {_verdict(ok)} |" for g, v, ok in goals(results)]
    L.append("")

    # 1
    L += ["## 1. Kernel speed", "",
          "`heavy_top_rhs` (generated) vs `benchmarks/handwritten_heavy_top.c` (the textbook equations "
          "by hand), each in its own translation unit, called through a pointer by `benchmarks/rhs_loop.c` "
          f"over 4096 rotating states; {results['c_loop'][0]['calls']:,} calls per timing, "
          f"{results['c_loop'][0]['repeats']} interleaved repeats, medians. Ratio = median of the "
          "per-repeat ratios. The no-op rhs is the loop's own cost (call, state rotation, accumulation).", "",
          "| flags | generated ns/call | hand-written ns/call | no-op ns/call | generated / hand | goal ≤ 1.2 | max rel. difference |",
          "|---|---|---|---|---|---|---|"]
    for r in results["c_loop"]:
        L.append(f"| `{r['flags']}` | {r['generated_ns']:.2f} | {r['handwritten_ns']:.2f} | {r['noop_ns']:.2f} | "
                 f"{r['ratio']:.3f} | {_verdict(r['ratio'] <= GOAL_KERNEL_RATIO)} | {r['max_rel_diff']:.1e} |")
    L += ["", "Generated NumPy `rhs(t, y, p)` on a batch `y` of shape (6, N) (median of repeats); "
              "the sin + cos column is `np.sin(beta)` and `np.cos(beta)` alone on the same N.", "",
          "| N | ns/state | of which sin + cos | goal ≤ 20 ns/state |", "|---|---|---|---|"]
    for r in results["numpy_batch"]:
        goal = _verdict(r["ns_per_state"] <= GOAL_NUMPY_NS) if r["n"] >= 100_000 else ""
        L.append(f"| {r['n']:,} | {r['ns_per_state']:.1f} | {r['sin_cos_ns_per_state']:.1f} | {goal} |")
    pc = results["python_calls"]
    L += ["", f"One state through Python: `Kernel.rhs` (ctypes) {pc['ctypes_us']:.1f} µs/call, "
              f"NumPy `rhs` {pc['numpy_us']:.1f} µs/call — "
              f"{pc['ctypes_us'] * 1e3 / results['c_loop'][-1]['generated_ns']:.0f}× and "
              f"{pc['numpy_us'] * 1e3 / results['c_loop'][-1]['generated_ns']:.0f}× the C call: "
              "why the integration loops run in C.", ""]

    # 2
    tr = results["trajectory"]
    o, s = tr["ours"], tr["scipy"]
    L += ["## 2. Whole trajectory", "",
          f"Looping top, t ∈ [0, {tr['t_end']:g}] s, {tr['samples']} samples; error = max |ê₃ − ê₃,ref| "
          f"against {tr['reference']}{' (' + tr['reference_note'] + ')' if tr['reference_note'] else ''}. "
          "Both through `derive.simulate` (same scene, same formulation, same outputs); SciPy's rtol "
          "halved from 1e-10 until its error was no larger than ours.", "",
          "| solver | formulation | rtol | wall time | error | rhs evaluations |", "|---|---|---|---|---|---|",
          f"| ours: `simulate` {o['method']} (C) | {o['formulation']} | {o['rtol']:g} | {_t(o['time'])} "
          f"(C solve alone {_t(o['kernel_time'])}) | {o['error']:.2e} | {o['nfev']:,} |",
          f"| `solve_ivp` DOP853 on the NumPy rhs | {o['formulation']} | {s['rtol']:.3g} | {_t(s['time'])} | "
          f"{s['error']:.2e} | {s['nfev']:,} |", "",
          f"**Speed-up {tr['speedup']:.0f}×** at equal or better error (goal ≥ {GOAL_TRAJECTORY_SPEEDUP:g}×: "
          f"{_verdict(tr['speedup'] >= GOAL_TRAJECTORY_SPEEDUP)}).", ""]
    if tr["first_calls"]:
        L += ["Derive + compile, in a fresh Python process (import excluded): the SymPy derivation, then "
              "code generation and the C build (or loading it from the disk cache), then the NumPy module, "
              "then the first and a second (cached) `simulate`.", "",
              "| condition | import | derive | C kernel | NumPy module | first `simulate` total | cached `simulate` |",
              "|---|---|---|---|---|---|---|"]
        for r in tr["first_calls"]:
            if "error" in r:
                L.append(f"| {r['condition']} | failed: {r['error']} ||||||")
                continue
            L.append(f"| {r['condition']} | {_t(r['import'])} | {_t(r['derive'])} | {_t(r['kernel'])} | "
                     f"{_t(r['numpy'])} | {_t(r['first_call'])} | {_t(r['cached_call'])} |")
        L.append("")

    # 3
    L += ["## 3. Work–precision", "",
          "Error = max over the output times of |ê₃ − ê₃,ref|. Ours (C): dop853 over rtol "
          f"{cfg['rtols'][0]:g} … {cfg['rtols'][-1]:g}, rk4 / gauss4 / gauss6 over h = Δt_out / 2^k, in every "
          "formulation that can run the scene"
          + ("" if cfg["all_formulations_fixed"] else " (fixed-step methods in the auto formulation only)")
          + "; SciPy (`solve_ivp` on the generated NumPy rhs, Jacobian given to Radau and LSODA) over the "
          f"same rtols, in the formulation `auto` picks. atol = {ATOL_RATIO:g} · rtol. Wall time = median of "
          f"{cfg['repeats']} runs for ours (more for runs under {cfg['min_total'] * 1e3:g} ms in all), "
          f"{cfg['scipy_repeats']} for SciPy's; a run over {cfg['long_run']:g} s is timed once, and a sweep "
          f"stops after a run over {cfg['cap']:g} s. Cost at an error level: log-log interpolation on each "
          "method's curve (`points.csv` has every run). Ratio = SciPy's best / ours' best.", "",
          "\\* = the cheapest run of at least one side was already below the level (its time is an upper "
          "bound); > = SciPy did not reach the level within its sweep (ratio against its slowest run); "
          "n/a = no run of ours reached it.", ""]
    levels = " | ".join(f"{lv:.0e}" for lv in ERROR_LEVELS)
    for key, what in (("ratios_same", "Same equations on both sides (ours restricted to the auto formulation):"),
                      ("ratios", "Each side's best (ours may use another formulation than SciPy's):")):
        L += [what, "", f"| scene | auto formulation | {levels} |", "|" + "---|" * (2 + len(ERROR_LEVELS))]
        for wp in results["work_precision"]:
            L.append(f"| {wp['scene']} | {wp['auto']} | " + " | ".join(_ratio_cell(r) for r in wp[key]) + " |")
        L.append("")
    L += ["References (error 0 against them is the goal): the exact solution (`derive.exact`) where it "
          f"exists, cross-checked against dop853 at rtol {REFERENCE_RTOL:g}.", "",
          "| scene | reference | max difference exact vs dop853 | note |", "|---|---|---|---|"]
    for wp in results["work_precision"]:
        L.append(f"| {wp['scene']} | {wp['reference']} | {_f(wp['reference_check'], '{:.1e}')} | "
                 f"{wp['reference_note']} |")
    L.append("")
    for wp in results["work_precision"]:
        L += [f"### {wp['scene']} — {wp['title']}", "",
              f"t ∈ [0, {wp['t_end']:g}] s, {wp['samples']} samples; auto formulation: {wp['auto']}; "
              f"reference: {wp['reference']}.", "",
              f"![work-precision {wp['scene']}](wp_{wp['scene']}.png)", "",
              "| error ≤ | ours best (any formulation) | time | ours best (auto formulation) | time | "
              "SciPy best | time | SciPy / ours (same) | SciPy / ours (any) |",
              "|---|---|---|---|---|---|---|---|---|"]
        for r, q in zip(wp["ratios"], wp["ratios_same"]):
            L.append(f"| {r['level']:.0e} | {r['ours'] or '—'} | {('≤ ' if r['ours_bound'] else '') + _t(r['ours_time'])} | "
                     f"{q['ours'] or '—'} | {('≤ ' if q['ours_bound'] else '') + _t(q['ours_time'])} | "
                     f"{r['scipy'] or '—'} | {('≤ ' if r['scipy_bound'] else '') + _t(r['scipy_time'])} | "
                     f"{_ratio_cell(q)} | {_ratio_cell(r)} |")
        L.append("")

    # 4
    d = results["drift"]
    L += ["## 4. Drift of the invariants", "",
          f"Looping top in the **{d['formulation']}** formulation (energy, p_α and p_γ are all computed from "
          f"the state, none is built in), t ∈ [0, {d['t_end']:g}] s; fixed-step methods with h = {d['h']:g} s, "
          "dop853 adaptive over the same span. Max over 1001 output times of the relative change. "
          "p_γ = I₃ω̃₃ stays exact for every method: for a symmetric body its equation is ω̃̇₃ = 0.", "",
          "| method | setting | steps | rhs evaluations | wall time | max ΔE/E₀ | ΔE/E₀ at the end | max Δp_α/p_α₀ | max Δp_γ/p_γ₀ | max \\|\\|q\\| − 1\\| |",
          "|---|---|---|---|---|---|---|---|---|---|"]
    for r in d["rows"]:
        if "error" in r:
            L.append(f"| {r['method']} | failed: {r['error']} |||||||||")
            continue
        L.append(f"| {r['method']} | {r['setting']} | {r['steps']:,} | {r['nfev']:,} | {_t(r['time'])} | "
                 f"{r['energy']:.2e} | {r['energy_end']:+.2e} | {r['p_alpha']:.2e} | {r['p_gamma']:.2e} | {r['qnorm']:.2e} |")
    L.append("")
    text = "\n".join(L)
    (out / "report.md").write_text(text)
    return text


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


# ---------------------------------------------------------------------------------------------
# entry point


def main(out: Path, quick: bool = False, smoke: bool = False) -> dict:
    """Run the benchmarks and write ``out/report.md``, ``out/wp_<scene>.png``, ``out/points.csv``
    and ``out/results.json``. ``quick``: fewer tolerances and repeats (about 2 minutes);
    ``smoke``: a few seconds, for the test suite. Returns the results (as written to JSON, with
    the work–precision curves as :class:`Curve` objects)."""
    cfg = SMOKE if smoke else QUICK if quick else FULL
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    results: dict = {"settings": {**asdict(cfg)}, "machine": _machine()}

    with tqdm(total=3, desc="kernel speed", unit="part", file=sys.stderr) as bar:
        results["c_loop"] = c_loop(cfg)
        bar.update()
        results["numpy_batch"] = numpy_batch(cfg)
        bar.update()
        results["python_calls"] = python_calls(cfg)
        bar.update()

    with tqdm(total=3, desc="whole trajectory", unit="part", file=sys.stderr) as bar:
        results["trajectory"] = trajectory(cfg, bar)

    results["work_precision"] = []
    for name in cfg.scenes:
        wp = work_precision(cfg, name)
        plot_work_precision(wp, out / f"wp_{name}.png")
        wp["plot"] = f"wp_{name}.png"
        results["work_precision"].append(wp)

    with tqdm(total=5, desc="drift", unit="method", file=sys.stderr) as bar:
        results["drift"] = drift(cfg, bar)

    results["elapsed"] = time.perf_counter() - start
    text = write_report(results, out)
    write_points(results, out)
    (out / "results.json").write_text(json.dumps(_jsonable(results), indent=1))
    print(text)
    return results
