"""The public API documents itself: its docstrings' examples run, and the API reference builds
warning-free with Sphinx (``make docs``)."""
from __future__ import annotations

import doctest
import subprocess
import sys
from pathlib import Path

import pytest

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
    pytest.importorskip("sphinx")
    r = subprocess.run([sys.executable, "-m", "sphinx", "-W", "-q", "-b", "html", "-d", str(tmp_path / "doctrees"),
                        str(ROOT / "docs" / "api"), str(tmp_path / "html")],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr[-3000:]
    page = (tmp_path / "html" / "index.html").read_text(encoding="utf-8")
    for name in ("derive.simulate", "derive.sweep", "derive.analyze", "Result", "SceneError"):
        assert name in page, name
