"""A batch that keeps only what its :class:`~derive.sim.saveat.SaveAt` asks for:
``derive.simulate_batch(scenes, saveat=...)``.

The compiled batch driver writes every output at every sample of each trajectory (and its
states) into the arrays it is given: 1000 trajectories of 1001 samples would map about 200 MB.
Here the driver runs in chunks of trajectories whose work arrays (a few MB) are allocated once
and reused, and only what was asked for is copied out of them into the arrays returned:

* ``SaveAt(t="final")``: every output (and the state) at the last sample only, arrays of shape
  (N,) or (N, 3) (state (N, NY));
* ``SaveAt(outputs=("beta", "axis", ...))``: those outputs at every sample, (N, n) or (N, n, 3)
  (``"state"``: (N, n, NY)); with ``t="final"``, those at the last sample.

The numbers are bit for bit those of the full batch (the same C call per trajectory; a chunk
changes nothing a trajectory computes). No Result per trajectory: one :class:`BatchResult`.

With ``t="final"`` and a formulation whose α and γ are states (``angle_states`` in the registry)
that loses no accuracy near a pole (no ``pole_loss``: its pole check needs β at every sample),
no sample but the last is made: the driver ``<model>_simulate_final_batch_<method>`` integrates
each trajectory straight to the end (the same steps: the interior samples of the full grid are
dense output; adaptive methods only: a fixed-step driver splits each output interval, so the
samples set its steps) and maps the last state alone; the angles of that one sample get β's canonical
range, without the unwrapping from the samples before (which for continuous α, γ moves nothing
in the usual case). Its numbers are then the full batch's last sample bit for bit wherever that
unwrapping did not fire; ``nfev`` counts no dense-output evaluations. The samples it does not
make are not checked either: an output that is not finite at an interior sample only (the full
batch's NONFINITE_OUTPUT there) goes unnoticed, as the sample is never made. The other formulations
(angles from atan2, unwrapped along the samples) take the full grid. A Taylor method's
final-only batch runs its lanes driver (``<model>_simulate_lanes_batch_<method>``, in a library
built for this CPU's vector width: W trajectories at once, each lane its own steps), whose
numbers, statuses and statistics are the scalar final-only driver's bit for bit.
``BatchResult.driver`` says which ran.

Takes: what :func:`derive.sim.simulation.batch_plan` takes. Gives: :class:`BatchResult`.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from derive.errors import IntegrationError
from derive.methods.status import Status
from derive.runtime.integrate import ModelKernel
from derive.sim import simulation
from derive.sim.saveat import SaveAt
from derive.symbolic.formulations import OUTPUTS, REGISTRY

#: Bytes of work arrays per chunk: large enough that the Python per chunk is noise (one call
#: per some tens of trajectories), small enough to stay in the caches.
CHUNK_BYTES = 4 << 20

_WIDTH = dict(OUTPUTS)
_OFFSET = {name: sum(w for _, w in OUTPUTS[:i]) for i, (name, _) in enumerate(OUTPUTS)}
_RANGE = int(Status.RANGE)


@dataclass
class BatchResult:
    """The outputs asked for of N trajectories, stacked along a first axis of length N.

    Attributes
    ----------
    outputs : dict
        ``{name: array}``: with ``final``, each output at the last sample ((N,) or (N, 3)) and
        ``state`` (N, NY); else the names asked for at every sample ((N, n) or (N, n, 3);
        ``state`` (N, n, NY)). Also readable as attributes (``res.beta``).
    t : ndarray
        The output times (n,) of the full trajectories (with ``final``, the last is the one
        the arrays are at).
    final : bool
        Whether the arrays hold the last sample only.
    nfev : ndarray, shape (N,)
        Right-hand-side evaluations per trajectory.
    method, formulation, model : str
        What ran (one model for the whole batch).
    effects : tuple
        The effects of the model.
    driver : str
        The compiled batch driver that ran: ``"full"`` (every sample, kept or not),
        ``"full-lanes"`` (that, a Taylor method's trajectories several at a time:
        ``<model>_simulate_lanes_full_batch_<method>``), ``"final"`` (straight to the end, the
        last sample only) or ``"lanes"`` (that, several at a time:
        ``<model>_simulate_lanes_batch_<method>``).
    """

    outputs: dict
    t: np.ndarray
    final: bool
    nfev: np.ndarray
    method: str
    formulation: str
    model: str
    effects: tuple = field(default=())
    driver: str = "full"

    def __len__(self) -> int:
        return len(self.nfev)

    def __getattr__(self, name):
        outputs = self.__dict__.get("outputs", {})
        if name in outputs:
            return outputs[name]
        raise AttributeError(name)


def simulate_batch(scenes, saveat: SaveAt, **overrides):
    """Simulate the scenes in one batch (:func:`derive.sim.simulation.batch_plan`): one Result
    per scene when ``saveat`` keeps everything (the default), else one :class:`BatchResult`
    with what it keeps (see the module); None for no scenes."""
    if saveat.everything:
        return simulation.simulate_batch(scenes, **overrides)
    final, names = simulation.selection(saveat)
    bp = simulation.batch_plan(scenes, **overrides)
    return None if bp is None else run_plan(bp, final, names)


def run_plan(bp, final: bool, names: tuple) -> BatchResult:
    """Run a batch plan (:class:`derive.sim.simulation.BatchPlan`, or a prepared scene's:
    :meth:`derive.sim.prepared.Prepared.run_batch`) keeping ``names`` at every sample, or at
    the last (``final``; see :func:`derive.sim.simulation.selection`): its candidate formulations in turn until
    none of the trajectories' starts is refused, by the full, the final-only or the lanes
    driver."""
    for formulation, pole_check in bp.candidates:
        desc, kernel, args = bp.kernel(formulation)
        driver = "full"
        if final and final_only(desc, kernel):
            driver = "final"
            if kernel.has_lanes:  # a Taylor method: its lanes, in a library built for this CPU
                lanes = ModelKernel.load(desc, bp.method, "lanes")
                if lanes.lanes:  # (none from a compiler without GNU C's vectors: the scalar's)
                    driver, kernel = "lanes", lanes
        if driver == "full":
            lanes = kernel.full_lanes(len(bp.scenes))
            if lanes is not None:  # a Taylor method's full grid, W trajectories at a time
                driver, kernel = "full-lanes", lanes
            refused, arrays, nfev = _run(bp, desc, kernel, args, pole_check, final, names, lanes is not None)
        else:
            refused, arrays, nfev = _run_final(bp, desc, kernel, args, pole_check, driver, names)
        if not refused:
            break
    else:  # every candidate refused a start: the last one's refusal, named as the full batch names it
        bp.raise_failure(desc, arrays, offset=nfev)
    return BatchResult(arrays, bp.t, final, nfev, bp.method, desc.formulation, desc.name, desc.effects,
                       driver)


def final_only(desc, kernel) -> bool:
    """Whether a batch keeping the last sample only may skip the others (see the module): the
    formulation's α, γ are states, its pole check needs no β along the way, the method steps by
    its tolerance (a fixed-step driver splits each output interval: the samples set its steps)
    and the kernel holds the driver."""
    f = REGISTRY[desc.formulation]
    return f.angle_states and not f.pole_loss and kernel.adaptive and kernel.has_final


def _run_final(bp, desc, kernel, args, pole_check, driver, names):
    """The final-only driver (``driver`` "final") or the lanes driver ("lanes") over the whole
    batch (its arrays are N rows: no chunks), with :func:`_run`'s results."""
    call = kernel.simulate_lanes_batch if driver == "lanes" else kernel.simulate_final_batch
    out, y, _, st = call(bp.inputs, bp.params(desc), bp.t, args, pole_check)
    if (st["status"] == _RANGE).any():
        return True, st, 0
    bp.raise_failure(desc, st)
    arrays = {}
    for name in names:
        if name == "state":
            arrays[name] = y
            continue
        o, width = _OFFSET[name], _WIDTH[name]
        arrays[name] = out[:, o].copy() if width == 1 else out[:, o:o + width].copy()
    return False, arrays, st["nfev"].astype(np.int64)


