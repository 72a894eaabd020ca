"""Sweep engines that fail fast, clean and closed.

A local pool that breaks fails at once (exit 3, one line); Ctrl-C and SIGTERM stop the workers
and leave no temporary; a scheduler address is validated and reached within a timeout (a closed
port, a silent listener, another protocol, a scheduler without workers: one line each); the
number of LocalCluster workers is capped; the LocalCluster derive starts speaks TLS with its own
credentials and listens on 127.0.0.1 only, without a dashboard unless asked.

Every wait is bounded (subprocess timeouts, an alarm around in-process sweeps, socket timeouts);
every socket is on 127.0.0.1. Internal hooks used: ``derive.sweeps.cluster`` (``local_cluster`` to get at
the cluster derive starts, ``worker_cap`` and ``_cpus`` for the cap) and ``derive.sweeps.local``
(``run_chunk`` and ``_receive`` patched to break the pool).
"""
from __future__ import annotations

import contextlib
import gc
import os
import signal
import socket
import subprocess
import sys
import threading
import time
import urllib.error
import urllib.request

import numpy as np
import pytest

import derive
import derive.cli
from derive.sweeps import cluster as sweeps
from derive.sweeps import local
from cli_in_process import derive_main

psutil = pytest.importorskip("psutil")
linux = pytest.mark.skipif(sys.platform != "linux", reason="fork and PR_SET_PDEATHSIG")

TOP = {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
       "initial": {"alpha": 0.0, "beta": 0.8, "gamma": 0.0, "alpha_dot": -0.4, "beta_dot": 0.3,
                   "gamma_dot": 6.0},
       "simulate": {"t_end": 0.5, "rtol": 1e-8, "atol": 1e-12}}
#: Enough points for the local engine's worker processes (derive.sweeps.local.IN_PROCESS is 200).
POOLED = {"scene": TOP, "random": {"n": 400, "seed": 5, "initial": {"beta": {"low": 0.3, "high": 1.2}}},
          "measures": ["beta_max", "nfev"]}
SMALL = {"scene": TOP, "vary": {"initial": {"beta": {"values": [0.4, 0.8]}}},
         "measures": ["beta_max", "nfev"]}

TOP_TOML = """[body]
I1 = 1.0
I3 = 0.5
[gravity]
M = 1.0
g = 1.0
l = 1.0
[initial]
alpha = 0.0
beta = 0.8
gamma = 0.0
alpha_dot = -0.4
beta_dot = 0.3
gamma_dot = 6.0
[simulate]
t_end = {t_end}
rtol = 1e-8
"""

#: Runs the command line with the local engine on two processes whatever the machine, after
#: breaking what argv[1] names: "killed" (every worker SIGKILLs itself in its chunk),
#: "term_while_writing" (SIGTERM arrives while the Parquet file is being written), "none"; or
#: "ready" FILE: every local worker appends its pid to FILE as it begins a chunk.
DRIVER = """
import os, signal, sys, time
import derive.sweeps.engine as sweeps
import derive.sweeps.local as local
sweeps._cpus = lambda: 2
case = sys.argv[1]
if case == "ready":  # each local worker says it has begun a chunk (a line in argv[2]), then runs it
    ready, run_chunk = sys.argv.pop(2), local.run_chunk
    def announced(*args):
        with open(ready, "a") as f:
            f.write(f"{os.getpid()}\\n")
        return run_chunk(*args)
    local.run_chunk = announced
if case == "killed":
    local.run_chunk = lambda *args: os.kill(os.getpid(), signal.SIGKILL)
elif case == "term_while_writing":
    import pandas
    def to_parquet(self, f, **kwargs):
        f.write(b"half a file")
        f.flush()
        os.kill(os.getpid(), signal.SIGTERM)
        time.sleep(30)
    pandas.DataFrame.to_parquet = to_parquet
from derive.cli import main
raise SystemExit(main(sys.argv[2:]))
"""


def _files(tmp_path, t_end=0.5, n=400):
    (tmp_path / "top.toml").write_text(TOP_TOML.format(t_end=t_end))
    sweep = tmp_path / "s.toml"
    sweep.write_text('scene = "top.toml"\n[random]\nn = %d\nseed = 1\n'
                     'initial.beta = { low = 0.3, high = 1.2 }\n'
                     '[measure]\nnames = ["beta_max", "nfev"]\n' % n)
    return sweep


