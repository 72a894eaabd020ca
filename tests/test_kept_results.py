"""tests/kept_results.py: a kept result is read back without computing, computed again when its
arguments or its sources change or when the kept file is damaged, and never kept when computing
it raises."""
from __future__ import annotations

import pytest

import kept_results


@pytest.fixture
def computed(tmp_path, monkeypatch):
    """A cache of the test's own and a computation that counts its calls."""
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path / "cache"))
    source = tmp_path / "reference.py"
    source.write_text("the code of the reference\n")
    calls = []

    def value(what, sources=(source,)):
        return kept_results.kept("unit", what, lambda: calls.append(what) or [what, len(calls)], sources)
    return value, calls, source, tmp_path / "cache" / kept_results.FOLDER / "unit"


def test_a_kept_result_is_read_back_without_computing(computed):
    value, calls, _, _ = computed
    assert value(("a", 1.0)) == [("a", 1.0), 1]
    assert value(("a", 1.0)) == [("a", 1.0), 1] and calls == [("a", 1.0)]
    assert value(("a", 2.0)) == [("a", 2.0), 2]  # other arguments: computed


def test_a_changed_source_computes_again(computed):
    value, calls, source, _ = computed
    value("x")
    source.write_text("the code of the reference, edited\n")
    assert value("x") == ["x", 2] and len(calls) == 2


def test_a_damaged_kept_result_is_computed_again(computed):
    value, calls, _, folder = computed
    value("x")
    (kept,) = folder.glob("*/*.pickle")
    kept.write_bytes(kept.read_bytes()[:5])
    assert value("x") == ["x", 2]
    assert value("x") == ["x", 2] and len(calls) == 2  # and kept again, whole


def test_a_computation_that_raises_is_not_kept(tmp_path, monkeypatch):
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path))
    source = tmp_path / "reference.py"
    source.write_text("")

    def fails():
        raise ArithmeticError("no reference")

    with pytest.raises(ArithmeticError):
        kept_results.kept("unit", "x", fails, [source])
    assert not list(tmp_path.rglob("*.pickle"))
