"""Hypothesis settings for the whole suite: deterministic by default, exploring on request.

* Profile ``derive`` (the default): ``derandomize=True`` (each property test draws the same
  examples on every run, derived from the test's code) and ``database=None`` (no examples are
  stored in ``.hypothesis/`` and replayed). The suite's outcome then depends on the code alone:
  a clone does not go red because an earlier run in it found (and stored) a failing example,
  and a fresh clone in CI runs exactly what the developer ran.
* The compile cache: ``.cache/derive-tests`` in the checkout (``DERIVE_CACHE``), so that the
  suite leaves nothing in the user's own cache.
* Profile ``explore``: fresh random examples, still nothing stored; a failure prints its
  ``@reproduce_failure`` blob. Selected by ``--hypothesis-seed=N`` (a reproducible exploration
  with seed N) or ``--hypothesis-profile=explore`` (a new seed each run)::

      .venv/bin/python -m pytest -p no:cacheprovider tests/test_fuzz_scene.py --hypothesis-seed=7

  A bug found this way is fixed in the code and pinned by a plain test (not by a stored seed).
"""
import fcntl
import gc
import hashlib
import json
import os
import pickle
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import settings

# The suite compiles into a cache of its own inside the checkout (kept between runs, ignored by
# git), never into the user's ~/.cache/derive; a test that needs another cache sets its own.
os.environ["DERIVE_CACHE"] = str(Path(__file__).resolve().parents[1] / ".cache" / "derive-tests")

from derive.runtime import cache as cache_folder  # noqa: E402  (after DERIVE_CACHE is set)

# The suite's kernels are compiled at -O0 (DERIVE_CFLAGS, after derive's -O3): most of them run
# for well under a second, where compiling costs more than the unoptimised code does. ISO C
# contracts nothing at any level, but at -O0 a square written pow(x, 2) is libm's pow where an
# optimised build multiplies, so last bits may differ from a user's build. Tests of what the
# optimiser could break (the vector and lanes builds, bit for bit) and tests that hold the
# suite's kernels to a user's build (the exported examples) carry the mark ``optimised`` and
# compile with derive's own flags.
os.environ.setdefault("DERIVE_CFLAGS", "-O0")

settings.register_profile("derive", database=None, derandomize=True)
settings.register_profile("explore", database=None, derandomize=False, print_blob=True)
settings.load_profile("derive")


def pytest_collection_finish(session):
    """Once the tests are collected, what is alive then (the modules, SymPy's and NumPy's tables,
    the collected items) is kept out of the cycle collector's walks (``gc.freeze``): it lives for
    the whole run, and each full collection would otherwise walk all of it again while the tests
    make and drop SymPy's expressions. When collections run is unchanged."""
    gc.collect()
    gc.freeze()


def _forget_loaded_libraries() -> None:
    """Empty the per-process tables of loaded libraries that are not keyed by the flags (a
    model's (method, build) kernels, the contact driver's per shape and law)."""
    from derive.contact import driver  # (SymPy with it: never in xdist's controller)
    from derive.runtime.integrate import ModelKernel

    ModelKernel._cache.clear()
    driver.library.cache_clear()


@pytest.fixture(scope="module", autouse=True)
def _optimised_builds(request):
    """A test module marked ``optimised`` (``pytestmark``) compiles with derive's own flags only,
    its module-scoped fixtures too: ``DERIVE_CFLAGS`` is unset while it runs, and it loads its
    own libraries (none another module loaded at -O0 in this process) and leaves none behind."""
    if request.node.get_closest_marker("optimised") is None:
        yield
        return
    _forget_loaded_libraries()
    with pytest.MonkeyPatch.context() as patch:
        patch.delenv("DERIVE_CFLAGS", raising=False)
        yield
    _forget_loaded_libraries()


@pytest.fixture
def cache(tmp_path, monkeypatch):
    """An empty compile cache of the test's own (and no private fallback left by another test)."""
    root = tmp_path / "cache"
    monkeypatch.setenv("DERIVE_CACHE", str(root))
    monkeypatch.setattr(cache_folder, "_fallback", None)
    return root


