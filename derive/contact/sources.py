"""The contact models derived: each shape and law's C evaluator and each shape's reduced one.

The derivation (:mod:`derive.contact.equations`, :mod:`derive.contact.integrals`, the reduced
Lagrangian of :mod:`derive.contact.reduced`) is printed block by block with common
subexpressions shared inside each block (``sympy.cse``): the contact point a(n), the sliding
normal force and contact force, the rolling system (A, b) whose 3×3 solve is in the template,
Euler's equations for a given force, and the monitored integrals. Each is written once: a
shape's formulas in ``contact_<shape>.inc``, its law's sliding force in
``contact_<shape>_<law>.c``, what every model shares in ``contact_model.inc``, each block a C
function reading the names it needs from ``struct contact_vars``. ``make derive`` writes every
file into ``generated/contact/`` (:func:`generated_sources`); a run reads them there
(:func:`derive.contact.kernel.text`) and reaches this module, and SymPy, only for a file that
is missing.
"""
from __future__ import annotations

import functools

import sympy as sp

from derive.codegen.render import render
from derive.contact.equations import FORCE, GRAV, I1, I2, I3, MASS, contact, omega_dot
from derive.contact.friction import DELTA, EPS, MU, NORMAL, R_SPIN, moment_per_normal
from derive.contact.geometry import N_VEC, OFFSET, RADIUS, SHAPES, height_in_angles
from derive.contact.integrals import expressions
from derive.contact.layout import LOOP, MODEL, OUTPUTS, REDUCED, PARAM_NAMES, RUN, STATE, loop_source, run_source
from derive.contact.laws import LAWS, takes_moments
from derive.symbolic.lagrangian import kinetic_energy_symmetric, p_alpha, p_gamma
from derive.symbolic.rotations import alpha_d, beta, beta_d, gamma_d

#: The full evaluator's parameter vector (the C names, :data:`~derive.contact.layout.PARAM_NAMES`,
#: are the symbols' names).
PARAMS = (I1, I2, I3, MASS, GRAV, RADIUS, OFFSET, MU, EPS, DELTA, R_SPIN)
#: The reduced evaluator's parameters, in order (:data:`~derive.contact.reduced.PARAM_NAMES`).
REDUCED_PARAMS = (I1, I3, MASS, GRAV, RADIUS, OFFSET, p_alpha, p_gamma)
BETA_DD = sp.Symbol("beta_dd", real=True)


#: The fields of ``struct contact_vars`` (``contact_model.inc``) in order: what a shape's or a
#: law's formulas read through ``v``.
VARS = PARAM_NAMES + ("n1", "n2", "n3", "w1", "w2", "w3", "vb1", "vb2", "vb3", "z",
                      "a1", "a2", "a3", "ut1", "ut2", "ut3", "d1", "d2", "d3",
                      "e1", "e2", "e3", "sigma", "m1", "m2", "m3")
#: The contact force's components, read from the array ``f``.
_FORCE_READ = {f"f{i + 1}": f"f[{i}]" for i in range(3)}


def c_block(assign: list[tuple[str, sp.Expr]]) -> str:
    """C statements assigning each expression to its (already declared) name (or adding it, for
    a name written ``x +=``), subexpressions shared through ``sympy.cse``."""
    subs, reduced = sp.cse([e for _, e in assign], symbols=sp.numbered_symbols("x"), optimizations="basic")
    lines = [f"const double {s} = {sp.ccode(e)};" for s, e in subs]
    lines += [f"{name}{'' if name.endswith('=') else ' ='} {sp.ccode(e)};" for (name, _), e in zip(assign, reduced)]
    return "\n".join(lines)


def c_body(assign: list[tuple[str, sp.Expr]], local: tuple[str, ...] = (), reads: dict[str, str] | None = None) -> str:
    """A C function's body: the symbols the expressions read, each from where ``reads`` says
    (by default ``v``, the fields of :data:`VARS`, and ``f``, the force), then :func:`c_block`;
    ``local`` names are the function's own."""
    reads = reads if reads is not None else {**{n: f"v->{n}" for n in VARS}, **_FORCE_READ}
    used = {str(x) for _, e in assign for x in e.free_symbols} - set(local)
    names = [n for n in reads if n in used]
    unknown = used - set(names)
    if unknown:
        raise ValueError(f"the formulas read {sorted(unknown)}, which no contact model has")
    lines, line = [], "const double"
    for k, n in enumerate(names):
        item = f" {n} = {reads[n]}" + (";" if k == len(names) - 1 else ",")
        if len(line) + len(item) > 96:
            lines.append(line)
            line = "   "
        line += item
    return "\n".join(lines + [line, c_block(assign)]) if names else c_block(assign)


