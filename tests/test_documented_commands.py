"""Every shell command in the README and in docs/*.md runs as written, in a scratch folder.

The commands are read from the Markdown itself (its ``sh``, ``bash``, ``shell`` and ``console``
blocks), so a documented command cannot break unnoticed. A block runs as one shell script, its
commands in order (a later one may use what an earlier one wrote), from a scratch folder that
holds the repository's ``scenes/``, ``docs/``, ``generated/`` and ``.venv`` as a clone does, and
the one input a reader brings (``mynotes.md``: the example notes of docs/verify.md).

In a transcript (lines ``$ command`` followed by what it prints), each printed line is checked
against the command's output: ``...`` stands for anything, and a number matches a number within
a relative 1e-9 (the last digits of a double may differ between C libraries).

A command is skipped, never silently, by one of the rules of :data:`SKIPPED` (each skip is its
own test, listed by ``pytest -rs`` with its rule): what a clone does not have (a Dask cluster,
an optional peer such as fmpy, a C compiler) or what the suite itself runs under (``make
derive``, ``make test``, ``pytest``).
"""
from __future__ import annotations

import importlib.util
import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent
DOCUMENTS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
FENCE = re.compile(r"^```(?:sh|bash|shell|console)\n(.*?)^```", re.S | re.M)
MARK = "@@derive-documented-command@@"


def _make_targets() -> set[str]:
    return set(re.findall(r"^([a-z][\w-]*):", (ROOT / "Makefile").read_text(), flags=re.M))


#: (pattern a command matches, why it does not run here, whether that holds on this machine)
SKIPPED = [
    (r"^make (%s)\b" % "|".join(sorted(_make_targets())),
     "a target of the repository's Makefile: the suite itself runs under `make derive` / `make test`",
     True),
    (r"-m pytest\b", "runs the test suite itself (a suite inside the suite)", True),
    (r"^dask ", "starts a Dask scheduler or worker on the reader's machines", True),
    (r"<host>", "names the reader's own Dask scheduler", True),
    (r"\bfmpy\b", "needs the optional peer fmpy (pip install fmpy)",
     importlib.util.find_spec("fmpy") is None),
    (r"(^|&& )cc |\bmake -", "needs a C compiler (cc) and make",
     shutil.which("cc") is None or shutil.which("make") is None),
]

#: Commands documented to exit with another status than 0 (README: a wrong verdict is exit 1;
#: the example notes hold two slips on purpose).
EXIT_STATUS = {r"^derive verify mynotes\.md": 1}


@dataclass
class Command:
    text: str
    expected: list  # the lines a transcript shows it printing


@dataclass
class Block:
    where: str  # file:line
    commands: list


def _skip_reason(command: str) -> str | None:
    for pattern, why, applies in SKIPPED:
        if applies and re.search(pattern, command):
            return why
    return None


def _commands(body: str) -> list[Command]:
    lines = body.splitlines()
    transcript = any(line.startswith("$ ") for line in lines)
    out: list[Command] = []
    pending = ""
    for line in lines:
        if transcript and not line.startswith("$ "):
            if out and line.strip():
                out[-1].expected.append(line)
            continue
        text = line[2:] if transcript else line
        text = re.split(r"(^|\s)#", text, maxsplit=1)[0].rstrip()
        if text.endswith("\\"):
            pending += text[:-1] + " "
            continue
        text, pending = (pending + text).strip(), ""
        if text:
            out.append(Command(text, []))
    return out


def _blocks() -> list[Block]:
    found = []
    for doc in DOCUMENTS:
        source = doc.read_text(encoding="utf-8")
        for m in FENCE.finditer(source):
            line = source.count("\n", 0, m.start()) + 1
            found.append(Block(f"{doc.relative_to(ROOT)}:{line}", _commands(m.group(1))))
    return found


BLOCKS = _blocks()
RUN = [b for b in BLOCKS if any(_skip_reason(c.text) is None for c in b.commands)]

#: The guides whose worked examples (each a few seconds of simulating, compiling or analysing)
#: run in ``make test-slow``, as do the blocks that build C with the system's compiler (the
#: builds themselves are checked in tests/test_export.py and tests/test_codegen.py); the README's
#: other blocks and the other documents' run in ``make test``.
GUIDES = ("docs/analyze.md", "docs/animate.md", "docs/export.md", "docs/own-body.md", "docs/sweeps.md")
BUILDS_C = r"(^|&& )cc |\bmake -"


