"""``derive export --fmu`` of a top on a table: an FMI 2.0 co-simulation FMU.

``fmi2DoStep`` runs the phases joined by their events (``contact_integrate`` of the exported
driver) from one communication point to the next, so every switch inside a step is located as
in a whole run. Model exchange is not offered: the phases are separate vector fields joined by
switch rules (the slip removed at a stick, an impact at a landing), which an importer's
integrator stepping one right-hand side cannot apply.

Parameters (variability "fixed", start values from the scene): the model's parameters by scene
key (``body.I1`` … ``contact.offset``, ``contact.mu`` where the law has it,
``contact.regularization`` where it is regularised), the start (``initial.alpha``,
``initial.beta``, ``initial.gamma``, ``initial.omega1`` … ``initial.omega3`` — the rates are
turned into ω̃ — and ``initial.vx``, ``initial.vy`` unless it rolls) and the settings
(``contact.restitution``, ``simulate.rtol``, ``simulate.atol``, ``simulate.max_steps``).
Outputs: the output file's names with component suffixes (``alpha``, ``beta``, ``gamma``,
``omega1``, ``axis_x``, ``energy``, ``com_x``, ``contact_x``, ``normal_force``, ``slip_speed``,
``gap``, ``p_alpha``, ``p_gamma``, ``integral_<name>``), and the Integers ``phase`` (0 slide,
1 roll, 2 flight) and ``switches``.
"""
from __future__ import annotations

from derive.codegen.render import TEMPLATES, c_double, render
from derive.contact import driver
from derive.contact.laws import EXTENSIONS, LAWS
from derive.export import contact as ce
from derive.export.fmi import HEADERS, UNITS, Var, guid, model_description, model_identifier

#: The outputs before the integrals, with their units and meaning.
OUTPUTS = (
    ("alpha", "rad", "precession angle (z-y-z), continued"),
    ("beta", "rad", "tilt of body axis 3 from the vertical"),
    ("gamma", "rad", "spin angle (z-y-z), continued"),
    ("omega1", "rad/s", "angular velocity, body axis 1"),
    ("omega2", "rad/s", "angular velocity, body axis 2"),
    ("omega3", "rad/s", "angular velocity, body axis 3"),
    ("axis_x", "", "body axis 3, inertial x"),
    ("axis_y", "", "body axis 3, inertial y"),
    ("axis_z", "", "body axis 3, inertial z"),
    ("energy", "J", "total energy, translation, rotation and M g z"),
    ("com_x", "m", "centre of mass, x"),
    ("com_y", "m", "centre of mass, y"),
    ("com_z", "m", "centre of mass, height"),
    ("contact_x", "m", "contact point, x"),
    ("contact_y", "m", "contact point, y"),
    ("contact_z", "m", "contact point, height (0 while touching)"),
    ("normal_force", "N", "normal force of the plane"),
    ("slip_speed", "m/s", "slip speed of the contact point"),
    ("gap", "m", "height of the contact point above the plane"),
    ("p_alpha", "kg m^2/s", "vertical angular momentum about the centre of mass"),
    ("p_gamma", "kg m^2/s", "I3 omega3"),
)
#: The units of the integrals.
INTEGRAL_UNITS = {"energy": "J", "p_alpha": "kg m^2/s", "p_gamma": "kg m^2/s",
                  "jellett": "kg m^3/s", "routh": "kg m^2/s"}
_START = ("alpha", "beta", "gamma", "omega1", "omega2", "omega3", "vx", "vy")
_START_UNITS = ("rad", "rad", "rad", "rad/s", "rad/s", "rad/s", "m/s", "m/s")


def _used(b: ce.ContactBundle) -> list[int]:
    """The parameters the scene's shape and law read (μ only with friction, ε only regularised,
    the radius not for a point)."""
    law = LAWS[b.scene.law]
    skip = set()
    if b.scene.friction not in ("coulomb", "viscous"):
        skip.add("mu")
    if law.name != "coulomb_regularized":
        skip.add("epsilon")
    if b.scene.shape == "point":
        skip.add("r")
    skip.update(e.param for e in EXTENSIONS.values() if b.scene.friction not in e.frictions)
    return [k for k, n in enumerate(ce.param_names(b.scene)) if n not in skip]