def _one_line(stderr: str) -> str:
    lines = stderr.splitlines()
    assert len(lines) == 1, stderr
    assert lines[0].startswith("error: "), stderr
    return lines[0]


def _children() -> set:
    return {k.pid for k in psutil.Process().children(recursive=True)}


def _gone(pids, within=30.0) -> list:
    """The processes of ``pids`` still alive (zombies count as gone) after up to ``within`` s."""
    deadline = time.monotonic() + within
    while True:
        alive = []
        for pid in pids:
            with contextlib.suppress(psutil.NoSuchProcess):
                if psutil.Process(pid).status() != psutil.STATUS_ZOMBIE:
                    alive.append(pid)
        if not alive or time.monotonic() > deadline:
            return alive
        time.sleep(0.05)


@pytest.fixture
def alarm():
    """An in-process sweep that would hang raises instead (SIGALRM after 60 s)."""
    def ring(signum, frame):
        raise TimeoutError("the sweep did not return within 60 s")

    old = signal.signal(signal.SIGALRM, ring)
    signal.alarm(60)
    yield
    signal.alarm(0)
    signal.signal(signal.SIGALRM, old)


@pytest.fixture(scope="module")
def reference():
    """SMALL on the calling process (and the model compiled once for the module)."""
    return derive.sweep(SMALL, processes=1)


# ---------------------------------------------------------------------------------------------
# item 3: a broken local pool fails at once


@linux
def test_a_killed_worker_fails_the_sweep_at_once(monkeypatch, alarm, reference):
    monkeypatch.setattr(local, "run_chunk", lambda *args: os.kill(os.getpid(), signal.SIGKILL))
    before = _children()
    with pytest.raises(derive.IntegrationError) as info:  # (the alarm: no wait for a lost chunk)
        derive.sweep(POOLED, processes=2)
    msg = str(info.value)
    assert msg.startswith("<sweep>: sweep: worker process ") and "killed by SIGKILL" in msg, msg
    assert _children() <= before  # every worker reaped


@linux
def test_a_worker_out_of_memory_fails_the_sweep(monkeypatch, alarm, reference):
    def no_memory(*args):
        raise MemoryError

    monkeypatch.setattr(local, "run_chunk", no_memory)
    before = _children()
    with pytest.raises(derive.IntegrationError, match=r"^<sweep>: sweep: worker process \d+ ran "
                                                      r"out of memory in chunk \d+ of \d+$"):
        derive.sweep(POOLED, processes=2)
    assert _children() <= before


@linux
def test_a_result_that_cannot_be_received_fails_the_sweep(monkeypatch, alarm, reference):
    """What used to kill multiprocessing.Pool's result thread (MemoryError unpickling a result)
    and leave the parent polling for ever."""
    def no_memory(conn):
        raise MemoryError

    monkeypatch.setattr(local, "_receive", no_memory)
    before = _children()
    with pytest.raises(derive.IntegrationError, match=r"^<sweep>: sweep: out of memory receiving "
                                                      r"the results of chunk \d+ of \d+"):
        derive.sweep(POOLED, processes=2)
    assert _children() <= before


@linux
def test_cli_dead_pool_is_exit_3_one_line_and_no_output(tmp_path):
    sweep, out = _files(tmp_path), tmp_path / "r.parquet"
    p = subprocess.run([sys.executable, "-c", DRIVER, "killed", "sweep", str(sweep), "-o", str(out)],
                       capture_output=True, text=True, timeout=60)
    assert p.returncode == 3, p.stderr
    line = _one_line(p.stderr)
    assert line.startswith(f"error: {sweep}: sweep: worker process ") and "SIGKILL" in line
    assert sorted(f.name for f in tmp_path.iterdir()) == ["s.toml", "top.toml"]


# ---------------------------------------------------------------------------------------------
# item 5: signals


def _computing(pid) -> bool:
    """The process has the measured library loaded: a Dask worker is in its first chunk."""
    with contextlib.suppress(psutil.Error):
        return any("_measures-" in m.path for m in psutil.Process(pid).memory_maps())
    return False


