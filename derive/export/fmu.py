"""``derive export SCENE --fmu OUT.fmu``: the scene's model as an FMI 2.0 FMU.

One FMU, both interfaces (FMI 2.0, model exchange and co-simulation):

* model exchange: the states ``state.<name>`` are the model's state y, their derivatives
  ``der(state.<name>)`` its right-hand side; the importer integrates;
* co-simulation: ``fmi2DoStep`` integrates from one communication point to the next with the
  generated solver of the scene's method (``<model>_run_<method>`` from the state, restarted at each point).

Parameters (variability "fixed", start values from the scene): the model's parameters by scene
key (``body.I1``, ``gravity.M``, …), the init map's inputs (``initial.alpha`` …
``initial.omega1`` … and the Boolean ``initial.rates_given``) and the solver's settings
(``simulate.rtol``, ``simulate.atol``, ``simulate.max_steps`` for dop853; ``simulate.h`` for a
fixed step). Outputs: the model's observables, the output file's names with component suffixes
(``alpha``, ``beta``, ``gamma``, ``omega1``, ``axis_x``, ``energy``, …), the angles canonical and
continued from one step to the next as in derive's arrays.

The FMU holds ``modelDescription.xml``, ``binaries/<platform>/<id>.so`` (compiled here with the C
compiler alone: ``cc -std=c99 -O2 -shared -fPIC``) and ``sources/`` (``fmu.c``, which includes the
model and its solvers, and the FMI 2.0 headers, whose BSD licence notice they carry). It is
written all or nothing; an existing file of that name is replaced, never an input.
"""
from __future__ import annotations

import os
from derive.codegen.render import TEMPLATES, c_double, render
from derive.errors import SceneError
from derive.export import bundle as bundles
from derive.export import contact as contact_export, contact_fmu
from derive.export.bundle import OUTPUT_DOCS, OUTPUT_UNITS, Bundle, notice, output_groups, state_unit
from derive.export.fmi import HEADERS, UNITS, Var, archive, guid, model_description, model_identifier, zip_files
from derive.sim.outputs import check_paths, write_all
from derive.sim.scene import contact_data

#: Solver settings shown as parameters (``simulate.<name>``); the rest keep the scene's value.
_SETTINGS = {"rtol": "", "atol": "", "max_steps": "", "h": "s"}
_SETTING_DOCS = {"rtol": "relative tolerance of each step's solve",
                 "atol": "absolute tolerance of each step's solve",
                 "max_steps": "step budget of each communication step",
                 "h": "the method's fixed step (each communication step is split into "
                      "ceil(dt/h) equal steps)"}


def variables(b: Bundle) -> list[Var]:
    """The FMU's variables in value-reference order: parameters, inputs, settings, states,
    derivatives, outputs."""
    out: list[Var] = []

    def add(name, kind, index, type_, causality, variability, initial, start, unit, doc, **kw):
        out.append(Var(name, len(out), kind, index, type_, causality, variability, initial,
                       start, unit if unit in UNITS else "", doc, **kw))

    for v in b.parameters():
        add(v.name, "V_PARAM", v.index, "Real", "parameter", "fixed", "exact", c_double(v.value),
            v.unit, v.doc)
    for v in b.initial():
        if v.name == "initial.rates_given":
            add(v.name, "V_FLAG", v.index, "Boolean", "parameter", "fixed", "exact",
                "true" if v.value else "false", "", v.doc)
        else:
            add(v.name, "V_INPUT", v.index, "Real", "parameter", "fixed", "exact",
                c_double(v.value), v.unit, v.doc)
    for k, (ctype, name, value) in enumerate(b.driver):
        if name not in _SETTINGS:
            continue
        if ctype == "double":
            add(f"simulate.{name}", "V_SETTING", k, "Real", "parameter", "fixed", "exact",
                c_double(value), _SETTINGS[name], _SETTING_DOCS[name])
        else:
            add(f"simulate.{name}", "V_ISETTING", k, "Integer", "parameter", "fixed", "exact",
                str(int(value)), "", _SETTING_DOCS[name])
    first_state = len(out)
    for k, s in enumerate(b.desc.states):
        add(f"state.{s}", "V_STATE", k, "Real", "local", "continuous", "calculated", None,
            state_unit(s), f"state component {k} of {b.name}")
    for k, s in enumerate(b.desc.states):
        unit = state_unit(s)
        rate = {"rad": "rad/s", "": ""}.get(unit, "")
        add(f"der(state.{s})", "V_DERIV", k, "Real", "local", "continuous", "calculated", None,
            rate, f"d/dt state.{s}", derivative=first_state + k + 1)
    for base, cols in output_groups(b.desc.outputs):
        for k in cols:
            add(b.desc.outputs[k], "V_OUTPUT", k, "Real", "output", "continuous", "calculated",
                None, OUTPUT_UNITS.get(base, ""), OUTPUT_DOCS.get(base, b.desc.outputs[k]))
    return out


