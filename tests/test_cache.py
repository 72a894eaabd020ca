"""The compile cache heals itself: checksums verified on load, corrupt libraries rebuilt once,
an unwritable cache replaced by a private one, stale build folders removed; `derive cache`."""
import contextlib
import ctypes
import hashlib
import io
import os
import shutil
import subprocess
import sys
import time
import uuid

import pytest

from derive import cli
from derive.runtime import cache as cache_folder
from derive.runtime import cbuild
from derive.codegen.render import ROOT


def tiny(tag: str) -> dict:
    """A one-function library, unique per test (so no process has loaded it yet)."""
    return {"tiny.c": f"/* {tag} */\nint tiny_answer(void) {{ return 42; }}\n"}


def libraries(root):
    return sorted(p.name for p in root.glob("*.so"))


def build_in_subprocess(root, tag, env=None):
    """Build-or-load the tiny library in a fresh process; (return code, stderr)."""
    code = ("import sys; from derive.runtime import cbuild; "
            f"lib = cbuild.compile_library('tiny', {tiny(tag)!r}, 'tiny.c'); "
            "sys.exit(0 if lib.tiny_answer() == 42 else 5)")
    e = dict(os.environ, **(env or {}))
    if root is not None:
        e["DERIVE_CACHE"] = str(root)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=e,
                       cwd=ROOT, timeout=120)
    return r.returncode, r.stderr


def test_a_build_writes_the_library_and_its_checksum(cache):
    lib = cbuild.compile_library("tiny", tiny(uuid.uuid4().hex), "tiny.c")
    assert lib.tiny_answer() == 42
    (so,) = cache.glob("tiny-*.so")
    side = so.with_name(so.name + ".sha256")
    digest, name = side.read_text().split()
    assert name == so.name and digest == hashlib.sha256(so.read_bytes()).hexdigest()
    assert [e.status for e in cache_folder.cache_entries() if e.name == so.name] == ["ok"]
    assert not [p for p in cache.iterdir() if p.name.startswith(".")]  # no build folder left


@pytest.mark.parametrize("damage", ["truncate", pytest.param("flip", marks=pytest.mark.slow),
                                    pytest.param("garbage-with-checksum", marks=pytest.mark.slow), "no-checksum"])
