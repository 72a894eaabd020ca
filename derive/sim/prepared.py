"""A prepared simulation: a scene validated, planned and compiled once, run many times.

``derive.prepare(scene)`` gives a :class:`Prepared`; its :meth:`~Prepared.run` makes the C call of
the plan (:mod:`derive.sim.plan`) with no validation of the scene, no look-up of the model and
no derivation, optionally with new initial values or parameters of the same shape;
:meth:`~Prepared.run_batch` runs N such variations in one batch call (arrays of initial values
and parameters, checked as arrays: no scene per trajectory).

Takes: a scene (path, example name, dict or Scene). Gives: :class:`derive.sim.result.Result`,
:class:`derive.sim.batch.BatchResult`.
"""
from __future__ import annotations

import math

import numpy as np

from derive.contact.prepared import ContactPrepared  # the contact hook
from derive.errors import SceneError
from derive.methods.registry import tolerance_driven
from derive.sim import batch, plan, simulation
from derive.sim.inputs import params_of
from derive.sim.result import kept, selection
from derive.sim.saveat import choose
from derive.sim.scene import contact_data, load_scene  # contact_data: the contact hook
from derive.symbolic.formulations import INPUT_NAMES, starts_accepted

_ANGLES = ("alpha", "beta", "gamma")
_RATES = ("alpha_dot", "beta_dot", "gamma_dot")


def prepare(scene, **overrides):
    """A :class:`Prepared` of ``scene``, or for a top on a table the contact stage's
    :class:`~derive.contact.prepared.ContactPrepared` (see :func:`derive.prepare`)."""
    found = contact_data(scene)  # contact hook: a top on a table is prepared by derive.contact
    if found is not None:
        return ContactPrepared(*found, **overrides)
    return Prepared(scene, **overrides)


class Prepared:
    """A scene planned once (see :func:`derive.prepare`).

    Attributes
    ----------
    plan : derive.sim.plan.Plan
        What runs: the method, the output times, the formulations to try and their kernels.
    """

    def __init__(self, scene, **overrides):
        self.plan = plan.make(load_scene(scene, **overrides))
        self._rates = bool(self.plan.inputs[INPUT_NAMES.index("rates_given")])
        desc = self.plan.candidates[0].desc
        derived = {desc.params[k] for k in desc.derived_params}
        self._params = tuple(n for n in desc.params if n not in derived)

    def run(self, initial=None, params=None, saveat=None):
        """Run the prepared simulation.

        Parameters
        ----------
        initial : dict, optional
            New values for keys of the scene's ``[initial]`` table: ``alpha``, ``beta``,
            ``gamma`` and, as the scene gave them, either ``alpha_dot``, ``beta_dot``,
            ``gamma_dot`` or ``omega`` (three body components). Keys not given keep the
            scene's values.
        params : dict, optional
            New values of the model's parameters by name (``I1``, ``I3``, ``M``, ``g``, ``l``,
            …: the names of ``[body]`` and the effect tables, as the model takes them).
        saveat : derive.SaveAt, optional
            What to keep (:func:`derive.sim.result.kept`); default every output at every
            sample.

        Returns
        -------
        derive.sim.result.Result
            As :func:`derive.simulate` gives it. ``Result.scene`` is the prepared scene (its
            initial values and parameters, not the ones given here), and the integrals are
            those of its integrable case.

        Raises
        ------
        SceneError
            An unknown key, a key of the other shape (rates for a scene given ``omega``, or
            the reverse), or a value that is not a finite number.
        IntegrationError
            Numerical failure, as for :func:`derive.simulate`.
        """
        self._check_keys(initial or {}, params or {})
        inputs = None if not initial else self._inputs(initial)
        for name, value in (params or {}).items():
            _finite(self.plan.scene.source, f"params.{name}", value)
        return kept(simulation.run(self.plan, inputs, params), saveat)

    def run_batch(self, initial=None, params=None, outputs=None, saveat=None):
        """Run the prepared scene N times in one batch call, trajectory b with the b-th entry of
        every array given: what ``derive.simulate_batch`` gives for N scenes that differ from
        this one only in those numbers, without reading N scenes.

        Parameters
        ----------
        initial : dict, optional
            Keys as :meth:`run` takes them, each a number (the same for every trajectory) or
            an array of N numbers (``omega``: three numbers or an (N, 3) array).
        params : dict, optional
            The model's parameters by name (as :meth:`run`), numbers or arrays of N.
        saveat : derive.SaveAt, optional
            What to keep, as ``derive.simulate_batch`` takes it; default ``SaveAt(t="final")``
            (every output at the last sample).
        outputs : str or sequence of str, optional
            The short spelling of ``saveat``: ``"final"`` or output names kept at every sample
            (:meth:`derive.SaveAt.of`).

        Returns
        -------
        derive.sim.batch.BatchResult
            One entry per trajectory, N the length of the arrays (1 when every value is a
            number). The formulations tried are this scene's plan's (:attr:`plan`), kept to
            those every start suits (a singular formulation's clearance of the poles at the
            start, :func:`derive.symbolic.formulations.starts_accepted`), with the batch's
            pole check in C sending the whole batch to the next as ``simulate_batch`` does.

        Raises
        ------
        SceneError
            An unknown key, a value that is not a finite number or an array of them, arrays
            of different lengths; a SciPy method; a fixed-step method without ``simulate.h``
            (its default step depends on each start); no formulation of the plan that suits
            every start.
        IntegrationError
            Numerical failure, naming the trajectory (``<scene>: trajectory b: ...``).
        """
        final, names = selection(choose(saveat, outputs, default="final"))
        return batch.run_plan(_PreparedBatch.of(self, initial or {}, params or {}), final, names)

    def _check_keys(self, initial: dict, params: dict) -> None:
        """SceneError for a key of ``initial`` of the other shape (rates for a scene given
        ``omega``, or the reverse) or unknown, or a parameter the model does not take."""
        source, allowed = self.plan.scene.source, _ANGLES + (_RATES if self._rates else ("omega",))
        for key in initial:
            if key not in allowed:
                raise SceneError(f"{source}: initial.{key}: not a key this prepared scene takes "
                                 f"(it takes {', '.join(allowed)})")
        for name in params:
            if name not in self._params:
                raise SceneError(f"{source}: params: unknown parameter {name!r} "
                                 f"(the model's: {', '.join(self._params)})")

    def _inputs(self, initial) -> np.ndarray:
        source = self.plan.scene.source
        inputs = self.plan.inputs.copy()
        for key, value in initial.items():
            if key == "omega":
                w = np.asarray(value, dtype=float) if not isinstance(value, str) else None
                if w is None or w.shape != (3,) or not np.isfinite(w).all():
                    raise SceneError(f"{source}: initial.omega: must be three finite numbers")
                inputs[3:6] = w
            else:
                inputs[INPUT_NAMES.index(key)] = _finite(source, f"initial.{key}", value)
        return inputs


