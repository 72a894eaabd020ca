"""The runtime's translation unit is compiled once per flag set into an object the compile cache
keeps (checksum and stamp, like a library), and linked into every library built with those flags;
`derive cache` lists it and `--clear` removes it."""
import hashlib
import os
import uuid

import pytest

from derive.codegen.render import ROOT
from derive.runtime import cache as cache_folder
from derive.runtime import cbuild

GENERATED_C = ROOT / "generated" / "c"


def with_runtime(tag: str, runtime_tail: str = "") -> dict:
    """A one-function library holding the runtime (its header among the sources), unique per
    ``tag``; ``runtime_tail`` is appended to derive_runtime.c (another runtime source)."""
    return {"derive_runtime.h": (GENERATED_C / "derive_runtime.h").read_text(),
            "derive_runtime.c": (GENERATED_C / "derive_runtime.c").read_text() + runtime_tail,
            "tiny.c": f'/* {tag} */\n#include "derive_runtime.h"\n'
                      "int tiny_answer(void) { derive_stats st; derive_stats_init(&st);"
                      " return 42 + st.status; }\n"}


def objects(root):
    return sorted(root.glob("derive_runtime-*.o"))


def test_libraries_of_one_flag_set_link_one_kept_runtime_object(cache):
    libs = [cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex), "tiny.c")]
    (obj,) = objects(cache)
    made = (os.lstat(obj).st_ino, os.lstat(obj).st_mtime_ns)
    libs.append(cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex), "tiny.c"))
    for lib in libs:  # the model's unit calls the runtime; the host's Ctrl-C guard is exported
        assert lib.tiny_answer() == 42
        assert lib.derive_sigint_guard(1) == 0 and lib.derive_sigint_guard(0) == 0
    assert len(list(cache.glob("tiny-*.so"))) == 2
    assert objects(cache) == [obj] and (os.lstat(obj).st_ino, os.lstat(obj).st_mtime_ns) == made
    digest, name = obj.with_name(obj.name + ".sha256").read_text().split()
    assert name == obj.name and digest == hashlib.sha256(obj.read_bytes()).hexdigest()
    assert cache_folder.library_problem(obj) is None
    assert [e.status for e in cache_folder.cache_entries(cache) if e.name == obj.name] == ["ok"]
    assert not [p for p in cache.iterdir() if p.name.startswith(".")]  # no build folder left
    (cache / "notes.txt").write_text("the user's own file\n")
    count, _ = cache_folder.clear_cache(cache)
    assert count == 6  # the libraries, the object and their checksums
    assert sorted(p.name for p in cache.iterdir()) == ["notes.txt"]


def test_other_flags_or_another_runtime_source_is_another_object(cache):
    cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex), "tiny.c")
    (first,) = objects(cache)
    lib = cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex), "tiny.c",
                                 [*cbuild.DEFAULT_FLAGS, "-O2"])
    assert lib.tiny_answer() == 42 and len(objects(cache)) == 2
    lib = cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex, "int derive_tiny_extra;\n"),
                                 "tiny.c")
    assert lib.tiny_answer() == 42 and len(objects(cache)) == 3 and first in objects(cache)


@pytest.mark.parametrize("damage", ["truncated", "foreign"])
def test_a_damaged_runtime_object_is_rebuilt_with_a_note(cache, damage, capsys):
    cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex), "tiny.c")
    (obj,) = objects(cache)
    whole = obj.read_bytes()
    if damage == "truncated":
        obj.write_bytes(whole[: len(whole) // 2])
    else:  # whole bytes of another object under its checksum: the stamp gives it away
        other = whole.replace(b"derive_build_", b"derive_built_")
        obj.write_bytes(other)
        obj.with_name(obj.name + ".sha256").write_text(f"{hashlib.sha256(other).hexdigest()}  {obj.name}\n")
    capsys.readouterr()
    assert cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex), "tiny.c").tiny_answer() == 42
    notes = [ln for ln in capsys.readouterr().err.splitlines() if ln.startswith("note: cached")]
    assert len(notes) == 1 and notes[0].startswith(f"note: cached object {obj}")
    assert notes[0].endswith("; rebuilding it")
    assert obj.read_bytes() == whole and cache_folder.library_problem(obj) is None
    assert cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex), "tiny.c").tiny_answer() == 42
    assert "note: cached" not in capsys.readouterr().err  # healed: the next build finds it whole


