"""The two kinds of failure a user can act on, and the notes that announce a slow step.

Both failures carry the one-line message that the command line prints on stderr, so the Python
API and the CLI say the same thing.
"""


class SceneError(ValueError):
    """Bad input: a scene file, a dict shaped like one, or a command-line flag.

    The message has the form ``<file>: <key or table>: <what is wrong>``. CLI exit status 2.
    """


def scene_error(source: str, key: str, what: str) -> SceneError:
    """``<source>: <key>: <what>`` on one line: newlines a value might smuggle in are flattened."""
    return SceneError(" ".join(f"{source}: {key}: {what}".splitlines()))


class IntegrationError(RuntimeError):
    """Numerical failure: step size underflow, non-finite state, coordinate singularity,
    Newton failure or tolerance not met. The message says where (time, quantity).
    CLI exit status 3.
    """


class CompilerError(RuntimeError):
    """No working C compiler, or the generated C failed to compile."""


#: Where :func:`note` writes: the command line puts its stderr here for the length of a command
#: when stderr is a terminal (derive.cli); None keeps notes silent (the Python API, and a stderr
#: that is a pipe or a file, where a script may expect nothing but the one error line).
NOTE_STREAM: list = [None]


def note(text: str) -> None:
    """Announce a step that takes more than a second (deriving a model, compiling a kernel, the
    symbolic analysis, generating every model) as one line ``note: <text>`` on the stream in
    :data:`NOTE_STREAM`; nothing when that is None. Never on stdout, which scripts parse.

    Parameters
    ----------
    text : str
        What is about to happen and roughly how long it takes, on one line.
    """
    stream = NOTE_STREAM[0]
    if stream is None:
        return
    try:
        print(f"note: {' '.join(text.split())}", file=stream, flush=True)
    except (OSError, ValueError):  # a closed or broken stderr: the note is not worth a failure
        pass


class EngineError(IntegrationError):
    """A sweep engine failed: a dead local pool (a worker killed, out of memory), an unreachable
    or silent Dask scheduler, a scheduler without workers. The message says which and where.
    CLI exit status 3, like a numerical failure: the input was good, the run could not finish.
    """


#: The signals (SIGINT) that came during the running command, recorded by the command line's
#: handler before it raises KeyboardInterrupt: an interrupt that a library swallowed (a
#: finaliser) or rewrapped (NumPy's import turns it into ImportError) still ends the command.
SIGNALLED: list[int] = []


def raise_if_signalled() -> None:
    """Raise KeyboardInterrupt if a Ctrl-C was recorded in :data:`SIGNALLED` (a Python loop
    calls it once per step, so a swallowed interrupt still stops it at the next step)."""
    if SIGNALLED:
        raise KeyboardInterrupt


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised where Ctrl-C would raise KeyboardInterrupt so that the same clean-up runs
    (workers stopped, temporaries removed). CLI exit status 143, ``error: terminated``."""
