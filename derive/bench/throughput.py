"""The sweep's throughput against SciPy per trajectory, and the local and Dask engines against
each other (a report of ``derive bench``, never a timed test).
"""
from __future__ import annotations

import time

import numpy as np

from derive.bench.contenders import baselines
from derive.bench.reference import reference_data
from derive.sim.scene import load_scene
from derive.sweeps import measures as ms
from derive.sweeps.spec import load
from derive.sweeps.cluster import local_cluster
from derive.sweeps.tasks import run_chunk
from derive.sweeps.engine import sweep


def bench_throughput(n: int = 2000, t_end: float = 10.0, rtol: float = 1e-8, scipy_n: int = 20,
                     engines: bool = False, big: int = 100_000, repeat: int = 2) -> dict:
    """Figures for the sweep targets, on the reference heavy top (I1 = 1, I3 = 0.5, M g l = 1,
    β₀ = 0.8, α̇₀ = −0.4, β̇₀ = 0.3, γ̇₀ = 6, random β₀ ∈ [0.3, 1.2]):

    * ``per_traj_sweep`` (s): one process, the measured loop (beta extrema, energy drift, nfev);
    * ``per_traj_scipy`` (s): ``solve_ivp(DOP853)`` with the bench's plain-Python scalar
      right-hand side of the Euler-angle equations (``derive/bench/baselines/scipy_baselines.py``: math.sin,
      the state as floats, returns a list), same rtol, atol 1e-12; the two timed in turns over
      five blocks, medians;
    * with ``engines``: ``big`` points through the local engine with 2 processes, a LocalCluster
      with 1 and with 2 workers (cluster start-up excluded: timed from submission); the best of
      ``repeat`` runs each, interleaved so that a neighbour's load hits them alike.
    """
    from scipy.integrate import solve_ivp

    def spec(num, seed=1):
        scene = reference_data(t_end)
        scene["simulate"] = {"t_end": t_end, "rtol": rtol, "atol": 1e-12}
        return {"scene": scene,
                "random": {"n": num, "seed": seed, "initial": {"beta": {"low": 0.3, "high": 1.2}}},
                "measures": ["beta_max", "beta_min", "energy_drift", "nfev"]}

    sweep(spec(10), processes=1)  # compile and load

    # the bench's hand-written plain-Python rhs (derive/bench/baselines/scipy_baselines.py), at the reference
    # scene's numbers
    ref = load_scene(reference_data(t_end))
    v, ini = ref.param_values(), ref.initial
    rhs = baselines().euler_top_rhs(v["I1"], v["I3"], v["M"] * v["g"] * v["l"])

    # In turns (a block of the sweep, then SciPy on some of the same points; medians over the
    # blocks), so that a change of machine load hits both sides alike.
    blocks = 5
    sweep_t, scipy_t, nfev = [], [], []
    for k in range(blocks):
        m = max(1, n // blocks)
        t0 = time.perf_counter()
        r = sweep(spec(m, seed=1 + k), processes=1)
        sweep_t.append((time.perf_counter() - t0) / m)
        nfev.append(r.measures["nfev"])
        betas = r.params["initial.beta"][:max(1, scipy_n // blocks)]
        t0 = time.perf_counter()
        for b0 in betas:
            y0 = [ini.alpha, b0, ini.gamma, ini.alpha_dot, ini.beta_dot, ini.gamma_dot]
            solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=rtol, atol=1e-12)
        scipy_t.append((time.perf_counter() - t0) / len(betas))
    per_traj, per_scipy = float(np.median(sweep_t)), float(np.median(scipy_t))
    out = {"per_traj_sweep": per_traj, "per_traj_scipy": per_scipy,
           "speedup": per_scipy / per_traj, "nfev_mean": float(np.mean(np.concatenate(nfev)))}
    if engines:
        from dask.distributed import Client

        big_spec = spec(big, seed=2)
        times = {"local_2proc": [], "dask_1w": [], "dask_2w": []}
        # the clusters --workers starts (TLS, loopback), reached as a scheduler with their keys
        with local_cluster(1) as c1, local_cluster(2) as c2:
            for cluster in (c1, c2):
                with Client(cluster) as c:
                    c.run(_warm_worker)  # every worker loads the library once, untimed
            for _ in range(repeat):
                t0 = time.perf_counter()
                local = sweep(big_spec, processes=2)
                times["local_2proc"].append(time.perf_counter() - t0)
                for name, cluster in (("dask_1w", c1), ("dask_2w", c2)):
                    t0 = time.perf_counter()
                    d = sweep(big_spec, scheduler=cluster.scheduler_address,
                              security=cluster.security)
                    times[name].append(time.perf_counter() - t0)
            out["identical"] = all(np.array_equal(local.measures[k], d.measures[k], equal_nan=True)
                                   for k in local.measures)
        out.update({k: min(v) for k, v in times.items()})
        out["dask2_over_local2"] = out["dask_2w"] / out["local_2proc"]
        out["scaling_1_to_2"] = out["dask_1w"] / (2 * out["dask_2w"])
    return out


def _warm_worker():
    """Load the reference sweep's measured libraries in this process (a Dask worker): every
    candidate of its plan, a start near the pole sending one point to the next."""
    sp = load({"scene": reference_data(1.0),
               "vary": {"initial": {"beta": {"values": [0.8, 0.05]}}}})
    run_chunk(sp.key, sp.method, sp.inputs, sp.ps, np.array([0.0, 1.0]), ms.driver_args(sp.method, 1e-8, 1e-12, 1000),
              ms.config_of(ms.DEFAULT), None, sp.terms, sp.pole_check, sp.fallback)
