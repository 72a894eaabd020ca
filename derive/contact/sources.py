"""The contact models derived: each shape and law's C evaluator and each shape's reduced one.

The derivation (:mod:`derive.contact.equations`, :mod:`derive.contact.integrals`, the reduced
Lagrangian of :mod:`derive.contact.reduced`) is printed block by block with common
subexpressions shared inside each block (``sympy.cse``): the contact point a(n), the sliding
normal force and contact force, the rolling system (A, b) whose 3×3 solve is in the template,
Euler's equations for a given force, and the monitored integrals. ``make derive`` writes every
file into ``generated/contact/`` (:func:`generated_sources`); a run reads them there
(:func:`derive.contact.kernel.text`) and reaches this module, and SymPy, only for a file that
is missing.
"""
from __future__ import annotations

import functools

import sympy as sp

from derive.codegen.render import render
from derive.contact.equations import FORCE, GRAV, I1, I2, I3, MASS, contact, omega_dot
from derive.contact.friction import EPS, MU, NORMAL
from derive.contact.geometry import OFFSET, RADIUS, SHAPES, height_in_angles
from derive.contact.integrals import expressions
from derive.contact.layout import LOOP, OUTPUTS, PARAM_NAMES, RUN, STATE, loop_source, run_source
from derive.contact.laws import LAWS
from derive.symbolic.lagrangian import kinetic_energy_symmetric, p_alpha, p_gamma
from derive.symbolic.rotations import alpha_d, beta, beta_d, gamma_d

#: The full evaluator's parameter vector (the C names, :data:`~derive.contact.layout.PARAM_NAMES`,
#: are the symbols' names).
PARAMS = (I1, I2, I3, MASS, GRAV, RADIUS, OFFSET, MU, EPS)
#: The reduced evaluator's parameters, in order (:data:`~derive.contact.reduced.PARAM_NAMES`).
REDUCED_PARAMS = (I1, I3, MASS, GRAV, RADIUS, OFFSET, p_alpha, p_gamma)
BETA_DD = sp.Symbol("beta_dd", real=True)


def c_block(assign: list[tuple[str, sp.Expr]]) -> str:
    """C statements assigning each expression to its (already declared) name, subexpressions
    shared through ``sympy.cse``."""
    subs, reduced = sp.cse([e for _, e in assign], symbols=sp.numbered_symbols("x"), optimizations="basic")
    lines = [f"const double {s} = {sp.ccode(e)};" for s, e in subs]
    lines += [f"{name} = {sp.ccode(e)};" for (name, _), e in zip(assign, reduced)]
    return "\n".join(lines)


@functools.lru_cache(maxsize=None)
def source(shape: str, law: str) -> str:
    """The C source of the evaluator for ``shape`` under the contact law ``law``."""
    c = contact(shape)
    lw = LAWS[law]
    geometry = c_block([(f"a{i + 1}", c.a[i]) for i in range(3)])
    slide = ""
    if lw.slides:
        N, f = c.sliding(lw)
        slide = c_block([("N", N)] + [(f"f{i + 1}", f[i].subs(NORMAL, sp.Symbol("N"))) for i in range(3)])
    roll = ""
    if lw.rolls:
        A, b = c.rolling
        roll = c_block([(f"A[{3 * i + j}]", A[i, j]) for i in range(3) for j in range(3)]
                       + [(f"b[{i}]", b[i]) for i in range(3)])
    accel = c_block([(f"wd{i + 1}", e) for i, e in enumerate(omega_dot(c.a, FORCE))])
    ints = expressions(c)
    monitors = c_block([(f"out[{13 + i}]", e) for i, e in enumerate(ints.values())])

    return render("contact/contact.c.j2", prefix=f"contact_{shape}_{law}", shape=shape, law=law,
                  ny=len(STATE), np=len(PARAMS), nout=len(OUTPUTS), params=PARAM_NAMES,
                  outputs=OUTPUTS, geometry=geometry, slide=slide, roll=roll, accel=accel,
                  monitors=monitors)


@functools.lru_cache(maxsize=None)
def _root(equation: sp.Expr, unknown: sp.Symbol) -> sp.Expr:
    """The solution of ``equation = 0`` for ``unknown`` (linear in it), simplified; once per
    equation: shapes whose heights differ by a constant (the point and the sphere) share it."""
    return sp.solve(equation, unknown)[0]


@functools.lru_cache(maxsize=None)
def equations(shape: str) -> dict[str, sp.Expr]:
    """α̇, γ̇, β̈ and N of the reduced problem for ``shape``, in β, β̇ and the parameters."""
    # the disc's rim height has |sin β|: β ∈ (0, π) here, where it is sin β
    z = height_in_angles(contact(shape).shape).replace(sp.Abs, lambda x: x)
    zdot = sp.diff(z, beta) * beta_d
    L = MASS * zdot**2 / 2 + kinetic_energy_symmetric() - MASS * GRAV * z
    rates = sp.solve([sp.diff(L, alpha_d) - p_alpha, sp.diff(L, gamma_d) - p_gamma], [alpha_d, gamma_d], dict=True)[0]
    R = (L - p_alpha * alpha_d - p_gamma * gamma_d).subs(rates)
    pb = sp.diff(R, beta_d)
    acc = sp.diff(pb, beta) * beta_d + sp.diff(pb, beta_d) * BETA_DD - sp.diff(R, beta)
    bdd = _root(acc, BETA_DD)
    zdd = sp.diff(z, beta, 2) * beta_d**2 + sp.diff(z, beta) * BETA_DD
    return {"alpha_d": rates[alpha_d], "gamma_d": rates[gamma_d], "beta_dd": bdd,
            "N": MASS * (GRAV + zdd), "z": z, "z_d": zdot}


@functools.lru_cache(maxsize=None)
def reduced_source(shape: str) -> str:
    """The C source of the reduced evaluator for ``shape`` (it includes the shared phase loop)."""
    eq = equations(shape)
    block = c_block([("alpha_d", eq["alpha_d"]), ("gamma_d", eq["gamma_d"]), ("beta_dd", eq["beta_dd"]),
                     ("N", eq["N"].subs(BETA_DD, sp.Symbol("beta_dd"))), ("z", eq["z"]), ("z_d", eq["z_d"])])
    return render("contact/reduced.c.j2", prefix=f"contact_{shape}_reduced", shape=shape, np=len(REDUCED_PARAMS),
                  params=[str(p) for p in REDUCED_PARAMS], nout=len(OUTPUTS), block=block,
                  o_N=OUTPUTS.index("N"), o_z=OUTPUTS.index("z"), o_vz=OUTPUTS.index("vz"))


def derivations() -> dict[str, functools.partial]:
    """Each file of ``generated/contact/`` by name, with the call that derives its text."""
    out = {f"contact_{shape}_{law}.c": functools.partial(source, shape, law) for shape in SHAPES for law in LAWS}
    out.update({f"contact_{shape}_reduced.c": functools.partial(reduced_source, shape) for shape in SHAPES})
    out[LOOP], out[RUN] = loop_source, run_source
    return out


def derive(name: str) -> str:
    """The text of ``generated/contact/<name>`` derived now."""
    return derivations()[name]()


def generated_sources() -> dict[str, str]:
    """Every contact file (each shape and law's evaluator, each shape's reduced one, the phase
    loop they share and the phase driver), keyed by its path under ``generated/``."""
    return {f"contact/{name}": make() for name, make in derivations().items()}
