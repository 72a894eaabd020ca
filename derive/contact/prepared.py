"""A top on a table prepared once and run many times: ``derive.prepare`` of a ``[contact]`` scene.

The scene is validated and its shape and law's kernel compiled (or loaded) once; a run is the
initial state and the phase loop's C calls. ``run(initial=..., params=...)`` reruns with new
start values or numbers, checked by the scene's own rules (a bad value is the SceneError a
scene file with it would give, naming its key); the shape and the law are the prepared ones.
"""
from __future__ import annotations

import copy

import numpy as np

from derive.contact.kernel import kernel
from derive.contact.laws import EXTENSIONS
from derive.contact.scene import GRAVITY, ContactScene, read
from derive.contact.simulate import ContactResult, simulate
from derive.errors import SceneError

#: The numbers ``params`` may replace, by their scene key's last part → its table.
PARAMS = {"I1": "body", "I2": "body", "I3": "body", "M": GRAVITY, "g": GRAVITY,
          "radius": "contact", "offset": "contact", "mu": "contact", "regularization": "contact",
          "restitution": "contact", **{key: "contact" for key in EXTENSIONS}}
_ANGLES = ("alpha", "beta", "gamma")
_RATES = ("alpha_dot", "beta_dot", "gamma_dot")


class ContactPrepared:
    """A contact scene validated and compiled once (see :func:`derive.prepare`).

    Attributes
    ----------
    scene : ContactScene
        The validated scene the runs start from.
    """

    def __init__(self, data: dict, source: str = "<dict>", **overrides):
        self.data, self.overrides = copy.deepcopy(data), overrides
        self.scene = read(data, source, **overrides)
        kernel(self.scene.shape, self.scene.law)  # compiled (or loaded) now, not at the first run

    def run(self, initial: dict | None = None, params: dict | None = None, saveat=None) -> ContactResult:
        """Run the prepared scene, optionally with new start values or parameters.

        Parameters
        ----------
        initial : dict, optional
            New values of ``[initial]`` keys: ``alpha``, ``beta``, ``gamma``, then as the scene
            gave them either the rates ``alpha_dot``, ``beta_dot``, ``gamma_dot`` or ``omega``
            (three body components, rad/s), and ``vx``, ``vy`` (m/s; not when rolling).
        params : dict, optional
            New numbers by their scene key's last part: ``I1``, ``I2``, ``I3`` (kg m², about
            the centre of mass), ``M`` (kg), ``g`` (m/s²), ``radius``, ``offset`` (m), ``mu``,
            ``regularization`` (m/s, a regularised scene only), ``restitution``,
            ``rolling_resistance``, ``spin_friction`` (m, where the law takes them).
        saveat : None
            Accepted for the signature :class:`derive.sim.prepared.Prepared` has; a contact
            run keeps every output at every sample.

        Returns
        -------
        ContactResult
            As :func:`derive.simulate` gives it for the scene with those values.

        Raises
        ------
        SceneError
            An unknown key, a key of the other shape (rates for a scene given ``omega``), or a
            value that is not a finite number (positive where the scene requires it).
        IntegrationError
            Numerical failure, saying where.
        """
        if saveat is not None:
            raise SceneError(f"{self.scene.source}: saveat: a contact run keeps every sample")
        return simulate(self._with(initial or {}, params or {}))

    def _with(self, initial: dict, params: dict) -> ContactScene:
        """The scene with the new values, validated by the scene's own rules (a dict edit)."""
        if not initial and not params:
            return self.scene
        sc, src = self.scene, self.scene.source
        allowed = _ANGLES + (_RATES if sc.rates is not None else ("omega",)) \
            + (() if sc.friction == "rolling" else ("vx", "vy"))
        data = copy.deepcopy(self.data)
        for key, value in initial.items():
            if key not in allowed:
                raise SceneError(f"{src}: initial.{key}: not a key this prepared scene takes "
                                 f"(it takes {', '.join(allowed)})")
            data.setdefault("initial", {})[key] = _plain(value)
        for name, value in params.items():
            if name not in PARAMS:
                raise SceneError(f"{src}: params: unknown parameter {name!r} (known: {', '.join(PARAMS)})")
            data.setdefault(PARAMS[name], {})[name] = _plain(value)
        return read(data, src, **self.overrides)


def _plain(value):
    """NumPy numbers and arrays as the TOML reader gives numbers and lists."""
    return value.tolist() if isinstance(value, (np.ndarray, np.generic)) else value
