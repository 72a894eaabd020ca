"""The Runge–Kutta solver loops of :mod:`derive.methods.registry`, rendered into C.

Every registered method (a tableau plus a driver) goes through the same templates
(``templates/c/solvers.h.j2``, ``templates/c/solvers.c.j2``); the tableau's exact rational
coefficients become correctly rounded C literals (:func:`lincomb`).
"""
from __future__ import annotations

import functools
import math
from fractions import Fraction

from derive.codegen.render import RUNTIME_FILES, c_double, render
from derive.methods.registry import METHODS, Method
from derive.methods.status import c_table
from derive.symbolic.formulations import POLE_CLEARANCE

# Status codes of derive_stats.status / the solvers' return value: the one enum (derive.methods.status).
STATUS = c_table()

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
            float(t.c[j] * math.prod(t.c[j] - t.c[m_] for m_ in range(s) if m_ != j))
            for j in range(s)]
    return ctx


def render_solvers(prefix: str, ny: int, methods: list[str] | None = None,
                   has_angles: bool = False, pole_clearance: float = POLE_CLEARANCE) -> dict[str, str]:
    """Render ``<prefix>_solvers.h`` and ``<prefix>_solvers.c`` for the model ``prefix``, with
    the shared runtime they include (:func:`runtime_sources`).

    The C includes ``"<prefix>.h"`` (the model ABI: ``<prefix>_NY``, ``<prefix>_NP``,
    ``<prefix>_rhs``, ``<prefix>_jac``, ``<prefix>_init``, ``<prefix>_observables_at``, the name
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
        "selected": None if names == list(METHODS) else names,
        "newton_halvings": NEWTON_HALVINGS,
        "has_angles": has_angles,
        "pole_clearance": pole_clearance,  # the formulation's (Formulation.clearance)
    }
    return {
        f"{prefix}_solvers.h": render("c/solvers.h.j2", **ctx),
        f"{prefix}_solvers.c": render("c/solvers.c.j2", **ctx),
        **runtime_sources(),
    }


def _solvers_inc() -> str:
    """``derive_solvers.inc``: every registered method's solvers, one text for every model
    (the model's names and sizes are macros its ``<model>_solvers.c`` defines)."""
    methods = [_method_context(m) for m in METHODS.values()]
    # One explicit step function per tableau, named after the first method that runs it and
    # compiled when any of them is (dop853 and dop853_fixed share DOP853's step).
    explicit = [m for m in methods if m["driver"] in ("adaptive", "fixed")]
    for m in explicit:
        m["step_users"] = [u["name"] for u in explicit if u["tableau"] is m["tableau"]]
        m["step_of"] = m["step_users"][0]
    return render("c/solvers.inc.j2", methods=methods, status=STATUS, lincomb=lincomb,
                  newton_halvings=NEWTON_HALVINGS,
                  any_implicit=any(m["driver"] == "implicit" for m in methods))


@functools.lru_cache(maxsize=1)
def runtime_sources() -> dict[str, str]:
    """The C runtime every model's solvers share, ``{file name: text}``: ``derive_runtime.h``
    and ``derive_runtime.c`` (statistics, status codes, the interrupt hook, argument checks,
    LU, the canonical angles), ``derive_libm.h`` (the vectorisable sin, cos and acos ported
    from fdlibm, with Sun's notice) and ``derive_solvers.inc`` (the Runge–Kutta solvers, which
    each model's ``<model>_solvers.c`` compiles for itself)."""
    h, c, libm, inc = RUNTIME_FILES
    return {h: render("c/runtime.h.j2", status=c_table()), c: render("c/runtime.c.j2"),
            libm: render("c/libm.h.j2"), inc: _solvers_inc()}