def _start_long_sweep(tmp_path, extra=(), computing=True):
    """``derive sweep`` (two local processes, or ``extra`` flags) on a sweep of about ten
    seconds on two quiet cores, in a session of its own; returns (process, output path, worker pids) once two
    workers run. Local workers say so themselves (a line each in a file as they begin a chunk:
    the parent is then past starting them, in its loop over the chunks); Dask workers are
    watched (``computing``: with the library loaded, in their chunks)."""
    sweep, out = _files(tmp_path, t_end=100.0, n=100_000), tmp_path / "r.parquet"
    ready = tmp_path / "ready"
    case = ["none"] if extra else ["ready", str(ready)]
    # SIGINT as in a terminal: a test runner started in the background has it ignored, and the
    # child would inherit that (a shell starts a foreground command with it at its default)
    p = subprocess.Popen([sys.executable, "-c", DRIVER, *case, "sweep", str(sweep), "-o", str(out),
                          *extra], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         start_new_session=True,
                         preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))

    def running(kid):  # a Dask worker (spawned), or one in its chunk
        with contextlib.suppress(psutil.Error):
            if computing:
                return _computing(kid.pid)
            return "spawn_main" in " ".join(kid.cmdline())
        return False

    def started() -> int:
        if not extra:
            return len(ready.read_text().split()) if ready.exists() else 0
        return sum(map(running, psutil.Process(p.pid).children(recursive=True)))

    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and p.poll() is None:
        if started() >= 2:
            break
        time.sleep(0.05)
    else:
        p.kill()
        _, err = p.communicate()
        raise AssertionError(f"the sweep's workers did not start within 120 s: {p.returncode} {err}")
    assert p.poll() is None, p.communicate()
    return p, out, [k.pid for k in psutil.Process(p.pid).children(recursive=True)]


def _stopped(p, tmp_path, out, workers, code, line):
    try:
        _, err = p.communicate(timeout=60)  # a bound on a hang, not a measurement: a loaded
        # machine may keep the stopping processes off the cores for seconds
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        raise
    assert p.returncode == code, err
    assert err == line + "\n"  # exactly one line: no worker traceback, no BrokenPipeError
    assert not out.exists()
    assert [f.name for f in tmp_path.iterdir() if f.name.startswith(".")] == []  # no .part
    assert _gone(workers) == []


@linux
def test_ctrl_c_to_the_process_group_stops_a_local_sweep_cleanly(tmp_path):
    p, out, workers = _start_long_sweep(tmp_path)
    os.killpg(p.pid, signal.SIGINT)
    _stopped(p, tmp_path, out, workers, 130, "error: interrupted")


@linux
def test_sigterm_to_the_parent_stops_a_local_sweep_and_its_workers(tmp_path):
    p, out, workers = _start_long_sweep(tmp_path)
    os.kill(p.pid, signal.SIGTERM)
    _stopped(p, tmp_path, out, workers, 143, "error: terminated")


@pytest.mark.slow
@linux
def test_sigkill_to_the_parent_takes_the_workers_along(tmp_path):
    p, out, workers = _start_long_sweep(tmp_path)
    os.kill(p.pid, signal.SIGKILL)
    p.communicate(timeout=60)
    assert _gone(workers) == []  # PR_SET_PDEATHSIG: no orphan computing for no one


def test_sigterm_while_writing_leaves_no_part_file_and_the_old_output(tmp_path):
    sweep, out = _files(tmp_path, n=4), tmp_path / "r.parquet"
    out.write_bytes(b"the previous results")
    p = subprocess.run([sys.executable, "-c", DRIVER, "term_while_writing", "sweep", str(sweep),
                        "-o", str(out)], capture_output=True, text=True, timeout=60)
    assert p.returncode == 143, p.stderr
    assert _one_line(p.stderr) == "error: terminated"
    assert out.read_bytes() == b"the previous results"
    assert sorted(f.name for f in tmp_path.iterdir()) == ["r.parquet", "s.toml", "top.toml"]


@pytest.mark.slow
@linux
@pytest.mark.parametrize("computing", [False, True], ids=["starting", "computing"])
@pytest.mark.parametrize("sig,code,line", [(signal.SIGINT, 130, "error: interrupted"),
                                           (signal.SIGTERM, 143, "error: terminated")],
                         ids=["SIGINT", "SIGTERM"])
