"""The Dask engine: a sweep's chunks on a closed LocalCluster derive starts (``workers``) or on
a running scheduler (``scheduler``, reached through ``distributed``'s own connection and
handshake within a timeout), and the checks of the engine arguments.

Takes: the runnable points and their arguments. Gives: (chunks, {chunk: result}).
"""
from __future__ import annotations

import concurrent.futures
import contextlib
import gc
import importlib.util
import logging
import signal
import socket
import sys

from derive.errors import EngineError, SceneError
from derive.sim.validator import _real
from derive.sweeps.tasks import _chunks, _cpus, _held, _progress_bar, run_chunk


#: Seconds to reach a ``scheduler`` (connect, Dask handshake) and then for its first worker.
DEFAULT_SCHEDULER_TIMEOUT = 5.0


#: Available memory the cap on ``workers`` leaves to each LocalCluster worker: a worker measured
#: about 75 MB resident after its chunks (Python, Dask, NumPy, the library), a chunk's arrays
#: and the transfers come on top.
WORKER_MEMORY = 256 * 2**20


#: LocalCluster workers per core at most (more only queue: each chunk is one C call on one core).
WORKERS_PER_CORE = 4


def _dask(run, submit_args, progress, workers, scheduler, *, source="<sweep>", timeout=None,
          dashboard=False, security=None):
    """The chunks through a Dask cluster (a closed LocalCluster of ``workers`` processes, see
    :func:`local_cluster`, or the one at ``scheduler``, probed first and joined within
    ``timeout`` seconds), cut for its worker count. Returns (tasks, results)."""
    from dask.distributed import Client, as_completed
    from distributed.scheduler import KilledWorker

    timeout = DEFAULT_SCHEDULER_TIMEOUT if timeout is None else timeout
    logging.getLogger("distributed").setLevel(logging.CRITICAL)  # failures are our one line
    cluster = client = None
    futures = []
    try:
        if scheduler is None:
            # The workers are spawned (exec'd) by threads the cluster starts, which inherit
            # SIGINT blocked from here, and so do the workers (Python does not unblock it): Ctrl-C
            # to the process group reaches only this process, which stops them (a worker taking
            # it while importing would print a traceback, and fail the cluster's start). The
            # resource tracker is started first: starting it unblocks SIGINT in the thread that
            # does, which would then spawn the workers with it unblocked.
            from multiprocessing import resource_tracker

            resource_tracker.ensure_running()
            with _held(signal.SIGINT):
                cluster = local_cluster(workers, dashboard=dashboard)
            if dashboard:
                print(f"note: dashboard at {cluster.dashboard_link}", file=sys.stderr, flush=True)
            client = Client(cluster, timeout=timeout)
        else:
            client = _connect(scheduler, source, timeout, security)
        tasks = _chunks(run, max(1, sum(client.nthreads().values())))
        futures = [client.submit(run_chunk, *submit_args(idx), pure=False) for idx in tasks]
        index = {f.key: k for k, f in enumerate(futures)}
        results = {}
        with _progress_bar(sum(len(i) for i in tasks), progress) as bar:
            for fut in as_completed(futures):
                k = index[fut.key]
                try:
                    results[k] = fut.result()
                except KilledWorker as exc:  # its workers died in it (Dask retried it)
                    raise EngineError(f"{source}: sweep: chunk {k + 1} of {len(tasks)} killed "
                                      f"the Dask workers that ran it (out of memory?): "
                                      f"{' '.join(str(exc).split())[:200]}") from None
                bar.update(len(tasks[k]))
        return tasks, results
    except BaseException:
        if futures and client is not None:
            with contextlib.suppress(Exception):
                client.cancel(futures, force=True)
        if cluster is not None:  # ours: stop its workers now, mid-chunk
            _stop_workers(cluster)
        raise
    finally:
        # (after Ctrl-C the futures are cancelled; a worker of another cluster busy in a chunk
        # finishes that C call). Signals wait for the close: a cluster closed half-way is closed
        # again by Dask's exit hook, which prints a traceback.
        with _held():
            with contextlib.suppress(Exception):
                if client is not None:
                    client.close()
            if cluster is not None:
                with contextlib.suppress(Exception):
                    cluster.close()


