"""Work–precision (``derive bench`` part 3): per scene, the cost of each error level for derive
(every method and formulation that can run the scene) and for the contenders, the ratios at the
target levels, and the figure.

Takes: a :class:`derive.bench.runner.Settings` and a scene. Gives: the curves, the comparisons
and ``wp_<scene>.png``.
"""
from __future__ import annotations

import csv
import math
import sys
import warnings
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
from tqdm import tqdm

import derive
from derive.bench import contenders as bc
from derive.bench.runner import (ADAPTIVE, ATOL_RATIO, ERROR_FLOOR, ERROR_LEVELS, FIXED, SCENES, WP_SCENES,
                                 Reference, Settings, axis_error, our_formulations, ours, reference)
from derive.errors import IntegrationError
from derive.bench.timing import timed


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
    sim = dict(bc.scene_data(path)["simulate"], **cfg.scene_overrides)
    t_end, samples = float(sim["t_end"]), int(sim.get("samples", 1001))
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