def once_per_run(tmp_path_factory, name: str, compute):
    """``compute()`` once per test run, whatever the number of test processes: the first
    process to ask computes it (under a lock) and leaves it pickled in the run's temporary
    folder, which every pytest-xdist worker shares; the others load it. For costly pure results
    (the lecture checked, every generated file) that several test files read."""
    root = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        root = root.parent  # the workers' folders sit side by side in one folder of the run
    path = root / f"{name}.pickle"
    with open(root / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if path.is_file():
            return pickle.loads(path.read_bytes())
        value = compute()
        part = path.with_suffix(".part")
        part.write_bytes(pickle.dumps(value))
        part.replace(path)
        return value


@pytest.fixture(scope="session")
def notes_reading(tmp_path_factory):
    """``notes_reading(path, convention=None)``: the claims of ``check_notes`` on a whole notes
    file, read once per test run (:func:`once_per_run`) and kept between runs (tests/kept_readings.py),
    for the texts several tests read (the corpus, the lecture)."""
    import kept_readings  # the reader (and SymPy) load in the processes that read, never in xdist's controller

    def reading(path, convention=None):
        path = Path(path)
        key = hashlib.sha256(repr((str(path), convention)).encode()).hexdigest()[:16]
        return once_per_run(tmp_path_factory, f"reading-{key}", lambda: kept_readings.check_notes(path, convention))
    return reading


@pytest.fixture(scope="session")
def once(tmp_path_factory):
    """``once(name, compute)``: :func:`once_per_run` for a test's own costly result (a path into
    the run's temporary folder is shared as well as a value)."""
    return lambda name, compute: once_per_run(tmp_path_factory, name, compute)


#: The course's notes file (not part of the repository): $DERIVE_NOTES, else the course folder
#: next to the checkout.
LECTURE_NOTES = Path(os.environ.get("DERIVE_NOTES")
                     or Path(__file__).resolve().parents[2] / "shared" / "notes" / "lecture26-rigid-body.md")


@pytest.fixture(scope="session")
def lecture_claims(notes_reading):
    """The lecture's notes read and checked once per test run (``check_notes``, kept between runs
    by :func:`notes_reading`), shared by the files that test the reader on them."""
    if not LECTURE_NOTES.is_file():
        pytest.skip(f"the lecture's notes file is not at {LECTURE_NOTES} (set DERIVE_NOTES)")
    return notes_reading(LECTURE_NOTES)


def _generate_in_a_fresh_process() -> dict[str, str]:
    """``generate_all(cache=True)`` as ``make derive`` runs it, in a process of its own (whose
    state no test has touched): derived in a fresh checkout (its cache is empty), read from the
    suite's cache when a generation from the same sources is kept there."""
    code = ("import json, sys; from derive import generate; "
            "sys.stdout.write(json.dumps(generate.generate_all(cache=True)))")
    r = subprocess.run([sys.executable, "-c", code], cwd=Path(__file__).resolve().parents[1],
                       capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"generate_all failed:\n{r.stderr}")
    return json.loads(r.stdout)


@pytest.fixture(scope="session")
def generated_files(tmp_path_factory):
    """Every file ``make derive`` writes (``derive.generate.generate_all``), once per test run
    and shared by the tests that compare or read them."""
    return once_per_run(tmp_path_factory, "generated-files", _generate_in_a_fresh_process)


@pytest.fixture(scope="session")
def generated_reports(generated_files):
    """The two reports ``make derive`` writes (``derive.lecture.report.documents``): the part of
    ``generated_files`` the lecture's tests read (derived once with the rest)."""
    return {name: generated_files[name] for name in ("lecture-verification.md", "derivation.md")}


def pytest_configure(config):
    # Under derandomize a --hypothesis-seed would be ignored (the digest of the test wins):
    # asking for a seed means asking to explore, unless a profile was named explicitly.
    seed = config.getoption("hypothesis_seed", None)
    if seed is not None and config.getoption("hypothesis_profile", None) is None:
        settings.load_profile("explore")


def pytest_collection(session):
    """In a fresh checkout each test process would rewrite every test module's asserts and keep
    the bytecode (``__pycache__``); run side by side, the processes would all do all of it. Each
    pytest-xdist worker first rewrites its share of the modules (every n-th), so that collecting
    finds the rest kept by the others; a module another has not kept yet is rewritten as before.
    Nothing is done where bytecode is not written or pytest's rewriter is not the one expected."""
    worker, count = os.environ.get("PYTEST_XDIST_WORKER", ""), os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1")
    if not worker[2:].isdigit() or not count.isdigit() or int(count) < 2 or sys.dont_write_bytecode:
        return
    try:
        from _pytest.assertion import rewrite
        state = session.config.stash[rewrite.assertstate_key]
    except (ImportError, AttributeError, KeyError):
        return
    for source in sorted(Path(__file__).parent.glob("test_*.py"))[int(worker[2:])::int(count)]:
        try:
            pyc = rewrite.get_cache_dir(source) / (source.name[:-3] + rewrite.PYC_TAIL)
            if rewrite._read_pyc(source, pyc) is None and rewrite.try_makedirs(pyc.parent):
                source_hash, code = rewrite._rewrite_test(source, session.config)
                rewrite._write_pyc(state, code, source_hash, pyc)
        except Exception:  # (a module that does not compile, another pytest): collection says why
            continue
