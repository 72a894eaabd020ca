"""``python -m derive``: the command line, :func:`derive.cli.main`."""
import os
import sys

from derive.cli import EXIT_INTERRUPTED, EXIT_TERMINATED, main

status = main()
if status in (EXIT_INTERRUPTED, EXIT_TERMINATED):
    # The CLI has cleaned up and said so; leave now, because CPython's ``-m`` runner ends a
    # process whose Ctrl-C interrupted exec'd library code (SciPy's import) by SIGINT instead
    # of with this status (the console script ``derive`` is not affected).
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(status)
raise SystemExit(status)