def variables(b: ce.ContactBundle) -> list[Var]:
    """The FMU's variables in value-reference order: parameters, start, settings, outputs."""
    sc, out = b.scene, []

    def add(name, kind, index, type_, causality, variability, initial, start, unit, doc):
        out.append(Var(name, len(out), kind, index, type_, causality, variability, initial,
                       start, unit if unit in UNITS else "", doc))

    p, names = ce.run_params(sc), ce.param_names(sc)
    for k in _used(b):
        n = names[k]
        unit = "N s/m" if n == "mu" and sc.friction == "viscous" else ce.PARAM_UNITS[n]
        add(ce.PARAM_KEYS[n], "V_PARAM", k, "Real", "parameter", "fixed", "exact", c_double(p[k]),
            unit, f"model parameter {n}")
    start = [*sc.angles, *ce.start_omega(sc), sc.vx, sc.vy]
    for k, (n, unit) in enumerate(zip(_START, _START_UNITS)):
        if n in ("vx", "vy") and sc.friction == "rolling":
            continue  # the no-slip condition sets it
        add(f"initial.{n}", "V_INPUT", k, "Real", "parameter", "fixed", "exact", c_double(start[k]),
            unit, f"start value {n}")
    add("contact.restitution", "V_SETTING", 0, "Real", "parameter", "fixed", "exact",
        c_double(sc.restitution), "", "restitution of a landing")
    add("simulate.rtol", "V_SETTING", 1, "Real", "parameter", "fixed", "exact", c_double(sc.rtol),
        "", "relative tolerance")
    add("simulate.atol", "V_SETTING", 2, "Real", "parameter", "fixed", "exact", c_double(sc.atol),
        "", "absolute tolerance")
    add("simulate.max_steps", "V_ISETTING", 3, "Integer", "parameter", "fixed", "exact",
        str(sc.max_steps), "", "step budget of each communication step")
    rows = list(OUTPUTS) + [(f"integral_{n}", INTEGRAL_UNITS[n], f"the integral {n}")
                            for n, _ in ce.integral_outputs(sc)]
    for k, (n, unit, doc) in enumerate(rows):
        add(n, "V_OUTPUT", k, "Real", "output", "continuous", "calculated", None, unit, doc)
    add("phase", "V_IOUTPUT", 0, "Integer", "output", "discrete", "calculated", None, "",
        "the phase: 0 slide, 1 roll, 2 flight")
    add("switches", "V_IOUTPUT", 1, "Integer", "output", "discrete", "calculated", None, "",
        "phase switches so far")
    return out


def sources(b: ce.ContactBundle) -> tuple[dict[str, str], str]:
    """(the FMU's ``sources/`` files, modelDescription.xml)."""
    sc, P, ID = b.scene, b.name, model_identifier(b)
    out = ce.model_files(sc)
    out[f"{P}_lib.c"] = driver.lib_source(sc.shape, sc.law, sc.stem is not None)
    for name in HEADERS:
        out[name] = (TEMPLATES / "fmi2" / name).read_text(encoding="utf-8")
    out["NOTICE.md"] = render("contact/NOTICE.md.j2", loop=ce.ck.LOOP, fmi=True)
    vs = variables(b)
    fmu_guid = guid(sorted(out.items()), [(v.name, v.start) for v in vs])
    start = [*sc.angles, *ce.start_omega(sc), sc.vx, sc.vy]
    integrals = ce.integral_outputs(sc)
    out["fmu.c"] = render(
        "contact/fmu.c.j2", P=P, ID=ID, guid=fmu_guid, variables=vs,
        p_start=[c_double(x) for x in ce.run_params(sc)], in_start=[c_double(x) for x in start],
        set_start=[c_double(x) for x in (sc.restitution, sc.rtol, sc.atol, sc.max_steps)],
        n_out=len(OUTPUTS) + len(integrals), integrals=integrals, max_switches=driver.MAX_SWITCHES)
    xml = model_description(
        "contact/modelDescription.xml.j2", vs, model_name=" ".join((sc.title or "").split()) or P,
        ID=ID, guid=fmu_guid,
        description=f"{P} (a top on a table: {sc.shape}, {LAWS[sc.law].description}) with the "
                    f"phase driver, exported by derive",
        t_end=c_double(sc.t_end), step=c_double(sc.t_end / (sc.samples - 1)), tolerance=c_double(sc.rtol))
    return out, xml
