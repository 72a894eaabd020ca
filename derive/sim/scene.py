"""Scene files: read, validate and describe one simulation of a rigid body about a fixed point.

A scene is a TOML file (or a dict shaped like one) with the tables ``[body]``, ``[gravity]``,
``[damping]`` (the effects' tables, declared in :mod:`derive.symbolic.effects`), ``[initial]`` and
``[simulate]`` and an optional top-level ``title``; see the README ("Scene files") and
``docs/scenes.md`` for every key, and ``scenes/*.toml`` for examples.

Conventions (those of the whole package):

* SI units; angles in radians, rates in rad/s, moments of inertia in kg m^2, times in s.
* z-y-z Euler angles: alpha about the inertial z axis, beta about the intermediate y' axis,
  gamma about the body 3 axis; R = Rz(alpha) Ry(beta) Rz(gamma) maps body to inertial components.
* ``omega`` is the angular velocity in the *body* frame, (w1, w2, w3) along the principal axes.

Every problem raises :class:`derive.errors.SceneError` with exactly one line,
``<file>: <key or table>: <what is wrong>``, keys dotted (``body.I3``, ``simulate.rtol``). The
first problem found is reported, tables in the order body, gravity, damping, initial, simulate.

Decisions where the contract is silent (documented here once):

* ``[body]``: I1 and I3 are required, I2 defaults to I1.
* Effect tables (``[gravity]``, ``[damping]``, …) are declared by their effects
  (:mod:`derive.symbolic.effects`): keys, units, checks, defaults and keys of which exactly one is given
  (gravity's ``l`` or ``com``). A table present switches its effect on unless its values make
  the effect vanish (``[damping] c = 0``, gravity with ``g = 0`` or the centre of mass at the
  pivot): then the scene runs the model without it (``Scene.effects``; ``named_effects`` keeps
  it), so a zero term costs nothing and one body gets one formulation. A centre of mass on axis
  3 is ``l`` however it was spelt (``com = [0, 0, l]`` is stored, and written back, as ``l``).
  ``l`` may be negative: the centre of mass then sits *below* the pivot when body axis 3 points
  up (a hanging, pendulum-like body).
* ``[initial]``: alpha, beta, gamma are required (any finite real). Give the Euler-angle rates or
  ``omega``. If at least one rate is given, missing rates default to 0.0 (``beta_dot`` is usually
  0 at a turning point, so scenes may omit it). When ``omega`` is given the rates are kept as
  None: the inverse map omega -> rates divides by sin(beta).
* ``[simulate]``: t_end is required; the other keys have the defaults in ``SIMULATE_DEFAULTS``.
  ``h`` (an extension of the contract) is the step size in s of the fixed-step methods
  ``FIXED_STEP_METHODS``; it is rejected with any other method (there it would be ignored
  silently). h = None lets the integrator choose. ``max_steps`` (default 1000000) is the work
  budget: fixed-step methods are refused up front when t_end / h exceeds it, adaptive ones stop
  with a numerical failure when they spend it. rtol must lie in [2.2e-14, 1) (``MIN_RTOL``:
  100 eps as the documentation prints it, so that the documented limit is accepted): below
  that no double-precision integrator can meet it. samples is capped at ``MAX_SAMPLES`` so that a typo
  cannot exhaust memory.
* A formulation that cannot represent the scene (its registry entry's ``applicable``, see
  :mod:`derive.symbolic.formulations`) is rejected naming ``simulate.formulation`` and the reason.
* Overrides (command-line flags, API keywords) replace keys of ``[simulate]`` before validation;
  None means "not given". A bad override is reported under its ``simulate.<key>`` name with the
  suffix "(given as an override)".
"""
from __future__ import annotations

import os
from collections.abc import Mapping

from derive.errors import scene_error
from derive.sim import examples
from derive.sim.reader import MAX_SCENE_BYTES, MAX_SCENE_DEPTH, read_toml
from derive.reference.rotation import body_omega
from derive.sim.scene_types import (FIXED_STEP_METHODS, FORMULATIONS, MAX_SAMPLES, MAX_STEPS_LIMIT, METHODS,
                                    MIN_RTOL, POLE_TOLERANCE, SIMULATE_DEFAULTS, TRIANGLE_SLACK, Body,
                                    Initial, Scene, Simulate, TableValues)
from derive.sim.validator import _Validator

__all__ = [
    "METHODS", "FIXED_STEP_METHODS", "FORMULATIONS", "SIMULATE_DEFAULTS", "MAX_SAMPLES", "MIN_RTOL",
    "POLE_TOLERANCE", "MAX_STEPS_LIMIT", "TRIANGLE_SLACK", "MAX_SCENE_BYTES", "MAX_SCENE_DEPTH",
    "Body", "TableValues", "Initial", "Simulate", "Scene", "load_scene", "read_toml", "body_omega",
]


def load_scene(scene, /, **overrides) -> Scene:
    """Read and validate a scene.

    ``scene`` is a path to a TOML file, a dict shaped like the TOML, or a :class:`Scene` (then
    only the overrides are applied and checked). ``overrides`` replace keys of ``[simulate]``
    (method, rtol, atol, ...); a value of None means "not given". Raises SceneError with one line
    ``<file>: <key or table>: <what is wrong>``.
    """
    if isinstance(scene, Scene):
        source, data = scene.source, scene.to_dict()
    elif type(scene) is dict or isinstance(scene, Mapping):
        source, data = "<dict>", scene
    elif isinstance(scene, (str, os.PathLike)) and not isinstance(scene, bytes):
        source = examples.resolve(os.fspath(scene), "scene")  # a bare name: a shipped example
        data = read_toml(source)
    else:
        raise scene_error("<scene>", "scene", f"must be a path to a TOML file, a dict shaped "
                                              f"like one or a Scene, not {type(scene).__name__}")
    overrides = {k: v for k, v in overrides.items() if v is not None}
    return _Validator(source).scene(data, overrides)


# -- tops on a table: a scene with a [contact] table belongs to derive.contact (hook) --
def contact_data(scene) -> tuple[dict, str] | None:
    """(the TOML dict, its source) when ``scene`` (a path, example name or dict) has a
    ``[contact]`` table — a top on a table, read and run by :mod:`derive.contact` — else None."""
    if isinstance(scene, Mapping):
        return (dict(scene), "<dict>") if "contact" in scene else None
    if not isinstance(scene, (str, os.PathLike)) or isinstance(scene, bytes):
        return None
    source = examples.resolve(os.fspath(scene), "scene")
    data = read_toml(source)
    return (data, source) if "contact" in data else None
# -- end of the contact hook --