def test_signals_stop_a_workers_sweep_cleanly(tmp_path, sig, code, line, computing):
    """--workers: Ctrl-C to the group (the Dask workers ignore it) or SIGTERM to the parent,
    while the cluster starts (held until it is up) or while the workers compute."""
    p, out, workers = _start_long_sweep(tmp_path, ("--workers", "2"), computing)
    if sig == signal.SIGINT:
        os.killpg(p.pid, sig)
    else:
        os.kill(p.pid, sig)
    _stopped(p, tmp_path, out, workers, code, line)  # nor a leaked-semaphore warning


# ---------------------------------------------------------------------------------------------
# item 4: schedulers


@pytest.fixture
def listener():
    """Start a loopback listener in a thread: ``start(reply)`` accepts every connection and
    sends ``reply`` (None: stays silent; b"": closes it); returns its port. Closed after the
    test."""
    started = []

    def start(reply):
        srv = socket.socket()
        srv.bind(("127.0.0.1", 0))
        srv.listen()
        srv.settimeout(0.1)
        stop, conns = threading.Event(), []

        def serve():
            while not stop.is_set():
                try:
                    conn, _ = srv.accept()
                except OSError:
                    continue
                conns.append(conn)
                if reply == b"":  # hangs up at once
                    conn.close()
                elif reply is not None:
                    conn.sendall(reply)

        thread = threading.Thread(target=serve, daemon=True)
        thread.start()
        started.append((srv, stop, thread, conns))
        return srv.getsockname()[1]

    yield start
    for srv, stop, thread, conns in started:
        stop.set()
        thread.join(2)
        srv.close()
        for conn in conns:
            conn.close()


def _closed_port() -> int:
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


@pytest.mark.parametrize("scheduler,what", [
    (5, "must be an address such as tcp://host:8786, got 5"),
    ("not-an-address", "'not-an-address' is not host:port"),
    ("http://127.0.0.1:8786", "the scheme must be tcp:// or tls://"),
    ("tcp://127.0.0.1:99999", "the port must be a number from 1 to 65535"),
    ("tcp://a b:8786", "bad host"),
])
def test_a_malformed_scheduler_is_refused_before_any_work(scheduler, what):
    with pytest.raises(derive.SceneError) as info:
        derive.sweep(SMALL, scheduler=scheduler)
    assert str(info.value).startswith("<sweep>: scheduler: ") and what in str(info.value)


@pytest.mark.parametrize("kwargs,key", [
    ({"scheduler": "127.0.0.1:8786", "scheduler_timeout": 0}, "scheduler_timeout"),
    ({"scheduler": "127.0.0.1:8786", "scheduler_timeout": float("nan")}, "scheduler_timeout"),
    ({"scheduler_timeout": 2.0}, "scheduler_timeout"),
    ({"dashboard": True}, "dashboard"),
    ({"workers": 1, "dashboard": "yes"}, "dashboard"),
    ({"workers": 2, "scheduler": "127.0.0.1:8786"}, "workers"),
])
def test_engine_arguments_are_checked(kwargs, key):
    with pytest.raises(derive.SceneError, match=rf"^<sweep>: {key}: "):
        derive.sweep(SMALL, **kwargs)


def _refused(scheduler, timeout, **kwargs) -> tuple[str, float]:
    t0 = time.monotonic()
    with pytest.raises(derive.IntegrationError) as info:
        derive.sweep(SMALL, scheduler=scheduler, scheduler_timeout=timeout, **kwargs)
    msg = str(info.value)
    assert "\n" not in msg
    return msg, time.monotonic() - t0


def test_a_closed_port_is_refused_at_once(reference):
    port = _closed_port()
    msg, took = _refused(f"127.0.0.1:{port}", 60)
    assert msg == f"<sweep>: scheduler tcp://127.0.0.1:{port}: connection refused (nothing listens there)"
    assert took < 30  # refused, not retried for the timeout (a loaded machine may take seconds to import Dask)


def test_an_unknown_host_is_named_at_once(reference):
    msg, took = _refused("tcp://no-such-host.invalid:8786", 60)
    assert msg.startswith("<sweep>: scheduler tcp://no-such-host.invalid:8786: unknown host (")
    assert took < 30  # not retried for the timeout


def test_a_silent_listener_times_out(listener, reference):
    port = listener(None)
    msg, took = _refused(f"tcp://127.0.0.1:{port}", 0.5)
    assert msg.startswith(f"<sweep>: scheduler tcp://127.0.0.1:{port}: accepted the connection "
                          "but sent no Dask handshake within 0.5 s")
    assert 0.5 <= took < 30  # the timeout given, not Dask's own (30 s)


