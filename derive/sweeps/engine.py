"""Parameter sweeps: one scene, many numbers, each trajectory measured while it is integrated.

A sweep (a TOML file or a dict of the same shape)::

    scene = "../sleeping_top.toml"     # relative to the sweep file; or an inline [scene] table
    [vary]                             # dotted scene keys; the Cartesian product, first key slowest
    initial.beta = { from = 0.05, to = 1.0, num = 40 }
    initial.gamma_dot = { values = [100.0, 150.0, 200.0] }
    # or, instead of [vary]:
    # [random]
    # n = 1000
    # seed = 1
    # initial.beta = { low = 0.05, high = 1.0 }
    [measure]
    names = ["beta_max", "time_to_tilt"]   # the registry: derive.sweeps.measures
    time_to_tilt = { angle = 1.0 }         # a measure's options

The points are numbers only: the base scene is validated once, each varied key's values are
checked against the scene contract (every distinct value of a grid, both bounds of a random
range), and the init map's inputs and the model's parameters are built as arrays from the base
scene and the varied columns, without a scene per point. A vector key is varied by component:
``initial.omega.0`` is ω̃₁.

Decisions (documented here once):

* Body moments varied jointly may violate the triangle inequality at some points only: those
  points are not run and their ``status`` says why; everything else wrong is a bad sweep file
  (SceneError, exit 2, ``<file>: <key>: <what>``).
* If any point has I2 != I1 the whole sweep runs the asymmetric model (it represents the
  symmetric points too; a symmetric one would not).
* Formulation "auto" runs, per point, the formulations auto would try for a single run,
  cheapest first (:func:`sweep_plan`): a start that a candidate's compiled pole check refuses
  (status RANGE, decided from the start by the Routh polynomial before any step) runs again
  with the next candidate, in the same chunk, down to the cheapest one without a singular set,
  which takes every point. The heavy symmetric top runs reduced-u clear of the poles
  (|sin beta| >= 0.1 all along) and euler-poisson elsewhere. Every point's outcome depends on
  its own numbers only, never on its chunk. ``SweepResult.formulation`` says which
  formulation ran each point. A singular formulation named in the scene is refused. The
  method must have a dense output that follows the tolerance (its family's measure window,
  :func:`derive.methods.registry.measure_window`): dop853 (its dense polynomial) or taylor (the
  step's series); ``auto`` takes the cost model's choice for the first candidate's model at
  the sweep's tolerance, t_end and rates (the representative point's), and dop853 if a
  candidate has no Taylor kernel.
* The scene's ``samples`` is not used: a sweep keeps the outputs at t_end only (final_state).
* The random points are drawn in the calling process (``numpy.random.default_rng(seed)``, one
  ``uniform`` per key, in the file's order), so a seed gives the same points whatever runs them.

Engines: local (default; chunks of at most ``CHUNK`` points, one process per core, each process
loading the compiled library once), a dask ``LocalCluster`` (``workers``) or an existing Dask
cluster (``scheduler``). Every trajectory is computed by the same compiled loop on its own, so
the results are bit-for-bit the same whatever the engine, chunking and worker count. A point
whose integration fails is recorded in ``status``; Ctrl-C cancels the outstanding chunks.
"""
from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading
import time

import numpy as np

from derive.errors import SceneError, Terminated
from derive.runtime import catalogue
from derive.runtime.records import STATS_DTYPE
from derive.sim.outputs import PLOT_FORMATS, TABLE_FORMATS, check_paths, output_format
from derive.sim.result import _explain
from derive.sweeps import measures as ms
from derive.sweeps.cluster import _dask, check_engine
from derive.sweeps.local import _in_process, _local
from derive.sweeps.contact import sweep as run_contact  # the contact hook
from derive.sweeps.points import _runnable
from derive.sweeps.result import SweepResult, write
from derive.sweeps.spec import contact_sweep, input_files, load
from derive.sweeps.tasks import _chunks, _cpus


