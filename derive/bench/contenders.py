"""The contenders `derive bench` races derive against: SciPy with hand-written right-hand sides,
and, when installed (``pip install -e '.[peers]'``), CasADi and PyDy on the same equations.

Every contender gets a :class:`Problem`: one scene (read as plain TOML data, no derive
internals) in one of the two formulations of ``derive/bench/baselines/scipy_baselines.py`` (Euler angles
for the symmetric top, quaternion + Euler's equations for any body), with the initial state and
constants that formulation needs and a map from its states to the symmetry axis ê₃ — the error
measure of the bench is the axis error against `derive.reference.exact`, the same for everyone.

Each ``solve_*`` returns ``(Y, nfev)``: the states at the output times (rows) and the number of
right-hand-side evaluations; a failure raises :class:`~derive.errors.IntegrationError`. The
wall time of that call is what the bench records (building an integrator or compiling a
right-hand side is a separate, one-off cost, reported apart as ``setup``).

* SciPy: ``solve_ivp`` (DOP853, LSODA, Radau) and ``odeint`` with the plain-Python rhs (closure
  over the constants, ``math``, a list returned); Radau and LSODA (both drivers) also get the
  plain-Python analytic Jacobian.
* CasADi: the same equations built as SX expressions (``sin``/``cos`` of CasADi), the constants
  as symbolic parameters, ``integrator('F', 'cvodes'|'idas', ...)`` with the output grid;
  cvodes in Adams (functional iteration) and BDF mode, idas (BDF).
* PyDy: the same equations as SymPy expressions through ``generate_ode_function`` with the
  Cython backend, integrated by ``scipy.integrate.odeint`` (LSODA).
* heyoka: the same equations as heyoka expressions (``heyoka.sin``/``cos``, the constants as
  runtime parameters ``par[i]``) in ``taylor_adaptive`` (LLVM-compiled Taylor method of adaptive
  order, one tolerance ``tol`` = our rtol for its relative and absolute error alike), its
  ``propagate_grid`` dense output (the series themselves) at the output times; the batch mode
  (``taylor_adaptive_batch``, one trajectory per SIMD lane) in :mod:`derive.bench.peers`. Its
  "nfev" is the number of Taylor steps (a Taylor step evaluates no right-hand side).
* numbalsoda: the same equations as a numba ``cfunc`` (the constants in its ``data`` array)
  through numbalsoda's ``dop853`` (Hairer's DOP853 in C++, the loop never in Python). It
  reports no rhs count ("nfev" 0). It builds from source and needs a Fortran compiler: raced
  only when it imports.
"""
from __future__ import annotations

import functools
import importlib.util
import math
import operator
import time
import tomllib
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from derive.errors import IntegrationError

#: The baselines the bench races (C and plain-Python right-hand sides), shipped in the package.
BENCH_SOURCES = Path(__file__).resolve().parent / "baselines"

#: The baseline formulations: state size and constants (in the factories' argument order).
STATE_SIZE = {"euler-angles": 6, "quaternion": 7}
CONST_NAMES = {"euler-angles": ("I1", "I3", "mgl"), "quaternion": ("I1", "I2", "I3", "mgl")}
#: SciPy's methods: ``solve_ivp``'s DOP853, LSODA and Radau, and ``odeint`` (LSODA's Fortran
#: driver, whose loop is not Python: the cheapest way SciPy offers to call a Python rhs).
SCIPY = {"scipy-dop853": "DOP853", "scipy-lsoda": "LSODA", "scipy-radau": "Radau", "scipy-odeint": "odeint"}
CASADI = {"casadi-cvodes-adams": ("cvodes", {"linear_multistep_method": "adams",
                                             "nonlinear_solver_iteration": "functional"}),
          "casadi-cvodes-bdf": ("cvodes", {}),
          "casadi-idas": ("idas", {})}


@functools.cache
def module_at(path: Path, name: str):
    """The Python file ``path`` as a module named ``name``: a file the bench reads from the
    checkout, not a module of the package."""
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or not path.is_file():
        raise FileNotFoundError(f"{path}: the bench needs a source checkout")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def baselines():
    """``derive/bench/baselines/scipy_baselines.py`` as a module (it is a user's file, not part of derive)."""
    return module_at(BENCH_SOURCES / "scipy_baselines.py", "derive_bench_scipy_baselines")


