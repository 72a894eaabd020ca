"""The dotted scene keys a sweep may vary (``initial.beta``, ``gravity.M``, ``initial.omega.1``, …)
with their tables and units, from the effects registry; and the params of the user's terms,
``potential.<name>.<param>`` / ``torque.<name>.<param>`` (:func:`term_key`), which depend on
the scene (their units are the user's business)."""
from __future__ import annotations

from derive.contact.scene import GRAVITY
from derive.symbolic import effects
from derive.symbolic.effects import USER_TABLES


def variable_keys() -> dict:
    """{dotted key: (table, key, index or None, unit)} of everything a point may vary."""
    out = {f"body.{k}": ("body", k, None, "kg m^2") for k in ("I1", "I2", "I3")}
    for name in ("alpha", "beta", "gamma"):
        out[f"initial.{name}"] = ("initial", name, None, "rad")
    for name in ("alpha_dot", "beta_dot", "gamma_dot"):
        out[f"initial.{name}"] = ("initial", name, None, "rad/s")
    for i in range(3):
        out[f"initial.omega.{i}"] = ("initial", "omega", i, "rad/s")
    for tname, table in effects.TABLES.items():
        for key in table.keys:
            if key.kind == "real":
                out[f"{tname}.{key.name}"] = (tname, key.name, None, key.unit)
    return out


def contact_keys() -> dict:
    """{dotted key: (table, key, index or None, unit)} of what a point of a sweep over a top on
    a table (a ``[contact]`` scene) may vary."""
    out = {k: v for k, v in variable_keys().items() if k.startswith(("body.", "initial."))}
    out.update({f"{GRAVITY}.M": (GRAVITY, "M", None, "kg"), f"{GRAVITY}.g": (GRAVITY, "g", None, "m/s^2")})
    for name, unit in (("radius", "m"), ("offset", "m"), ("mu", ""), ("regularization", "m/s"),
                       ("restitution", "")):
        out[f"contact.{name}"] = ("contact", name, None, unit)
    for name in ("vx", "vy"):
        out[f"initial.{name}"] = ("initial", name, None, "m/s")
    return out


def unit_of(key: str) -> str:
    """The SI unit of a dotted scene key a sweep may vary ('' if it has none)."""
    found = variable_keys().get(key) or contact_keys().get(key)
    return found[3] if found else ""


def term_key(key: str):
    """(kind, term name, param) of a user term's param key (``potential.magnet.mu``), else
    None."""
    parts = key.split(".")
    if len(parts) == 3 and parts[0] in USER_TABLES and all(parts):
        return tuple(parts)
    return None
