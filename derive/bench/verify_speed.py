"""The notes reader's speed target: ``derive verify`` on the corpus of public texts, in seconds of
user CPU per 100 displays (goal: ≤ 10 for every text).

Takes: the corpus, ``tests/notes/real/`` of a checkout (Markdown, LaTeX and notebook texts) (test data, not part of the installed
package: an installed package reports this part as not measured, saying why). Gives:
`bench_verify_speed` (each text verified by a fresh ``python -m derive verify TEXT``, as a user
runs it, the whole command counted: start-up, imports, reading, judging) and `rows` (the
targets table's rows, one per text). The time is the child process's user CPU
(``resource.getrusage``), which a busy machine does not inflate as it does wall time; the
displays are what the notes reader counts as displays (every ``$$`` or environment block,
checked or not).

May import: the standard library, :mod:`derive.lecture.notes`.
"""
from __future__ import annotations

import os
import resource
import subprocess
import sys
from pathlib import Path

from derive.lecture import notes as nt

CORPUS = Path(__file__).resolve().parents[2] / "tests" / "notes" / "real"
"""Where a checkout keeps the corpus (next to the package's directory)."""
GOAL_KEY = "verify_per_100"
FORMATS = (".md", ".tex", ".ipynb")
"""The formats a corpus text is kept in (the notes reader reads each)."""


def corpus_texts(root: Path = CORPUS) -> list[Path]:
    """The corpus's texts (those with a truth table), sorted by name; none without a checkout."""
    found = []
    for table in root.glob("*.truth.toml"):
        slug = table.name[:-len(".truth.toml")]
        found += [p for p in (table.with_name(slug + ext) for ext in FORMATS) if p.is_file()][:1]
    return sorted(found)


def displays(path: Path) -> int:
    """The displays of a text, as the notes reader finds them (a ``$…$`` standing alone as its
    paragraph's line, how texts kept from rendered pages write a display, counts as one)."""
    return sum(item.kind == "display" or item.alone for item in nt.read_notes(path).items)


def user_seconds(path: Path) -> float:
    """User CPU seconds of one ``python -m derive verify PATH`` in a fresh process."""
    env = dict(os.environ)
    package_parent = str(Path(__file__).resolve().parents[2])
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [package_parent, env.get("PYTHONPATH")]))
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    done = subprocess.run([sys.executable, "-m", "derive", "verify", str(path)], env=env,
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    if done.returncode not in (0, 1):        # 1: the text has flagged claims (the corpus's slips)
        raise RuntimeError(f"derive verify {path.name}: exit {done.returncode}: {done.stderr.strip()[:200]}")
    return after - before


def bench_verify_speed(texts: list[Path] | None = None, timer=user_seconds) -> dict:
    """Seconds of user CPU per 100 displays of each text (``texts``: the corpus by default).

    Returns ``{"texts": [{"text", "displays", "user_s", "per_100"}], "worst": the largest
    per_100}``, or ``{"skipped": why}`` when there is no text to time (no checkout)."""
    texts = corpus_texts() if texts is None else texts
    if not texts:
        return {"skipped": f"the corpus is test data of a checkout ({CORPUS} is absent): run `derive bench` "
                           "from the repository"}
    out = []
    for path in texts:
        n = displays(path)
        seconds = timer(path)
        out.append({"text": path.stem, "displays": n, "user_s": seconds,
                    "per_100": 100.0 * seconds / n if n else None})
    return {"texts": out, "worst": max((t["per_100"] for t in out if t["per_100"] is not None), default=None)}


def rows(vs: dict) -> list[tuple[str, str, float | None]]:
    """The targets table's rows (what, goal key, value): one per text."""
    if not vs or "skipped" in vs or "error" in vs:
        return []
    return [(f"`derive verify` {t['text']}.md ({t['displays']} displays, {t['user_s']:.2f} s): user CPU per "
             "100 displays [s]", GOAL_KEY, t["per_100"]) for t in vs["texts"]]
