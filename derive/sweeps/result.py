"""A sweep's result (one row per point) and its files, written all or nothing.

Takes: the measures of every point. Gives: :class:`SweepResult`, its table and plot.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from derive.sim.outputs import TABLE_FORMATS, write_data_and_plot
from derive.sweeps.maps import plot_sweep


@dataclass
class SweepResult:
    """``params`` and ``measures``: {name: (N,) array}, one entry per point (grid points in C
    order, the first varied key slowest); ``status``: (N,) str, "ok" or why the point failed;
    ``formulation``: (N,) str, the formulation whose run gave the point's numbers ("" for a
    point not run: invalid); ``model``: the models that ran any point, in the order tried."""
    params: dict
    measures: dict
    status: np.ndarray
    keys: tuple
    shape: tuple | None
    measure_names: tuple
    title: str = ""
    source: str = ""
    model: str = ""
    scene: object = field(default=None, repr=False)
    files: tuple = ()  # the files the sweep read (outputs may not replace them: ``write``)
    formulation: np.ndarray = field(default=None, repr=False)

    @property
    def ok(self) -> np.ndarray:
        return self.status == "ok"

    def to_pandas(self):
        """The sweep as a ``pandas.DataFrame``: a column per varied key, per measure column, and
        ``status``; one row per point."""
        import pandas as pd

        cols = {**self.params, **self.measures, "status": self.status.astype(str)}
        return pd.DataFrame(cols)


def write(result: SweepResult, parquet: str | None, png: str | None = None,
          measure: str | None = None) -> None:
    """The table (one row per point: .parquet, or .csv with one header row) and the plot (.png,
    .pdf or .svg), each in the format its extension names, all or nothing; neither may be a
    file the sweep read (``result.files``: SceneError naming both)."""
    write_data_and_plot(
        parquet, {"parquet": lambda f: result.to_pandas().to_parquet(f, engine="pyarrow", index=False),
                  # repr: the shortest text that reads back to the same double
                  "csv": lambda f: result.to_pandas().to_csv(f, index=False, float_format=lambda x: repr(float(x)),
                                                             na_rep="nan")},
        TABLE_FORMATS, png, lambda fmt: lambda f: plot_sweep(result, f, measure, fmt), inputs=result.files)
