"""What a run keeps: one argument for every entry point (in the spirit of diffrax's ``SaveAt``).

``derive.simulate``, ``derive.prepare(...).run``, ``run_batch``, ``derive.simulate_batch`` and
``derive.sweep`` take ``saveat=SaveAt(...)``: which times (``t``: the scene's output grid, or the
final time alone) and which outputs (``outputs``: names of the output file, ``"state"`` for the
integrator's state; None keeps every one). The names are checked where they are used, against
the outputs of the model that runs.

Takes: nothing from derive. Gives: :class:`SaveAt`.
"""
from __future__ import annotations

from dataclasses import dataclass

from derive.errors import SceneError

#: The times a run can keep: every sample of the scene's grid, or the last one (t_end) alone.
TIMES = ("grid", "final")


@dataclass(frozen=True)
class SaveAt:
    """Which times and which outputs a run keeps.

    Parameters
    ----------
    t : {"grid", "final"}
        ``"grid"`` (default): the ``[simulate] samples`` equally spaced times from 0 to t_end;
        ``"final"``: t_end alone (a batch may then integrate each trajectory straight to the
        end: no interior sample is made).
    outputs : tuple of str, optional
        The outputs kept (``"beta"``, ``"axis"``, …, ``"state"``); None (default) keeps every
        output and the state.

    Raises
    ------
    SceneError
        ``t`` not one of :data:`TIMES`, or ``outputs`` not a non-empty sequence of names (one
        line naming the key). A name that is not an output is refused where it is used.

    Examples
    --------
    >>> from derive import SaveAt
    >>> SaveAt(t="final").final, SaveAt(outputs=("beta",)).outputs
    (True, ('beta',))
    >>> SaveAt.of("final") == SaveAt(t="final"), SaveAt.of(("beta", "axis")).outputs
    (True, ('beta', 'axis'))
    """

    t: str = "grid"
    outputs: tuple[str, ...] | None = None

    def __post_init__(self):
        if self.t not in TIMES:
            raise SceneError(f"<saveat>: t: one of {', '.join(TIMES)}, not {self.t!r}")
        if self.outputs is not None:
            names = (self.outputs,) if isinstance(self.outputs, str) else self.outputs
            try:
                names = tuple(dict.fromkeys(names))
            except TypeError:
                names = ()
            if not names or not all(isinstance(n, str) for n in names):
                raise SceneError(f"<saveat>: outputs: a sequence of output names, not {self.outputs!r}")
            object.__setattr__(self, "outputs", names)

    @property
    def final(self) -> bool:
        """Whether only t_end is kept."""
        return self.t == "final"

    @property
    def everything(self) -> bool:
        """Whether every output is kept at every sample (the default)."""
        return self.t == "grid" and self.outputs is None

    @classmethod
    def of(cls, value) -> "SaveAt":
        """A SaveAt from what the entry points take: a SaveAt, None (the default), ``"final"``,
        ``"grid"``, or a sequence of output names (kept at every sample)."""
        if value is None:
            return cls()
        if isinstance(value, SaveAt):
            return value
        if isinstance(value, str) and value in TIMES:
            return cls(t=value)
        return cls(outputs=value)


def choose(saveat, outputs=None, default=None) -> SaveAt:
    """The SaveAt of an entry point given ``saveat`` and the older spelling ``outputs``
    (``"final"`` or output names), at most one of them; ``default`` when neither is given."""
    if saveat is not None and outputs is not None:
        raise SceneError("<saveat>: saveat: give saveat or outputs, not both")
    if saveat is None and outputs is None:
        return SaveAt.of(default)
    return SaveAt.of(saveat if saveat is not None else outputs)