def sweep(spec, *, workers=None, scheduler=None, progress=None, processes=None,
          add_measure=None, scheduler_timeout=None, dashboard=False, security=None,
          saveat=None) -> SweepResult:
    """Run a sweep (a file path or a dict shaped like one).

    Parameters
    ----------
    spec : str, os.PathLike or dict
        The sweep file, or a dict of the same shape.
    workers : int, optional
        Start a Dask LocalCluster of that many worker processes for this sweep, closed to
        everyone else (:func:`local_cluster`), at most :func:`worker_cap`.
    scheduler : str, optional
        The address of a running Dask scheduler (``tcp://host:8786``, ``tls://...``).
    progress : bool, optional
        A tqdm bar on stderr (None: when stderr is a TTY).
    processes : int, optional
        The local engine's pool size (neither ``workers`` nor ``scheduler``; default one per core).
    add_measure : str, optional
        A measure (or one of its columns) added to the file's list.
    scheduler_timeout : float, optional
        Seconds to reach ``scheduler`` and, again, for its first worker
        (default ``DEFAULT_SCHEDULER_TIMEOUT``).
    dashboard : bool
        With ``workers``: serve Dask's dashboard on 127.0.0.1 (its address is printed on
        stderr; needs bokeh).
    security : distributed.security.Security, optional
        The credentials for a ``tls://`` scheduler.
    saveat : derive.SaveAt, optional
        What to keep besides the measures: a sweep keeps t_end only (``t="final"``); its
        outputs there (:func:`final_measures`: ``alpha``, ``beta``, ``gamma``, ``omega``) add
        the ``final_state`` measure's columns.

    Returns
    -------
    SweepResult

    Raises
    ------
    SceneError
        A bad sweep or engine argument (``<file>: <key>: <what>``).
    EngineError
        The engine could not finish: a broken local pool, an unreachable or silent scheduler,
        a scheduler without workers.
    """
    source = os.fspath(spec) if isinstance(spec, (str, os.PathLike)) else "<sweep>"
    scheduler = check_engine(source, workers, scheduler, scheduler_timeout, dashboard)
    found = contact_sweep(spec)  # -- contact hook: a top on a table, run by derive.sweeps.contact --
    if found is not None:
        if saveat is not None:
            raise SceneError(f"{source}: saveat: a sweep over a top on a table keeps its measures only")
        return run_contact(found, workers=workers, scheduler=scheduler, add_measure=add_measure)
    sp = load(spec)
    extra = final_measures(saveat, sp.source)
    if extra:
        sp.measures = tuple(dict.fromkeys((*sp.measures, *extra)))
    if add_measure is not None:  # the column to plot: a measure's (final_beta) or a measure
        name = ms.owner(add_measure)
        if name is None:
            raise SceneError(f"{sp.source}: --measure: unknown measure {add_measure!r} "
                             f"(one of {', '.join(ms.REGISTRY)})")
        if len(ms.REGISTRY[name].columns) > 1 and add_measure == name:
            raise SceneError(f"{sp.source}: --measure: {name} has several columns; plot one of "
                             f"{', '.join(ms.REGISTRY[name].columns)}")
        sp.measures = tuple(dict.fromkeys((*sp.measures, name)))
    descs = [catalogue.describe(k) for k in (sp.key, *(f[0] for f in sp.fallback))]
    desc = descs[0]
    for d in descs:  # compile here, once, before any worker needs them
        ms.MeasureKernel.load(d, sp.method)
    s = sp.scene.simulate
    t = np.array([0.0, s.t_end])
    args = ms.driver_args(sp.method, s.rtol, s.atol, s.max_steps)
    config = ms.config_of(sp.measures, sp.options)
    run = _runnable(sp.n, sp.invalid)
    processes = processes or _cpus()
    integral = None
    if "integral_drift" in sp.measures:
        choice = sp.options.get("integral_drift", {}).get("integral", "case")
        integral = ms.integral_rows(sp.general, sp.damping, choice)

    def submit_args(idx):
        return (sp.key, sp.method, sp.inputs[idx], sp.ps[idx], t, args, config,
                None if integral is None else integral[idx], sp.terms, sp.pole_check,
                tuple((k, c, p[idx]) for k, c, p in sp.fallback), True)

    if workers is None and scheduler is None:
        # in this process: chunks of CHUNK points (one C call each, no pool to feed)
        tasks = _chunks(run, 0 if _in_process(run.size, processes) else processes)
        results = _local(tasks, submit_args, progress, processes, sp.source)
    else:
        timeout = None if scheduler_timeout is None else float(scheduler_timeout)
        tasks, results = _dask(run, submit_args, progress, workers, scheduler, source=sp.source,
                               timeout=timeout, dashboard=dashboard, security=security)

    n = sp.n
    res = np.full((n, len(ms.SLOTS)), np.nan)
    final = np.full((n, len(desc.outputs)), np.nan)

    stats = np.zeros(n, dtype=STATS_DTYPE)
    status = np.full(n, "ok", dtype=object)
    ran = np.full(n, -1, dtype=np.int8)  # the candidate that ran each point (-1: not run)
    for i, why in sp.invalid.items():
        status[i] = why
    for k, idx in enumerate(tasks):
        r, f, st, which = results[k]
        res[idx], final[idx], stats[idx], ran[idx] = r, f, st, which
    for i in np.flatnonzero(stats["status"] != 0):
        status[i] = _explain(descs[ran[i]], stats[i], s.max_steps)
    for i in run[~np.isfinite(final[run]).all(axis=1)]:
        if status[i] == "ok":
            status[i] = f"t = {s.t_end:.8g}: non-finite outputs (overflow)"
            res[i] = np.nan
    values = ms.read(sp.measures, desc, res, stats, final)
    names = np.array(["", *(d.formulation for d in descs)], dtype=object)
    used = [d.name for j, d in enumerate(descs) if (ran == j).any()] or [desc.name]
    return SweepResult(params={k: sp.columns[k] for k in sp.keys}, measures=values,
                       status=status.astype(str), keys=sp.keys, shape=sp.shape,
                       measure_names=sp.measures, title=sp.scene.title or "", source=sp.source,
                       model=", ".join(used), scene=sp.scene, files=sp.files,
                       formulation=names[ran.astype(int) + 1].astype(str))


