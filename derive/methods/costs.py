"""What a run will cost before it starts: the cost model behind ``method = "auto"`` (which of the
compiled tolerance-driven methods is cheaper), and the floor on a run's steps
(:func:`least_steps`, :data:`STEP_LAWS`) by which a run its step budget cannot cover is refused
up front (:func:`over_budget`, asked where a plan is made).

A run's time is its steps times the work per step plus its samples times the work per sample,
in the units of the kernel spec's operation count (:data:`derive.codegen.kernelspec.OP_WEIGHTS`,
roughly cycles). For a model with right-hand-side cost ``c_f`` (the description's ``cost``:
operations plus the stepper's work per state), Taylor-jet weight ``w`` (the description's
``jet_weight``: for each series node of the decomposition the multiply-adds of its rule per
term of a Cauchy sum, :func:`derive.codegen.jet.jet_weight`), ``ny`` states and ``n_out``
outputs, over a span of ``s`` radians of the fastest natural motion (``t_end`` times the
fastest rate the scene sets, see :func:`derive.sim.inputs.fastest_rate`):

``dop853``  steps ≈ K_D s ε^(−1/8) (an order-8 error per step), each 12 right-hand sides;
            per sample the order-7 interpolant (7 ny) and the output map ``c_out``:

                cost = K_D s ε^(−1/8) · 12 c_f + n (7 ny + c_out)

``taylor``  order p = ⌈−ln ε / 2⌉ + 1 (:class:`derive.methods.taylor.TaylorMethod`); the
            Jorba–Zou step is a fraction of the series' radius of convergence that grows with
            the order, so the steps fall slowly with ε: steps ≈ K_T s (1 + A/p); the jet costs
            w p²/2 multiply-adds plus the step control and the states' evaluation (2 ny p), each
            ``TAYLOR_UNIT`` operation units (the recurrences' loops and loads), and a step
            ``TAYLOR_STEP`` units more (the order-0 libm calls, the norms, the step size);
            per sample the states by Horner (ny p, four samples' chains side by side: a
            fraction ``TAYLOR_SAMPLE`` of that) and the output map over a block of samples
            (one vectorised loop, the cyclic angles' sines from arithmetic: a fraction
            ``TAYLOR_OUTPUT`` of ``c_out``):

                cost = K_T s (1 + A/p) · (TAYLOR_UNIT (w p²/2 + 2 ny p) + TAYLOR_STEP)
                       + n (TAYLOR_SAMPLE ny p + TAYLOR_OUTPUT c_out)

ε is ``rtol`` (``atol`` when ``rtol`` is 0). ``K_D`` and ``K_T`` are fitted to measured step
counts (:data:`CALIBRATION` says on what); only the comparison of the two costs is used, and
``derive bench`` checks it (:mod:`derive.bench.autochoice`: on scenes of different shapes and
tolerances, does auto pick the faster method?).
"""
from __future__ import annotations

import functools
import math
from typing import NamedTuple

from derive.methods.registry import DEFAULT_METHOD, METHODS as RUNGE_KUTTA, STEP_LAWS
from derive.methods.taylor import METHODS as TAYLOR

#: Steps per radian of the fastest motion: DOP853 at ε = 1 (scaled by ε^(−1/8)), the Taylor
#: method's (scaled by 1 + A/p); the time of a jet's operation unit against the right-hand
#: side's, a Taylor step's fixed work, the share of a sample's Horner scheme that costs (the
#: samples of a step are evaluated four at a time), and the share of the output map's cost a
#: Taylor sample pays (the map runs over a block in one vectorised loop). K_D, K_T, A are fitted
#: to step counts, the Taylor constants to the times of ``derive.bench.autochoice``
#: (:data:`CALIBRATION`), which the bench re-measures on every run (docs/bench/).
K_D = 0.062
K_T = 0.32
A = 12.5
TAYLOR_UNIT = 3.0
TAYLOR_STEP = 700.0
TAYLOR_SAMPLE = 0.25
TAYLOR_OUTPUT = 0.7

CALIBRATION = ("step counts of dop853 and taylor on reference_top, off_axis_top, damped_top, "
               "tennis_racket, looping_top, sleeping_top, kovalevskaya_top at rtol 1e-6, 1e-8, "
               "1e-10, 1e-12 (auto's formulation, atol = rtol/100); the unit from the times of "
               "heavy_top and reduced_u_sym_gravity per step")

