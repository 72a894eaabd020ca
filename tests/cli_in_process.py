"""``derive ARGS`` run by ``derive.cli.main`` in the test's own process, for the tests that check
what a command prints and returns, not what a fresh interpreter does (signals, tracebacks that
reach a terminal, imports): no interpreter to start, no NumPy to import again."""
from __future__ import annotations

import contextlib
import io
import os
import subprocess

from derive import cli


def derive_main(*argv, env: dict[str, str] | None = None, cwd=None) -> subprocess.CompletedProcess:
    """The exit status, stdout and stderr of ``derive ARGV`` as a CompletedProcess; ``env``
    entries are set for the command's duration (and restored), ``cwd`` is the folder it runs in."""
    argv = [str(a) for a in argv]
    before = {k: os.environ.get(k) for k in env or {}}
    out, err = io.StringIO(), io.StringIO()
    with contextlib.ExitStack() as stack:
        if cwd is not None:
            stack.enter_context(contextlib.chdir(cwd))
        os.environ.update(env or {})
        try:
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                rc = cli.main(argv)
        finally:
            for k, v in before.items():
                if v is None:
                    os.environ.pop(k, None)
                else:
                    os.environ[k] = v
    return subprocess.CompletedProcess(["derive", *argv], rc, out.getvalue(), err.getvalue())