def test_the_object_s_unit_is_what_the_runtime_source_includes():
    sources = with_runtime("t")
    sources[cbuild.HOST_SOURCE] = '#include "derive_runtime.c"\n'
    assert set(cbuild._included(sources, cbuild.HOST_SOURCE)) == {
        cbuild.HOST_SOURCE, "derive_runtime.c", "derive_runtime.h"}
    computed = dict(sources, **{"derive_runtime.c": "#include RUNTIME_PART\n"})
    assert cbuild._included(computed, cbuild.HOST_SOURCE) == computed  # not followed: everything


def test_a_method_s_selection_macro_leaves_the_object_alone(cache):
    """The object is keyed by the runtime as the preprocessor gives it: a macro the runtime never
    reads (a model's method selection) leaves it alone, the libraries share it; one it reads, by
    name or pasted, makes another object where it changes the text."""
    for flag in ("-DDERIVE_WITH_DOP853", "-DDERIVE_WITH_RK4"):
        lib = cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex), "tiny.c",
                                     [*cbuild.DEFAULT_FLAGS, "-DDERIVE_SELECT", flag])
        assert lib.tiny_answer() == 42
    assert len(objects(cache)) == 1
    reads = "#ifdef DERIVE_WITH_RK4\nint derive_tiny_rk4;\n#endif\n"
    for flag in ("-DDERIVE_WITH_DOP853", "-DDERIVE_WITH_RK4"):
        lib = cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex, reads), "tiny.c",
                                     [*cbuild.DEFAULT_FLAGS, "-DDERIVE_SELECT", flag])
        assert lib.tiny_answer() == 42
    # the unit that reads it compiles to the plain one's object without it, to another with it
    assert len(objects(cache)) == 2
    pastes = ("#define DERIVE_TINY_READ(m) DERIVE_CAT(DERIVE_WITH_, m)\n"  # a name it pastes
              "#if DERIVE_TINY_READ(RK4) + 0\nint derive_tiny_pasted_rk4;\n#endif\n")
    for flag in ("-DDERIVE_WITH_DOP853", "-DDERIVE_WITH_RK4"):
        cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex, pastes), "tiny.c",
                               [*cbuild.DEFAULT_FLAGS, "-DDERIVE_SELECT", flag])
    assert len(objects(cache)) == 3


def test_a_process_preprocesses_the_runtime_once_per_flag_set_and_unit(cache, tmp_path, monkeypatch):
    """Libraries of one flag set built in one process run the preprocessor on the runtime's unit
    once; other flags or another runtime source run it again, and so does every build whose
    flags name the user's files (an include folder may change between two builds)."""
    runs = []
    real_run = cbuild._run

    def counted(cmd, cwd, what):
        runs.extend(["-E"] if "-E" in cmd else [])
        return real_run(cmd, cwd, what)

    monkeypatch.setattr(cbuild, "_PREPROCESSED", {})
    monkeypatch.setattr(cbuild, "_run", counted)
    for _ in range(3):
        assert cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex), "tiny.c").tiny_answer() == 42
    assert len(runs) == 1 and len(objects(cache)) == 1
    cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex), "tiny.c", [*cbuild.DEFAULT_FLAGS, "-O2"])
    cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex, "int derive_tiny_extra;\n"), "tiny.c")
    assert len(runs) == 3 and len(objects(cache)) == 3
    (tmp_path / "include").mkdir()
    for _ in range(2):
        cbuild.compile_library("tiny", with_runtime(uuid.uuid4().hex), "tiny.c",
                               [*cbuild.DEFAULT_FLAGS, "-I", str(tmp_path / "include")])
    assert len(runs) == 5 and len(objects(cache)) == 4