def peers_available() -> dict[str, str | None]:
    """{peer: version or None (not installed)} for casadi, pydy (+ cython, its backend), heyoka
    and numbalsoda (+ numba, its rhs compiler)."""
    out = {}
    for name in ("casadi", "pydy", "Cython", "heyoka", "numbalsoda", "numba"):
        try:
            mod = __import__(name)
            version = getattr(mod, "__version__", None)
            if version is None:  # numbalsoda has no __version__: its distribution's
                from importlib.metadata import version as dist_version

                version = dist_version(name)
            out[name.lower()] = version
        except Exception:  # noqa: BLE001 - a broken install counts as absent
            out[name.lower()] = None
    return out


# ---------------------------------------------------------------------------------------------
# one scene in one formulation


@dataclass
class Problem:
    """A scene as a contender sees it: ``formulation`` of scipy_baselines, constants
    ``consts`` (I1, I2, I3, mgl), initial state ``y0`` and output times ``t``."""

    name: str
    formulation: str
    consts: dict
    y0: list
    t: np.ndarray

    @property
    def const_values(self) -> list[float]:
        return [self.consts[k] for k in CONST_NAMES[self.formulation]]

    def functions(self, sin=math.sin, cos=math.cos, values=operator.methodcaller("tolist")):
        """(rhs, jac) of scipy_baselines for this formulation, over the constants given as
        positional values in ``CONST_NAMES`` order (numbers, or symbols for the peers)."""
        b = baselines()
        if self.formulation == "euler-angles":
            return (b.euler_top_rhs(*self.const_values, sin=sin, cos=cos, values=values),
                    b.euler_top_jac(*self.const_values, sin=sin, cos=cos, values=values))
        return (b.quaternion_rhs(*self.const_values, values=values),
                b.quaternion_jac(*self.const_values, values=values))

    def axis(self, Y: np.ndarray) -> np.ndarray:
        """ê₃ at every row of ``Y`` (states in this formulation), shape (n, 3)."""
        b = baselines()
        if self.formulation == "euler-angles":
            return np.stack(b.euler_top_axis(Y.T, sin=np.sin, cos=np.cos), axis=1)
        return np.stack(b.quaternion_axis(Y.T), axis=1)


def scene_data(path_or_dict, **simulate) -> dict:
    """The TOML data of a scene (a path or a dict), ``[simulate]`` keys replaced by ``simulate``."""
    if isinstance(path_or_dict, dict):
        data = {k: (dict(v) if isinstance(v, dict) else v) for k, v in path_or_dict.items()}
    else:
        with open(path_or_dict, "rb") as fh:
            data = tomllib.load(fh)
    data.setdefault("simulate", {}).update({k: v for k, v in simulate.items() if v is not None})
    return data


def problem(data: dict, formulation: str, name: str = "") -> Problem:
    """The contenders' problem for scene data in one formulation. Raises ValueError when the
    formulation cannot take the scene (Euler angles: asymmetric body, or ω̃ given at a pole)."""
    b = baselines()
    body, init, sim = data["body"], data["initial"], data["simulate"]
    I1, I3 = float(body["I1"]), float(body["I3"])
    I2 = float(body.get("I2", I1))
    grav = data.get("gravity")
    mgl = float(grav["M"]) * float(grav["g"]) * float(grav["l"]) if grav else 0.0
    if data.get("damping"):
        raise ValueError("damping: no hand-written baseline (no closed form to measure against)")
    a, be, ga = (float(init[k]) for k in ("alpha", "beta", "gamma"))
    has_rates = any(k in init for k in ("alpha_dot", "beta_dot", "gamma_dot"))
    rates = [float(init.get(k, 0.0)) for k in ("alpha_dot", "beta_dot", "gamma_dot")] if has_rates else None
    t = np.linspace(0.0, float(sim["t_end"]), int(sim.get("samples", 1001)))
    consts = {"I1": I1, "I2": I2, "I3": I3, "mgl": mgl}
    if formulation == "euler-angles":
        if I2 != I1:
            raise ValueError("euler-angles: the hand-written Euler-angle top is symmetric (I1 = I2)")
        if rates is None:
            if abs(math.sin(be)) < 1e-3:
                raise ValueError("euler-angles: omega given at a pole, the Euler rates are undefined")
            rates = b.euler_rates(be, ga, *map(float, init["omega"]))
        return Problem(name, formulation, consts, [a, be, ga, *rates], t)
    if formulation == "quaternion":
        w = b.body_rates(be, ga, *rates) if rates is not None else list(map(float, init["omega"]))
        return Problem(name, formulation, consts, [*b.quaternion_from_angles(a, be, ga), *w], t)
    raise ValueError(f"unknown baseline formulation {formulation!r}")


