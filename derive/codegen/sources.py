"""Render a model through the templates into its source files.

model (symbolic) → KernelSpec (layout + CSE) → templates/ → {relative path: text}

:func:`model_sources` gives one model's C, NumPy and JSON description; :func:`shipped_keys` the
models the package ships in ``generated/`` (written by :mod:`derive.generate`). Nothing here
reads the clock or iterates over unordered collections, so two runs produce identical bytes.
"""
from __future__ import annotations

import functools
import json

from derive.codegen.jet import NoTaylorRule, jet_weight
from derive.codegen.kernelspec import STEP_COST_PER_STATE, KernelSpec, operation_cost
from derive.codegen.render import render
from derive.codegen.solvers import render_solvers
from derive.codegen.splitting import render_splitting
from derive.codegen.taylor import render_taylor
from derive.methods.splitting import applicable as splitting_applicable
from derive.symbolic.formulations import INPUT_NAMES, POLE_CLEARANCE, REGISTRY as FORMULATIONS, model_name
from derive.symbolic.integrable import C_INTEGRALS, C_PARAMS, c_code
from derive.symbolic.models import CATALOGUE_KEYS, Model


#: (formulation, symmetric, effects) of the models written to generated/ besides the contract's
#: catalogue: the ones the example scenes and the common scene shapes run, so that a warm
#: `derive simulate` of any of them needs no derivation.
SHIPPED = (
    ("euler-angles", True, ()),
    ("reduced", True, ()),
    ("reduced-u", True, ("gravity",)),
    ("reduced-u", True, ()),
    ("euler-poisson", False, ()),
    ("euler-poisson", True, ()),
    ("euler-poisson", True, ("gravity",)),
    ("euler-poisson", True, ("gravity", "damping")),
    ("euler-poisson", True, ("gravity_general",)),
    ("euler-poisson", False, ("gravity_general",)),
)


def description_json(spec) -> str:
    """The JSON description of a model from its kernel spec (``models/<name>.json``, read back by :class:`derive.runtime.catalogue.Description`)."""
    m = spec.model
    return json.dumps({
        "name": m.name, "formulation": m.formulation, "symmetric": m.symmetric,
        "effects": list(m.effects), "states": list(m.state_names), "params": list(m.param_names),
        "outputs": list(spec.observable_names), "nin": len(INPUT_NAMES),
        "cost": spec.cost + STEP_COST_PER_STATE * len(m.states),
        "jet_weight": jet_weight(spec), "output_cost": operation_cost(spec.obs),
        "derived_params": list(spec.init_param_index), "checks": list(spec.check_names),
        "has_angles": spec.observable_names[:3] == ("alpha", "beta", "gamma"),
        "domain_note": m.domain_note,
    }, indent=1, sort_keys=True) + "\n"


def _clearance(formulation: str) -> float:
    """The |sin β| a formulation's pole check keeps (the registry's; the default for a model
    outside it, e.g. Euler's equations, whose check answers 0 anyway)."""
    f = FORMULATIONS.get(formulation)
    return f.clearance if f is not None else POLE_CLEARANCE


def model_sources(model: Model) -> dict[str, str]:
    """C header, C source and NumPy module of one model, plus its C solver kernels (the
    Runge–Kutta family, the splittings where they apply, the Taylor methods where every
    function of the right-hand side has a rule)."""
    spec = KernelSpec.of(model)
    c_ctx, np_ctx = spec.context("c"), spec.context("numpy")
    files = {
        f"c/{model.name}.h": render("c/model.h.j2", **c_ctx),
        f"c/{model.name}.c": render("c/model.c.j2", **c_ctx),
        f"numpy/{model.name}.py": render("numpy/model.py.j2", **np_ctx),
    }
    for fname, text in render_solvers(model.name, len(model.states), has_angles=c_ctx["has_angles"],
                                      pole_clearance=_clearance(model.formulation)).items():
        files[f"c/{fname}"] = text
    if splitting_applicable(model) is None:
        files.update({f"c/{k}": v for k, v in render_splitting(model).items()})
    try:  # every model whose right-hand side has a Taylor rule for each function in it
        files.update({f"c/{k}": v for k, v in render_taylor(model, spec=spec).items()})
    except NoTaylorRule:
        pass
    files[f"models/{model.name}.json"] = description_json(spec)
    files["c/derive_integrals.h"] = integrals_header()  # the measures' integrals (one file for every model)
    return files


def shipped_keys() -> dict[str, tuple]:
    """{model name: key} of every model written to generated/: the contract's catalogue, then
    the models the example scenes run (`catalogue.SHIPPED`)."""
    keys = dict(CATALOGUE_KEYS)
    for key in SHIPPED:
        keys.setdefault(model_name(*key), key)
    return keys


@functools.lru_cache(maxsize=1)
def integrals_header() -> str:
    """``derive_integrals.h``: the extra integrals of
    :data:`derive.symbolic.integrable.C_INTEGRALS` as one C function."""
    entries = [{"name": i.name, "expression": i.expression, "code": k + 1,
                "value": v, "scale": s} for k, i in enumerate(C_INTEGRALS) for v, s in [c_code(i)]]
    return render("c/integrals.h.j2", integrals=entries, params=C_PARAMS)
