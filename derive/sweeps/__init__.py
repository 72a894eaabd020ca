"""Stage 6, sweeps: many motions of one scene, measured while they are integrated.

Takes: a sweep (a TOML path, an example's name, or a dict: a base scene, the keys to vary, the
measures). Gives: a :class:`~derive.sweeps.engine.SweepResult` (one row per point, a column per
varied key and per measure) and its Parquet file; run locally in processes or on a Dask cluster
(:mod:`~derive.sweeps.engine`). The measures are a registry compiled into the C loop
(:mod:`~derive.sweeps.measures`); the variable keys and their units are
:mod:`~derive.sweeps.keys`; the maps are :mod:`~derive.sweeps.maps`.

May import: :mod:`derive.sim` and every stage below it, :mod:`derive.errors`.
"""