# ---------------------------------------------------------------------------------------------
# SciPy


def scipy_setup(prob: Problem, method: str):
    """The callables SciPy gets (built once, outside the timing)."""
    rhs, jac = prob.functions()
    return {"fun": rhs, **({"jac": jac} if SCIPY[method] in ("Radau", "LSODA", "odeint") else {})}


def _odeint(who: str, f, prob: Problem, rtol: float, atol: float, **kw):
    """(Y, nfev) of ``scipy.integrate.odeint`` of ``f`` over the output times; its failure an
    IntegrationError naming ``who``."""
    from scipy.integrate import odeint

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        Y, info = odeint(f, prob.y0, prob.t, rtol=rtol, atol=atol, mxstep=1_000_000, full_output=True, **kw)
    if info["message"] != "Integration successful.":
        raise IntegrationError(f"{who}: {info['message']}")
    return Y, int(info["nfe"][-1])


def solve_scipy(prob: Problem, method: str, rtol: float, atol: float, setup=None):
    from scipy.integrate import solve_ivp

    kw = setup or scipy_setup(prob, method)
    t = prob.t
    if SCIPY[method] == "odeint":
        return _odeint("scipy odeint", kw["fun"], prob, rtol, atol, Dfun=kw["jac"], tfirst=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sol = solve_ivp(kw["fun"], (t[0], t[-1]), prob.y0, method=SCIPY[method], t_eval=t,
                        rtol=rtol, atol=atol, **({"jac": kw["jac"]} if "jac" in kw else {}))
    if not sol.success:
        raise IntegrationError(f"scipy {SCIPY[method]}: {sol.message}")
    return sol.y.T, sol.nfev


# ---------------------------------------------------------------------------------------------
# CasADi


@functools.cache
def _casadi_ode(formulation: str):
    """(x, p, ode): the baseline equations as CasADi SX, the constants symbolic."""
    import casadi as ca

    ny, names = STATE_SIZE[formulation], CONST_NAMES[formulation]
    x, p = ca.SX.sym("x", ny), ca.SX.sym("p", len(names))
    sym = Problem("", formulation, {k: p[i] for i, k in enumerate(names)}, [], np.zeros(2))
    rhs, _ = sym.functions(sin=ca.sin, cos=ca.cos, values=list)
    return x, p, ca.vertcat(*rhs(0.0, [x[i] for i in range(ny)]))


def casadi_setup(prob: Problem, method: str, rtol: float, atol: float):
    """The integrator function for one tolerance and output grid (built outside the timing)."""
    import casadi as ca

    x, p, ode = _casadi_ode(prob.formulation)
    plugin, opts = CASADI[method]
    opts = dict(opts, reltol=rtol, abstol=atol, max_num_steps=1_000_000)
    return ca.integrator("F", plugin, {"x": x, "p": p, "ode": ode}, float(prob.t[0]), prob.t[1:].tolist(), opts)


def solve_casadi(prob: Problem, method: str, rtol: float, atol: float, setup=None):
    F = setup or casadi_setup(prob, method, rtol, atol)
    try:
        xf = F(x0=prob.y0, p=prob.const_values)["xf"]
    except RuntimeError as exc:
        raise IntegrationError(f"casadi {method}: {str(exc).splitlines()[-1][:120]}") from None
    Y = np.vstack([np.asarray(prob.y0, dtype=float), np.asarray(xf).T])
    return Y, int(F.stats().get("nfevals", 0))


# ---------------------------------------------------------------------------------------------
# PyDy


#: formulation -> seconds PyDy took to generate and Cython-compile its rhs (the first time).
PYDY_BUILD_TIME: dict[str, float] = {}


@functools.cache
def _pydy_rhs(formulation: str):
    """The baseline equations as SymPy expressions through PyDy's ODE function generator
    (Cython backend): f(x, t, constants)."""
    import sympy as sp
    from pydy.codegen.ode_function_generators import generate_ode_function

    if formulation == "euler-angles":
        coords, speeds = sp.symbols("alpha beta gamma"), sp.symbols("alpha_d beta_d gamma_d")
    else:
        coords, speeds = sp.symbols("q0:4"), sp.symbols("w1:4")
    names = CONST_NAMES[formulation]
    consts = sp.symbols(" ".join(names))
    sym = Problem("", formulation, dict(zip(names, consts)), [], np.zeros(2))
    rhs, _ = sym.functions(sin=sp.sin, cos=sp.cos, values=list)
    expr = sp.Matrix(rhs(0, [*coords, *speeds]))
    t0 = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        f = generate_ode_function(expr, list(coords), list(speeds), list(consts), generator="cython")
    PYDY_BUILD_TIME[formulation] = time.perf_counter() - t0
    return f


def solve_pydy(prob: Problem, method: str, rtol: float, atol: float, setup=None):
    f = setup or _pydy_rhs(prob.formulation)
    return _odeint("pydy odeint", f, prob, rtol, atol, args=(np.array(prob.const_values),))


# ---------------------------------------------------------------------------------------------
# heyoka


@functools.cache
def heyoka_system(formulation: str):
    """The baseline equations as heyoka expressions: [(variable, rhs)], the constants as the
    runtime parameters ``par[0..]`` in ``CONST_NAMES`` order (so one compiled integrator serves
    every scene of a formulation and tolerance)."""
    import heyoka as hy

    names = CONST_NAMES[formulation]
    x = hy.make_vars(*(f"y{i}" for i in range(STATE_SIZE[formulation])))
    sym = Problem("", formulation, {k: hy.par[i] for i, k in enumerate(names)}, [], np.zeros(2))
    rhs, _ = sym.functions(sin=hy.sin, cos=hy.cos, values=list)
    return list(zip(x, rhs(0.0, list(x))))


@functools.cache
def _heyoka_integrator(formulation: str, tol: float):
    import heyoka as hy

    return hy.taylor_adaptive(heyoka_system(formulation), [0.0] * STATE_SIZE[formulation], tol=tol,
                              pars=[1.0] * len(CONST_NAMES[formulation]))


def heyoka_setup(prob: Problem, method: str, rtol: float, atol: float):
    """heyoka's ``taylor_adaptive`` for the formulation at ``tol = rtol`` (JIT-compiled once per
    formulation and tolerance, outside the timing; heyoka has one tolerance, relative above
    |y| = 1 and absolute below, and no atol)."""
    return _heyoka_integrator(prob.formulation, float(rtol))


def solve_heyoka(prob: Problem, method: str, rtol: float, atol: float, setup=None):
    """Reset the integrator to t₀, y₀ and the constants, then ``propagate_grid`` over the output
    times: the states there from its dense output. Returns (states, Taylor steps)."""
    ta = setup or heyoka_setup(prob, method, rtol, atol)
    ta.time = float(prob.t[0])
    ta.state[:] = prob.y0
    ta.pars[:] = prob.const_values
    outcome, _, _, nsteps, _, Y = ta.propagate_grid(prob.t)
    if str(outcome) != "taylor_outcome.time_limit":
        raise IntegrationError(f"heyoka: {outcome}")
    return Y, int(nsteps)


# ---------------------------------------------------------------------------------------------
# numbalsoda


@functools.cache
def _numba_rhs(formulation: str) -> int:
    """The address of the baseline rhs as a numba ``cfunc`` of numbalsoda's signature
    f(t, u, du, p), p the constants in ``CONST_NAMES`` order (the same equations as
    ``scipy_baselines``, written with scalar indexing: numba compiles no closures over lists)."""
    import math as m

    from numba import cfunc
    from numbalsoda import lsoda_sig

    if formulation == "euler-angles":
        @cfunc(lsoda_sig)
        def rhs(t, u, du, p):
            I1, I3, mgl = p[0], p[1], p[2]
            b, ad, bd, gd = u[1], u[3], u[4], u[5]
            sb = m.sin(b)
            cb = m.cos(b)
            w3 = ad * cb + gd
            add = bd * (I3 * w3 - 2.0 * I1 * ad * cb) / (I1 * sb)
            du[0] = ad
            du[1] = bd
            du[2] = gd
            du[3] = add
            du[4] = (I1 * ad * ad * sb * cb - I3 * w3 * ad * sb + mgl * sb) / I1
            du[5] = -add * cb + ad * bd * sb
    else:
        @cfunc(lsoda_sig)
        def rhs(t, u, du, p):
            I1, I2, I3, mgl = p[0], p[1], p[2], p[3]
            q0, q1, q2, q3, w1, w2, w3 = u[0], u[1], u[2], u[3], u[4], u[5], u[6]
            k1 = 2.0 * (q1 * q3 - q0 * q2)  # the vertical in body axes, k = Rᵀ ẑ
            k2 = 2.0 * (q2 * q3 + q0 * q1)
            du[0] = 0.5 * (-q1 * w1 - q2 * w2 - q3 * w3)
            du[1] = 0.5 * (q0 * w1 + q2 * w3 - q3 * w2)
            du[2] = 0.5 * (q0 * w2 + q3 * w1 - q1 * w3)
            du[3] = 0.5 * (q0 * w3 + q1 * w2 - q2 * w1)
            du[4] = ((I2 - I3) * w2 * w3 + mgl * k2) / I1
            du[5] = ((I3 - I1) * w3 * w1 - mgl * k1) / I2
            du[6] = (I1 - I2) * w1 * w2 / I3
    return rhs.address


def numbalsoda_setup(prob: Problem, method: str = "numbalsoda-dop853", rtol=None, atol=None):
    """(rhs address, constants): the cfunc compiled once per formulation, outside the timing."""
    return _numba_rhs(prob.formulation), np.array(prob.const_values, dtype=float)


def solve_numbalsoda(prob: Problem, method: str, rtol: float, atol: float, setup=None):
    from numbalsoda import dop853

    address, consts = setup or numbalsoda_setup(prob, method)
    # the step budget derive's scenes have by default (numbalsoda's own is 10 000: a long run
    # would fail at every tolerance only for want of steps), as odeint gets above
    Y, ok = dop853(address, np.asarray(prob.y0, dtype=float), prob.t, data=consts, rtol=rtol, atol=atol,
                   mxstep=1_000_000)
    if not ok:
        raise IntegrationError("numbalsoda dop853: failed")
    return Y, 0


# ---------------------------------------------------------------------------------------------
# one registry for the bench


@dataclass(frozen=True)
class Contender:
    family: str            # "scipy" | "casadi" | "pydy" | "heyoka" | "numbalsoda"
    methods: tuple[str, ...]
    setup: object          # (problem, method, rtol, atol) -> whatever solve takes, built untimed
    solve: object          # (problem, method, rtol, atol, setup) -> (Y, nfev)
    per_tolerance_setup: bool = False


CONTENDERS = {
    "scipy": Contender("scipy", tuple(SCIPY), lambda p, m, r, a: scipy_setup(p, m), solve_scipy),
    "casadi": Contender("casadi", tuple(CASADI), casadi_setup, solve_casadi, per_tolerance_setup=True),
    "pydy": Contender("pydy", ("pydy-odeint",), lambda p, m, r, a: _pydy_rhs(p.formulation), solve_pydy),
    "heyoka": Contender("heyoka", ("heyoka-taylor",), heyoka_setup, solve_heyoka, per_tolerance_setup=True),
    "numbalsoda": Contender("numbalsoda", ("numbalsoda-dop853",), numbalsoda_setup, solve_numbalsoda),
}


def families(peers: bool = True) -> list[str]:
    """The contender families to run: SciPy always; casadi, pydy, heyoka, numbalsoda when asked
    and installed."""
    have = peers_available() if peers else {}
    needs = {"casadi": ("casadi",), "pydy": ("pydy", "cython"), "heyoka": ("heyoka",),
             "numbalsoda": ("numbalsoda", "numba")}
    return ["scipy"] + [fam for fam, names in needs.items() if all(have.get(n) for n in names)]
