"""Integration methods: a registry of tableaux, rendered into C solver kernels.

A method is a :class:`~derive.tableaux.Tableau` plus the *driver* that runs it:

``adaptive``  explicit embedded pair, step-size control (Hairer's DOP853 controller), dense
              output at the requested times — ``(rtol, atol, h0, max_steps)``
``fixed``     explicit, each output interval split into ``ceil(dt/h)`` equal steps — ``(h,)``
``implicit``  fully implicit (Gauss–Legendre), fixed steps as above, simplified Newton with the
              model's Jacobian — ``(h, newton_tol, newton_maxiter)``

Adding a method adds a tableau and one :data:`METHODS` entry; ``templates/c/solvers.c.j2``
renders every entry through the same stepper code. The generated C API (``<prefix>_solvers.h``)
is, for each method ``m`` and model prefix ``M``::

    int M_solve_m(const double *y0, const double *p, const double *t_out, long n_out,
                  <driver parameters>, double *y_out, derive_stats *st);
    int M_solve_batch_m(long n_batch, const double *y0s, const double *ps,
                        const double *t_out, long n_out, <driver parameters>,
                        double *y_out, derive_stats *st);
"""
from __future__ import annotations

import functools

from dataclasses import dataclass
from fractions import Fraction

from .render import c_double, render
from .effects import VERSION as _EFFECTS_VERSION  # a list bumped in place
from .formulations import POLE_CLEARANCE
from .status import c_table
from .tableaux import DOP853, GAUSS4, GAUSS6, RK4, Tableau

# Each driver's extra C parameters, in order: (C type, name). Used by the header template and by
# derive.integrate for the ctypes signatures, so the two cannot disagree.
DRIVER_PARAMS: dict[str, tuple[tuple[str, str], ...]] = {
    "adaptive": (("double", "rtol"), ("double", "atol"), ("double", "h0"), ("long", "max_steps")),
    "fixed": (("double", "h"),),
    "implicit": (("double", "h"), ("double", "newton_tol"), ("int", "newton_maxiter")),
}

# Status codes of derive_stats.status / the solvers' return value: the one enum (derive.status).
STATUS = c_table()


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

#: The method "auto" runs: adaptive, any tolerance, dense output.
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


def compiled_methods() -> dict:
    """Every compiled method: the Runge–Kutta family rendered from tableaux (:data:`METHODS`) and
    the Lie–Poisson splittings of :mod:`derive.splitting` (their own template). Each entry has
    ``name``, ``summary``, ``driver`` and ``params`` (the C parameters after ``n_out``)."""
    return _compiled()


@functools.lru_cache(maxsize=1)
def _compiled():
    from types import MappingProxyType

    from .splitting import METHODS as SPLITTING

    return MappingProxyType({**METHODS, **SPLITTING})  # both fixed at import: merged once


def method(name: str):
    """The compiled method called ``name`` (KeyError if there is none)."""
    return compiled_methods()[name]


def method_reason(name: str, formulation: str, effects) -> str | None:
    """None if the compiled method ``name`` can run that formulation with those effects, else
    why not ("auto" as the formulation: can any formulation)."""
    return _method_reason(name, formulation, tuple(effects), _EFFECTS_VERSION[0])


@functools.lru_cache(maxsize=512)
def _method_reason(name: str, formulation: str, effects: tuple, version: int) -> str | None:
    """``method_reason``, cached per effects-registry version (the answer depends on the
    effects' declarations)."""
    from . import splitting
    from .formulations import UNIVERSAL

    if name not in splitting.METHODS:
        return None
    from types import SimpleNamespace

    form = UNIVERSAL if formulation == "auto" else formulation
    return splitting.applicable(SimpleNamespace(formulation=form, effects=tuple(effects)))


def scene_methods() -> dict[str, str]:
    """What a scene's ``simulate.method`` may name: "auto", the compiled methods, the SciPy
    references; name -> one-line description."""
    out = {"auto": f"let derive choose ({DEFAULT_METHOD} unless the scene says otherwise)"}
    out.update({name: m.summary for name, m in compiled_methods().items()
                if name not in INTERNAL_METHODS})
    out.update({name: text for name, (_, text) in REFERENCE_METHODS.items()})
    return out


def fixed_step_methods() -> tuple[str, ...]:
    """The compiled methods that take a fixed step h."""
    return tuple(name for name, m in compiled_methods().items() if m.driver != "adaptive"
                 and name not in INTERNAL_METHODS)


# Newton: the step is retried on 2, 4, ... 2**NEWTON_HALVINGS substeps before giving up.
NEWTON_HALVINGS = 4


def lincomb(terms, fmt: str) -> str:
    """C expression ``sum_j a_j * <fmt with j>`` over the non-zero coefficients, as literals."""
    parts: list[str] = []
    for j, a in terms:
        a = Fraction(a)
        if a == 0:
            continue
        sign = "-" if a < 0 else "+"
        mag = abs(a)
        term = fmt.format(j=j) if mag == 1 else f"{c_double(float(mag))} * {fmt.format(j=j)}"
        if not parts:
            parts.append(term if sign == "+" else f"-{term}")
        else:
            parts.append(f"{sign} {term}")
    return " ".join(parts) if parts else "0.0"


