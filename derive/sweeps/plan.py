"""Which formulations and method a sweep runs: the candidates of ``formulation = "auto"`` for a
model's structure and the methods that can measure on their dense output.

Takes: a model's structure (body symmetry, effects) and a method. Gives: the candidates.
"""
from __future__ import annotations

from derive.methods.registry import INTERNAL_METHODS, compiled_methods, measure_window
from derive.runtime import catalogue
from derive.sim import auto
from derive.symbolic.formulations import REGISTRY as FORMS


def measuring_methods() -> tuple[str, ...]:
    """The methods a sweep can run: those with a measure window
    (:func:`derive.methods.registry.measure_window`), scene-visible ones only.

    Returns
    -------
    tuple of str
        Their names, in the registry's order (``("dop853", "taylor")``).
    """
    return tuple(m for m in compiled_methods() if m not in INTERNAL_METHODS and measure_window(m))


def sweep_plan(symmetric: bool, effects: tuple, method: str) -> tuple:
    """The formulations a sweep of formulation "auto" tries per point, cheapest first, each
    with the pole check its C driver runs on the start: ((formulation, pole check), ...), the
    last one without a singular set (check 0: it takes every point).

    They are the candidates of :func:`derive.sim.auto.plan` for the model's structure (body
    symmetry, effects, method; a point's start is judged by the compiled check, per point),
    except:

    * a formulation whose accuracy near a pole is judged after the run from the sampled beta
      (``pole_loss``: euler-angles) is left out: a sweep keeps no samples to judge it on, so a
      point refused by the first candidate runs the universal one instead;
    * a singular formulation is tried only when its model exists (generated or cached): the
      plan must not cost a derivation in SymPy;
    * the check of mode 2 (the reduced equations may meet a pole where they stay regular) is
      made mode 1 (clear of both poles): a start at a pole, which ``derive.simulate`` refuses
      for those formulations up front, cannot then reach their integration.
    """
    out = []
    for name, mode in auto.structural(symmetric, effects, method):
        if not mode:
            out.append((name, 0))
            break
        if FORMS[name].pole_loss or catalogue.available((name, symmetric, effects)) is None:
            continue
        out.append((name, 1))
    return tuple(out)
