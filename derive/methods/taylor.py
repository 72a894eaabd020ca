"""Taylor-series integrators: the method as data (its driver and its order policy).

A Taylor method has no tableau. Each step expands the solution about the current point,

    y(t + τ) = Σ_{n=0}^{p} y_n τⁿ,     y_{n+1} = f(t, y)_n / (n + 1),

with the coefficients of the right-hand side f from the recurrences of automatic
differentiation, one rule per elementary function of the model's expression graph
(:mod:`derive.codegen.jet`, rendered by ``templates/c/taylor.c.j2``), and evaluates the series
at the step's end and at every requested output time inside the step (dense output is the
series itself).

Order and step follow Jorba & Zou, Experiment. Math. 14 (2005) 99, as heyoka does:

* the order from the tolerance ε (``rtol``; ``atol`` when ``rtol`` is 0):
  p = ⌈−ln(ε)/2⌉ + 1, clamped to [:attr:`TaylorMethod.min_order`, :attr:`TaylorMethod.max_order`];
* the step from the last two coefficients, with S = max(‖y‖∞, atol/rtol) (S = 1 when rtol = 0):

      ρ = min( (S/‖y_{p−1}‖∞)^{1/(p−1)}, (S/‖y_p‖∞)^{1/p} ),   h = ρ e⁻² · exp(−0.7/(p − 1)),

  so the truncation error ‖y_p‖ hᵖ ≲ S e⁻²ᵖ ≤ e⁻² max(rtol ‖y‖∞, atol) per step.

S is per state: the states that feed something back are held to their own size; a state that
feeds nothing back (a cyclic angle, a quadrature; :func:`derive.codegen.jet.controlled_states`)
to the size of its rate, max(|y_{i,1}|, atol/rtol): its truncation error is controlled, and its
growth never loosens the tolerance of everything else.

Driver ``taylor``: its C parameters are ``(rtol, atol, max_steps)``
(:data:`derive.methods.registry.DRIVER_PARAMS`). The generated C API (``<prefix>_taylor.h``) is
that of the adaptive solvers, plus the coefficients themselves::

    int M_taylor_coefficients(double t, const double *y, const double *p, int order,
                              double *c);      /* c[i*(order+1) + n] = y_i,n */
    int M_run_taylor(const derive_saveat *save, long n_batch, const double *ins, double *ps,
                     double rtol, double atol, long max_steps, double *y, double *out,
                     derive_stats *st);
"""
from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class TaylorMethod:
    """A registered Taylor method: the order policy of Jorba & Zou and the bounds of the order.

    ``max_order`` is the compile-time size of the coefficient arrays (the runtime order never
    exceeds it); ``safety`` is heyoka's factor exp(−0.7/(p − 1)) applied as
    ``exp(-safety / (p - 1))``."""

    name: str
    summary: str
    min_order: int = 2
    max_order: int = 30
    safety: float = 0.7
    driver: str = "taylor"
    #: The library build its drivers run in (:data:`derive.runtime.cbuild.BUILDS`): this CPU's
    #: vector width, for the output map over a step's block of samples (same numbers).
    build: str = "vector"

    def __post_init__(self):
        if not 2 <= self.min_order <= self.max_order:
            raise ValueError(f"{self.name}: need 2 <= min_order <= max_order")

    @property
    def params(self) -> tuple[tuple[str, str], ...]:
        return (("double", "rtol"), ("double", "atol"), ("long", "max_steps"))

    @property
    def measure_window(self) -> str:
        """What a sweep's measures search on (:func:`derive.methods.registry.measure_window`):
        the step's series, the dense output the solver has anyway."""
        return "series"

    def order(self, rtol: float, atol: float) -> int:
        """The order the C driver takes for these tolerances (the same formula, in Python)."""
        eps = rtol if rtol > 0 else atol
        p = math.ceil(-math.log(eps) / 2.0) + 1
        return min(max(p, self.min_order), self.max_order)


METHODS: dict[str, TaylorMethod] = {m.name: m for m in (
    TaylorMethod("taylor", "Taylor series from the model's expression graph, order and step from the "
                 "tolerance (Jorba-Zou), dense output from the series"),
)}