def final_measures(saveat, source: str = "<sweep>") -> tuple[str, ...]:
    """The measures a sweep adds for ``saveat`` (a :class:`derive.SaveAt` or None): a sweep
    keeps no samples, only t_end, where the ``final_state`` measure gives α, β, γ and ω̃; ()
    for None. SceneError for the grid or another output."""
    if saveat is None:
        return ()
    if not saveat.final:
        raise SceneError(f"{source}: saveat: a sweep keeps t_end only (SaveAt(t=\"final\")), not the grid")
    allowed = ("alpha", "beta", "gamma", "omega")
    for name in saveat.outputs or ():
        if name not in allowed:
            raise SceneError(f"{source}: saveat: a sweep keeps {', '.join(allowed)} at t_end, not {name!r}")
    return ("final_state",)


def cli(args) -> int:
    """``derive sweep``: run, write, print a one-line summary. SIGTERM is handled as Ctrl-C is
    (workers stopped, no temporary left), raised as :class:`Terminated` (exit 143)."""
    timeout = getattr(args, "scheduler_timeout", None)
    dashboard = bool(getattr(args, "dashboard", False))
    check_engine(args.sweep, args.workers, args.scheduler, timeout, dashboard, flags=True)
    # before the work: an output that would replace the sweep file or its scene is known now
    check_paths([args.output, args.plot], inputs=input_files(args.sweep))
    output_format(args.output, "-o", TABLE_FORMATS)
    output_format(args.plot, "--plot", PLOT_FORMATS)
    with _sigterm_raises():
        t0 = time.perf_counter()
        res = sweep(args.sweep, workers=args.workers, scheduler=args.scheduler, progress=None,
                    add_measure=args.measure, scheduler_timeout=timeout, dashboard=dashboard)
        write(res, args.output, args.plot, args.measure)
    failed = int((~res.ok).sum())
    print(f"{res.source}: {len(res.status)} points ({failed} failed), model {res.model}, "
          f"{time.perf_counter() - t0:.2f} s -> {args.output}", file=sys.stdout)
    return 0


@contextlib.contextmanager
def _sigterm_raises():
    """Within the ``with`` body (main thread only), SIGTERM raises :class:`Terminated` where
    Ctrl-C would raise KeyboardInterrupt, once: a second SIGTERM during the clean-up is ignored
    (the workers die with this process in any case). The previous handler is restored after."""
    def raise_terminated(signum, frame):
        signal.signal(signal.SIGTERM, signal.SIG_IGN)
        raise Terminated()

    old = None
    if (threading.current_thread() is threading.main_thread()
            and signal.getsignal(signal.SIGTERM) is not signal.SIG_IGN):  # kept ignored
        old = signal.signal(signal.SIGTERM, raise_terminated)
    try:
        yield
    finally:
        if old is not None:
            signal.signal(signal.SIGTERM, old)