#: The methods "auto" chooses between: the default (an adaptive Runge–Kutta pair) first, taken
#: on a tie and whenever the model has no Taylor kernel, then the Taylor methods.
CHOICES = (DEFAULT_METHOD, *TAYLOR)


class Work(NamedTuple):
    """What a run asks of a model: its costs (from the description) and the scene's numbers
    (a named tuple: made for every scene auto plans, at a third of a frozen dataclass's cost)."""

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
    rk = RUNGE_KUTTA.get(method)
    if rk is not None and rk.tableau.adaptive:
        # an embedded pair: the step goes as eps^(1/(q+1)), q its error order (DOP853: 7),
        # each costing its stages' right-hand sides; its dense output about `order` per state
        tab = rk.tableau
        steps = max(1.0, K_D * work.span * eps ** (-1.0 / ((tab.err_order or tab.order) + 1)))
        return steps * tab.stages * work.rhs_cost + n * ((tab.order - 1) * work.ny + work.output_cost)
    if method in TAYLOR:
        if work.jet_weight <= 0:
            return math.inf
        p = TAYLOR[method].order(rtol, atol)
        steps = max(1.0, K_T * work.span * (1.0 + A / p))
        jet = TAYLOR_UNIT * (work.jet_weight * p * p / 2.0 + 2.0 * work.ny * p) + TAYLOR_STEP
        return steps * jet + n * (TAYLOR_SAMPLE * work.ny * p + TAYLOR_OUTPUT * work.output_cost)
    return math.inf  # a fixed-step or implicit method: not weighed by tolerance


@functools.lru_cache(maxsize=1024)
def choose(work: Work, rtol: float, atol: float) -> str:
    """The method of :data:`CHOICES` with the least modelled cost (the first on a tie).
    Cached: a scan of one scene's numbers asks the same question every call."""
    return min(CHOICES, key=lambda m: (cost(m, work, rtol, atol), CHOICES.index(m)))


# ---------------------------------------------------------------------------------------------
# the work a run needs, before it starts


def least_steps(method: str, span: float, rtol: float, atol: float) -> float:
    """The fewest steps a run of ``method`` over ``span`` radians of its fastest motion can take.

    ``k s ε^(−1/(q+1))`` (an embedded pair of error order q) or ``k s (1 + A/p)`` (a Taylor
    method of order p, :meth:`derive.methods.taylor.TaylorMethod.order`), with ε = rtol (atol
    when rtol is 0) and k, q from :data:`STEP_LAWS`.

    Parameters
    ----------
    method : str
        A scene method name (``"dop853"``, ``"taylor"``, ``"scipy-rk45"``, ...).
    span : float
        ``t_end`` times the scene's fastest natural rate, radians.
    rtol, atol : float
        The run's tolerances.

    Returns
    -------
    float
        The floor on the steps; 0 for a method without a law (a fixed step counts its steps
        exactly, :func:`derive.sim.inputs.fixed_steps`).
    """
    law = STEP_LAWS.get(method)
    if law is None or not span > 0:
        return 0.0
    if law.q is None:
        return law.k * span * (1.0 + A / TAYLOR[method].order(rtol, atol))
    eps = rtol if rtol > 0 else atol
    return law.k * span * eps ** (-1.0 / (law.q + 1))


def over_budget(method: str, span: float, rtol: float, atol: float, max_steps: int) -> str | None:
    """Why a run cannot finish within its step budget, said before it starts, or None when it may.

    Parameters
    ----------
    method : str
        The method that will run.
    span : float
        ``t_end`` times the fastest natural rate, radians.
    rtol, atol : float
        The run's tolerances.
    max_steps : int
        The step budget (``[simulate] max_steps``).

    Returns
    -------
    str or None
        ``"<method> needs at least about N steps ..., more than simulate.max_steps = M; ..."``
        when :func:`least_steps` exceeds ``max_steps``.
    """
    steps = least_steps(method, span, rtol, atol)
    if steps <= max_steps:
        return None
    return (f"{method} needs at least about {steps:.2g} steps (t_end × the fastest rate = "
            f"{span:.3g} rad at rtol {rtol:g}), more than simulate.max_steps = {max_steps}; "
            f"raise it ([simulate] max_steps or --max-steps, up to 1e12), loosen the tolerances, "
            f"or shorten t_end")
