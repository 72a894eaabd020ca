"""The public API documents itself: its docstrings' examples run, and the API reference builds
warning-free with Sphinx (``make docs``)."""
from __future__ import annotations

import doctest
import subprocess
import sys
from importlib import metadata
from pathlib import Path

import pytest

import compile_once
import derive

ROOT = Path(__file__).resolve().parent.parent


def test_the_public_functions_examples_run():
    result = doctest.testmod(derive, optionflags=doctest.ELLIPSIS, report=False)
    assert result.attempted >= 8 and result.failed == 0, result


@pytest.mark.parametrize("name", derive.__all__)
def test_each_public_name_has_a_numpydoc_docstring(name):
    doc = getattr(derive, name).__doc__ or ""
    if name.endswith("Error"):
        assert "CLI exit status" in doc or "compile" in doc, name
        return
    sections = ("Parameters", "Raises", "Examples") if isinstance(getattr(derive, name), type) \
        else ("Parameters", "Returns", "Raises", "Examples")  # a class returns nothing
    for section in sections:
        assert f"\n    {section}\n    ---" in doc, (name, section)


def test_the_api_reference_builds_without_a_warning(tmp_path):
    """Sphinx with ``-W``: any warning fails the build. The build is a function of the reference's
    sources, the package it documents and the versions of Sphinx and what it renders with: it
    is kept for exactly these (``compile_once.once``), so any change to one builds it again."""
    pytest.importorskip("sphinx")

    def build(work: Path) -> None:
        r = subprocess.run([sys.executable, "-m", "sphinx", "-W", "-q", "-b", "html", "-d", str(tmp_path / "doctrees"),
                            str(ROOT / "docs" / "api"), str(work / "html")],
                           capture_output=True, text=True, timeout=300)
        assert r.returncode == 0, r.stderr[-3000:]

    inputs = compile_once.files_under(ROOT / "docs" / "api", ROOT / "derive")
    what = ["sphinx -W -b html", sys.version,
            *(f"{dist} {metadata.version(dist)}" for dist in ("sphinx", "docutils", "alabaster", "jinja2",
                                                               "pygments", "numpy"))]
    page = (compile_once.once(what, inputs, build) / "html" / "index.html").read_text(encoding="utf-8")
    for name in ("derive.simulate", "derive.sweep", "derive.analyze", "Result", "SceneError"):
        assert name in page, name
