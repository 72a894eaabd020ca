"""``derive generate`` keeps its files in the compile cache under a key covering every input of
the derivation: an unchanged input reads them back, a changed one (a source file, a template,
a library's version, SymPy's settings) misses and derives again, a damaged folder is derived
again, and old generations the cache made are pruned while anything else is left alone.

The derivation itself is replaced by a small stand-in (the whole one is what
``tests/test_codegen.py`` compares with ``generated/``), so each test costs milliseconds."""
import importlib.metadata
import os

import pytest

from derive import generate
from derive.runtime import cache as cache_folder

FILES = {"numpy/__init__.py": "MODELS = ()\n", "c/model.c": "int model;\n"}


@pytest.fixture
def fake(tmp_path, monkeypatch):
    """A cache in ``tmp_path`` and a stand-in derivation counting its calls; each call of
    ``run()`` is a fresh process's ``generate_all(cache=True)``."""
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path / "cache"))
    calls = []

    def derivation():
        calls.append(1)
        return tuple(sorted(FILES.items()))

    monkeypatch.setattr(generate, "_generate_everything", derivation)

    def run():
        generate._cached_everything.cache_clear()
        return generate.generate_all(cache=True)

    yield run, calls, tmp_path / "cache" / cache_folder.MODELS
    generate._cached_everything.cache_clear()


def test_a_second_generation_with_the_same_inputs_reads_the_cache(fake):
    run, calls, models = fake
    assert run() == FILES and len(calls) == 1
    (folder,) = models.iterdir()
    assert folder.name == generate.PREFIX + generate.derivation_key() and cache_folder.is_marked(folder)
    assert run() == FILES and len(calls) == 1


def test_a_changed_input_misses_the_cache(fake, monkeypatch):
    run, calls, models = fake
    run()
    monkeypatch.setattr(generate, "derivation_fingerprint", lambda folders: "0" * 64)
    assert run() == FILES and len(calls) == 2
    assert len(list(models.iterdir())) == 2


def test_a_damaged_generation_is_derived_again_once(fake, capsys):
    run, calls, models = fake
    run()
    (folder,) = models.iterdir()
    (folder / "c" / "model.c").write_text("int damaged;\n")
    assert run() == FILES and len(calls) == 2
    assert "deriving it again" in capsys.readouterr().err
    assert run() == FILES and len(calls) == 2


def test_only_the_newest_generations_the_cache_made_are_kept(fake, monkeypatch):
    run, calls, models = fake
    models.mkdir(parents=True)
    mine = models / (generate.PREFIX + "mine")  # a folder of the user's with the cache's prefix
    mine.mkdir()
    for i in range(generate.KEEP + 2):
        monkeypatch.setattr(generate, "derivation_fingerprint", lambda folders, i=i: str(i) * 64)
        run()
        os.utime(models / (generate.PREFIX + str(i) * 32), (1000.0 + i, 1000.0 + i))
    kept = sorted(p.name for p in models.iterdir() if p != mine)
    assert kept == sorted(generate.PREFIX + str(i) * 32 for i in range(2, generate.KEEP + 2))
    assert mine.is_dir()


def test_the_key_covers_every_file_of_the_sources(tmp_path, monkeypatch):
    monkeypatch.setattr(importlib.metadata, "distributions", lambda: [])  # (read once per key: slow)
    pkg, templates = tmp_path / "derive", tmp_path / "templates"
    (pkg / "sub").mkdir(parents=True)
    templates.mkdir()
    (pkg / "sub" / "a.py").write_text("x = 1\n")
    (templates / "t.j2").write_text("{{ x }}\n")
    key = lambda: cache_folder.derivation_fingerprint((pkg, templates))  # noqa: E731
    first = key()
    (pkg / "__pycache__").mkdir()
    (pkg / "__pycache__" / "a.pyc").write_bytes(b"\0")
    assert key() == first  # compiled bytecode is not an input
    seen = {first}
    for change in (lambda: (pkg / "sub" / "a.py").write_text("x = 2\n"),
                   lambda: (templates / "t.j2").write_text("{{ y }}\n"),
                   lambda: (pkg / "sub" / "b.py").write_text(""),
                   lambda: (pkg / "sub" / "b.py").rename(pkg / "b.py")):
        change()
        assert key() not in seen
        seen.add(key())


def test_the_key_covers_the_libraries_and_sympys_settings(tmp_path, monkeypatch):
    key = lambda: cache_folder.derivation_fingerprint((tmp_path,))  # noqa: E731
    first = key()
    monkeypatch.setenv("SYMPY_GROUND_TYPES", "python")
    assert key() != first
    monkeypatch.delenv("SYMPY_GROUND_TYPES")
    assert key() == first
    real = list(importlib.metadata.distributions())

    class Upgraded:
        def __init__(self, dist):
            self.metadata, self.version = dist.metadata, dist.version + ".post1"

    sympy = next(d for d in real if d.metadata["Name"].lower() == "sympy")
    monkeypatch.setattr(importlib.metadata, "distributions",
                        lambda: [Upgraded(d) if d is sympy else d for d in real])
    assert key() != first


def test_generate_keys_on_the_package_and_the_templates(monkeypatch):
    seen = []
    monkeypatch.setattr(generate, "derivation_fingerprint", lambda folders: seen.append(folders) or "0" * 64)
    generate.derivation_key()
    (folders,) = seen
    assert [f.resolve() for f in folders] == [generate.PACKAGE.resolve(), generate.TEMPLATES.resolve()]
    assert (folders[0] / "symbolic" / "models.py").is_file() and any(folders[1].rglob("*.j2"))