def model_source() -> str:
    """``contact_model.inc``: the state, its kinematics and the phases' forces put together, the
    part every shape and law shares."""
    m = moment_per_normal(N_VEC)
    return render("contact/model.c.j2", ny=len(STATE), np=len(PARAMS), nout=len(OUTPUTS),
                  params=PARAM_NAMES, outputs=OUTPUTS,
                  moment=c_body([(f"v->m{i + 1}", m[i]) for i in range(3)]))


@functools.lru_cache(maxsize=None)
def shape_source(shape: str) -> str:
    """``contact_<shape>.inc``: the shape's contact point a(n), the rolling system (A, b), Euler's
    equations for a given force and the monitored integrals, once for all its laws."""
    c = contact(shape)
    A, b = c.rolling
    ints = expressions(c)
    return render("contact/shape.c.j2", shape=shape,
                  point=c_body([(f"a[{i}]", c.a[i]) for i in range(3)]),
                  omega_dot=c_body([(f"wd[{i}]", e) for i, e in enumerate(omega_dot(c.a, FORCE))]),
                  integrals=c_body([(f"out[{i}]", e) for i, e in enumerate(ints.values())]),
                  rolling=c_body([(f"A[{3 * i + j}]", A[i, j]) for i in range(3) for j in range(3)]
                                 + [(f"b[{i}]", b[i]) for i in range(3)]),
                  rolling_moment=c_body([(f"A[{3 * i + j}] +=", c.rolling_moment[i, j])
                                         for i in range(3) for j in range(3) if c.rolling_moment[i, j] != 0]))


@functools.lru_cache(maxsize=None)
def source(shape: str, law: str) -> str:
    """``contact_<shape>_<law>.c``: the evaluator of ``shape`` under the contact law ``law``, its
    law's sliding force with the shape's formulas and the shared model included."""
    c = contact(shape)
    lw = LAWS[law]
    sliding = moment = ""
    if lw.slides:
        N, f = c.sliding(lw)
        force = [(f"f[{i}]", f[i].subs(NORMAL, sp.Symbol("N"))) for i in range(3)]
        if takes_moments(lw):  # N first, with c1 and k.m to correct it; then f from N
            c1, _, _ = c.gap_coefficients(lw)
            moment = c_body([("N", N), ("c1", c1), ("km", c.moment_coefficient)])
            sliding = c_body(force, local=("N",))
        else:
            sliding = c_body([("N", N)] + force, local=("N",))
    return render("contact/contact.c.j2", prefix=f"contact_{shape}_{law}", shape=shape, law=law,
                  phases=lw.phases,
                  slides=int(lw.slides), rolls=int(lw.rolls), moments=int(takes_moments(lw)),
                  sliding=sliding, moment=moment)


@functools.lru_cache(maxsize=None)
def _root(equation: sp.Expr, unknown: sp.Symbol) -> sp.Expr:
    """The solution :math:`x = -c_0 / c_1` of ``equation`` :math:`= c_0 + c_1 x = 0` for ``unknown``
    (linear in it), with :math:`c_0` and :math:`c_1` simplified apart: each is far smaller than
    their quotient, which SymPy simplifies many times slower to no shorter a result. Once per
    equation: shapes whose heights differ by a constant (the point and the sphere) share it."""
    c1 = sp.diff(equation, unknown)
    if c1.has(unknown) or c1 == 0:
        raise ValueError(f"the equation is not linear in {unknown}")
    return -sp.simplify(equation.subs(unknown, 0)) / sp.simplify(c1)


