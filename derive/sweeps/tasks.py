"""One task of a sweep (a chunk of points, one measured C call per candidate) and what both
engines share: the chunking, the progress bar, signals held over the steps that must not stop
half-way.

Takes: a chunk's arrays. Gives: its measures, final outputs and statistics.
"""
from __future__ import annotations

import math
import os
import signal
import sys
import threading

import numpy as np

from derive.methods.status import Status
from derive.runtime import catalogue
from derive.sweeps import measures as ms
from derive.symbolic import terms as user_terms


#: Largest number of trajectories in one task (one C call).
CHUNK = 10_000


def run_chunk(key, method, inputs, ps, t, args, config, integral=None, terms=(), pole_check=0,
              fallback=(), which=False):
    """One task: measured simulations of a block of points (the libraries are compiled or
    loaded once per process).

    Parameters
    ----------
    key, method : tuple, str
        The first candidate's model and the method.
    inputs, ps : ndarray
        The init map's inputs (N, NIN) and the first candidate's parameters (N, NP).
    t, args, config, integral
        As :meth:`derive.sweeps.measures.MeasureKernel.run` takes them.
    terms : tuple
        The user's terms of the model, registered here first (a worker started afresh knows
        only the built-in effects).
    pole_check : int
        The first candidate's check of each start (0: none).
    fallback : tuple
        The next candidates, ``(key, pole check, ps (N, NP))``: the points the previous
        candidate's check refused (status RANGE) run again with the next, in one C call each.
    which : bool
        Also return ``ran`` (the engines' tasks do; every argument is positional there, so
        that a stand-in for this function in the tests takes ``*args``).

    Returns
    -------
    tuple
        (res (N, len(SLOTS)), final outputs (N, NOBS), stats (N,)), and with ``which`` ``ran``
        (N,) int8: the index of the candidate whose run gave each point's numbers (0 the
        first).
    """
    for term in terms:
        user_terms.register(term)

    desc = catalogue.describe(key)
    kernel = ms.MeasureKernel.load(desc, method)
    res, out, st = kernel.run(inputs, ps, t, args, config, integral, pole_check)
    final = np.ascontiguousarray(out[:, :, -1])
    ran = np.zeros(len(st), dtype=np.int8)
    todo = np.flatnonzero(st["status"] == Status.RANGE) if pole_check else np.zeros(0, int)
    for j, (fkey, fcheck, fps) in enumerate(fallback, start=1):
        if todo.size == 0:
            break
        fdesc = catalogue.describe(fkey)
        if fdesc.outputs != desc.outputs:  # the rows below mix the two models' outputs
            raise AssertionError(f"{fdesc.name} and {desc.name} have different outputs")
        sub = None if integral is None else np.asarray(integral)[todo]
        r, o, s = ms.MeasureKernel.load(fdesc, method).run(inputs[todo], fps[todo], t, args,
                                                          config, sub, fcheck)
        res[todo], final[todo], st[todo], ran[todo] = r, o[:, :, -1], s, j
        todo = todo[s["status"] == Status.RANGE] if fcheck else todo[:0]
    return (res, final, st, ran) if which else (res, final, st)


def _chunks(idx: np.ndarray, parallel: int) -> list:
    """The points ``idx`` in chunks of at most CHUNK, about four per worker of ``parallel``
    (0: no workers, the calling process runs them: chunks of CHUNK)."""
    size = max(1, min(CHUNK, math.ceil(idx.size / max(1, 4 * parallel))))
    return [idx[i:i + size] for i in range(0, idx.size, size)]


def _progress_bar(total, progress):
    from tqdm import tqdm

    if progress is None:
        progress = sys.stderr.isatty()
    return tqdm(total=total, unit="pt", disable=not progress, desc="sweep", leave=False)


class _held:
    """Ctrl-C and SIGTERM wait until the end of the ``with`` body, then act as they would have.

    For the steps that must not stop half-way: starting a pool or a cluster (stopped half-way,
    its processes are left to Dask's exit hook or nobody) and their clean-up. In the main thread
    SIGINT and SIGTERM get a handler that notes them, and the first one noted is raised again on
    exit under the handlers restored (KeyboardInterrupt, :class:`Terminated`, or SIGTERM's
    default action). ``masked`` signals are also blocked in the calling thread, so that the
    processes forked and the threads started in the body begin with them blocked.
    """
    def __init__(self, *masked):
        self.masked = set(masked)

    def __enter__(self):
        self.pending, self.old, self.mask = [], {}, None
        if threading.current_thread() is threading.main_thread():
            for sig in (signal.SIGINT, signal.SIGTERM):
                self.old[sig] = signal.signal(sig, self._note)
        if self.masked:
            self.mask = signal.pthread_sigmask(signal.SIG_BLOCK, self.masked)
        return self

    def _note(self, signum, frame):
        self.pending.append(signum)

    def __exit__(self, *exc):
        if self.mask is not None:  # a signal blocked meanwhile is noted now, before the restore
            signal.pthread_sigmask(signal.SIG_SETMASK, self.mask)
        for sig, old in self.old.items():
            signal.signal(sig, old)
        if self.pending:
            signal.raise_signal(self.pending[0])


def _signal_name(number: int) -> str:
    try:
        return signal.Signals(number).name
    except ValueError:
        return f"signal {number}"


def _cpus() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1
