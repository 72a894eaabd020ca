"""Status codes of the compiled solvers: one enum, rendered into the C header (``DERIVE_*``) and
used for the Python messages, so the two cannot disagree (diffrax's ``RESULTS``, SciPy's
``MESSAGES``)."""
from __future__ import annotations

import enum


class Status(enum.IntEnum):
    """What a solver returns (``derive_stats.status``); 0 is success."""

    OK = 0
    STEP_UNDERFLOW = 1
    NONFINITE = 2
    MAX_STEPS = 3
    DOMAIN = 4
    NEWTON = 5
    BAD_ARGS = 6
    INTERRUPTED = 7
    RANGE = 8
    NONFINITE_OUTPUT = 9


_TEXT = {
    Status.OK: "success",
    Status.STEP_UNDERFLOW: "step size underflow",
    Status.NONFINITE: "non-finite value in the state",
    Status.MAX_STEPS: "step budget (max_steps) spent",
    Status.DOMAIN: "state outside the model's domain",
    Status.NEWTON: "Newton iteration failed to converge",
    Status.BAD_ARGS: "bad arguments",
    Status.INTERRUPTED: "interrupted",
    Status.RANGE: "the motion comes closer to a pole than the formulation allows",
    Status.NONFINITE_OUTPUT: "non-finite value in the output",
}


def c_table() -> dict[int, tuple[str, str]]:
    """{code: (C macro name, text)} for the C header template."""
    return {int(s): (f"DERIVE_{s.name}", _TEXT[s]) for s in Status}


def message(stats, state_names=(), max_steps: int | None = None) -> str:
    """The one-line description of a failed solve (``stats``: a ``derive_stats`` record)."""
    status = Status(int(stats["status"]))
    t = f"{float(stats['t_fail']):.8g}"
    if status is Status.STEP_UNDERFLOW:
        return f"t = {t}: step size underflow (h = {float(stats['h_fail']):.3g})"
    if status is Status.NONFINITE:
        i = int(stats["fail_index"])
        if 0 <= i < len(state_names):
            return f"t = {t}: non-finite value in state y[{i}] ({state_names[i]})"
        return f"t = {t}: non-finite value in the state"
    if status is Status.MAX_STEPS:
        return (f"t = {t}: step budget spent (simulate.max_steps = {max_steps}); raise it, "
                f"loosen the tolerances, or shorten t_end")
    if status is Status.DOMAIN:
        return f"t = {t}: state outside the model's domain (rhs returned {int(stats['rhs_code'])})"
    if status is Status.NEWTON:
        return (f"t = {t}: Newton iteration failed to converge "
                f"(h = {float(stats['h_fail']):.3g}, after halving the step)")
    return f"t = {t}: {_TEXT[status]}"
