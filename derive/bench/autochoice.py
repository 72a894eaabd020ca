"""Does ``method = "auto"`` pick the faster method? (a report of ``derive bench``)

For a few example scenes of different shapes (the reference heavy top at its 1001 samples and at
11, an off-axis asymmetric top, a damped top, the tennis racket) and each tolerance of
``LEVELS``, the same scene is prepared three times — ``method = "dop853"``, ``"taylor"`` and
``"auto"`` — and the three prepared runs are timed in turns (blocks of calls alternating, median
per side), so a change of machine load hits them alike. The row says which method auto chose
(:func:`derive.sim.plan.make`, by the cost model of :mod:`derive.methods.costs`), which one was
faster, and auto's time over the faster one's: 1.0 when the choice was right, the price of the
wrong choice otherwise.
"""
from __future__ import annotations

import warnings

from derive.bench import timing
from derive.bench.contenders import scene_data
from derive.sim import examples
import derive

#: The tolerances raced (atol = rtol / 100, as the scenes' defaults relate them).
LEVELS = (1e-6, 1e-8, 1e-10, 1e-12)

#: (label, example name, [simulate] overrides): shapes that pull the choice different ways.
SCENES = (
    ("reference top, 1001 samples", "reference_top", {}),
    ("reference top, 11 samples", "reference_top", {"samples": 11}),
    ("off-axis asymmetric top", "off_axis_top", {}),
    ("damped top", "damped_top", {}),
    ("tennis racket", "tennis_racket", {}),
)


def _variant(data: dict, method: str, rtol: float, extra: dict) -> dict:
    sim = dict(data.get("simulate", {}), **extra, method=method, rtol=rtol, atol=rtol / 100)
    return dict(data, simulate=sim)


def bench_auto_choice(levels=LEVELS, scenes=SCENES, blocks: int = 5) -> dict:
    """Rows ``{scene, rtol, chose, faster, dop853, taylor, auto, auto_over_best}`` (times in s
    per prepared run) and ``right``: how many rows auto chose the faster method, or one within
    10 % of it (a tie)."""
    rows = []
    for label, name, extra in scenes:
        data = scene_data(examples.path(name))
        for rtol in levels:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                prepared = {m: derive.prepare(_variant(data, m, rtol, extra))
                            for m in ("dop853", "taylor", "auto")}
                fns = [prepared[m].run for m in ("dop853", "taylor", "auto")]
                t_d, t_t, t_a = timing.interleaved(fns, 0, blocks=blocks, counts=timing.block_counts(fns, most=5_000))
            best = min(t_d, t_t)
            rows.append({"scene": label, "rtol": rtol, "chose": prepared["auto"].plan.method,
                         "faster": "dop853" if t_d <= t_t else "taylor", "dop853": t_d,
                         "taylor": t_t, "auto": t_a, "auto_over_best": t_a / best})
    right = sum(1 for r in rows if r["chose"] == r["faster"]
                or min(r["dop853"], r["taylor"]) * 1.1 >= r[r["chose"]])
    return {"rows": rows, "right": right, "total": len(rows)}
