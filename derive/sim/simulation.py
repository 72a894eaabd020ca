"""Simulate a scene: scene → model → compiled kernel → one C call → results.

The flow runs one way:

1. the scene (validated, :mod:`derive.sim.scene`) names the body, its effects and the settings;
2. :mod:`derive.sim.auto` picks the formulation (and the method, for "auto") from derived
   quantities: the formulations' costs and, for the ones with a singular set, the β range from
   the Routh reduction's polynomial, evaluated in compiled code;
3. :mod:`derive.runtime.catalogue` gives the generated model (shipped in generated/, or derived once and
   cached) and :class:`derive.runtime.integrate.ModelKernel` its compiled (model, method) library;
4. one C call runs the init map (scene inputs → state and derived parameters), the integration
   and the output map at every sample (angles made canonical) into preallocated arrays;
5. the arrays become a :class:`Result`; ``integral_<name>`` arrays are added for the integrable
   cases (:mod:`derive.symbolic.integrable`).

Nothing on this path imports SymPy (unless a model must be derived first), matplotlib or the
reference solutions of :mod:`derive.reference.exact`.
"""
from __future__ import annotations

import numpy as np

from derive.contact.simulate import run_scene  # the contact hook
from derive.errors import IntegrationError
from derive.methods.status import Status
from derive.sim import plan
from derive.sim.outputs import RESULT_FORMATS, write_csv, write_data_and_plot
from derive.sim.plots import plot_result
from derive.sim.result import Result, _check_pole, _explain, _quiet, _result, kept
from derive.sim.saveat import SaveAt
from derive.sim.scene import contact_data, load_scene  # contact_data: the contact hook
from derive.sim.scipy_ref import _solve_scipy

_RANGE = int(Status.RANGE)


@_quiet
def simulate(scene, saveat: SaveAt | None = None, **overrides) -> Result:
    """Simulate a scene (path or dict shaped like the TOML); overrides replace [simulate] keys:
    validate it, plan it, run the plan, keep what ``saveat`` asks for (:func:`kept`)."""
    found = contact_data(scene)  # -- contact hook: a top on a table runs in derive.contact --
    if found is not None:
        return run_scene(*found, **overrides)  # -- end of the contact hook --
    return kept(run(plan.make(load_scene(scene, **overrides))), saveat)


def run(pl: "plan.Plan", inputs: np.ndarray | None = None, params: dict | None = None) -> Result:
    """Run a plan: the C call of the first candidate whose pole check passes (or SciPy on the
    generated NumPy right-hand side), then the Result. ``inputs`` replaces the plan's init-map
    inputs and ``params`` ({name: value}) some of the model's parameters, unchecked (the plan's
    caller, :class:`derive.sim.prepared.Prepared`, checks them).

    NumPy's floating-point warnings are off wherever a NumPy operation could raise one (the
    SciPy path, the integrals: see :func:`_quiet`); the compiled path's other operations
    (copies, views, the pole check on finite angles) cannot warn."""
    if pl.scipy:
        return _run_scipy(pl, pl.inputs if inputs is None else inputs, params)
    # The compiled path: the candidates' calls were bound once per plan (layout, pointers,
    # converted arguments), so a run is an allocation, the C call and the Result.
    t = pl.t
    given = inputs is not None and inputs is not pl.inputs
    if given:
        inputs = np.ascontiguousarray(inputs, dtype=np.float64)
    for c in pl.candidates:
        bound = c.bound(t, pl.inputs)
        out, y, p, status, nfev, buf = bound(c.params if not params else _with(c, params),
                                             inputs if given else None)
        if status != _RANGE:
            break
    if status:
        raise IntegrationError(_explain(c.desc, bound.stats(buf), pl.scene.simulate.max_steps))
    if c.pole_loss:
        _check_pole(c.desc, t, out[1], pl.scene.simulate.rtol)
    # The compiled drivers checked the outputs finite (status NONFINITE_OUTPUT).
    return _compiled_result(pl, c, out, y, nfev)


@_quiet
def _run_scipy(pl: "plan.Plan", inputs: np.ndarray, params: dict | None) -> Result:
    sc, t, c = pl.scene, pl.t, pl.candidates[0]
    desc = c.desc
    out, y, _, nfev = _solve_scipy(desc, pl.scipy, inputs, _with(c, params), t, sc)
    _check_pole(desc, t, out[1], sc.simulate.rtol)
    # SciPy's solver did not check the outputs finite: _result does
    return _result(desc, out, y, t, sc, pl.method, nfev, integrals=pl.integral_rows)


def _compiled_result(pl: "plan.Plan", c: "plan.Candidate", out: np.ndarray, y: np.ndarray,
                     nfev: int) -> Result:
    """The Result of outputs the C driver checked finite, with the plan's integral formulas."""
    return _result(c.desc, out, y, pl.t, pl.scene, c.method, nfev, finite=True, integrals=pl.integral_rows)


def _with(c, params: dict | None) -> np.ndarray:
    """The candidate's parameter vector, with ``params`` ({name: value}) replacing entries."""
    if not params:
        return c.params
    p = c.params.copy()
    for name, value in params.items():
        p[c.desc.params.index(name)] = value
    return p


def write_outputs(res: Result, npz: str | None = None, png: str | None = None) -> None:
    """Write the arrays (``npz``) and the plot (``png``), all or nothing (see
    :mod:`derive.sim.outputs`), each in the format its extension names: the arrays as .npz (NumPy)
    or .csv (``outputs.write_csv``), the plot as .png, .pdf or .svg. Another extension raises
    SceneError naming ``-o`` or ``--plot`` before anything is written; neither may be the
    scene file the result came from (SceneError naming both)."""
    source = res.scene.source if res.scene is not None else None
    # the plot: a top on a table draws its own page (the contact hook)
    plot = res.plot_to if hasattr(res, "plot_to") else lambda f, fmt: plot_result(res, f, fmt)
    write_data_and_plot(npz, {"csv": lambda f: write_csv(f, {"t": res.t, **res.arrays()}),  # t first
                              "npz": lambda f: np.savez(f, **res.arrays())}, RESULT_FORMATS,
                        png, lambda fmt: lambda f: plot(f, fmt),
                        inputs=[source] if source and source != "<dict>" else [])
