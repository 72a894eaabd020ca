"""Derivation-side helpers for tests and benchmarks (SymPy; never on the simulate path): a
model derived in this process, its generated files, its compiled kernel of every solver, and
the init map's y0 and p for a scene.

Takes: a model's key or a scene. Gives: models, sources, kernels and states.
"""
from __future__ import annotations

import functools
from pathlib import Path

import numpy as np

from derive.codegen.sources import model_sources
from derive.errors import IntegrationError
from derive.runtime import catalogue
from derive.runtime.integrate import ModelKernel
from derive.runtime.kernel import Kernel
from derive.sim import auto
from derive.sim.inputs import inputs_of, params_of
from derive.sim.scene import Scene
from derive.symbolic import models


@functools.lru_cache(maxsize=None)
def model_for(formulation: str, symmetric: bool, effects: tuple):

    return models.build(formulation, symmetric, effects)


@functools.lru_cache(maxsize=None)
def sources_for(formulation: str, symmetric: bool, effects: tuple) -> dict:
    """The generated files of a model (CSE and rendering done once per process)."""
    return model_sources(model_for(formulation, symmetric, effects))


@functools.lru_cache(maxsize=None)
def kernel_for(formulation: str, symmetric: bool, effects: tuple):
    """The compiled C kernel (model + every solver) for a model, for tests and benchmarks."""

    model = model_for(formulation, symmetric, effects)
    files = sources_for(formulation, symmetric, effects)
    sources = {Path(k).name: v for k, v in files.items() if k in (f"c/{model.name}.h", f"c/{model.name}.c")}
    return Kernel.from_sources(model.name, sources)


def effect_names(scene: Scene) -> tuple[str, ...]:
    """The registry effects a scene calls for."""
    return scene.effects


def choose_formulation(scene: Scene) -> str:
    """The formulation ``simulate`` runs for this scene."""
    return auto.model_key(scene)[0]


def _initial_state(scene: Scene, model) -> np.ndarray:
    """y0 of ``model`` for the scene (by the compiled init map)."""
    return _init(scene, model)[0]


def _params(scene: Scene, model) -> np.ndarray:
    """p of ``model`` for the scene, derived parameters included (by the compiled init map)."""
    return _init(scene, model)[1]


def _init(scene: Scene, model):
    desc = catalogue.describe((model.formulation, model.symmetric, model.effects))
    y0, p, rc = ModelKernel.load(desc, None).init(inputs_of(scene), params_of(scene, desc))
    if rc:
        raise IntegrationError("the initial state is not finite")
    return y0, p


def _quaternion(a, b, c) -> np.ndarray:
    """q of R = Rz(α) Ry(β) Rz(γ), scalar first (the quaternion model's init map, in NumPy)."""
    qa = np.array([np.cos(a / 2), 0.0, 0.0, np.sin(a / 2)])
    qb = np.array([np.cos(b / 2), 0.0, np.sin(b / 2), 0.0])
    qc = np.array([np.cos(c / 2), 0.0, 0.0, np.sin(c / 2)])
    return _qmul(_qmul(qa, qb), qc)


def _qmul(p, q) -> np.ndarray:
    p0, pv, q0, qv = p[0], p[1:], q[0], q[1:]
    return np.concatenate([[p0 * q0 - pv @ qv], p0 * qv + q0 * pv + np.cross(pv, qv)])
