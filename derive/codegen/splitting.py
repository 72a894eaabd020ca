"""The Lie–Poisson splitting solvers of :mod:`derive.methods.splitting`, rendered into C.

``templates/c/splitting.{h,c}.j2`` receive each method's sequence of sub-flows (the exact free
flow and the gravity kick, :meth:`derive.methods.splitting.Splitting.ops`) and the model's
parameter layout; a body with three distinct moments also gets ``derive_elliptic.h`` (the C
port of :mod:`derive.reference.elliptic`, rendered from ``templates/c/elliptic.h.j2``).
"""
from __future__ import annotations

from derive.codegen.render import render
from derive.methods.splitting import _GRAVITY, METHODS, applicable


def _context(model, names) -> dict:
    why = applicable(model)
    if why:
        raise ValueError(why)
    pn = model.param_names
    idx = {name: pn.index(name) for name in pn}
    idx["I2"] = idx.get("I2", idx["I1"])  # symmetric body: I2 = I1
    gravity = _GRAVITY[model.effects[0]] if model.effects else "none"
    methods = []
    for name in names:
        m = METHODS[name]
        ops = [{"kind": k, "c": float(c)} for k, c in m.scheme.ops()]
        eps = " + ".join(f"eps{'^' + str(i + 1) if i else ''} h^{p}"
                         for i, p in enumerate(m.scheme.eps_orders))
        methods.append({"name": m.name, "summary": m.summary, "order": m.order,
                        "scheme": m.scheme.name, "form": "ABA" if ops[0]["kind"] == "free" else "BAB",
                        "stages": m.scheme.stages, "kicks": sum(op["kind"] == "kick" for op in ops),
                        "eps_note": f", error O({eps})" if eps else "",
                        "edge": ops[0], "inner": [op for op in ops[1:-1] if op["c"] != 0]})
    return {"prefix": model.name, "symmetric": model.symmetric, "gravity": gravity,
            "axial": model.symmetric and gravity == "axial",
            "idx": idx, "methods": methods, "omega_state": _omega_state(model)}


def _omega_state(model) -> bool:
    """True when the model's state starts with ω̃ (else with L = I ω̃)."""
    head = model.state_names[:3]
    if head not in (("omega1", "omega2", "omega3"), ("L1", "L2", "L3")):
        raise ValueError(f"{model.name}: expected the state to start with omega1:3 or L1:3")
    return head[0] == "omega1"


def render_splitting(model, methods: list[str] | None = None) -> dict[str, str]:
    """``<name>_splitting.h``, ``<name>_splitting.c`` and (three distinct moments) the shared
    ``derive_elliptic.h`` for an Euler–Poisson ``model``. The C includes ``<name>_solvers.h``
    (``derive_stats``, the ``DERIVE_*`` codes, the model header) and needs nothing else from
    the model: it reads the parameters by their names in ``model.param_names``."""
    names = list(METHODS) if methods is None else list(methods)
    for n in names:
        if n not in METHODS:
            raise ValueError(f"unknown splitting method {n!r}; known: {', '.join(METHODS)}")
    ctx = _context(model, names)
    files = {f"{model.name}_splitting.h": render("c/splitting.h.j2", **ctx),
             f"{model.name}_splitting.c": render("c/splitting.c.j2", **ctx)}
    if not model.symmetric:
        files["derive_elliptic.h"] = render("c/elliptic.h.j2")
    return files