def _nonzero(row) -> list[tuple[int, Fraction]]:
    return [(j, a) for j, a in enumerate(row) if a != 0]


def _method_context(m: Method) -> dict:
    t = m.tableau
    s = t.stages
    ctx = {
        "name": m.name,
        "driver": m.driver,
        "summary": m.summary,
        "params": m.params,
        # The driver parameters as a C declaration list and as a call's argument list.
        "decl": ", ".join(f"{ty} {nm}" for ty, nm in m.params),
        "args": ", ".join(nm for _, nm in m.params),
        "tableau": t,
        "s": s,
        "c": [float(x) for x in t.c],
        "A": [[float(x) for x in row] for row in t.A],
        "b_terms": _nonzero(t.b),
        # Explicit stages i = 1..s-1 (stage 0 is f(t, y)).
        "stages": [{"i": i, "c": float(t.c[i]), "terms": _nonzero(t.A[i][:i])}
                   for i in range(1, s)] if not t.implicit else [],
        "A_terms": [_nonzero(row) for row in t.A],
        "err_terms": _nonzero(t.b_err) if t.b_err is not None else None,
        "err2_terms": _nonzero(t.b_err2) if t.b_err2 is not None else None,
        "err_exponent": 1.0 / (t.err_order + 1) if t.err_order is not None else None,
        "n_k": s,
        "dense": None,
    }
    if m.driver == "adaptive":
        ctx["n_k"] = s + 1  # room for the FSAL stage f(t+h, y_new)
        d = t.dense
        if d is None:
            raise NotImplementedError(f"{m.name}: the adaptive driver needs a dense output")
        if d.kind != "dop853":
            raise NotImplementedError(f"dense output kind {d.kind!r}")
        ctx["dense"] = {
            "kind": d.kind,
            "stages": [{"i": s + 1 + r, "c": float(cx), "terms": _nonzero(row)}
                       for r, (row, cx) in enumerate(zip(d.A_extra, d.c_extra))],
            "D_terms": [_nonzero(row) for row in d.D],
        }
        ctx["n_k"] = s + 1 + len(d.A_extra)
    if t.implicit:
        # Lagrange basis on the nodes {0, c_1..c_s} (the collocation polynomial through y_n and
        # the stage values), for extrapolating the next step's Newton start values.
        ctx["lagrange_den"] = [
            float(t.c[j] * _prod(t.c[j] - t.c[m_] for m_ in range(s) if m_ != j))
            for j in range(s)]
    return ctx


def _prod(it):
    out = Fraction(1)
    for x in it:
        out *= x
    return out


def render_solvers(prefix: str, ny: int, methods: list[str] | None = None,
                   has_angles: bool = False) -> dict[str, str]:
    """Render ``<prefix>_solvers.h`` and ``<prefix>_solvers.c`` for the model ``prefix``.

    The C includes ``"<prefix>.h"`` (the model ABI: ``<prefix>_NY``, ``<prefix>_NP``,
    ``<prefix>_rhs``, ``<prefix>_jac``, ``<prefix>_init``, ``<prefix>_observables``, the name
    arrays); ``ny`` is checked against ``<prefix>_NY`` at compile time. ``methods`` defaults to
    every registered method. ``has_angles``: the first three outputs are z-y-z angles, made
    canonical by ``<prefix>_outputs_at``.
    """
    if not prefix.isidentifier():
        raise ValueError(f"prefix {prefix!r} is not a C identifier")
    if ny < 1:
        raise ValueError("ny must be >= 1")
    names = list(METHODS) if methods is None else list(methods)
    for n in names:
        if n not in METHODS:
            raise ValueError(f"unknown method {n!r}; known: {', '.join(METHODS)}")
    ctx = {
        "prefix": prefix,
        "ny": ny,
        "methods": [_method_context(METHODS[n]) for n in names],
        "status": STATUS,
        "lincomb": lincomb,
        "newton_halvings": NEWTON_HALVINGS,
        "has_angles": has_angles,
        "pole_clearance": POLE_CLEARANCE,
    }
    ctx["any_implicit"] = any(m["driver"] == "implicit" for m in ctx["methods"])
    # One explicit step function per tableau, named after the first method that runs it and
    # compiled when any of them is (dop853 and dop853_fixed share DOP853's step).
    explicit = [m for m in ctx["methods"] if m["driver"] in ("adaptive", "fixed")]
    for m in explicit:
        m["step_users"] = [u["name"] for u in explicit if u["tableau"] is m["tableau"]]
        m["step_of"] = m["step_users"][0]
    return {
        f"{prefix}_solvers.h": render("c/solvers.h.j2", **ctx),
        f"{prefix}_solvers.c": render("c/solvers.c.j2", **ctx),
    }
