"""What an export carries: the model a scene runs, with its numbers and their names.

The scene is planned as ``derive simulate`` plans it (:func:`derive.sim.plan.make`) and run once:
with formulation "auto" the plan may hold several candidates (a singular formulation first,
refused at the start by its pole check when the motion comes too close to a pole), and the
export is of the one that ran, so the exported code gives the numbers ``derive simulate`` gives.
A scene that cannot be simulated (exit 3) is not exported either.

Names, as the exported README, ``example.c`` and the FMU's ``modelDescription.xml`` show them:

* the model's parameters as scene keys: ``body.I1``, ``gravity.M``, ``damping.c``, … (the
  table of the effect that adds a parameter, then its name; the parameters the init map derives,
  such as the reduced top's ``p_alpha``, are not inputs and carry no scene name);
* the init map's inputs as ``initial.alpha`` … ``initial.omega1`` … ``initial.rates_given``;
* the outputs as the output file's arrays with component suffixes (``beta``, ``energy``,
  ``axis_x``, ``omega1``, …): the model's observable names.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from derive.codegen.render import render
from derive.errors import SceneError
from derive.methods.registry import METHODS, method as compiled_method
from derive.runtime.catalogue import Description
from derive.sim import plan, simulation
from derive.sim.scene import Scene, load_scene
from derive.symbolic import effects as fx
from derive.symbolic.formulations import INPUT_NAMES

#: The unit of the body's moments (an effect's keys carry their own units).
_BODY_UNIT = "kg m^2"
#: The init map's inputs: (unit, meaning) by name.
_INPUTS = {
    "alpha": ("rad", "z-y-z Euler angle about the inertial z axis at t = 0"),
    "beta": ("rad", "z-y-z Euler angle about the intermediate y' axis at t = 0 (tilt of body axis 3)"),
    "gamma": ("rad", "z-y-z Euler angle about body axis 3 at t = 0"),
    "omega1": ("rad/s", "body angular velocity, component 1, at t = 0 (read when rates_given = 0)"),
    "omega2": ("rad/s", "body angular velocity, component 2, at t = 0 (read when rates_given = 0)"),
    "omega3": ("rad/s", "body angular velocity, component 3, at t = 0 (read when rates_given = 0)"),
    "alpha_dot": ("rad/s", "Euler-angle rate at t = 0 (read when rates_given = 1)"),
    "beta_dot": ("rad/s", "Euler-angle rate at t = 0 (read when rates_given = 1)"),
    "gamma_dot": ("rad/s", "Euler-angle rate at t = 0 (read when rates_given = 1)"),
    "rates_given": ("", "1: start from the angles and their rates; 0: from the angles and omega"),
}

#: Units and meanings of the outputs (observables) by the output file's array name.
OUTPUT_UNITS = {"alpha": "rad", "beta": "rad", "gamma": "rad", "omega": "rad/s", "axis": "",
                "energy": "J", "p_alpha": "kg m^2/s", "p_gamma": "kg m^2/s", "n": "",
                "L": "kg m^2/s", "L_squared": "kg^2 m^4/s^2"}
OUTPUT_DOCS = {
    "alpha": "z-y-z Euler angle, continuous (not wrapped)",
    "beta": "z-y-z Euler angle in [0, pi]",
    "gamma": "z-y-z Euler angle, continuous (not wrapped)",
    "omega": "angular velocity, body axes",
    "axis": "body axis 3 in inertial components",
    "energy": "total energy T + V",
    "p_alpha": "momentum conjugate to alpha",
    "p_gamma": "momentum conjugate to gamma",
    "n": "the upward vertical in body axes",
    "L": "angular momentum about the pivot, body axes",
    "L_squared": "|L|^2",
}


@dataclass(frozen=True)
class Variable:
    """A named number of the export: ``index`` into the model's ``p`` (parameters) or the init
    map's ``in`` (inputs); ``unit`` SI as the scene states it ("" dimensionless or unknown)."""

    name: str
    index: int
    value: float
    unit: str
    doc: str