def _stop_workers(cluster) -> None:
    """Terminate the worker processes of a LocalCluster at once (SIGTERM), mid-chunk."""
    with contextlib.suppress(Exception):
        for w in list(cluster.workers.values()):
            proc = getattr(getattr(w, "process", None), "process", None)
            if proc is not None:
                proc.terminate()


def local_cluster(workers: int, dashboard: bool = False):
    """Start the Dask ``LocalCluster`` of ``derive sweep --workers``: closed to everyone else.

    Parameters
    ----------
    workers : int
        Worker processes, one thread each (a process runs one measured C call at a time).
    dashboard : bool
        Serve Dask's dashboard (``/status``) on 127.0.0.1 (a free port: ``dashboard_link``).
        Without it the scheduler's HTTP server answers only ``/health``.

    Returns
    -------
    distributed.LocalCluster
        Its scheduler and workers speak TLS with credentials made for this cluster only
        (``Security.temporary()``: a fresh CA and key, in memory, required of both ends), so a
        client without them (another local user) is refused; everything it starts (scheduler,
        nannies, workers, HTTP servers) listens on 127.0.0.1 only. The caller closes it.
    """
    import dask
    from dask.distributed import LocalCluster
    from distributed.security import Security

    routes = (dask.config.get("distributed.scheduler.http.routes") if dashboard
              else ["distributed.http.health"])
    # dashboard_address ":0" would bind 0.0.0.0; a scheduler always serves HTTP, so its
    # address is given even without the dashboard (loopback, any free port, never 8787's clash)
    with dask.config.set({"distributed.scheduler.http.routes": routes}):
        return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                            host="127.0.0.1", security=Security.temporary(),
                            dashboard_address=None, worker_dashboard_address=None,
                            scheduler_kwargs={"dashboard": dashboard,
                                              "dashboard_address": "127.0.0.1:0"},
                            silence_logs=logging.CRITICAL)