@functools.lru_cache(maxsize=1)
def _rates() -> dict[sp.Symbol, sp.Expr]:
    """α̇ and γ̇ in the momenta p_α, p_γ (∂L/∂α̇ = p_α, ∂L/∂γ̇ = p_γ). Of the reduced Lagrangian
    :func:`equations` builds, only the kinetic energy holds α̇ or γ̇ (the height's M ż²/2 has β̇
    alone), so the rates are the same for every shape: solved once."""
    T = kinetic_energy_symmetric()
    rates = sp.solve([sp.diff(T, alpha_d) - p_alpha, sp.diff(T, gamma_d) - p_gamma], [alpha_d, gamma_d], dict=True)[0]
    # sin²β + cos²β = 1 in the rates first: the Routhian and β̈'s coefficients simplify faster and shorter
    return {rate: sp.factor(sp.trigsimp(sp.together(value))) for rate, value in rates.items()}


@functools.lru_cache(maxsize=None)
def equations(shape: str) -> dict[str, sp.Expr]:
    """α̇, γ̇, β̈ and N of the reduced problem for ``shape``, in β, β̇ and the parameters."""
    # the disc's rim height has |sin β|: β ∈ (0, π) here, where it is sin β
    z = height_in_angles(contact(shape).shape).replace(sp.Abs, lambda x: x)
    zdot = sp.diff(z, beta) * beta_d
    L = MASS * zdot**2 / 2 + kinetic_energy_symmetric() - MASS * GRAV * z
    rates = _rates()
    R = (L - p_alpha * alpha_d - p_gamma * gamma_d).subs(rates)
    pb = sp.diff(R, beta_d)
    acc = sp.diff(pb, beta) * beta_d + sp.diff(pb, beta_d) * BETA_DD - sp.diff(R, beta)
    bdd = _root(acc, BETA_DD)
    zdd = sp.diff(z, beta, 2) * beta_d**2 + sp.diff(z, beta) * BETA_DD
    return {"alpha_d": rates[alpha_d], "gamma_d": rates[gamma_d], "beta_dd": bdd,
            "N": MASS * (GRAV + zdd), "z": z, "z_d": zdot}


@functools.lru_cache(maxsize=None)
def reduced_source(shape: str) -> str:
    """``contact_<shape>_reduced.c``: the shape's reduced formulas (α̇, γ̇, β̈, N, z, ż), with the
    evaluator every shape shares included (``contact_reduced.inc``)."""
    eq = equations(shape)
    block = c_body([("alpha_d", eq["alpha_d"]), ("gamma_d", eq["gamma_d"]), ("beta_dd", eq["beta_dd"]),
                    ("N", eq["N"].subs(BETA_DD, sp.Symbol("beta_dd"))), ("z", eq["z"]), ("z_d", eq["z_d"])],
                   local=("beta", "beta_d", "beta_dd"), reads={str(q): f"p[{i}]" for i, q in enumerate(REDUCED_PARAMS)})
    return render("contact/reduced.c.j2", prefix=f"contact_{shape}_reduced", shape=shape, block=block)


def reduced_model_source() -> str:
    """``contact_reduced.inc``: the reduced evaluator every shape shares (the state on the unit
    circles, the outputs), around the shape's ``reduced_formulas``."""
    return render("contact/reduced_model.c.j2", np=len(REDUCED_PARAMS), params=[str(p) for p in REDUCED_PARAMS],
                  nout=len(OUTPUTS), o_N=OUTPUTS.index("N"), o_z=OUTPUTS.index("z"), o_vz=OUTPUTS.index("vz"))


def derivations() -> dict[str, functools.partial]:
    """Each file of ``generated/contact/`` by name, with the call that derives its text."""
    out = {f"contact_{shape}_{law}.c": functools.partial(source, shape, law) for shape in SHAPES for law in LAWS}
    out.update({f"contact_{shape}.inc": functools.partial(shape_source, shape) for shape in SHAPES})
    out[MODEL] = model_source
    out.update({f"contact_{shape}_reduced.c": functools.partial(reduced_source, shape) for shape in SHAPES})
    out[REDUCED] = reduced_model_source
    out[LOOP], out[RUN] = loop_source, run_source
    return out


def derive(name: str) -> str:
    """The text of ``generated/contact/<name>`` derived now."""
    return derivations()[name]()


def generated_sources() -> dict[str, str]:
    """Every contact file (each shape and law's evaluator, each shape's reduced one, the phase
    loop they share and the phase driver), keyed by its path under ``generated/``."""
    return {f"contact/{name}": make() for name, make in derivations().items()}
