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

Takes: scenes that share a model. Gives: a Result per scene (:func:`batch_results`) or a
:class:`BatchResult`; the plan of a batch (:func:`batch_plan`).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from derive.errors import IntegrationError, SceneError
from derive.methods.registry import tolerance_driven
from derive.methods.status import Status
from derive.runtime import catalogue
from derive.runtime.integrate import ModelKernel
from derive.runtime.records import driver_args
from derive.sim import auto, plan
from derive.sim.inputs import AUTO, _check_budget, _settings, choose_method, default_step, inputs_of, params_of
from derive.sim.result import Result, _check_pole, _explain, _pole_suspects, _quiet, _result, selection
from derive.sim.saveat import SaveAt
from derive.sim.scene import load_scene
from derive.sim.validator import _Validator, same_model_part
from derive.symbolic import effects as fx
from derive.symbolic import integrable
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


@_quiet
def simulate_batch(scenes, saveat: SaveAt, **overrides):
    """Simulate the scenes in one batch (:func:`batch_plan`): one Result
    per scene when ``saveat`` keeps everything (the default), else one :class:`BatchResult`
    with what it keeps (see the module); None for no scenes."""
    bp = batch_plan(scenes, **overrides)
    if saveat.everything:
        return [] if bp is None else batch_results(bp)
    final, names = selection(saveat)
    return None if bp is None else run_plan(bp, final, names)


