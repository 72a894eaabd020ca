"""What ``method = "auto"`` runs: a cost model of the compiled tolerance-driven methods.

A run's time is its steps times the work per step plus its samples times the work per sample,
in the units of the kernel spec's operation count (:data:`derive.codegen.kernelspec.OP_WEIGHTS`,
roughly cycles). For a model with right-hand-side cost ``c_f`` (the description's ``cost``:
operations plus the stepper's work per state), Taylor-jet weight ``w`` (the description's
``jet_weight``: for each series node of the decomposition the multiply-adds of its rule per
term of a Cauchy sum, :func:`derive.codegen.taylor.jet_weight`), ``ny`` states and ``n_out``
outputs, over a span of ``s`` radians of the fastest natural motion (``t_end`` times the
fastest rate the scene sets, see :func:`derive.sim.inputs.fastest_rate`):

``dop853``  steps ≈ K_D s ε^(−1/8) (an order-8 error per step), each 12 right-hand sides;
            per sample the order-7 interpolant (7 ny) and the output map ``c_out``:

                cost = K_D s ε^(−1/8) · 12 c_f + n (7 ny + c_out)

``taylor``  order p = ⌈−ln ε / 2⌉ + 1 (:class:`derive.methods.taylor.TaylorMethod`); the
            Jorba–Zou step is a fixed fraction of the series' radius of convergence, so the
            steps do not depend on ε: steps ≈ K_T s; the jet costs w p²/2 multiply-adds plus
            the step control and the evaluation of the states (2 ny p); per sample the
            outputs' series by Horner (n_out p):

                cost = K_T s (w p²/2 + 2 ny p) + n n_out p

ε is ``rtol`` (``atol`` when ``rtol`` is 0). ``K_D`` and ``K_T`` are fitted to measured step
counts (:data:`CALIBRATION` says on what); only the comparison of the two costs is used, and
``derive bench`` checks it (:mod:`derive.bench.autochoice`: on scenes of different shapes and
tolerances, does auto pick the faster method?).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from derive.methods.taylor import METHODS as TAYLOR

#: Steps per radian of the fastest motion: DOP853 at ε = 1 (scaled by ε^(−1/8)) and the Taylor
#: method (any ε). Fitted to the step counts of the example scenes (see the module docstring).
K_D = 0.07
K_T = 0.6

CALIBRATION = ("step counts of dop853 and taylor on reference_top, off_axis_top, damped_top, "
               "tennis_racket at rtol 1e-6 … 1e-12 (derive.bench.autochoice)")

#: The methods "auto" chooses between, the default first (taken on a tie, and whenever the
#: model has no Taylor kernel).
CHOICES = ("dop853", "taylor")


@dataclass(frozen=True)
class Work:
    """What a run asks of a model: its costs (from the description) and the scene's numbers."""

    rhs_cost: float        # c_f
    jet_weight: float      # w (0: the model has no Taylor kernel)
    output_cost: float     # c_out
    ny: int
    n_out: int
    samples: int
    span: float            # s: t_end × the fastest rate, radians


def cost(method: str, work: Work, rtol: float, atol: float) -> float:
    """The modelled cost of a run (operation-count units); ``inf`` for a method the model
    cannot run."""
    eps = rtol if rtol > 0 else atol
    n = work.samples
    if method == "dop853":
        steps = max(1.0, K_D * work.span * eps ** (-1.0 / 8.0))
        return steps * 12.0 * work.rhs_cost + n * (7.0 * work.ny + work.output_cost)
    if method in TAYLOR:
        if work.jet_weight <= 0:
            return math.inf
        p = TAYLOR[method].order(rtol, atol)
        steps = max(1.0, K_T * work.span)
        return steps * (work.jet_weight * p * p / 2.0 + 2.0 * work.ny * p) + n * work.n_out * p
    raise KeyError(method)


def choose(work: Work, rtol: float, atol: float) -> str:
    """The method of :data:`CHOICES` with the least modelled cost (the first on a tie)."""
    return min(CHOICES, key=lambda m: (cost(m, work, rtol, atol), CHOICES.index(m)))
