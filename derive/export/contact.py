"""``derive export`` of a top on a table: its contact model and the phase driver as C99.

A ``[contact]`` scene's model is one shape and law's evaluator (``generated/contact/``), the
phase loop every contact model includes (``contact_phase_loop.inc``: DOP853 on one phase with
located events) and the driver that joins the phases by their switch rules
(``contact_run.inc``, from ``templates/contact/run.c.j2``). The folder holds those, a
translation unit ``<model>_lib.c`` that puts them together with the law's phases
(``CONTACT_SLIDES``, ``CONTACT_ROLLS``), ``example.c`` (the scene run as ``derive simulate`` runs
it, one JSON line), a ``Makefile``, a ``README.md`` and ``NOTICE.md``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from derive.codegen.render import c_double, render
from derive.contact import driver, kernel as ck
from derive.contact.laws import EXTENSIONS, LAWS
from derive.contact.scene import COMPILED, METHOD, ContactScene, integrals_held, read
from derive.contact.simulate import params, simulate
from derive.reference.rotation import body_omega
from derive.errors import SceneError

#: The units of the parameters, by name.
PARAM_UNITS = {"I1": "kg m^2", "I2": "kg m^2", "I3": "kg m^2", "M": "kg", "g": "m/s^2",
               "r": "m", "s": "m", "mu": "", "epsilon": "m/s", "r2": "m", "s2": "m",
               **{e.param: "m" for e in EXTENSIONS.values()}}
#: The scene key each parameter comes from.
PARAM_KEYS = {"I1": "body.I1", "I2": "body.I2", "I3": "body.I3", "M": "gravity.M",
              "g": "gravity.g", "r": "contact.radius", "s": "contact.offset", "mu": "contact.mu",
              "epsilon": "contact.regularization", "r2": "contact.stem.radius",
              "s2": "contact.stem.offset", **{e.param: f"contact.{e.key}" for e in EXTENSIONS.values()}}
#: The names of the stem's parameters, after the model's in a run's parameters.
STEM_NAMES = ("r2", "s2")


def param_names(sc: ContactScene) -> tuple[str, ...]:
    """The names of a run's parameters: the model's, then the stem's radius and offset if any."""
    return tuple(ck.PARAM_NAMES) + (STEM_NAMES if sc.stem is not None else ())


def run_params(sc: ContactScene) -> np.ndarray:
    """The parameters the driver takes (``CONTACT_NPAR``): the model's, then the stem's."""
    p = params(sc)
    return np.concatenate([p, sc.stem]) if sc.stem is not None else p


def model_name(sc: ContactScene) -> str:
    return f"contact_{sc.shape}_{sc.law}"


def model_files(sc: ContactScene) -> dict[str, str]:
    """The model's C: its evaluator, the phase loop, the shared runtime (the loop's interrupt
    hook) and the driver, by file name."""
    return {**ck.model_sources(sc.shape, sc.law), ck.RUN: ck.text(ck.RUN)}


def start_omega(sc: ContactScene) -> np.ndarray:
    """ω̃ at the start (body axes): the scene's ``omega``, or its z-y-z rates turned into it."""
    if sc.omega is not None:
        return np.array(sc.omega)
    return np.array(body_omega(sc.angles[1], sc.angles[2], *sc.rates))


def integral_outputs(sc: ContactScene) -> list[tuple[str, int]]:
    """The integrals the case has and their index in the evaluator's outputs."""
    names = integrals_held(sc.shape, sc.law, sc.symmetric, sc.moments)
    return [(n, ck.OUTPUTS.index(n)) for n in names]


def files(sc: ContactScene) -> dict[str, str]:
    """Every file of the exported folder of a contact scene: ``{name: text}``."""
    P = model_name(sc)
    out = model_files(sc)
    out[f"{P}_lib.c"] = driver.lib_source(sc.shape, sc.law, sc.stem is not None)
    scene_file = sc.source.rsplit("/", 1)[-1] if sc.source != "<dict>" else "the scene"
    p = run_params(sc)
    common = dict(P=P, scene_file=scene_file, title=" ".join((sc.title or "").split()))
    out["example.c"] = render(
        "contact/example.c.j2", params=[c_double(x) for x in p], param_names=param_names(sc),
        angles=[c_double(x) for x in sc.angles], omega=[c_double(x) for x in start_omega(sc)],
        vx=c_double(sc.vx), vy=c_double(sc.vy), samples=sc.samples, t_end=c_double(sc.t_end),
        rtol=c_double(sc.rtol), atol=c_double(sc.atol), restitution=c_double(sc.restitution),
        max_steps=sc.max_steps, max_switches=driver.MAX_SWITCHES, integrals=integral_outputs(sc), **common)
    out["Makefile"] = render("contact/Makefile.j2", sources=list(model_files(sc)), **common)
    law = LAWS[sc.law]
    out["README.md"] = render(
        "contact/README.md.j2", law=law, shape=sc.shape, states=ck.STATE, outputs=ck.OUTPUTS,
        parameters=[(n, PARAM_KEYS[n], c_double(v), PARAM_UNITS[n]) for n, v in zip(param_names(sc), p)],
        integrals=[n for n, _ in integral_outputs(sc)], run=ck.RUN, loop=ck.LOOP, model=ck.MODEL,
        shape_file=ck.shape_file(sc.shape), **common)
    out["NOTICE.md"] = render("contact/NOTICE.md.j2", loop=ck.LOOP, fmi=False)
    return out


@dataclass(frozen=True)
class ContactBundle:
    """What a contact scene's export holds: the validated scene, its model and method."""

    scene: ContactScene
    name: str
    method: str
    nfev: int
    #: The FMU's interfaces (no model exchange: the switch rules act between the phases).
    interfaces: str = "co-simulation"


def bundle(found: tuple[dict, str], method: str | None = None) -> ContactBundle:
    """The export of a contact scene ``(data, source)``: validated, and run once, since a scene
    whose simulation fails has nothing correct to export.

    Raises
    ------
    SceneError
        Bad input, or a method other than the compiled phase loop (SciPy's DOP853 steps the
        phases from Python and has nothing to export).
    IntegrationError
        The scene's simulation fails.
    """
    sc = read(*found, method=method)
    if sc.method == METHOD:
        raise SceneError(f"{sc.source}: simulate.method: {METHOD} steps the phases from Python; "
                         f"export the compiled phase loop (--method {COMPILED})")
    res = simulate(sc)
    return ContactBundle(sc, model_name(sc), COMPILED, int(res.nfev))
