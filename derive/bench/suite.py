"""`derive bench`: every part of the benchmark in one run, and the report.

The parts: the kernel speed and work–precision races (:mod:`derive.bench.runner`), the targets
(:mod:`derive.bench.targets`, with the sweep's throughput, :mod:`derive.bench.throughput`), the
Lie–Poisson splittings (:mod:`derive.bench.splitting`); :mod:`derive.bench.report` writes it up.
"""
from __future__ import annotations

import json
import os
import sys
import time
from dataclasses import asdict
from pathlib import Path

from tqdm import tqdm

from derive.bench import contenders as bc
from derive.bench import report as bench_report
from derive.bench import splitting
from derive.bench import targets as bench_targets
from derive.bench.runner import FULL, QUICK, SMOKE, Settings, c_loop, drift, machine, numpy_batch, python_calls
from derive.bench.workprecision import _jsonable, plot_work_precision, work_precision, write_points


def splitting_runs(cfg: Settings) -> list[dict]:
    """Where the Lie–Poisson splitting pays: each (case, measure) of ``cfg.splitting_cases``
    through :func:`derive.bench.splitting.bench_energy` (each method at its cheapest setting that meets
    the target over the periods; a failure is reported, not raised)."""
    rows = []
    for case, measure in tqdm(cfg.splitting_cases, desc="splitting", unit="case", file=sys.stderr):
        try:
            rows.append(splitting.bench_energy(case, periods=cfg.splitting_periods,
                                               target=cfg.splitting_target, measure=measure,
                                               repeat=min(cfg.repeats, 3), budget=cfg.splitting_budget))
        except Exception as exc:  # a failed part is reported; the bench goes on
            rows.append({"case": case, "measure": measure, "failed": f"{type(exc).__name__}: {exc}"})
    return rows


def main(out: Path, quick: bool = False, smoke: bool = False, peers: bool = True) -> dict:
    """Run the benchmarks and write ``out/report.md``, ``out/wp_<scene>.png``, ``out/points.csv``
    and ``out/results.json``. ``quick``: fewer tolerances and repeats (about 2 minutes);
    ``smoke``: a few seconds, for the test suite; ``peers``: race CasADi, PyDy, heyoka and
    numbalsoda too when they are installed. Returns the results (as written to JSON, with the work–precision curves as
    :class:`Curve` objects)."""
    cfg = SMOKE if smoke else QUICK if quick else FULL
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    fams = [f for f in bc.families(peers) if f in cfg.families]
    results: dict = {"settings": {**asdict(cfg)}, "machine": machine(), "families": fams,
                     "peers_missing": [f for f in ("casadi", "pydy", "heyoka", "numbalsoda")
                                       if f not in bc.families(peers)]}

    with tqdm(total=3, desc="kernel speed", unit="part", file=sys.stderr) as bar:
        results["c_loop"] = c_loop(cfg)
        bar.update()
        results["numpy_batch"] = numpy_batch(cfg)
        bar.update()
        results["python_calls"] = python_calls(cfg, fams)
        bar.update()

    results["targets"] = bench_targets.run(cfg, fams)

    results["work_precision"] = []
    for name in cfg.scenes:
        wp = work_precision(cfg, name, fams)
        plot_work_precision(wp, out / f"wp_{name}.png")
        wp["plot"] = f"wp_{name}.png"
        results["work_precision"].append(wp)

    with tqdm(total=4, desc="drift", unit="method", file=sys.stderr) as bar:
        results["drift"] = drift(cfg, bar)

    results["splitting"] = splitting_runs(cfg)

    results["elapsed"] = time.perf_counter() - start
    results["machine"]["load_average_end"] = list(os.getloadavg()) if hasattr(os, "getloadavg") else None
    text = bench_report.write_report(results, out)
    write_points(results, out)
    (out / "results.json").write_text(json.dumps(_jsonable(results), indent=1))
    print(text)
    return results