def worker_cap() -> tuple[int, str]:
    """The most LocalCluster workers this machine can hold, and why.

    Returns
    -------
    (int, str)
        ``min(WORKERS_PER_CORE * cores, available memory // WORKER_MEMORY)``, at least 1, and a
        phrase naming the figures, for the message that refuses more.
    """
    cores = _cpus()
    by_cores = WORKERS_PER_CORE * cores
    try:
        import psutil

        available = int(psutil.virtual_memory().available)
    except Exception:  # psutil comes with dask; without it the cores alone cap
        return by_cores, f"{WORKERS_PER_CORE} per core on {cores} cores"
    by_memory = max(1, available // WORKER_MEMORY)
    why = (f"{WORKERS_PER_CORE} per core on {cores} cores, and {WORKER_MEMORY >> 20} MB of the "
           f"{available / 2**30:.1f} GB available memory each")
    return max(1, min(by_cores, by_memory)), why


_FLAG_NAMES = {"workers": "--workers", "scheduler": "--scheduler",
               "scheduler_timeout": "--scheduler-timeout", "dashboard": "--dashboard"}


def check_engine(source, workers=None, scheduler=None, scheduler_timeout=None, dashboard=False,
                 flags=False) -> str | None:
    """Validate a sweep's engine arguments before any work; returns the scheduler address.

    Parameters
    ----------
    source : str
        The sweep file (or ``<sweep>``), first in the message.
    workers, scheduler, scheduler_timeout, dashboard
        As :func:`sweep` takes them.
    flags : bool
        Name them as the command line does (``--workers``) rather than as the API does.

    Returns
    -------
    str or None
        The scheduler address, ``tcp://`` added when no scheme is given.

    Raises
    ------
    SceneError
        ``<source>: <name>: <what>`` for a bad value, both engines, more workers than
        :func:`worker_cap` allows, a malformed address, a dashboard without ``workers`` or
        without bokeh (which Dask's dashboard needs).
    """
    name = (lambda k: _FLAG_NAMES[k]) if flags else (lambda k: k)

    def bad(key, what):
        raise SceneError(f"{source}: {name(key)}: {what}")

    if workers is not None and scheduler is not None:
        bad("workers", f"give {name('workers')} or {name('scheduler')}, not both")
    if workers is not None:
        if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
            bad("workers", f"must be a positive integer, got {workers!r}")
        cap, why = worker_cap()
        if workers > cap:
            bad("workers", f"{workers} worker processes is more than this machine holds (at most "
                           f"{cap}: {why}); a bigger sweep goes to a cluster ({name('scheduler')})")
    if not isinstance(dashboard, bool):
        bad("dashboard", f"must be true or false, got {dashboard!r}")
    if dashboard and workers is None:
        bad("dashboard", f"only with {name('workers')} (the cluster derive starts; a scheduler "
                         f"serves its own)")
    if dashboard and importlib.util.find_spec("bokeh") is None:
        bad("dashboard", "Dask's dashboard needs bokeh, which is not installed "
                         "(pip install 'bokeh>=3.1')")
    if scheduler_timeout is not None:
        t = _real(scheduler_timeout)
        if t is None or not 0 < t <= 3600:
            bad("scheduler_timeout", f"must be a number of seconds in (0, 3600], got "
                                     f"{scheduler_timeout!r}")
        if scheduler is None:
            bad("scheduler_timeout", f"only with {name('scheduler')}")
    if scheduler is None:
        return None
    if not isinstance(scheduler, str):
        bad("scheduler", f"must be an address such as tcp://host:8786, got {scheduler!r}")
    try:
        return _parse_address(scheduler)
    except ValueError as exc:
        bad("scheduler", f"{exc} (an address such as tcp://host:8786)")


def _parse_address(address: str) -> str:
    """``[tcp:// | tls://]host:port`` -> ``scheme://host:port``; ValueError saying what is wrong."""
    text = address.strip()
    scheme, sep, loc = text.partition("://")
    if not sep:
        scheme, loc = "tcp", text
    if scheme not in ("tcp", "tls"):
        raise ValueError(f"{address!r}: the scheme must be tcp:// or tls://")
    host, colon, port = loc.rpartition(":")
    if not colon or not host:
        raise ValueError(f"{address!r} is not host:port")
    bare = host[1:-1] if host.startswith("[") and host.endswith("]") else host
    if not bare or any(c.isspace() or c in "/?#@[]" for c in bare) or (":" in bare and bare == host):
        raise ValueError(f"{address!r}: bad host {host!r}")
    if not port.isdigit() or not 1 <= int(port) <= 65535:
        raise ValueError(f"{address!r}: the port must be a number from 1 to 65535")
    return f"{scheme}://{host}:{int(port)}"


def _probe(address: str, source: str, timeout: float, security=None) -> None:
    """Reach the scheduler at ``address`` and read its Dask handshake within ``timeout`` seconds,
    through ``distributed``'s connector and comm, so that a closed port, an unknown host, a
    silent listener, another protocol or a tls:// address without credentials is one clear
    EngineError instead of Dask's retries or a wait for ever."""
    import asyncio

    from distributed.comm.addressing import parse_address
    from distributed.comm.core import CommClosedError
    from distributed.comm.registry import get_backend
    from distributed.security import Security

    where = f"{source}: scheduler {address}"
    closed = f"{where}: closed the connection without a Dask handshake"
    scheme, loc = parse_address(address)
    args = (security or Security()).get_connection_args("client")

    async def handshake():
        # The connector, not distributed.comm.connect: connect() retries a refused port until
        # its timeout and then names only the timeout, and waits for the handshake for ever.
        loop = asyncio.get_running_loop()
        deadline = loop.time() + timeout
        try:
            comm = await asyncio.wait_for(
                get_backend(scheme).get_connector().connect(loc, deserialize=False, **args),
                timeout)
        except OSError as exc:
            cause = exc.__cause__ or exc
            if isinstance(cause, socket.gaierror):
                raise EngineError(f"{where}: unknown host ({cause.strerror or cause})") from None
            if isinstance(cause, ConnectionRefusedError):
                raise EngineError(f"{where}: connection refused (nothing listens there)") from None
            if isinstance(exc, TimeoutError):
                raise EngineError(f"{where}: no answer within {timeout:g} s") from None
            if type(exc) is CommClosedError and exc.__cause__ is None:  # accepted, then closed
                raise EngineError(closed) from None
            raise EngineError(f"{where}: cannot connect ({_why(cause)})") from None
        except (TypeError, RuntimeError) as exc:  # no ssl_context; encryption required on tcp://
            if scheme == "tls" and args.get("ssl_context") is None:
                raise EngineError(f"{where}: cannot connect ({_NO_CREDENTIALS})") from None
            raise EngineError(f"{where}: cannot connect ({_why(exc)})") from None
        try:
            await comm.write(comm.handshake_info())
            return await asyncio.wait_for(comm.read(), max(0.01, deadline - loop.time()))
        except TimeoutError:
            raise EngineError(f"{where}: accepted the connection but sent no Dask handshake "
                              f"within {timeout:g} s (is it a Dask scheduler?)") from None
        except (CommClosedError, ConnectionError):
            raise EngineError(closed) from None
        except Exception:  # undecodable, or a length no handshake has ("HTTP/1.1": 3 EiB)
            raise EngineError(f"{where}: answered, but not as a Dask scheduler (is it one?)") \
                from None
        finally:
            comm.abort()

    try:
        asyncio.get_running_loop()
    except RuntimeError:
        hello = asyncio.run(handshake())
    else:  # called from a running loop (a notebook): the probe gets a thread of its own
        with concurrent.futures.ThreadPoolExecutor(1) as pool:
            hello = pool.submit(asyncio.run, handshake()).result()
    if not isinstance(hello, dict) or "python" not in hello:
        raise EngineError(f"{where}: answered, but not as a Dask scheduler (is it one?)")


_NO_CREDENTIALS = ("a tls:// scheduler needs credentials: security= in the API, or Dask's "
                   "distributed.comm.tls configuration")


def _why(exc: BaseException) -> str:
    return " ".join(str(getattr(exc, "strerror", None) or exc).split())[:200]


def _connect(address: str, source: str, timeout: float, security=None):
    """A Client of the scheduler at ``address`` with a worker, within ``timeout`` seconds for
    the connection and as much again for the first worker; EngineError otherwise."""
    from dask.distributed import Client

    _probe(address, source, timeout, security)
    where = f"{source}: scheduler {address}"
    try:
        client = Client(address, timeout=timeout, security=security)
    except (OSError, TimeoutError, TypeError, ValueError) as exc:
        client = None
        why = _NO_CREDENTIALS if address.startswith("tls://") and security is None else _why(exc)
    if client is None:
        # The half-made Client is held in a cycle by its traceback; collected now, its __del__
        # (which stops Dask's loop runner) cannot fire inside a later Client's start and deadlock.
        gc.collect()
        raise EngineError(f"{where}: cannot connect ({why})")
    try:
        client.wait_for_workers(1, timeout=timeout)
    except (TimeoutError, OSError):
        client.close()
        raise EngineError(f"{where}: has no workers (none joined within {timeout:g} s; start "
                          f"some with `dask worker {address} --nthreads 1`)") from None
    except BaseException:
        client.close()
        raise
    return client
