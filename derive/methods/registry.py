"""Integration methods: the registry of tableaux and drivers (rendered into C by :mod:`derive.codegen.solvers`).

A method is a :class:`~derive.methods.tableaux.Tableau` plus the *driver* that runs it:

``adaptive``  explicit embedded pair, step-size control (Hairer's DOP853 controller), dense
              output at the requested times — ``(rtol, atol, h0, max_steps)``
``fixed``     explicit, each output interval split into ``ceil(dt/h)`` equal steps — ``(h,)``
``implicit``  fully implicit (Gauss–Legendre), fixed steps as above, simplified Newton with the
              model's Jacobian — ``(h, newton_tol, newton_maxiter)``
``taylor``    Taylor series of the model's expression graph, order and step from the tolerance
              (Jorba–Zou), dense output from the series — ``(rtol, atol, max_steps)``; no
              tableau: the method is its order policy (:mod:`derive.methods.taylor`)

Adding a Runge–Kutta method adds a tableau and one :data:`METHODS` entry;
``templates/c/solvers.c.j2`` renders every entry through the same stepper code. The splittings
(:mod:`derive.methods.splitting`) and the Taylor methods (:mod:`derive.methods.taylor`) are
registries of their own, with their own templates, merged by :func:`compiled_methods`. The generated C API (``<prefix>_solvers.h``)
is, for each method ``m`` and model prefix ``M``::

    int M_run_m(const derive_saveat *save, long n_batch, const double *ins, double *ps,
                <driver parameters>, double *y, double *out, derive_stats *st);

(``derive_saveat`` of ``derive_runtime.h``: which times and which outputs to save).
"""
from __future__ import annotations

from types import MappingProxyType
from dataclasses import dataclass
from typing import NamedTuple

from derive.methods.tableaux import DOP853, GAUSS4, GAUSS6, RK4, Tableau
from derive.methods import splitting
from derive.methods.taylor import METHODS as TAYLOR
from derive.symbolic.formulations import UNIVERSAL

# Each driver's extra C parameters, in order: (C type, name). Used by the header template and by
# derive.runtime.integrate for the ctypes signatures, so the two cannot disagree.
DRIVER_PARAMS: dict[str, tuple[tuple[str, str], ...]] = {
    "adaptive": (("double", "rtol"), ("double", "atol"), ("double", "h0"), ("long", "max_steps")),
    "fixed": (("double", "h"),),
    "implicit": (("double", "h"), ("double", "newton_tol"), ("int", "newton_maxiter")),
    "taylor": (("double", "rtol"), ("double", "atol"), ("long", "max_steps")),
}

#: The drivers that step by a tolerance (rtol, atol, max_steps) rather than a given step h.
TOLERANCE_DRIVERS = ("adaptive", "taylor")

@dataclass(frozen=True)
class Method:
    """A registered integration method: what runs (tableau) and how (driver)."""

    name: str
    tableau: Tableau
    driver: str
    summary: str

    def __post_init__(self):
        if self.driver not in DRIVER_PARAMS:
            raise ValueError(f"unknown driver {self.driver!r}")
        if self.driver == "adaptive" and not self.tableau.adaptive:
            raise ValueError(f"{self.name}: adaptive driver needs error-estimator weights")
        if (self.driver == "implicit") != self.tableau.implicit:
            raise ValueError(f"{self.name}: implicit tableaux need the implicit driver")

    @property
    def params(self) -> tuple[tuple[str, str], ...]:
        return DRIVER_PARAMS[self.driver]

    @property
    def measure_window(self) -> str | None:
        """What a sweep's measures search on (:func:`measure_window`): ``"stages"``, the dense
        polynomial of an adaptive pair formed from its stages; None for a fixed-step or an
        implicit method (no dense output between its steps that follows the tolerance)."""
        return "stages" if self.driver == "adaptive" and self.tableau.dense else None


METHODS: dict[str, Method] = {m.name: m for m in (
    Method("dop853", DOP853, "adaptive",
           "Dormand-Prince 8(5,3), adaptive step, order-7 dense output (Hairer's DOP853)"),
    Method("rk4", RK4, "fixed", "classical Runge-Kutta, order 4, fixed step"),
    Method("gauss4", GAUSS4, "implicit",
           "Gauss-Legendre, 2 stages, order 4, symplectic, fixed step"),
    Method("gauss6", GAUSS6, "implicit",
           "Gauss-Legendre, 3 stages, order 6, symplectic, fixed step"),
    Method("dop853_fixed", DOP853, "fixed",
           "DOP853's order-8 formula on fixed steps, no error control (reference runs)"),
)}

#: The method "auto" runs unless the cost model (:mod:`derive.methods.costs`) finds a Taylor
#: method cheaper, and always where the model has no Taylor kernel: adaptive, any tolerance,
#: dense output.
DEFAULT_METHOD = "dop853"

#: Methods run by SciPy's solve_ivp on the generated NumPy right-hand side (references for
#: comparison, not the fast path): scene name -> (solve_ivp method, one-line description).
REFERENCE_METHODS: dict[str, tuple[str, str]] = {
    "scipy-rk45": ("RK45", "scipy.integrate.solve_ivp RK45 (reference)"),
    "scipy-dop853": ("DOP853", "scipy.integrate.solve_ivp DOP853 (reference)"),
    "scipy-radau": ("Radau", "scipy.integrate.solve_ivp Radau, implicit (reference)"),
    "scipy-lsoda": ("LSODA", "scipy.integrate.solve_ivp LSODA, stiffness switching (reference)"),
}

