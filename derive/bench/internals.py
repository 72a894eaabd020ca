"""The few places where `derive bench` reaches below the public API, kept in one module.

Everything else in the bench goes through ``derive.simulate``, ``derive.simulate_batch``, the
command line (``python -m derive simulate``) and the committed ``generated/`` artefacts, so it
keeps working while the pipeline behind them changes. What needs more lives here, each piece
small, and each caller degrades to "unavailable (<why>)" in the report if one breaks:

* :func:`kernel_case` — the compiled kernel of a scene with its initial state and parameters,
  for one rhs call through ctypes and the solve-only C batch loop (:func:`model_for`,
  :func:`sources_for` and :func:`kernel_for` derive, render and compile a model in this
  process, with SymPy: never the path ``simulate`` takes);
* :func:`own_batch_call` — the one C call ``simulate_batch`` makes, inputs prepared: its cost
  without Python;
* :func:`output_map_call` — the output map alone (the compiled ``outputs_at``) on a solved
  trajectory: the part of that C call that is not the integration;
* :func:`heavy_top_expressions` — the SymPy right-hand side of the heavy top, for the
  ``sympy.lambdify`` comparison;
* :data:`DERIVE_SCRIPT` — a fresh process that times the SymPy derivation and the code
  generation of one scene's model.
"""
from __future__ import annotations

from dataclasses import dataclass

import functools
from pathlib import Path

import numpy as np

from derive.codegen.sources import model_sources
from derive.errors import IntegrationError
from derive.runtime import catalogue
from derive.runtime.integrate import ModelKernel
from derive.runtime.kernel import Kernel
from derive.sim import auto, batch
from derive.sim.inputs import _settings, choose_method, inputs_of, params_of
from derive.sim.scene import load_scene
from derive.symbolic import models


@functools.lru_cache(maxsize=None)
def model_for(formulation: str, symmetric: bool, effects: tuple):
    """A model derived in this process (SymPy)."""
    return models.build(formulation, symmetric, effects)


@functools.lru_cache(maxsize=None)
def sources_for(formulation: str, symmetric: bool, effects: tuple) -> dict:
    """The generated files of a model (CSE and rendering done once per process)."""
    return model_sources(model_for(formulation, symmetric, effects))


@functools.lru_cache(maxsize=None)
def kernel_for(formulation: str, symmetric: bool, effects: tuple):
    """The compiled C kernel (model + every solver) of a model."""
    model = model_for(formulation, symmetric, effects)
    files = sources_for(formulation, symmetric, effects)
    sources = {Path(k).name: v for k, v in files.items() if k in (f"c/{model.name}.h", f"c/{model.name}.c")}
    return Kernel.from_sources(model.name, len(model.states), sources)


@dataclass
class KernelCase:
    kernel: object          # derive.runtime.kernel.Kernel
    formulation: str
    y0: np.ndarray
    p: np.ndarray
    t: np.ndarray
    rtol: float
    atol: float


def kernel_case(scene, formulation: str | None = None, **overrides) -> KernelCase:
    """The kernel `simulate` would run for ``scene`` (path or dict), with its inputs."""
    sc = load_scene(scene, **overrides)
    form = formulation or auto.model_key(sc)[0]
    desc = catalogue.describe((form, sc.symmetric, sc.effects))
    y0, p, rc = ModelKernel.load(desc, None).init(inputs_of(sc), params_of(sc, desc))
    if rc:
        raise IntegrationError("the initial state is not finite")
    return KernelCase(kernel_for(form, sc.symmetric, sc.effects), form, y0, p, sc.t_out, sc.simulate.rtol,
                      sc.simulate.atol)


def batch_inputs(scenes, formulation: str):
    """(kernel, y0s, ps, t, rtol, atol) of a list of scenes in one formulation: what
    ``Kernel.solve_batch`` takes, i.e. the raw C batch loop."""
    cases = [kernel_case(s, formulation) for s in scenes]
    c = cases[0]
    return (c.kernel, np.array([k.y0 for k in cases]), np.array([k.p for k in cases]), c.t, c.rtol, c.atol)


def own_batch_call(scenes):
    """A callable making the one C call ``simulate_batch`` makes for ``scenes`` (state maps,
    integration and outputs of every scene), its inputs prepared beforehand: what
    ``simulate_batch`` costs without its Python. The batch's own plan
    (:func:`derive.sim.batch.batch_plan`: its method, first formulation, inputs and
    parameters) and its driver: a Taylor method's full-grid lanes where the batch takes them
    (:meth:`ModelKernel.full_lanes`)."""
    bp = batch.batch_plan(scenes)
    formulation, pole_check = bp.candidates[0]
    desc, kernel, args = bp.kernel(formulation)
    inputs, ps, t = bp.inputs, bp.params(desc), bp.t
    lanes = kernel.full_lanes(len(bp.scenes))
    k = lanes or kernel
    return lambda: k.simulate_batch(inputs, ps, t, args, pole_check, lanes=lanes is not None)


def output_map_call(scene):
    """A callable running the compiled output map (``<model>_outputs_at``: every output at every
    sample) on the states ``simulate`` integrated for ``scene``: what of ``simulate``'s C call is
    not the integration."""
    sc = load_scene(scene)
    formulation, pole_check = auto.plan(sc)[0]
    desc = catalogue.describe((formulation, sc.symmetric, sc.effects))
    method = choose_method(sc)
    kernel = ModelKernel.load(desc, method)
    t = sc.t_out
    _, y, p, _ = kernel.simulate(inputs_of(sc), params_of(sc, desc), t,
                                 _settings(sc, method, kernel), pole_check)
    y, p = y.copy(), p.copy()
    return lambda: kernel.outputs_at(t, y, p)


def heavy_top_expressions():
    """(states, params, rhs) of the contract's heavy top (generated/c/heavy_top.c) as SymPy."""
    m = models.CATALOGUE["heavy_top"]()
    return tuple(m.states), tuple(m.params), tuple(m.rhs)


#: Run in a fresh interpreter: ``python -c DERIVE_SCRIPT <scene file or JSON>``; prints one JSON
#: line: seconds of the SymPy derivation of the scene's model and of its code generation (what a
#: model that is not in generated/ or the cache costs before anything is compiled).
DERIVE_SCRIPT = r"""
import json, sys, time
arg = sys.argv[1]
scene = json.loads(arg) if arg.startswith("{") else arg
from derive.bench.internals import model_for, sources_for
from derive.sim import auto
from derive.sim.scene import load_scene
sc = load_scene(scene)
key = (auto.model_key(sc)[0], sc.symmetric, sc.effects)
a = time.perf_counter(); model_for(*key)
b = time.perf_counter(); sources_for(*key)
c = time.perf_counter()
print(json.dumps({"derivation": b - a, "codegen": c - b}))
"""
