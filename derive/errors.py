"""The two kinds of failure a user can act on.

Both carry the one-line message that the command line prints on stderr, so the Python API and
the CLI say the same thing.
"""


class SceneError(ValueError):
    """Bad input: a scene file, a dict shaped like one, or a command-line flag.

    The message has the form ``<file>: <key or table>: <what is wrong>``. CLI exit status 2.
    """


class IntegrationError(RuntimeError):
    """Numerical failure: step size underflow, non-finite state, coordinate singularity,
    Newton failure or tolerance not met. The message says where (time, quantity).
    CLI exit status 3.
    """


class CompilerError(RuntimeError):
    """No working C compiler, or the generated C failed to compile."""


class EngineError(IntegrationError):
    """A sweep engine failed: a dead local pool (a worker killed, out of memory), an unreachable
    or silent Dask scheduler, a scheduler without workers. The message says which and where.
    CLI exit status 3, like a numerical failure: the input was good, the run could not finish.
    """


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised where Ctrl-C would raise KeyboardInterrupt so that the same clean-up runs
    (workers stopped, temporaries removed). CLI exit status 143, ``error: terminated``."""