#: Methods hidden from scenes (reference runs of the benchmarks and tests).
INTERNAL_METHODS = ("dop853_fixed",)


_COMPILED = MappingProxyType({**METHODS, **splitting.METHODS, **TAYLOR})


def compiled_methods() -> dict:
    """Every compiled method: the Runge–Kutta family rendered from tableaux (:data:`METHODS`),
    the Lie–Poisson splittings of :mod:`derive.methods.splitting` and the Taylor methods of
    :mod:`derive.methods.taylor` (each their own template). Each entry has ``name``,
    ``summary``, ``driver`` and ``params`` (the C parameters after ``n_out``)."""
    return _COMPILED


def method(name: str):
    """The compiled method called ``name`` (KeyError if there is none)."""
    return compiled_methods()[name]


def tolerance_driven(name: str) -> bool:
    """True when the compiled method ``name`` steps by a tolerance (rtol, atol, max_steps), not by
    a given step h."""
    return compiled_methods()[name].driver in TOLERANCE_DRIVERS


def measure_window(name: str) -> str | None:
    """The flavour of the sweep measures' window for the compiled method ``name``
    (``templates/c/measures.c.j2``): what its dense output between step ends is evaluated from,
    as the method's family declares it — ``"stages"`` (an adaptive Runge–Kutta pair's dense
    polynomial, formed from the step's stages where a search reads it), ``"series"`` (a Taylor
    step's series, the solver's own) — or None: the method cannot run a sweep's measures.

    Parameters
    ----------
    name : str
        A compiled method (:func:`compiled_methods`).

    Returns
    -------
    str or None
    """
    return getattr(compiled_methods()[name], "measure_window", None)


def build(name: str | None) -> str:
    """The library build the compiled method ``name`` runs in, as its family declares it
    (:data:`derive.runtime.cbuild.BUILDS`): ``"vector"`` (this CPU's vector width, the same
    numbers: the Taylor methods, whose output map over a step's samples vectorises) or
    ``"portable"`` (the others, and the model's own library: ``name`` None)."""
    return "portable" if name is None else getattr(compiled_methods()[name], "build", "portable")


def method_reason(name: str, formulation: str, effects) -> str | None:
    """None if the compiled method ``name`` can run that formulation with those effects, else
    why not ("auto" as the formulation: can any formulation)."""
    if name not in splitting.METHODS:
        return None
    from types import SimpleNamespace

    form = UNIVERSAL if formulation == "auto" else formulation
    return splitting.applicable(SimpleNamespace(formulation=form, effects=tuple(effects)))


def scene_methods() -> dict[str, str]:
    """What a scene's ``simulate.method`` may name: "auto", the compiled methods, the SciPy
    references; name -> one-line description."""
    out = {"auto": f"let derive choose: {DEFAULT_METHOD} or a Taylor method, whichever a cost model of "
                   f"the model, the tolerance, the samples and the span finds cheaper "
                   f"(derive.methods.costs)"}
    out.update({name: m.summary for name, m in compiled_methods().items()
                if name not in INTERNAL_METHODS})
    out.update({name: text for name, (_, text) in REFERENCE_METHODS.items()})
    return out


def fixed_step_methods() -> tuple[str, ...]:
    """The compiled methods that take a fixed step h."""
    return tuple(name for name, m in compiled_methods().items()
                 if m.driver not in TOLERANCE_DRIVERS and name not in INTERNAL_METHODS)


# ---------------------------------------------------------------------------------------------
# the least work of each tolerance-driven method (read by derive.methods.costs.least_steps)


class StepLaw(NamedTuple):
    """How many steps a tolerance-driven method takes at the least, per radian of the fastest
    motion: ``k · s · ε^(−1/(q+1))`` for an embedded pair with error order ``q``, and
    ``k · s · (1 + A/p)`` for a Taylor method of order ``p`` (``q`` None)."""

    k: float
    q: int | None


#: The least steps each tolerance-driven method takes (keys: scene method names). ``k`` is half
#: the smallest constant fitted to the step counts of the example scenes (:data:`STEP_CALIBRATION`):
#: the span ``s`` over-counts a motion whose fastest part a formulation integrates in closed form
#: (the spin of a reduced top), so the law is a floor, and a run below it is refused only when
#: even the floor exceeds the budget.
STEP_LAWS: dict[str, StepLaw] = {
    "dop853": StepLaw(0.003, 7),
    "taylor": StepLaw(0.02, None),
    "scipy-rk45": StepLaw(0.0015, 4),
    "scipy-dop853": StepLaw(0.003, 7),
    "scipy-radau": StepLaw(0.004, 3),
    "scipy-lsoda": StepLaw(0.05, 11),
}

STEP_CALIBRATION = ("steps of each method on every example scene at its own tolerance (SciPy's "
                    "over t ∈ [0, 0.5]), against t_end × the fastest rate; the smallest constant "
                    "seen halved")
