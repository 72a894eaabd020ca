"""``derive verify``'s reader for the tests, its claims kept between test runs.

:func:`check_notes` and :func:`check_text` are `derive.lecture.notes_check`'s, but a reading is
kept in the suite's cache (``$DERIVE_CACHE/notes-readings/<source key>/``), named by everything
its claims depend on: the text (a file's path and bytes, or the text and the path it is given),
the convention asked for, and :func:`source_key` (derive's source, the interpreter, the installed
libraries and SymPy's settings). A run reads again what any of them changed; a run after one that
changed nothing asserts on the same claims without reading. A reading the reader refuses (an
exception) is never kept. The most recently used source keys stay (tests/kept_results.py's
:data:`KEEP`).
"""
from __future__ import annotations

import functools
import os
from pathlib import Path

from derive.lecture import notes_check as nc
from kept_results import kept_in
from derive.runtime.cache import derivation_fingerprint

PACKAGE = Path(__file__).resolve().parents[1] / "derive"
FOLDER = "notes-readings"


@functools.cache
def source_key() -> str:
    """:func:`derive.runtime.cache.derivation_fingerprint` of derive's source (with the
    interpreter, the installed libraries' versions and SymPy's settings)."""
    return derivation_fingerprint([PACKAGE])[:32]


def _kept(what: tuple, read) -> list:
    """``read()`` from the cache under the name of ``what`` and :func:`source_key`, else read and
    kept there."""
    return kept_in(Path(os.environ["DERIVE_CACHE"]) / FOLDER / source_key(), what, read)


def check_notes(path, convention: str | None = None) -> list:
    """`derive.lecture.notes_check.check_notes`, kept between runs."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except OSError:
        return nc.check_notes(path, convention)  # the reader's own refusal
    return _kept(("file", str(path), data, convention), lambda: nc.check_notes(path, convention))


def check_text(text: str, convention: str | None = None, path: str = "<notes>") -> list:
    """`derive.lecture.notes_check.check_text`, kept between runs."""
    return _kept(("text", text, convention, path), lambda: nc.check_text(text, convention, path))


def by_line(text: str, convention: str | None = None) -> dict[int, list]:
    """:func:`check_text`'s claims grouped by the line of the notes they come from."""
    out: dict[int, list] = {}
    for claim in check_text(text, convention):
        out.setdefault(claim.line, []).append(claim)
    return out


def verdicts_by_line(text: str, convention: str | None = None) -> dict[int, set]:
    """The set of verdicts :func:`check_text` gives each line of the notes."""
    return {line: {c.verdict for c in claims} for line, claims in by_line(text, convention).items()}


def line_of(text: str, marker: str) -> int:
    """The line of ``text`` on which ``marker`` first stands."""
    return text[:text.index(marker)].count("\n") + 1
