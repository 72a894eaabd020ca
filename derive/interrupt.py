"""Ctrl-C inside compiled loops.

While a ctypes call runs, Python's own SIGINT handler only notes the signal; the
KeyboardInterrupt comes when the call returns, which for a long integration may be hours. So a
solver library exports a flag that its loops poll::

    volatile sig_atomic_t derive_interrupt_flag = 0;   /* in the generated solver C */
    ...
    if (derive_interrupt_flag) { stats->status = <interrupted>; return; }  /* every N steps */

and a tiny helper library (compiled once, like every kernel) installs a C-level SIGINT handler
that sets the flag of every library it watches and then calls the handler that was there
before -- Python's, so the KeyboardInterrupt still happens as usual. The handler is installed
only where Python's is (never over SIG_IGN, e.g. a background job, or SIG_DFL), and put back on
the next call if someone has replaced it since (``signal.signal`` re-installs Python's own).
Nothing runs in another thread and the cost per call is one ``sigaction`` (about a microsecond).

Use::

    with interrupt.interruptible(lib):     # lib: the ctypes.CDLL of a solver library
        lib.M_solve_dop853(...)
    # leaving the block after a Ctrl-C raises KeyboardInterrupt (Python's pending one, or
    # a new one if Python's handler did not raise), whatever status the loop returned

A library without ``derive_interrupt_flag`` (older kernels, test libraries) runs unwatched.
"""
from __future__ import annotations

import contextlib
import ctypes
import threading

FLAG = "derive_interrupt_flag"

_HELPER = r"""/* SIGINT -> set the interrupt flag of every watched solver library, then chain to the
 * handler that was installed before (Python's, which raises KeyboardInterrupt later). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stddef.h>

#define MAX_WATCHED 1024

static volatile sig_atomic_t *watched[MAX_WATCHED];
static volatile sig_atomic_t n_watched = 0;
static struct sigaction previous;

const int derive_sig_atomic_size = (int)sizeof(sig_atomic_t);

static void on_sigint(int sig, siginfo_t *info, void *context)
{
    int i;
    for (i = 0; i < n_watched; i++)
        *watched[i] = 1;
    if (previous.sa_flags & SA_SIGINFO) {
        if (previous.sa_sigaction != NULL)
            previous.sa_sigaction(sig, info, context);
    } else if (previous.sa_handler != SIG_DFL && previous.sa_handler != SIG_IGN) {
        previous.sa_handler(sig);
    }
}

/* Watch one more flag; 0 on success, -1 if the table is full. Called with SIGINT handled by
 * whoever: the slot is written before the count grows, so the handler never sees a hole. */
int derive_watch(volatile sig_atomic_t *flag)
{
    int i;
    for (i = 0; i < n_watched; i++)
        if (watched[i] == flag)
            return 0;
    if (n_watched >= MAX_WATCHED)
        return -1;
    watched[n_watched] = flag;
    n_watched = n_watched + 1;
    return 0;
}

/* Make on_sigint SIGINT's handler, chaining to the current one. Returns 1 if it is (now)
 * installed, 0 if SIGINT is ignored or has its default action (left alone), -1 on error. */
int derive_arm(void)
{
    struct sigaction current, mine;
    if (sigaction(SIGINT, NULL, &current) != 0)
        return -1;
    if ((current.sa_flags & SA_SIGINFO) && current.sa_sigaction == on_sigint)
        return 1;
    if (!(current.sa_flags & SA_SIGINFO)
        && (current.sa_handler == SIG_DFL || current.sa_handler == SIG_IGN))
        return 0;
    previous = current; /* ours is not installed: nothing reads it now */
    mine.sa_sigaction = on_sigint;
    mine.sa_mask = current.sa_mask;
    mine.sa_flags = (current.sa_flags | SA_SIGINFO) & ~SA_RESETHAND;
    return sigaction(SIGINT, &mine, NULL) == 0 ? 1 : -1;
}
"""

_lock = threading.Lock()
_helper: ctypes.CDLL | None = None
_helper_failed = False
_flags: dict[int, object] = {}  # id(lib) -> its flag (a ctypes int in the library) or None


def _load_helper() -> ctypes.CDLL | None:
    """The compiled helper, or None if it cannot be built (then loops run unwatched)."""
    global _helper, _helper_failed
    if _helper is None and not _helper_failed:
        from .cbuild import compile_library
        from .errors import CompilerError

        try:
            lib = compile_library("derive_interrupt", {"derive_interrupt.c": _HELPER},
                                  "derive_interrupt.c")
        except CompilerError:
            _helper_failed = True
            return None
        lib.derive_watch.argtypes = [ctypes.c_void_p]
        lib.derive_watch.restype = ctypes.c_int
        lib.derive_arm.argtypes = []
        lib.derive_arm.restype = ctypes.c_int
        _helper = lib
    return _helper


def _ctype(helper: ctypes.CDLL):
    size = ctypes.c_int.in_dll(helper, "derive_sig_atomic_size").value
    return {ctypes.sizeof(t): t for t in (ctypes.c_long, ctypes.c_int, ctypes.c_byte)}[size]


def flag(lib: ctypes.CDLL):
    """The library's interrupt flag (a ctypes integer living in the library), watched from now
    on; None if the library exports none or the helper is unavailable."""
    key = id(lib)
    with _lock:
        if key not in _flags:
            value = None
            helper = _load_helper() if hasattr(lib, FLAG) else None
            if helper is not None:
                value = _ctype(helper).in_dll(lib, FLAG)
                if helper.derive_watch(ctypes.addressof(value)) != 0:
                    value = None
            _flags[key] = (lib, value)  # keep lib alive: id() must not be reused
        return _flags[key][1]


def arm() -> bool:
    """Install the SIGINT handler (again, if replaced); False where SIGINT is ignored or left
    at its default action, or the helper is unavailable."""
    helper = _load_helper()
    return helper is not None and helper.derive_arm() == 1


@contextlib.contextmanager
def interruptible(lib: ctypes.CDLL):
    """Run the block (a call into ``lib``) so that Ctrl-C sets the library's interrupt flag;
    on leaving after a Ctrl-C, raise KeyboardInterrupt."""
    f = flag(lib)
    if f is None:
        yield
        return
    f.value = 0
    arm()
    hit = False
    try:
        yield
    finally:
        hit = bool(f.value)
        f.value = 0
    if hit:
        # Python's handler has run too (chained): let it raise now, at this exact point,
        # rather than at some later bytecode; if it was replaced by one that does not raise,
        # the interrupted loop still must not pass for a finished one.
        ctypes.pythonapi.PyErr_CheckSignals()
        raise KeyboardInterrupt