def run_plan(bp, final: bool, names: tuple) -> BatchResult:
    """Run a batch plan (:class:`BatchPlan`, or a prepared scene's:
    :meth:`derive.sim.prepared.Prepared.run_batch`) keeping ``names`` at every sample, or at
    the last (``final``; see :func:`derive.sim.result.selection`): its candidate formulations in turn until
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
    arrays = _arrays(names, len(y), 1, y.shape[1], True)
    _fill(arrays, slice(None), out[:, :, None], y[:, None], True)
    return False, arrays, st["nfev"].astype(np.int64)


def _arrays(names, nb: int, n: int, ny: int, final: bool) -> dict:
    """The arrays a batch returns: each output (N,) or (N, width), at every sample (N, n, ...)
    unless ``final``; ``state`` (N, [n,] NY)."""
    arrays = {}
    for name in names:
        width = ny if name == "state" else _WIDTH[name]
        shape = (nb,) + (() if final else (n,)) + (() if width == 1 and name != "state" else (width,))
        arrays[name] = np.empty(shape)
    return arrays


def _fill(arrays: dict, rows: slice, out: np.ndarray, y: np.ndarray, final: bool) -> None:
    """Copy trajectories ``rows`` of the driver's outputs ``out`` (N, NOBS, n) and states ``y``
    (N, n, NY) into ``arrays`` (:func:`_arrays`): every sample, or the last (``final``)."""
    k = slice(None) if not final else -1
    for name, dest in arrays.items():
        if name == "state":
            dest[rows] = y[:, k]
            continue
        o, width = _OFFSET[name], _WIDTH[name]
        if width == 1:
            dest[rows] = out[:, o, k]
        elif final:
            dest[rows] = out[:, o:o + width, -1]
        else:  # the driver writes (NOBS, n) per trajectory: a wide output is (width, n)
            dest[rows] = np.swapaxes(out[:, o:o + width], 1, 2)


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
    arrays = _arrays(names, nb, n, ny, final)
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
            suspect = _pole_suspects(desc, out[:, 1], rtol)
            for b in np.flatnonzero(suspect):
                try:
                    _check_pole(desc, t, out[b, 1], scs[s + b].simulate.rtol)
                except IntegrationError as exc:  # kept until every chunk ran
                    pole_error = exc
                    break
        _fill(arrays, slice(s, e), out, y, final)
    if pole_error is not None:
        raise pole_error
    return False, arrays, nfev


def batch_results(bp: "BatchPlan") -> list[Result]:
    """A batch plan run, one Result per trajectory (what :func:`simulate_batch` returns):
    its candidate formulations in turn until no start is refused, by the full batch driver
    (a Taylor method's lanes for a batch of at least LANES_MIN). The integrals of the
    integrable cases are classified once for the scenes read with the first one's model part
    (:func:`_validated`)."""
    scs, t, method = bp.scenes, bp.t, bp.method
    for formulation, pole_check in bp.candidates:
        desc, kernel, args = bp.kernel(formulation)
        lanes = kernel.full_lanes(len(scs))  # a Taylor method's trajectories W at a time
        out, y, ps, st = (lanes or kernel).simulate_batch(bp.inputs, bp.params(desc), t, args, pole_check,
                                                          lanes=lanes is not None)
        if not (st["status"] == Status.RANGE).any():
            break
    bp.raise_failure(desc, st)
    # The pole check of every trajectory at once; one that fails is then found and named per
    # scene. The C call has checked the outputs finite (status NONFINITE_OUTPUT).
    suspect = _pole_suspects(desc, out[:, 1], scs[0].simulate.rtol)
    for b in np.flatnonzero(suspect).tolist():
        _check_pole(desc, t, out[b, 1], scs[b].simulate.rtol)
    nfev = st["nfev"].tolist()
    first = plan.integral_rows_of(scs[0])
    # (a Goryachev–Chaplygin body's case depends on the state, each scene's own)
    by_state = integrable.needs_area_level(*scs[0].body.moments)
    return [_result(desc, out[b], y[b], t, sc, method, nfev[b], finite=True,
                    integrals=first if not by_state and _model_part_of(sc, scs[0]) else plan.integral_rows_of(sc))
            for b, sc in enumerate(scs)]


@dataclass
class BatchPlan:
    """What a batch runs, decided once for all its scenes (:func:`batch_plan`): the validated
    ``scenes``, the ``method``, the shared output times ``t``, the init-map ``inputs`` (N, NIN),
    the ``effects`` of the one model, the fixed step ``h`` (None: the scene's or adaptive) and
    the ``candidates`` (formulation, pole check) in the order they are tried."""
    scenes: list
    method: str
    t: np.ndarray
    inputs: np.ndarray
    effects: tuple
    h: float | None
    candidates: tuple

    def kernel(self, formulation: str, build: str | None = None):
        """(model description, compiled kernel, driver arguments) of one candidate; ``build``
        (:data:`derive.runtime.cbuild.BUILDS`) the kernel's, by default the method's own (the
        arguments are the same in every build)."""
        first = self.scenes[0]
        desc = catalogue.describe((formulation, first.symmetric, self.effects))
        kernel = ModelKernel.load(desc, self.method, build)
        if self.h is not None:
            args = driver_args(self.method, first.simulate.rtol, first.simulate.atol, self.h, first.simulate.max_steps)
        else:
            args = _settings(first, self.method, kernel)
        return desc, kernel, args

    def params(self, desc, rows: slice = slice(None)) -> np.ndarray:
        """The parameter vectors (N, NP) of the scenes ``rows`` (default: all) for a model: one
        row for all when they have the first scene's model part (:func:`_validated`)."""
        scs = self.scenes[rows]
        if scs and all(_model_part_of(sc, scs[0]) for sc in scs):
            return np.repeat(params_of(scs[0], desc)[None, :], len(scs), axis=0)
        return np.array([params_of(sc, desc) for sc in scs])

    def where(self, b: int) -> str:
        """How an error names trajectory ``b``: its scene's source."""
        return self.scenes[b].source

    def raise_failure(self, desc, st, offset: int = 0) -> None:
        """IntegrationError naming the first trajectory whose status (in ``st``, the stats of
        trajectories ``offset``, ``offset + 1``, …) is a failure; nothing when all succeeded."""
        status = st["status"]
        if status.any():
            b = int(np.flatnonzero(status)[0])
            sc = self.scenes[offset + b]
            raise IntegrationError(f"{self.where(offset + b)}: {_explain(desc, st[b], sc.simulate.max_steps)}")


def _validated(scenes, overrides: dict) -> list:
    """Each scene of a batch validated (:func:`derive.sim.scene.load_scene`). A dict whose model
    part is the first dict's (everything but ``[initial]``, value for value and type for type:
    :func:`derive.sim.validator.same_model_part`) has only its initial state read: its model,
    settings and so its plan are the first's."""
    out, first, like = [], None, None
    for s in scenes:
        if like is not None and same_model_part(s, first):
            out.append(_Validator("<dict>").with_initial(s, like))
            continue
        sc = load_scene(s, **overrides)
        if not out and type(s) is dict:
            first, like = s, sc
        out.append(sc)
    return out


def _model_part_of(sc, first) -> bool:
    """Whether ``sc`` was read with ``first``'s model part (the very objects: :func:`_validated`)."""
    return (sc.body is first.body and sc.tables is first.tables and sc.terms is first.terms
            and sc.simulate is first.simulate and sc.title is first.title)


def batch_plan(scenes, **overrides) -> BatchPlan | None:
    """Validate the scenes of a batch and decide what it runs (None for no scenes): one model
    with every effect that acts in any scene, the shared method, output times and settings."""
    scs = _validated(scenes, overrides)
    if not scs:
        return None
    first = scs[0]

    # One model for the batch: the effects that act in any scene (registry order), each named
    # by every scene so that each gives its parameters.
    effects = first.effects
    if any(sc.effects != effects for sc in scs):
        effects = tuple(e.name for e in fx.lookup(set().union(*(sc.effects for sc in scs))))

    def shared(sc):
        s = sc.simulate
        return (sc.symmetric, set(effects) <= set(sc.named_effects), s.samples, s.t_end,
                choose_method(sc), s.rtol, s.atol, s.h, s.max_steps, s.formulation)

    ref = shared(first)
    for sc in scs[1:]:
        if _model_part_of(sc, first):
            continue  # (its model part is the first's: shared(sc) is ref)
        if shared(sc) != ref or not set(sc.effects) <= set(first.named_effects):
            raise SceneError(f"{sc.source}: simulate: a batch needs the same effects, body symmetry, output "
                             f"times, method, tolerances and formulation as {first.source}")
    method = choose_method(first)
    if method in plan.SCIPY_METHODS:
        raise SceneError(f"{first.source}: simulate.method: batches run in the C kernels, not {method}")
    h = None
    if not tolerance_driven(method) and first.simulate.h is None:
        h = min(default_step(sc) for sc in scs)
        for sc in scs:
            _check_budget(sc, method, h)
    candidates = tuple(auto.batch_plan(scs, effects))
    if first.simulate.method == AUTO and candidates:
        # one method for the batch: the cost model's, for its first scene and first model
        desc = catalogue.describe((candidates[0][0], first.symmetric, effects))
        method = plan.auto_method(first, desc)
    return BatchPlan(scs, method, first.t_out, np.array([inputs_of(sc) for sc in scs]), effects, h,
                     candidates)