def sources(b: Bundle) -> tuple[dict[str, str], str]:
    """(the FMU's ``sources/`` files, modelDescription.xml)."""
    P, ID = b.name, model_identifier(b)
    files = b.desc.c_sources()
    model, extra = b.model_files()
    out = {n: files[n] for n in model + extra}
    for name in HEADERS:
        out[name] = (TEMPLATES / "fmi2" / name).read_text(encoding="utf-8")
    out["NOTICE.md"] = notice(out)
    vs = variables(b)
    fmu_guid = guid(sorted(out.items()), [(v.name, v.start) for v in vs], b.method, b.pole_check)
    derived = sorted(b.desc.derived_params)
    p_start = [0.0 if k in derived else float(x) for k, x in enumerate(b.params)]
    out["fmu.c"] = render("fmi2/fmu.c.j2",
        P=P, ID=ID, method=b.method, family=b.family, guid=fmu_guid, variables=vs,
        p_start=p_start, in_start=[float(x) for x in b.inputs], driver=b.driver,
        derived=derived, has_angles=b.desc.has_angles, pole_check=b.pole_check,
        formulation=b.desc.formulation)
    title = " ".join((b.scene.title or "").split())
    adaptive = any(name == "rtol" for _, name, _ in b.driver)
    xml = model_description(
        "fmi2/modelDescription.xml.j2", vs, model_name=title or P, ID=ID, guid=fmu_guid,
        description=(f"{P} ({b.desc.formulation}; effects: {', '.join(b.desc.effects) or 'none'}) "
                     f"with {b.method}, exported by derive"),
        t_end=c_double(b.t_end), step=c_double(b.t_end / (b.samples - 1)),
        tolerance=c_double(b.scene.simulate.rtol) if adaptive else None)
    return out, xml


def export_fmu(scene, out, method: str | None = None) -> Bundle:
    """Build the FMI 2.0 FMU of ``scene`` into the file ``out`` (``.fmu``), all or nothing.

    Parameters
    ----------
    scene : str, path or dict
        The scene (a TOML path, an example's name, or a dict shaped like the TOML).
    out : str or path
        The FMU file to write (its extension must be ``.fmu``; an existing file is replaced,
        an input never).
    method : str, optional
        Replaces the scene's ``[simulate] method`` (a compiled method).

    Returns
    -------
    Bundle
        What was exported.

    Raises
    ------
    SceneError
        Bad input (the scene, the method, the path).
    IntegrationError
        The scene's simulation fails.
    CompilerError
        No working C compiler.
    """
    name = os.fspath(out)
    source = scene if isinstance(scene, (str, os.PathLike)) and os.path.isfile(scene) else None
    check_paths([name], inputs=[source] if source else [])
    if not name.lower().endswith(".fmu"):
        raise SceneError(f"{name}: --fmu: the file name must end in .fmu")
    found = contact_data(scene) if not isinstance(scene, bundles.Scene) else None
    if found is not None:  # a top on a table: co-simulation of the phases and their events
        b = contact_export.bundle(found, method)
        files = archive(*contact_fmu.sources(b), model_identifier(b))
    else:
        b = bundles.make(scene, method)
        files = archive(*sources(b), model_identifier(b))
    write_all({name: lambda fh: zip_files(files, fh)}, inputs=[b.scene.source] if source else [])
    return b