@dataclass(frozen=True)
class Bundle:
    """The model and method a scene runs, and the scene's numbers for them.

    Attributes
    ----------
    scene : Scene
        The validated scene (with the method override applied).
    desc : Description
        The generated model that ran (its folder holds the C and NumPy files).
    method : str
        The compiled method.
    driver : tuple
        The driver's arguments after ``n_out``, as ``(C type, name, value)``.
    pole_check : int
        What the simulate driver's pole check must pass (0 none; see
        :func:`derive.sim.auto.pole_mode`).
    inputs : ndarray
        The init map's inputs (``formulations.INPUT_NAMES``).
    params : ndarray
        The model's parameters, the derived ones 0 (the init map writes them).
    nfev : int
        What the run took (right-hand-side evaluations), as ``derive simulate`` reports it.
    """

    scene: Scene
    desc: Description
    method: str
    driver: tuple
    pole_check: int
    inputs: np.ndarray
    params: np.ndarray
    nfev: int

    @property
    def name(self) -> str:
        return self.desc.name

    @property
    def family(self) -> str | None:
        """The C file of the method's own family beside the solvers (``<name>_<family>.{h,c}``):
        "splitting" for a Lie–Poisson splitting, "taylor" for a Taylor method, None for the
        Runge–Kutta family (in ``<name>_solvers.c``) — as the kernel build includes them."""
        if self.method in METHODS:
            return None
        return "taylor" if compiled_method(self.method).driver == "taylor" else "splitting"

    def parameters(self) -> list[Variable]:
        """The model's parameters the scene gives (not the derived ones), by scene key."""
        derived = set(self.desc.derived_params)
        owners = {}
        for e in fx.lookup(self.desc.effects):
            table = fx.TABLES.get(e.table)
            for p in e.param_names:
                key = next((k for k in table.keys if k.name == p), None) if table else None
                owners[p] = (f"{e.table}.{p}", key.unit if key else "",
                             key.doc if key else f"parameter {p} of {e.table}")
        out = []
        for k, p in enumerate(self.desc.params):
            if k in derived:
                continue
            if p in ("I1", "I2", "I3"):
                name, unit, doc = f"body.{p}", _BODY_UNIT, f"principal moment of inertia {p}"
            else:
                name, unit, doc = owners.get(p, (p, "", f"parameter {p}"))
            out.append(Variable(name, k, float(self.params[k]), unit, doc))
        return out

    def initial(self) -> list[Variable]:
        """The init map's inputs, as ``initial.<name>``."""
        return [Variable(f"initial.{n}", k, float(self.inputs[k]), *_INPUTS[n]) for k, n in enumerate(INPUT_NAMES)]

    def model_files(self) -> tuple[list[str], list[str]]:
        """(the model's C files with its solvers and its method family's, the other generated
        files they include by name, such as ``derive_elliptic.h``)."""
        P, sources = self.name, self.desc.c_sources()
        model = [f"{P}.h", f"{P}.c", f"{P}_solvers.h", f"{P}_solvers.c"]
        if self.family:
            model += [f"{P}_{self.family}.h", f"{P}_{self.family}.c"]
        text = "".join(sources[n] for n in model)
        return model, sorted(n for n in sources if n not in model and f'"{n}"' in text)

    @property
    def t_end(self) -> float:
        return self.scene.simulate.t_end

    @property
    def samples(self) -> int:
        return self.scene.simulate.samples


def state_unit(name: str) -> str:
    """The unit of a state component by its name: angles, rates, momenta; "" for the
    dimensionless ones (quaternion, direction cosines)."""
    if name in ("alpha", "beta", "gamma"):
        return "rad"
    if name.endswith("_dot") or name.startswith("omega"):
        return "rad/s"
    if name.startswith(("p_", "L")):
        return "kg m^2/s"
    return ""


_COMPONENT = re.compile(r"^(.+?)_?([123]|[xyz])$")


def output_groups(outputs) -> list[tuple[str, list[int]]]:
    """The observables grouped as the output file's arrays: ``omega1, omega2, omega3`` →
    ``("omega", [3, 4, 5])``, ``axis_x …`` → ``("axis", …)``; a scalar stays alone."""
    out, k = [], 0
    outputs = list(outputs)
    while k < len(outputs):
        m = _COMPONENT.match(outputs[k])
        if m and k + 2 < len(outputs):
            base, first = m.groups()
            trio = [_COMPONENT.match(o) for o in outputs[k:k + 3]]
            series = "123" if first == "1" else "xyz" if first == "x" else None
            if series and all(t and t.group(1) == base and t.group(2) == s
                              for t, s in zip(trio, series)):
                out.append((base, [k, k + 1, k + 2]))
                k += 3
                continue
        out.append((outputs[k], [k]))
        k += 1
    return out


def make(scene, method: str | None = None) -> Bundle:
    """The export of a scene (a path, an example's name or a dict), with ``method`` replacing
    the scene's ``[simulate] method``.

    Raises
    ------
    SceneError
        Bad input, or a method that runs in SciPy (nothing of it is compiled to export).
    IntegrationError
        The scene's simulation fails: there is nothing correct to export.
    """
    sc = load_scene(scene, method=method)
    pl = plan.make(sc)
    if pl.scipy:
        raise SceneError(f"{sc.source}: simulate.method: {pl.method} runs SciPy's solve_ivp in "
                         f"Python; export a compiled method (--method dop853, rk4, gauss4, ...)")
    res = simulation.run(pl)  # which candidate ran (auto falls back past a refused start)
    c = next(c for c in pl.candidates if c.desc.name == res.model)
    spec = compiled_method(pl.method)
    driver = tuple((ctype, name, value) for (ctype, name), value in zip(spec.params, c.args))
    return Bundle(scene=sc, desc=c.desc, method=pl.method, driver=driver,
                  pole_check=c.pole_check, inputs=np.array(pl.inputs, dtype=float),
                  params=np.array(c.params, dtype=float), nfev=int(res.nfev))


def notice(names) -> str:
    """``NOTICE.md`` of an export holding the files ``names``: the notice of every third-party
    piece among them (fdlibm's in ``derive_libm.h``, the FMI headers'), as the licences ask."""
    names = set(names)
    return render("export/NOTICE.md.j2", libm="derive_libm.h" in names,
                  fmi="fmi2Functions.h" in names)