def _finite(source: str, key: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.number)) \
            or not math.isfinite(float(value)):
        raise SceneError(f"{source}: {key}: must be a finite number, not {value!r}")
    return float(value)


def _column(source: str, key: str, value, width: int = 1) -> np.ndarray:
    """A checked value of a prepared batch: finite float64 of shape () or (N,) ((width,) or
    (N, width) when ``width`` > 1); SceneError naming ``key`` otherwise."""
    a = None if isinstance(value, str) else np.asarray(value)
    shapes = (0, 1) if width == 1 else (1, 2)
    if a is None or a.dtype.kind not in "iuf" or a.ndim not in shapes or (width > 1 and a.shape[-1] != width):
        what = "a number or an array of numbers" if width == 1 else "three numbers or an (N, 3) array"
        raise SceneError(f"{source}: {key}: must be {what}, not {value!r:.60}")
    a = a.astype(np.float64)
    finite = np.isfinite(a) if width == 1 else np.isfinite(a).all(axis=-1)
    if not finite.all():
        where = f"[{int(np.flatnonzero(~finite.reshape(-1))[0])}]" if a.ndim == shapes[1] else ""
        raise SceneError(f"{source}: {key}{where}: must be finite")
    return a


class _PreparedBatch(batch.BatchPlan):
    """A batch plan of a prepared scene (:meth:`Prepared.run_batch`): every trajectory is the
    prepared scene but for the numbers given as arrays; their parameter vectors are the
    scene's with columns replaced, made once per model."""

    @classmethod
    def of(cls, prepared: Prepared, initial: dict, params: dict) -> "_PreparedBatch":
        pl = prepared.plan
        sc, source = pl.scene, pl.scene.source
        prepared._check_keys(initial, params)
        cols: dict = {("initial", key): _column(source, f"initial.{key}", value, 3 if key == "omega" else 1)
                      for key, value in initial.items()}
        cols.update({("params", name): _column(source, f"params.{name}", value) for name, value in params.items()})
        lengths = [(f"{kind}.{key}", a.shape[0]) for (kind, key), a in cols.items()
                   if a.ndim == (2 if key == "omega" else 1)]
        for label, size in lengths[1:]:
            if size != lengths[0][1]:
                raise SceneError(f"{source}: {label}: {size} values, but {lengths[0][0]} has "
                                 f"{lengths[0][1]} (a batch's arrays have one value per trajectory)")
        n = lengths[0][1] if lengths else 1
        inputs = np.repeat(pl.inputs[None, :], n, axis=0)
        for (kind, key), a in cols.items():
            if kind == "initial":
                if key == "omega":
                    inputs[:, 3:6] = a
                else:
                    inputs[:, INPUT_NAMES.index(key)] = a
        if pl.scipy:
            raise SceneError(f"{source}: simulate.method: batches run in the C kernels, not {pl.method}")
        sin_beta = np.abs(np.sin(inputs[:, INPUT_NAMES.index("beta")]))
        accepted = [c for c in pl.candidates
                    if starts_accepted(c.desc.formulation, sin_beta, prepared._rates).all()]
        if not accepted:
            name = pl.candidates[0].desc.formulation
            b = int(np.flatnonzero(~starts_accepted(name, sin_beta, prepared._rates))[0])
            raise SceneError(f"{source}: initial.beta[{b}]: the formulation {name!r} cannot start at "
                             f"|sin(beta)| = {sin_beta[b]:.3g}; use 'auto' or 'quaternion'")
        candidates = tuple((c.desc.formulation, c.pole_check) for c in accepted)
        # the method of the first formulation that runs (auto's for its model, as
        # simulate_batch takes it), for the whole batch
        method = accepted[0].method
        if not tolerance_driven(method) and sc.simulate.h is None:
            raise SceneError(f"{source}: simulate.h: a prepared batch of the fixed-step method {method} "
                             f"needs simulate.h (its default step depends on each start)")
        out = cls([sc] * n, method, pl.t, inputs, sc.effects, None, candidates)
        out._given = {key: a for (kind, key), a in cols.items() if kind == "params"}
        out._made = {}
        return out

    def params(self, desc, rows: slice = slice(None)) -> np.ndarray:
        p = self._made.get(desc.name)
        if p is None:
            p = np.repeat(params_of(self.scenes[0], desc)[None, :], len(self.scenes), axis=0)
            for name, a in self._given.items():
                p[:, desc.params.index(name)] = a
            self._made[desc.name] = p
        return p[rows]

    def where(self, b: int) -> str:
        return f"{self.scenes[b].source}: trajectory {b}"