#: derive's costliest commands (a whole text verified, equilibria derived, a sweep run): their
#: behaviour is pinned by their own tests in ``make test``; their documented blocks run in the slow run.
COSTLY = r"\bderive (verify|analyze|sweep)\b"


def _slow(block: Block) -> bool:
    return block.where.startswith(GUIDES) or any(re.search(BUILDS_C, c.text) or re.search(COSTLY, c.text)
                                                 for c in block.commands)
SKIP = [(b.where, c.text, why) for b in BLOCKS for c in b.commands if (why := _skip_reason(c.text))]


def _verify_example_notes() -> str:
    """The ``top.md`` example of docs/verify.md: the notes a README reader would verify."""
    doc = (ROOT / "docs" / "verify.md").read_text()
    return re.search(r"`top\.md`:\n\n```\n(.*?)```", doc, flags=re.S).group(1)


def test_the_readme_has_the_tour_commands():
    joined = "\n".join(c.text for b in BLOCKS if b.where.startswith("README") for c in b.commands)
    for sub in ("simulate", "analyze", "verify", "sweep", "export"):
        assert f"derive {sub} " in joined


def test_every_document_with_commands_is_read():
    docs = {b.where.split(":")[0] for b in BLOCKS}
    assert {"README.md", "docs/analyze.md", "docs/export.md", "docs/sweeps.md", "docs/own-body.md",
            "docs/c-abi.md", "docs/taylor.md"} <= docs


_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def _matches(expected: str, actual: str) -> bool:
    """``actual`` is ``expected`` with ``...`` standing for anything and each number equal to
    within a relative 1e-9."""
    parts = re.split(rf"(\.\.\.|{_NUMBER})", expected)
    pattern = "".join(".*?" if p == "..." else f"({_NUMBER})" if re.fullmatch(_NUMBER, p) and p
                      else re.escape(p) for p in parts)
    m = re.fullmatch(pattern, actual)
    if m is None:
        return False
    shown = [p for p in parts if p and p != "..." and re.fullmatch(_NUMBER, p)]
    return all(abs(float(a) - float(e)) <= 1e-9 * max(abs(float(e)), 1e-300)
               for a, e in zip(m.groups(), shown))


def test_a_transcript_line_matches_with_dots_and_close_numbers():
    assert _matches('{"t_end": 10, "nfev": 88, ...}', '{"t_end": 10, "nfev": 88, "alpha": 3.3}')
    assert _matches("0.9449560697936944", "0.9449560697936972")
    assert not _matches("0.9449560697936944", "0.9449")
    assert not _matches('{"nfev": 88, ...}', '{"nfev": 2141, "beta": 1}')


@pytest.mark.parametrize("block", [pytest.param(b, marks=pytest.mark.slow) if _slow(b) else b for b in RUN],
                         ids=lambda b: b.where)
def test_a_documented_command_runs_as_written(block, tmp_path):
    for part in ("generated", "docs", "scenes"):
        (tmp_path / part).symlink_to(ROOT / part)
    (tmp_path / ".venv").symlink_to(BIN.parent)
    (tmp_path / "mynotes.md").write_text(_verify_example_notes())
    env = dict(os.environ, PATH=f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}")
    script = ["set -e"]
    runs = [c for c in block.commands if _skip_reason(c.text) is None]
    for c in runs:
        status = next((s for p, s in EXIT_STATUS.items() if re.search(p, c.text)), 0)
        script.append(c.text if status == 0 else f"{{ {c.text}; }} || [ $? -eq {status} ]")
        script.append(f"echo {MARK}")
    proc = subprocess.run(["bash", "-c", "\n".join(script)], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, (block.where, proc.stdout[-2000:], proc.stderr[-2000:])
    assert "Traceback" not in proc.stderr
    outputs = proc.stdout.split(MARK + "\n")
    for c, out in zip(runs, outputs):
        lines = out.splitlines()
        for want in c.expected:
            assert any(_matches(want, got) for got in lines), (block.where, c.text, want, out[-2000:])


@pytest.mark.parametrize("where,command,why", SKIP, ids=[f"{w}:{c[:40]}" for w, c, _ in SKIP])
def test_a_documented_command_skipped_here(where, command, why):
    pytest.skip(f"{where}: `{command}`: {why}")