def test_a_damaged_library_is_rebuilt_once_with_a_note(cache, damage):
    tag = uuid.uuid4().hex
    rc, err = build_in_subprocess(cache, tag)
    assert rc == 0 and err == ""
    (so,) = cache.glob("tiny-*.so")
    side = so.with_name(so.name + ".sha256")
    good = so.read_bytes()
    if damage == "truncate":  # a compile or copy cut short
        so.write_bytes(good[: len(good) // 3])
    elif damage == "flip":  # a bit flipped somewhere in the code
        so.write_bytes(good[:2000] + bytes([good[2000] ^ 0x40]) + good[2001:])
    elif damage == "garbage-with-checksum":  # verifies, but the loader refuses it
        so.write_bytes(b"not an ELF file at all\n" * 50)
        side.write_text(f"{hashlib.sha256(so.read_bytes()).hexdigest()}  {so.name}\n")
    else:  # built by an older version, or the checksum was lost
        side.unlink()
    rc, err = build_in_subprocess(cache, tag)
    lines = err.strip().splitlines()
    assert rc == 0 and len(lines) == 1 and lines[0].startswith(f"note: cached library {so}")
    assert lines[0].endswith("rebuilding it")
    assert so.read_bytes() == good
    rc, err = build_in_subprocess(cache, tag)  # healed: no note any more
    assert rc == 0 and err == ""


def test_damaged_in_process_before_the_first_load(cache, capsys):
    """The same inside one process: a corrupt file where the library should be is replaced."""
    sources = tiny(uuid.uuid4().hex)
    key = cbuild._key(sources, ["tiny.c"], cbuild.compiler(), [*cbuild.DEFAULT_FLAGS, *cbuild.extra_flags()])
    cache.mkdir()
    so = cache / f"tiny-{key[:24]}.so"
    so.write_bytes(b"\x7fELF truncated")
    lib = cbuild.compile_library("tiny", sources, "tiny.c")
    assert lib.tiny_answer() == 42
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"note: cached library {so} has no checksum; rebuilding it"]
    assert libraries(cache) == [so.name]


def unwritable(tmp_path):
    """A cache path nobody can create, root included: its parent is a regular file."""
    blocker = tmp_path / "blocker"
    blocker.write_text("a file, not a folder\n")
    return blocker / "cache"


def test_unwritable_cache_falls_back_to_a_private_folder(tmp_path):
    rc, err = build_in_subprocess(unwritable(tmp_path), uuid.uuid4().hex)
    lines = err.strip().splitlines()
    assert rc == 0 and len(lines) == 1
    assert lines[0].startswith(f"warning: compile cache {unwritable(tmp_path)} is not writable")
    private = lines[0].split("using ")[1].split(" for this run")[0]
    assert not os.path.exists(private)  # removed at exit


def test_unwritable_home_falls_back(tmp_path):
    env = {"HOME": str(unwritable(tmp_path))}
    e = {k: v for k, v in os.environ.items() if k != "DERIVE_CACHE"}
    code = ("import sys; from derive.runtime import cbuild; "
            f"sys.exit(cbuild.compile_library('tiny', {tiny(uuid.uuid4().hex)!r}, 'tiny.c')"
            ".tiny_answer() != 42)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       env=dict(e, **env), cwd=ROOT, timeout=120)
    assert r.returncode == 0
    assert r.stderr.startswith("warning: compile cache ") and len(r.stderr.splitlines()) == 1


def test_fallback_in_process_warns_once(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("DERIVE_CACHE", str(unwritable(tmp_path)))
    monkeypatch.setattr(cache_folder, "_fallback", None)
    a = cbuild.compile_library("tiny", tiny(uuid.uuid4().hex), "tiny.c")
    b = cbuild.compile_library("tiny", tiny(uuid.uuid4().hex), "tiny.c")
    assert a.tiny_answer() == b.tiny_answer() == 42
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("warning: compile cache")
    assert len(libraries(cache_folder._fallback)) == 2


def test_simulate_with_an_unwritable_cache_runs_with_one_warning(tmp_path):
    """The whole command: derived models and compiled kernels go to the private cache (the free
    body with DOP853: the cheapest kernel to compile there)."""
    out = tmp_path / "out.npz"
    env = dict(os.environ, DERIVE_CACHE=str(unwritable(tmp_path)))
    r = subprocess.run([sys.executable, "-m", "derive", "simulate", "scenes/free_symmetric.toml",
                        "--method", "dop853", "-o", out], capture_output=True, text=True, env=env,
                       cwd=ROOT, timeout=300)
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 0 and out.is_file(), r.stderr
    assert len(lines) == 1 and lines[0].startswith("warning: compile cache "), r.stderr


def test_stale_build_folders_are_removed(cache):
    cache.mkdir()
    stale, fresh, legacy = (cache / ".build-tiny-abcd1234", cache / ".build-tiny-zzzz9999",
                            cache / ".heavy_top-k2j4h5g6")
    for d in (stale, fresh, legacy):
        d.mkdir()
        cache_folder.mark(d)  # what the cache removes is what it made: marked folders only
        (d / "tiny.c").write_text("int x;\n")
    old = time.time() - 2 * cache_folder.STALE_BUILD_SECONDS
    for d in (stale, legacy):
        os.utime(d, (old, old))
    foreign = cache / ".not-ours"
    foreign.mkdir()
    os.utime(foreign, (old, old))
    stale_lock, fresh_lock, foreign_lock = (cache / ".tiny-abcd.so.lock", cache / ".tiny-ef01.so.lock",
                                            cache / ".mine.lock")
    for f in (stale_lock, fresh_lock):
        f.write_text(cache_folder.LOCK_TEXT)  # what a process killed while it held a lock leaves
    foreign_lock.write_text("the user's own lock\n")
    for f in (stale_lock, foreign_lock):
        os.utime(f, (old, old))
    models = cache / "models"
    model = models / "quaternion_sym-0123abcd-4567ef"
    stale_model = models / ".quaternion_sym-0123abcd-4567ef-k2j4h5g6"  # a killed derivation
    for d in (stale_model, model):
        d.mkdir(parents=True)
        cache_folder.mark(d)
        os.utime(d, (old, old))
    cbuild.compile_library("tiny", tiny(uuid.uuid4().hex), "tiny.c")
    assert not stale.exists() and not legacy.exists() and not stale_model.exists()
    assert fresh.exists() and foreign.exists() and model.exists()
    assert not stale_lock.exists() and fresh_lock.exists() and foreign_lock.exists()


#: A compiler that logs each compile (not the ``--version`` the cache keys on) and does not
#: compile until the other process waits at the library's lock (:func:`_two_at_once`'s
#: ``$WAITING`` folder, given at most a minute), so that the second asks while the first compiles.
LOGGING_CC = """#!/bin/sh
case "$*" in *--version*) ;; *) echo compile >> "$0.log"
  i=0; while [ -n "$WAITING" ] && [ -z "$(ls -A "$WAITING")" ] && [ $i -lt 6000 ]; do sleep 0.01; i=$((i+1)); done ;; esac
exec cc "$@"
"""

#: What each process of :func:`_two_at_once` runs first: a lock that another process holds is
#: waited for only after a file named by the waiting process is left in ``$WAITING``, so the
#: holder's stand-in (the compiler, the derivation) knows the other is waiting (no fixed sleep).
_SAY_WHEN_WAITING = """import fcntl, os
_flock = fcntl.flock
def _flock_saying_when_waiting(fd, op):
    if op != fcntl.LOCK_EX:
        return _flock(fd, op)
    try:
        return _flock(fd, op | fcntl.LOCK_NB)
    except BlockingIOError:
        open(os.path.join(os.environ["WAITING"], str(os.getpid())), "w").close()
        return _flock(fd, op)
fcntl.flock = _flock_saying_when_waiting
"""

#: The holder's wait (Python) for the other process to wait at its lock, at most a minute.
_UNTIL_THE_OTHER_WAITS = ("t0 = time.monotonic()\n"
                          "while not os.listdir(os.environ['WAITING']) and time.monotonic() - t0 < 60:\n"
                          "    time.sleep(0.01)\n")


def _two_at_once(tmp_path, setup: str, code: str, env: dict) -> list[tuple[int, str]]:
    """Run ``setup`` then ``code`` in two fresh processes that start ``code`` together (each
    waits for the other at a barrier in between); their (return code, stderr). A process that
    finds a cache lock taken says so in ``$WAITING`` before it waits (:data:`_SAY_WHEN_WAITING`)."""
    barrier, waiting = tmp_path / "barrier", tmp_path / "waiting"
    barrier.mkdir()
    waiting.mkdir()
    wait = (f"\nimport os, time\nopen(os.path.join({str(barrier)!r}, str(os.getpid())), 'w').close()\n"
            f"while len(os.listdir({str(barrier)!r})) < 2:\n    time.sleep(0.01)\n")
    procs = [subprocess.Popen([sys.executable, "-c", _SAY_WHEN_WAITING + setup + wait + code],
                              env=dict(os.environ, **env, WAITING=str(waiting)),
                              cwd=ROOT, stderr=subprocess.PIPE, text=True) for _ in range(2)]
    return [(p.wait(timeout=120), p.stderr.read()) for p in procs]


def test_two_processes_needing_one_library_build_it_once_and_both_load_it(cache, tmp_path):
    cc = tmp_path / "logging-cc"
    cc.write_text(LOGGING_CC)
    cc.chmod(0o755)
    setup = "import sys; from derive.runtime import cbuild"
    code = (f"lib = cbuild.compile_library('tiny', {tiny(uuid.uuid4().hex)!r}, 'tiny.c')\n"
            "sys.exit(0 if lib.tiny_answer() == 42 else 5)")
    env = {"DERIVE_CACHE": str(cache), "CC": str(cc)}
    assert _two_at_once(tmp_path, setup, code, env) == [(0, ""), (0, "")]
    assert (tmp_path / "logging-cc.log").read_text() == "compile\n"  # one compile, two loads
    assert len(libraries(cache)) == 1
    assert not [p for p in cache.iterdir() if p.name.startswith(".")]  # no lock nor build folder left


def test_two_processes_needing_one_model_derive_it_once_and_both_read_it(cache, tmp_path):
    """The derivation (SymPy) stood in for by one that logs, waits until the other process
    waits at the model's lock and writes a shipped model's description under the asked model's
    name."""
    log = tmp_path / "derivations.log"
    setup = ("import json, sys, time; from derive.runtime import cache, catalogue\n"
             "shipped = catalogue.describe(('euler-poisson', False, ()))\n"
             "def derive_model(key, folder):\n"
             f"    open({str(log)!r}, 'a').write('derive\\n')\n"
             + "".join(f"    {line}\n" for line in _UNTIL_THE_OTHER_WAITS.splitlines()) +
             "    d = json.loads(shipped.source('models/euler_poisson_asym.json')); d['name'] = 'quaternion_asym_gravity'\n"
             "    cache.write_folder(folder, {'models/quaternion_asym_gravity.json': json.dumps(d)},\n"
             "                       'models/quaternion_asym_gravity.json')\n"
             "catalogue.derive_model = derive_model")
    code = "sys.exit(0 if catalogue.describe(('quaternion', False, ('gravity',))).name == 'quaternion_asym_gravity' else 5)"
    assert _two_at_once(tmp_path, setup, code, {"DERIVE_CACHE": str(cache)}) == [(0, ""), (0, "")]
    assert log.read_text() == "derive\n"  # one derivation, two readers
    (variant,) = (cache / "models").iterdir()  # no lock left beside it
    assert variant.name.startswith("quaternion_asym_gravity-")


def run(*argv):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = cli.main(list(argv))
    return rc, out.getvalue(), err.getvalue()


def test_cache_command_lists_and_clears(cache):
    cbuild.compile_library("tiny", tiny(uuid.uuid4().hex), "tiny.c")
    (so,) = cache.glob("tiny-*.so")
    (cache / "notes.txt").write_text("the user's own file\n")
    (cache / ".build-tiny-abcd1234").mkdir()
    cache_folder.mark(cache / ".build-tiny-abcd1234")  # the cache's own (marked) folders
    (cache / "models" / "quaternion_sym-0123abcd-4567ef" / "c").mkdir(parents=True)
    cache_folder.mark(cache / "models" / "quaternion_sym-0123abcd-4567ef")
    (cache / "models" / "quaternion_sym-0123abcd-4567ef" / "c" / "m.c").write_text("int m;\n")
    rc, out, err = run("cache")
    assert rc == 0 and err == ""
    lines = out.splitlines()
    assert lines[0] == f"compile cache: {cache} (DERIVE_CACHE)"
    assert any(ln.split()[0] == so.name and ln.split()[-1] == "ok" for ln in lines)
    assert any(ln.split()[0] == ".build-tiny-abcd1234" for ln in lines)
    assert any(ln.split()[0] == "models" and ln.endswith("derived models (1 variants)") for ln in lines)
    assert not any("notes.txt" in ln or ".sha256" in ln for ln in lines)
    assert lines[-1].startswith("1 libraries, ")

    rc, out, err = run("cache", "--clear")
    assert rc == 0 and out.startswith("removed 4 entries") and err == ""
    assert sorted(p.name for p in cache.iterdir()) == ["notes.txt"]
    rc, out, err = run("cache")
    assert rc == 0 and out.splitlines()[-1] == "empty"


def test_cache_command_shows_damage(cache):
    cbuild.compile_library("tiny", tiny(uuid.uuid4().hex), "tiny.c")
    (so,) = cache.glob("tiny-*.so")
    head = so.read_bytes()[:100]
    # A new file where the library was: truncating the loaded one in place would pull the
    # pages from under this process's mapping (SIGBUS at the next touch, e.g. at exit).
    so.unlink()
    so.write_bytes(head)
    rc, out, _ = run("cache")
    (line,) = [ln for ln in out.splitlines() if ln.split()[0] == so.name]
    assert "does not match its checksum" in line


def test_cache_command_without_a_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path / "nothing-here"))
    assert run("cache")[:2] == (0, f"compile cache: {tmp_path / 'nothing-here'} (DERIVE_CACHE)\nempty\n")
    rc, out, _ = run("cache", "--clear")
    assert rc == 0 and out.startswith("removed 0 entries")


def test_make_clean_clears_the_cache():
    text = (ROOT / "Makefile").read_text()
    clean = text.split("\nclean:", 1)[1].split("\n\n", 1)[0]
    assert "-m derive cache --clear" in clean


def test_loaded_library_is_reused_in_process(cache):
    sources = tiny(uuid.uuid4().hex)
    a = cbuild.compile_library("tiny", sources, "tiny.c")
    (so,) = cache.glob("tiny-*.so")
    so.unlink()  # a second call does not even look at the disk
    assert cbuild.compile_library("tiny", sources, "tiny.c") is a
    assert isinstance(a, ctypes.CDLL)


def test_a_compiler_killed_by_ctrl_c_is_an_interrupt(cache, tmp_path, monkeypatch):
    """Ctrl-C in a terminal reaches the compiler too; its death is not a compile error."""
    fake = tmp_path / "cc"
    fake.write_text(f"#!{sys.executable}\n"  # a shell could not undo an inherited SIG_IGN
                    "import os, signal, sys\n"
                    "if sys.argv[1:] == ['--version']: print('fake 1.0'); sys.exit(0)\n"
                    "signal.signal(signal.SIGINT, signal.SIG_DFL)\n"
                    "os.kill(os.getpid(), signal.SIGINT)\n")
    fake.chmod(0o755)
    monkeypatch.setenv("CC", str(fake))
    with pytest.raises(KeyboardInterrupt):
        cbuild.compile_library("tiny", tiny(uuid.uuid4().hex), "tiny.c")
    assert not [p for p in cache.iterdir() if p.name.startswith(".build-")]


def test_a_native_build_is_keyed_by_this_cpu(monkeypatch):
    """A library built with -march=native (the Taylor lanes) runs only on the CPU it was built
    for: its key holds that CPU's instruction sets, so a cache shared with another CPU never
    loads it there; a build without the flag does not depend on them."""
    sources = tiny("native")
    cmd = cbuild.compiler()
    native = list(cbuild.DEFAULT_FLAGS) + list(cbuild.NATIVE_FLAGS)
    plain = list(cbuild.DEFAULT_FLAGS)
    here = cbuild._key(sources, ["tiny.c"], cmd, native)
    identity = cbuild._native_identity(tuple(cmd))
    assert identity and identity != "?"
    if os.path.exists("/proc/cpuinfo"):  # Linux: the CPU as the kernel reports it (no compiler run)
        assert any(line.startswith(("flags", "Features")) for line in identity.splitlines())
    keys = {}
    for cpu in ("#define __AVX512F__ 1", "#define __SSE2__ 1"):
        monkeypatch.setattr(cbuild, "_native_identity", lambda cmd, cpu=cpu: cpu)
        keys[cpu] = (cbuild._key(sources, ["tiny.c"], cmd, native), cbuild._key(sources, ["tiny.c"], cmd, plain))
    (a, a_plain), (b, b_plain) = keys.values()
    assert len({a, b, here}) == 3
    assert a_plain == b_plain


def test_a_compiler_without_march_native_gets_the_baseline_build(cache, tmp_path, monkeypatch):
    """The vector and lanes builds ask for -march=native; a compiler that refuses it (older clang
    on Arm) gets the same build for the architecture's baseline, and is not asked again."""
    real = shutil.which("cc") or shutil.which("gcc")
    log = tmp_path / "calls"
    wrapper = tmp_path / "cc-no-native"
    wrapper.write_text("#!/bin/sh\n"
                       f'echo "$*" >> "{log}"\n'
                       'for a in "$@"; do [ "$a" = "-march=native" ] && '
                       '{ echo "error: unsupported option -march=native" >&2; exit 1; }; done\n'
                       f'exec "{real}" "$@"\n')
    wrapper.chmod(0o755)
    monkeypatch.setenv("CC", str(wrapper))
    monkeypatch.setattr(cbuild, "_native_refused", set())
    flags = [*cbuild.DEFAULT_FLAGS, *cbuild.BUILDS["vector"]]
    lib = cbuild.compile_library("tiny", tiny(uuid.uuid4().hex), "tiny.c", flags)
    assert lib.tiny_answer() == 42
    assert (str(wrapper),) in cbuild._native_refused
    builds = [line for line in log.read_text().splitlines() if "tiny.c" in line]
    assert sum("-march=native" in line for line in builds) == 1  # the refused try, then without
    lib2 = cbuild.compile_library("tiny", tiny(uuid.uuid4().hex), "tiny.c", flags)
    assert lib2.tiny_answer() == 42
    builds = [line for line in log.read_text().splitlines() if "tiny.c" in line]
    assert sum("-march=native" in line for line in builds) == 1  # not asked again


def test_the_users_cflags_reach_the_compiler_after_derives_and_key_the_library(cache, monkeypatch):
    source = {"answer.c": "int answer(void) { return ANSWER; }\n"}
    monkeypatch.setenv("DERIVE_CFLAGS", "-DANSWER=7 -O0")
    seven = cbuild.compile_library("answer", source, "answer.c")
    monkeypatch.setenv("DERIVE_CFLAGS", "-DANSWER=8")
    eight = cbuild.compile_library("answer", source, "answer.c")
    assert (seven.answer(), eight.answer()) == (7, 8)
    assert len(list(cache.glob("answer-*.so"))) == 2  # two keys, two libraries
