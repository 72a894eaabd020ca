"""A prepared simulation: a scene validated, planned and compiled once, run many times.

``derive.prepare(scene)`` gives a :class:`Prepared`; its :meth:`~Prepared.run` makes the C call of
the plan (:mod:`derive.sim.plan`) with no validation of the scene, no look-up of the model and
no derivation, optionally with new initial values or parameters of the same shape.

Takes: a scene (path, example name, dict or Scene). Gives: :class:`derive.sim.simulation.Result`.
"""
from __future__ import annotations

import math

import numpy as np

from derive.errors import SceneError
from derive.sim import plan, simulation
from derive.sim.scene import load_scene
from derive.symbolic.formulations import INPUT_NAMES

_ANGLES = ("alpha", "beta", "gamma")
_RATES = ("alpha_dot", "beta_dot", "gamma_dot")


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

    def run(self, initial=None, params=None):
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

        Returns
        -------
        derive.sim.simulation.Result
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
        inputs = None if not initial else self._inputs(initial)
        if params:
            for name, value in params.items():
                if name not in self._params:
                    raise SceneError(f"{self.plan.scene.source}: params: unknown parameter {name!r} "
                                     f"(the model's: {', '.join(self._params)})")
                _finite(self.plan.scene.source, f"params.{name}", value)
        return simulation.run(self.plan, inputs, params)

    def _inputs(self, initial) -> np.ndarray:
        source = self.plan.scene.source
        inputs = self.plan.inputs.copy()
        allowed = _ANGLES + (_RATES if self._rates else ("omega",))
        for key, value in initial.items():
            if key not in allowed:
                raise SceneError(f"{source}: initial.{key}: not a key this prepared scene takes "
                                 f"(it takes {', '.join(allowed)})")
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
