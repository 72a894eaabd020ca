"""Every ``derive`` command in the README's shell blocks runs as written, in a scratch folder.

The commands are read from README.md itself (its ```sh blocks), so a documented command cannot
break unnoticed. ``make`` and ``source`` lines are the setup the suite itself runs under; the
one input a reader brings (``mynotes.md``) is the example notes of docs/verify.md.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent


def _readme_commands():
    text = (ROOT / "README.md").read_text()
    for block in re.findall(r"```sh\n(.*?)```", text, flags=re.S):
        for line in block.splitlines():
            command = line.split("#", 1)[0].strip()
            if command and not command.startswith(("make ", "source ")):
                yield command


COMMANDS = list(_readme_commands())


def _verify_example_notes() -> str:
    """The ``top.md`` example of docs/verify.md: the notes a README reader would verify."""
    doc = (ROOT / "docs" / "verify.md").read_text()
    return re.search(r"`top\.md`:\n\n```\n(.*?)```", doc, flags=re.S).group(1)


def test_the_readme_has_the_tour_commands():
    joined = "\n".join(COMMANDS)
    for sub in ("simulate", "analyze", "verify", "sweep", "export"):
        assert f"derive {sub} " in joined


@pytest.mark.parametrize("command", COMMANDS)
def test_a_readme_command_runs_as_written(command, tmp_path):
    # The repository's files the tour names (generated/c, docs/examples) are where it says.
    for part in ("generated", "docs"):
        (tmp_path / part).symlink_to(ROOT / part)
    (tmp_path / "mynotes.md").write_text(_verify_example_notes())
    (tmp_path / ".venv").symlink_to(BIN.parent)
    env = dict(os.environ, PATH=f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}")
    if shutil.which("cc") is None and "cc " in command:
        pytest.skip("no C compiler")
    proc = subprocess.run(["bash", "-c", f"set -e; {command}"], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=300)
    # verify exits 1 when the notes hold a slip (the example has two, on purpose).
    expected = {1} if shlex.split(command)[:2] == ["derive", "verify"] and "mynotes.md" in command else {0}
    assert proc.returncode in expected, (command, proc.stdout[-2000:], proc.stderr[-2000:])
    assert "Traceback" not in proc.stderr
