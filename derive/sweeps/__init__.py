"""Stage 6, sweeps: many motions of one scene, measured while they are integrated.

Takes: a sweep (a TOML path, an example's name, or a dict: a base scene, the keys to vary, the
measures). Gives: a :class:`~derive.sweeps.result.SweepResult` (one row per point, a column per
varied key and per measure) and its Parquet file (:mod:`~derive.sweeps.result`). The stages:
the sweep read and validated (:mod:`~derive.sweeps.spec`), every point as numbers
(:mod:`~derive.sweeps.points`), the formulations and method (:mod:`~derive.sweeps.plan`), one
task (:mod:`~derive.sweeps.tasks`) run by the local engine (:mod:`~derive.sweeps.local`) or on
a Dask cluster (:mod:`~derive.sweeps.cluster`), all driven by :mod:`~derive.sweeps.engine`. The measures are a registry compiled into the C loop
(:mod:`~derive.sweeps.measures`); the variable keys and their units are
:mod:`~derive.sweeps.keys`; the maps are :mod:`~derive.sweeps.maps`.

May import: :mod:`derive.sim` and every stage below it, :mod:`derive.errors`.
"""
