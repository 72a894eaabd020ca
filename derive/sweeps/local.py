"""The local engine: a sweep's chunks in this process, or in worker processes of its own (one
pipe each, watched with the processes, so a dead worker ends the sweep at once).

Takes: the chunks and their arguments. Gives: {chunk: result}.
"""
from __future__ import annotations

import ctypes
import multiprocessing as mp
import os
import signal
from multiprocessing.connection import wait

from derive.errors import EngineError
from derive.sweeps.tasks import _held, _progress_bar, _signal_name, run_chunk


#: Below this many points the local engine runs in the calling process (no pool to start).
IN_PROCESS = 200


def _in_process(points: int, processes: int) -> bool:
    """Does the local engine run ``points`` in the calling process (no pool to start)?"""
    return processes <= 1 or points < IN_PROCESS


def _die_with_parent(parent: int) -> None:
    """Ask the kernel to kill this process when its parent dies (Linux ``PR_SET_PDEATHSIG``), so
    that a parent killed outright (SIGKILL, the OOM killer) leaves no worker computing for no
    one and printing BrokenPipeError; elsewhere a worker ends when its pipe closes."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, int(signal.SIGKILL), 0, 0, 0)  # 1: PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        return
    if os.getppid() != parent:  # the parent died before the request: nothing will send it
        os._exit(1)


def _worker_init(parent: int) -> None:
    """Set up a local worker process: Ctrl-C and SIGTERM are the parent's to handle.

    SIGINT stays blocked (it was blocked when the worker was forked): Ctrl-C reaches the whole
    process group, and a worker that took it would print a traceback while the parent is
    already stopping the workers; the compiled loop's interrupt guard installs its own SIGINT
    handler, which a blocked signal never reaches. SIGTERM gets its default action (the end),
    not the parent's handlers the fork copied, and the worker dies with its parent."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGTERM})
    _die_with_parent(parent)


def _worker_main(conn, parent: int) -> None:
    """A local pool worker: run the chunks the parent sends, ``(k, args)``, and send back
    ``(k, True, result)`` or ``(k, False, exception)``, until None or the pipe closes."""
    _worker_init(parent)
    while True:
        try:
            task = conn.recv()
        except (EOFError, OSError):
            return
        if task is None:
            return
        k, args = task
        try:
            reply = (k, True, run_chunk(*args))
        except Exception as exc:  # raised again in the parent
            reply = (k, False, exc)
        try:
            conn.send(reply)
        except (OSError, ValueError):  # the parent is gone
            return
        except Exception as exc:  # e.g. an exception that does not pickle
            try:
                conn.send((k, False, RuntimeError(f"{type(exc).__name__}: {exc}")))
            except Exception:
                return  # the parent sees a dead worker


def _receive(conn):
    """One reply from a worker (a function of its own: the tests make it fail)."""
    return conn.recv()


def _exit_reason(code: int | None) -> str:
    if code is not None and code < 0:
        hint = " (out of memory?)" if code == -9 else ""
        return f"was killed by {_signal_name(-code)}{hint}"
    return f"exited with status {code}"


def _local(tasks, submit_args, progress, processes, source="<sweep>"):
    """In this process when the sweep is small, else ``processes`` worker processes (fork where
    the system has it: they inherit the loaded library), each sent one chunk at a time.

    A worker that dies (the OOM killer, a signal) or a result that cannot be received (out of
    memory) ends the sweep at once with :class:`EngineError` ``<source>: sweep: ...``: every
    worker has its own pipe and the parent watches both the pipes and the processes, so nothing
    waits for a chunk that will not come (``multiprocessing.Pool`` would: a dead worker's chunk
    is lost, a dead result thread stops every reply, and its terminate can wait on a lock a
    killed worker held). Ctrl-C and SIGTERM (:class:`Terminated`) stop the workers; they ignore
    both themselves and die with this process (:func:`_worker_init`)."""
    results = {}
    with _progress_bar(sum(len(i) for i in tasks), progress) as bar:
        if len(tasks) == 1 or _in_process(sum(len(i) for i in tasks), processes):
            for k, idx in enumerate(tasks):
                results[k] = run_chunk(*submit_args(idx))
                bar.update(len(idx))
            return results
        ctx = mp.get_context("fork" if "fork" in mp.get_all_start_methods() else "spawn")
        workers = []  # (process, connection)
        try:
            # Forked with SIGINT and SIGTERM blocked (and a signal meanwhile held back): a
            # worker must not take either before its initializer has set them.
            with _held(signal.SIGINT, signal.SIGTERM):
                for _ in range(min(processes, len(tasks))):
                    mine, theirs = ctx.Pipe()
                    proc = ctx.Process(target=_worker_main, args=(theirs, os.getpid()), daemon=True)
                    proc.start()
                    theirs.close()
                    workers.append((proc, mine))
            todo = list(range(len(tasks)))[::-1]  # popped from the end: chunk 0 first
            busy = {}  # connection -> (process, chunk)

            def dead(proc, k):
                what = f"running chunk {k + 1} of {len(tasks)}" if k is not None else "idle"
                return EngineError(f"{source}: sweep: worker process {proc.pid} "
                                   f"{_exit_reason(proc.exitcode)} ({what}); "
                                   f"{len(tasks) - len(results)} of {len(tasks)} chunks unfinished")

            def send(proc, conn):
                k = todo.pop()
                try:
                    conn.send((k, submit_args(tasks[k])))
                except (BrokenPipeError, ConnectionError):
                    proc.join(1)
                    raise dead(proc, k) from None
                busy[conn] = (proc, k)

            for proc, conn in workers:
                if todo:
                    send(proc, conn)
            while len(results) < len(tasks):
                ready = wait([*busy, *(p.sentinel for p, _ in workers)], timeout=1.0)
                for conn in [r for r in ready if r in busy]:
                    proc, k = busy.pop(conn)
                    try:
                        got, ok, value = _receive(conn)
                    except (EOFError, OSError):
                        proc.join(1)
                        raise dead(proc, k) from None
                    except MemoryError:
                        raise EngineError(f"{source}: sweep: out of memory receiving the results "
                                          f"of chunk {k + 1} of {len(tasks)} ({len(tasks[k])} "
                                          f"points)") from None
                    if not ok:
                        if isinstance(value, MemoryError):
                            raise EngineError(f"{source}: sweep: worker process {proc.pid} ran "
                                              f"out of memory in chunk {k + 1} of {len(tasks)}")
                        raise value
                    results[got] = value
                    bar.update(len(tasks[got]))
                    if todo:
                        send(proc, conn)
                for proc, conn in workers:  # a worker gone while idle or busy: never expected
                    if proc.exitcode is not None:
                        raise dead(proc, busy.get(conn, (None, None))[1])
        finally:
            with _held():  # a second Ctrl-C waits for this (bounded) clean-up
                _stop_local(workers, clean=len(results) == len(tasks))
    return results


def _stop_local(workers, clean: bool) -> None:
    """End the local workers: asked to (None) after a complete sweep, else SIGKILL at once
    (a chunk in a C loop is not worth finishing); every process is reaped."""
    for proc, conn in workers:
        if clean:
            try:
                conn.send(None)
            except OSError:
                pass
        elif proc.exitcode is None:
            proc.kill()
    for proc, conn in workers:
        proc.join(5)
        if proc.exitcode is None:
            proc.kill()
            proc.join(5)
        conn.close()