def test_an_http_server_is_not_taken_for_a_scheduler(listener, reference):
    port = listener(b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n")
    msg, took = _refused(f"127.0.0.1:{port}", 60)  # not: "out of memory" (10^18 bytes asked)
    assert msg == f"<sweep>: scheduler tcp://127.0.0.1:{port}: answered, but not as a Dask scheduler (is it one?)"
    assert took < 30


def test_a_listener_that_hangs_up_is_refused(listener, reference):
    port = listener(b"")
    msg, took = _refused(f"127.0.0.1:{port}", 60)
    assert msg == (f"<sweep>: scheduler tcp://127.0.0.1:{port}: closed the connection without "
                   "a Dask handshake")
    assert took < 30


def test_cli_unreachable_scheduler_is_exit_3_one_line(tmp_path):
    sweep, out = _files(tmp_path, n=4), tmp_path / "r.parquet"
    port = _closed_port()
    p = derive_main("sweep", sweep, "-o", out, "--scheduler", f"127.0.0.1:{port}", "--scheduler-timeout", "2")
    assert p.returncode == 3, p.stderr
    assert _one_line(p.stderr) == (f"error: {sweep}: scheduler tcp://127.0.0.1:{port}: "
                                   "connection refused (nothing listens there)")
    assert not out.exists()


@pytest.mark.parametrize("flags,what", [
    (["--scheduler", "not-an-address"], "--scheduler: 'not-an-address' is not host:port"),
    (["--scheduler", "127.0.0.1:8786", "--scheduler-timeout", "-1"],
     "--scheduler-timeout: must be a number of seconds in (0, 3600], got -1.0"),
    (["--dashboard"], "--dashboard: only with --workers (the cluster derive starts; a scheduler "
                      "serves its own)"),
])
def test_cli_bad_engine_flags_are_exit_2_naming_the_flag(tmp_path, capsys, flags, what):
    """derive.cli.main in this process (what `derive` and `python -m derive` run)."""
    sweep, out = _files(tmp_path, n=4), tmp_path / "r.parquet"
    assert derive.cli.main(["sweep", str(sweep), "-o", str(out), *flags]) == 2
    assert _one_line(capsys.readouterr().err).startswith(f"error: {sweep}: {what}")
    assert not out.exists()


# ---------------------------------------------------------------------------------------------
# item 6: the worker cap


def test_workers_above_the_cap_are_refused_before_anything_starts(tmp_path, capsys, monkeypatch):
    try:  # the memory available now, for both readings (other processes change it in between)
        import psutil

        memory = psutil.virtual_memory()
        monkeypatch.setattr(psutil, "virtual_memory", lambda: memory)
    except ImportError:
        pass
    cap, why = sweeps.worker_cap()
    assert 1 <= cap <= sweeps.WORKERS_PER_CORE * sweeps._cpus()
    sweep, out = _files(tmp_path, n=4), tmp_path / "r.parquet"
    before = _children()
    assert derive.cli.main(["sweep", str(sweep), "-o", str(out), "--workers", "1000"]) == 2
    assert _children() == before  # no process started (nor left)
    line = _one_line(capsys.readouterr().err)
    assert line == (f"error: {sweep}: --workers: 1000 worker processes is more than this machine "
                    f"holds (at most {cap}: {why}); a bigger sweep goes to a cluster (--scheduler)")
    assert not out.exists()


def test_the_cap_follows_cores_and_available_memory(monkeypatch):
    class Memory:
        available = 3 * sweeps.WORKER_MEMORY + 1

    monkeypatch.setattr(sweeps, "_cpus", lambda: 64)
    monkeypatch.setattr(psutil, "virtual_memory", lambda: Memory)
    assert sweeps.worker_cap()[0] == 3  # memory: 3 workers' worth
    Memory.available = 10**15
    assert sweeps.worker_cap()[0] == 64 * sweeps.WORKERS_PER_CORE  # cores
    Memory.available = 1
    assert sweeps.worker_cap()[0] == 1  # never below one
    with pytest.raises(derive.SceneError, match=r"^<sweep>: workers: 2 worker processes is more "
                                                r"than this machine holds \(at most 1: "):
        derive.sweep(SMALL, workers=2)


# ---------------------------------------------------------------------------------------------
# item 10: the cluster derive starts is closed


def _listening(pid) -> set:
    return {(c.laddr.ip, c.laddr.port) for c in psutil.Process(pid).net_connections(kind="inet")
            if c.status == psutil.CONN_LISTEN}


@pytest.fixture(scope="module")
def cluster():
    """The LocalCluster ``--workers 1`` starts, and what it listens on (this process's new
    sockets and its worker processes')."""
    before = _listening(os.getpid())
    c = sweeps.local_cluster(1)
    try:
        ours = _listening(os.getpid()) - before
        for kid in psutil.Process().children(recursive=True):
            ours |= _listening(kid.pid)
        yield c, ours
    finally:
        c.close()


def _get(url):
    try:
        with urllib.request.urlopen(url, timeout=5) as r:
            return r.status
    except urllib.error.HTTPError as exc:
        return exc.code


def test_the_cluster_listens_on_loopback_only_and_serves_no_dashboard(cluster):
    c, ours = cluster
    assert len(ours) >= 4  # scheduler, its HTTP server, the nanny, the worker
    assert {ip for ip, _ in ours} == {"127.0.0.1"}
    assert c.scheduler_address.startswith("tls://127.0.0.1:")
    http = c.scheduler.http_server
    assert (http.address, http.port) in ours
    base = f"http://127.0.0.1:{http.port}"
    assert _get(base + "/health") == 200  # the scheduler's HTTP server answers here...
    for page in ("/status", "/info/main/workers.html", "/json/counts.json"):
        assert _get(base + page) == 404, page  # ...but serves no dashboard or cluster pages


def test_the_cluster_refuses_a_client_without_its_credentials(cluster, reference):
    from distributed import Client
    from distributed.security import Security

    c, _ = cluster
    address = c.scheduler_address
    with pytest.raises(OSError):  # plain TCP to the TLS port: the handshake fails
        Client(address.replace("tls://", "tcp://"), timeout=1)
    with pytest.raises(OSError):  # TLS with other credentials: its CA did not sign them
        Client(address, security=Security.temporary(), timeout=1)
    # the refused Clients sit in cycles with their tracebacks: collected here, not inside the
    # next Client's start, where their __del__ would wait on the lock that start holds
    gc.collect()
    with pytest.raises(derive.IntegrationError, match=rf"^<sweep>: scheduler {address}: cannot connect"):
        derive.sweep(SMALL, scheduler=address, scheduler_timeout=1)  # no credentials at all
    # with them, a sweep runs there and gives the local numbers
    res = derive.sweep(SMALL, scheduler=address, security=c.security)
    for k in reference.measures:
        assert np.array_equal(res.measures[k], reference.measures[k], equal_nan=True), k


def test_a_scheduler_without_workers_says_so_after_the_timeout(reference):
    c = sweeps.local_cluster(0)
    try:
        msg, took = _refused(c.scheduler_address, 0.5, security=c.security)
    finally:
        c.close()
    assert msg.startswith(f"<sweep>: scheduler {c.scheduler_address}: has no workers (none "
                          "joined within 0.5 s")
    assert took < 5


@pytest.mark.skipif(__import__("importlib").util.find_spec("bokeh") is not None,
                    reason="bokeh is installed")
def test_a_dashboard_without_bokeh_is_refused():
    with pytest.raises(derive.SceneError, match=r"^<sweep>: dashboard: Dask's dashboard needs bokeh"):
        derive.sweep(SMALL, workers=1, dashboard=True)


@pytest.mark.slow
def test_a_dashboard_asked_for_is_bound_to_loopback():
    before = _listening(os.getpid())
    c = sweeps.local_cluster(1, dashboard=True)
    try:
        ours = _listening(os.getpid()) - before
        for kid in psutil.Process().children(recursive=True):
            ours |= _listening(kid.pid)
        assert {ip for ip, _ in ours} == {"127.0.0.1"}
        assert c.dashboard_link.startswith("http://127.0.0.1:")
        http = c.scheduler.http_server
        # the pages a dashboard serves are there (the Bokeh ones too, where bokeh is installed)
        assert _get(f"http://127.0.0.1:{http.port}/info/main/workers.html") == 200
    finally:
        c.close()