def _run(bp, desc, kernel, args, pole_check, final, names, lanes=False):
    """The chunks of one candidate formulation: (False, {name: array}, nfev), or (True, the
    chunk's stats, its offset) when the driver's pole check refused a start (status RANGE: the
    next candidate runs the whole batch). ``lanes``: by the kernel's full-grid lanes driver,
    chunks of whole lane sets."""
    scs, t = bp.scenes, bp.t
    nb, n = len(scs), len(t)
    nout, ny = kernel.nout, kernel.ny
    per = 8 * n * (nout + ny)
    chunk = max(1, min(nb, CHUNK_BYTES // per))
    if lanes:  # (a chunk's last lanes idle while its last trajectories run)
        chunk = min(nb, max(kernel.lanes, chunk // kernel.lanes * kernel.lanes))
    work = (np.empty((chunk, nout, n)), np.empty((chunk, n, ny)))
    arrays = {}
    for name in names:
        width = ny if name == "state" else _WIDTH[name]
        shape = (nb,) + (() if final else (n,)) + (() if width == 1 and name != "state" else (width,))
        arrays[name] = np.empty(shape)
    nfev = np.empty(nb, dtype=np.int64)
    rtol = scs[0].simulate.rtol
    pole_error = None
    for s in range(0, nb, chunk):
        e = min(nb, s + chunk)
        out, y, _, st = kernel.simulate_batch(bp.inputs[s:e], bp.params(desc, slice(s, e)), t, args, pole_check,
                                              buffers=work, lanes=lanes)
        if (st["status"] == _RANGE).any():
            return True, st, s
        bp.raise_failure(desc, st, offset=s)
        nfev[s:e] = st["nfev"]
        # The pole check of the full batch, per chunk while β is at hand; its error is raised
        # after every chunk ran, so a failed integration elsewhere is named first, as there.
        if pole_error is None:
            suspect = simulation._pole_suspects(desc, out[:, 1], rtol)
            for b in np.flatnonzero(suspect):
                try:
                    simulation._check_pole(desc, t, out[b, 1], scs[s + b].simulate.rtol)
                except IntegrationError as exc:  # kept until every chunk ran
                    pole_error = exc
                    break
        k = slice(None) if not final else -1
        for name, dest in arrays.items():
            if name == "state":
                dest[s:e] = y[:, k]
                continue
            o, width = _OFFSET[name], _WIDTH[name]
            if width == 1:
                dest[s:e] = out[:, o, k]
            elif final:
                dest[s:e] = out[:, o:o + width, -1]
            else:  # the driver writes (NOBS, n) per trajectory: a wide output is (width, n)
                dest[s:e] = np.swapaxes(out[:, o:o + width], 1, 2)
    if pole_error is not None:
        raise pole_error
    return False, arrays, nfev
