"""The Taylor method: recurrences generated from the model's expression graph.

References, none of them derive's own recurrences:

* the coefficients of the composed solution, y_{n+1} = [τⁿ] f(Σ_{k≤n} y_k τᵏ) / (n + 1), with
  [τⁿ] taken by mpmath's high-precision differentiation of the model's SymPy right-hand side
  (lambdified for mpmath, 60 digits), and the closed form of the free symmetric top;
* the closed-form solutions of derive/reference/exact.py (heavy top, free bodies) for the error
  against the tolerance;
* the hard cases of tests/test_hard_cases*.py, run again with ``method = "taylor"``.
"""
from __future__ import annotations

import ctypes
import inspect
import math
import sys
import tomllib
from pathlib import Path

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

import derive
from derive.codegen import jet
from derive.codegen import taylor as taylor_codegen
from derive.codegen.jet import NoTaylorRule, controlled_states, decompose
from derive.codegen.kernelspec import KernelSpec
from derive.codegen.render import ROOT, environment
from derive.codegen.solvers import render_solvers
from derive.codegen.sources import shipped_keys
from derive.codegen.taylor import render_taylor
from derive.methods.registry import compiled_methods, fixed_step_methods, tolerance_driven
from derive.methods.taylor import METHODS as TAYLOR
from derive.reference import exact
from derive.runtime import catalogue
from derive.runtime.cbuild import STRICT_FLAGS, compile_library
from derive.runtime.integrate import ModelKernel
from derive.runtime.records import STATS_DTYPE, SaveAt, saveat
from derive.sim.scene import METHODS as SCENE_METHODS
from derive.symbolic.models import Model, build

SCENES = ROOT / "scenes"
_D, _P, _I = ctypes.c_double, ctypes.c_void_p, ctypes.c_int


# ---------------------------------------------------------------------------------------------
# references


def composed_series(model, y0, p, order, t0=0.0, dps=60):
    """Taylor coefficients c[i][n], n ≤ order, of the solution through (t0, y0), order by order:
    c_{n+1} = [τⁿ] f(t0 + τ, Σ_{k≤n} c_k τᵏ) / (n + 1), the τⁿ coefficient by mpmath.taylor
    (numerical differentiation at ``dps`` digits) of the model's SymPy right-hand side."""
    t = sp.Symbol("t")
    with mpmath.workdps(dps):
        f = sp.lambdify([t, list(model.states), list(model.params)], list(model.rhs),
                        modules="mpmath")
        c = [[mpmath.mpf(v)] for v in y0]
        pm = [mpmath.mpf(v) for v in p]
        for n in range(order):
            def g(tau, i):
                return f(t0 + tau, [mpmath.polyval(ci[::-1], tau) for ci in c], pm)[i]
            new = [mpmath.taylor(lambda tau, i=i: g(tau, i), 0, n)[n] / (n + 1)
                   for i in range(len(c))]
            for ci, v in zip(c, new):
                ci.append(v)
        return np.array([[float(v) for v in ci] for ci in c])


def kernel(name):
    desc = catalogue.describe(shipped_keys()[name])
    return desc, ModelKernel.load(desc, "taylor")


def c_coefficients(lib, prefix, y, p, order, t=0.0):
    fn = getattr(lib, f"{prefix}_taylor_coefficients")
    fn.argtypes = [_D, _P, _P, _I, _P]
    fn.restype = _I
    y = np.ascontiguousarray(y, dtype=float)
    p = np.ascontiguousarray(p, dtype=float)
    out = np.full((len(y), order + 1), np.nan)
    rc = fn(t, y.ctypes.data, p.ctypes.data, order, out.ctypes.data)
    return rc, out


def assert_coefficients_close(got, ref, rel=1e-12):
    """Each order against its own scale (the largest reference coefficient of that order)."""
    scale = np.maximum(np.max(np.abs(ref), axis=0), 1e-300)
    err = np.max(np.abs(got - ref), axis=0) / scale
    assert np.all(err <= rel), err


# ---------------------------------------------------------------------------------------------
# 1. the coefficients

# (model, state, parameters): a point of each shipped kind, the rules they use (sin/cos pairs,
# quotients, squares, the reduced top's piecewise terms at p_α ≠ ±p_γ and at p_α = p_γ).
POINTS = {
    "heavy_top": ([0.1, 0.8, 0.2, -0.4, 0.3, 6.0], [1.0, 0.5, 1.0, 1.0, 1.0]),
    "heavy_top_reduced": ([0.1, 0.8, 0.2, 0.3], [1.0, 0.5, 1.0, 9.81, 0.1, 1.7, 2.3]),
    "heavy_top_reduced/equal": ([0.1, 0.8, 0.2, 0.3], [1.0, 0.5, 1.0, 9.81, 0.1, 2.3, 2.3]),
    "rigid_body": ([0.9, 0.1, -0.3, 0.2, 1.5, -2.0, 7.0],
                   [1.0, 1.3, 0.6, 1.0, 9.81, 0.02, -0.01, 0.1, 0.05]),
    "euler_poisson_asym_gravity_general": (
        [1.5, -2.0, 7.0, 0.1, 0.2, 0.97, 0.99, 0.0, -0.1],
        [1.0, 1.3, 0.6, 1.0, 9.81, 0.02, -0.01, 0.1]),
}


@pytest.mark.parametrize("case", [pytest.param(c, marks=pytest.mark.slow) if c in ("heavy_top", "heavy_top_reduced/equal")
                                  else c for c in sorted(POINTS)])  # the other two heavy tops: slow
def test_coefficients_match_the_composed_series(case):
    """Order 10, every state: within 1e-12 of each order's scale (measured ≤ 3e-15)."""
    name = case.split("/")[0]
    desc, k = kernel(name)
    y, p = POINTS[case]
    assert (len(y), len(p)) == (len(desc.states), len(desc.params))
    rc, got = c_coefficients(k.lib, desc.name, y, p, 10)
    assert rc == 0
    ref = composed_series(build(*shipped_keys()[name]), y, p, 10)
    assert_coefficients_close(got, ref)


def test_free_symmetric_top_coefficients_are_the_closed_form_to_order_25():
    """Euler–Poisson, I1 = I2: ω1 = A cos(Ωt + φ), ω2 = A sin(Ωt + φ), ω3 constant with
    Ω = ω3 (I3 − I1)/I1, so ω1,n = A Ωⁿ cos(φ + nπ/2)/n!, ω2,n = A Ωⁿ sin(φ + nπ/2)/n!, ω3,n = 0
    (n ≥ 1): within 1e-13 of A |Ω|ⁿ/n! (measured ≤ 2e-16)."""
    desc, k = kernel("euler_poisson_sym")
    assert desc.states[:3] == ("omega1", "omega2", "omega3") and desc.params == ("I1", "I3")
    I1, I3 = 1.0, 0.4
    w = np.array([3.0, -2.0, 20.0])
    y = np.concatenate([w, [0.1, 0.2, 0.97], [0.99, 0.0, -0.1]])
    rc, got = c_coefficients(k.lib, desc.name, y, [I1, I3], 25)
    assert rc == 0
    A, phi, Om = math.hypot(w[0], w[1]), math.atan2(w[1], w[0]), w[2] * (I3 - I1) / I1
    n = np.arange(26)
    fact = np.array([float(math.factorial(int(j))) for j in n])
    amp, size = A * Om ** n / fact, A * abs(Om) ** n / fact
    assert np.all(np.abs(got[0] - amp * np.cos(phi + n * np.pi / 2)) <= 1e-13 * size)
    assert np.all(np.abs(got[1] - amp * np.sin(phi + n * np.pi / 2)) <= 1e-13 * size)
    assert got[2, 0] == w[2] and np.all(got[2, 1:] == 0.0)


@pytest.mark.parametrize("order", [4, 8])
def test_the_truncated_series_has_its_order(order):
    """The series of order p through a point of the free symmetric top, against the closed form
    at τ and τ/2: the error falls by 2^(p+1) (measured order within 0.15 of p + 1)."""
    desc, k = kernel("euler_poisson_sym")
    I1, I3 = 1.0, 0.4
    w = np.array([3.0, -2.0, 20.0])
    y = np.concatenate([w, [0.1, 0.2, 0.97], [0.99, 0.0, -0.1]])
    _, c = c_coefficients(k.lib, desc.name, y, [I1, I3], order)
    A, phi, Om = math.hypot(w[0], w[1]), math.atan2(w[1], w[0]), w[2] * (I3 - I1) / I1

    def err(tau):
        series = np.polynomial.polynomial.polyval(tau, c[0])
        return abs(series - A * math.cos(Om * tau + phi))

    tau = 0.4 / abs(Om) if order == 4 else 1.0 / abs(Om)
    measured = math.log2(err(tau) / err(tau / 2))
    assert abs(measured - (order + 1)) < 0.15, measured


# ---------------------------------------------------------------------------------------------
# 2. every rule, on a model that uses them all (no shipped model has exp, log, pow, atan2, t)


def _rules_model():
    y0, y1, y2 = sp.symbols("y0 y1 y2", real=True)
    a, b = sp.symbols("a b", positive=True)
    t = sp.Symbol("t")
    rhs = (sp.exp(-y1) * sp.sqrt(1 + y0**2) - a * sp.log(2 + y2**2) + sp.sin(t),
           sp.atan2(y2, y0 + 2) + sp.atan(y1) + (1 + y1**2) ** sp.Rational(1, 3) / (b + y0**2),
           sp.Piecewise((y0 * y1, y2 > 0), (-y0, True)) + y0**3 - 1 / y1**2
           + sp.cos(y2) * y2**4 + (2 + y0**2) ** (-sp.Rational(1, 2)))
    return Model(name="taylor_rules", formulation="test", description="every Taylor rule",
                 states=(y0, y1, y2), params=(a, b), rhs=rhs, domain=(y1**2 - sp.Rational(1, 100),))


def _rules_library(model, name="taylor_rules"):
    ny, npar = len(model.states), len(model.params)
    header = (f"#ifndef {name.upper()}_H\n#define {name.upper()}_H\n#define {name}_NY {ny}\n"
              f"#define {name}_NP {npar}\n#endif\n")
    files = {f"{name}.h": header}
    files.update(render_solvers(name, ny))
    files.update(render_taylor(model))
    # strict C99, every warning an error: the Taylor file compiled alone (the solvers only)
    return compile_library(name, files, f"{name}_taylor.c", (*STRICT_FLAGS, "-O2", "-fPIC"))


def test_every_rule_against_the_composed_series_and_strict_c99():
    model = _rules_model()
    d = decompose(KernelSpec.of(model))
    assert {"add", "scale", "mul", "sqr", "div", "sqrt", "pow", "exp", "log", "sincos", "atan2",
            "piecewise"} <= set(d.rules)
    assert d.time_node is not None
    lib = _rules_library(model)
    y, p = [0.3, 0.7, 0.4], [0.8, 1.5]
    for t0, yy in ((0.0, y), (1.3, [0.3, 0.7, -0.4])):  # both branches of the piecewise term
        rc, got = c_coefficients(lib, "taylor_rules", yy, p, 12, t=t0)
        assert rc == 0
        assert_coefficients_close(got, composed_series(model, yy, p, 12, t0=t0))
    # the domain guard (y1² > 1/100) fails at order 0: the rhs's code 1, as <prefix>_rhs does
    assert c_coefficients(lib, "taylor_rules", [0.3, 0.05, 0.4], p, 4)[0] == 1
    assert c_coefficients(lib, "taylor_rules", y, p, TAYLOR["taylor"].max_order + 1)[0] == -1


def test_the_solver_alone_against_mpmath():
    """taylor_rules_run_taylor from given starts (no model header beyond the sizes, no init map) against
    SciPy's DOP853 at rtol 1e-13 on the lambdified SymPy right-hand side, t ∈ [0, 1], rtol
    1e-12: within 1e-11."""
    model = _rules_model()
    lib = _rules_library(model)
    fn = lib.taylor_rules_run_taylor
    fn.argtypes = [ctypes.POINTER(SaveAt), ctypes.c_long, _P, _P, _D, _D, ctypes.c_long, _P, _P, _P]
    fn.restype = _I
    y0, p = np.array([0.3, 0.7, 0.4]), np.array([0.8, 1.5])
    t_out = np.linspace(0.0, 1.0, 11)
    y = np.full((11, 3), np.nan)
    st = np.zeros(1, dtype=STATS_DTYPE)
    rc = fn(saveat(t_out, outputs=False), 1, y0.ctypes.data, p.ctypes.data, 1e-12, 1e-14, 10000,
            y.ctypes.data, None, st.ctypes.data)
    assert rc == 0 and st[0]["status"] == 0 and st[0]["nfev"] == st[0]["nstep"] > 0
    t = sp.Symbol("t")
    f = sp.lambdify([t, list(model.states), list(model.params)], list(model.rhs), modules="math")
    ref = solve_ivp(lambda tt, yy: f(tt, yy, list(p)), (0.0, 1.0), y0, method="DOP853",
                    t_eval=t_out, rtol=1e-13, atol=1e-15).y.T
    assert np.max(np.abs(y - ref)) < 1e-11


def _expo_rule(tmp_path, monkeypatch):
    """A rule added from data alone: ``expo`` (the exp recurrence under a name of its own), its
    file (exp's, its helpers renamed) in a templates folder searched first, and its one row of
    RULE_TABLE taking the SymPy function ``expo``. Returns that function."""
    import jinja2

    folder = tmp_path / "c" / "taylor_rules"
    folder.mkdir(parents=True)
    text = (ROOT / "templates" / "c" / "taylor_rules" / "exp.j2").read_text()
    (folder / "expo.j2").write_text(text.replace("tc_exp(", "tc_expo(").replace("tcl_exp(", "tcl_expo("))
    env = environment()
    monkeypatch.setattr(env, "loader", jinja2.ChoiceLoader([jinja2.FileSystemLoader(str(tmp_path)),
                                                            env.loader]))
    expo = sp.Function("expo")
    monkeypatch.setattr(jet, "RULE_TABLE", (*jet.RULE_TABLE, jet.Rule("expo", 1.0, unary=(expo,))))
    return expo


def _exp_model(f, outputs=False):
    y0, y1 = sp.symbols("y0 y1", real=True)
    a = sp.Symbol("a", positive=True)
    return Model(name="expo_model", formulation="test", description="", states=(y0, y1), params=(a,),
                 rhs=(f(-y1) * y0, a * y0 - f(y0 * y1)), outputs={"q": y0 * y1} if outputs else {})


def test_a_rule_from_its_file_and_one_row_gives_the_scalar_and_the_lanes_jet(tmp_path, monkeypatch):
    """A rule added as its file and one row of RULE_TABLE, nothing else: the scalar jet calls its
    helper and gives exp's coefficients bit for bit (the same recurrence), and the lanes jet (a
    model with outputs) defines and calls its lanes helper, from the same steps."""
    expo = _expo_rule(tmp_path, monkeypatch)
    d = decompose(KernelSpec.of(_exp_model(expo)))
    assert "expo" in d.rules and "exp" not in d.rules
    lib = _rules_library(_exp_model(expo), "expo_model")
    files = render_taylor(_exp_model(expo))
    source = files["expo_model_taylor.c"]
    assert "tc_expo(int n" in files["derive_taylor_base.inc"]  # its helper, from its file
    assert "tc_expo(n, " in source and "tc_exp(n, " not in source  # the jet calls it
    monkeypatch.undo()  # the shipped rules again: the same model with exp
    ref = _rules_library(_exp_model(sp.exp), "expo_model")
    y, p = [0.4, -0.3], [1.7]
    assert lib._name != ref._name  # two libraries (their sources differ)
    got, want = (c_coefficients(lib_, "expo_model", y, p, 14) for lib_ in (lib, ref))
    assert got[0] == want[0] == 0 and got[1].tobytes() == want[1].tobytes()
    expo = _expo_rule(tmp_path / "again", monkeypatch)
    files = render_taylor(_exp_model(expo, outputs=True))
    lanes = files["expo_model_taylor.c"]
    steps = [s for s in decompose(KernelSpec.of(_exp_model(expo, outputs=True))).steps if s.rule == "expo"]
    assert len(steps) == 2 and "tcl_expo(int n" in files["derive_taylor_base.inc"]
    for s in steps:
        call = f"tc_expo(n, u[{s.args[0]}], u[{s.index}]);"
        assert call in lanes and f"tcl_expo(n, u[{s.args[0]}], u[{s.index}]);" in lanes


def test_the_jet_is_not_read_back_from_c_text():
    """The decomposition and its rendering hold no regular expression: the lanes jet, the
    scopes and the dependencies come from the steps, not from the scalar jet's C."""
    for module in (jet, taylor_codegen):
        assert "import re\n" not in inspect.getsource(module), module.__name__


def test_a_function_without_a_rule_is_named():
    x = sp.Symbol("x")
    model = Model(name="m", formulation="test", description="", states=(x,), params=(),
                  rhs=(sp.tanh(x),))
    with pytest.raises(NoTaylorRule, match="no Taylor rule for tanh"):
        decompose(KernelSpec.of(model))


# ---------------------------------------------------------------------------------------------
# 3. the registry and the step control


def test_taylor_is_a_registered_tolerance_method():
    m = compiled_methods()["taylor"]
    assert m.driver == "taylor" and tolerance_driven("taylor") and "taylor" not in fixed_step_methods()
    assert [nm for _, nm in m.params] == ["rtol", "atol", "max_steps"]
    assert "taylor" in SCENE_METHODS
    # Jorba–Zou's order, as the C driver takes it
    assert [m.order(r, r * 1e-2) for r in (1e-6, 1e-8, 1e-10, 1e-12, 1e-16)] == [8, 11, 13, 15, 20]


def test_cyclic_angles_are_out_of_the_step_control():
    """α and γ of the Euler-angle top appear in no right-hand side; β does."""
    m = build(*shipped_keys()["heavy_top"])
    assert dict(zip(m.state_names, controlled_states(m))) == {
        "alpha": False, "beta": True, "gamma": False, "alpha_dot": True, "beta_dot": True,
        "gamma_dot": True}
    assert all(controlled_states(build(*shipped_keys()["rigid_body"])))


# ---------------------------------------------------------------------------------------------
# 4. the error against the tolerance, on the scenes with exact solutions


def _reference(res):
    sc = res.scene
    b, i = sc.body, sc.initial
    if sc.effects:
        g = sc.gravity
        return exact.heavy_top(b.I1, b.I3, g.M, g.g, g.l, i.alpha, i.beta, i.gamma,
                               i.alpha_dot, i.beta_dot, i.gamma_dot, res.t)
    return exact.free_symmetric(b.I1, b.I3, np.array(i.omega), res.t,
                                exact.euler_matrix(i.alpha, i.beta, i.gamma))


def _error(res):
    ex = _reference(res)
    return max(float(np.max(np.abs(res.axis - ex.axis))),
               float(np.max(np.abs(res.omega - ex.omega))) / float(np.max(np.abs(ex.omega))))


@pytest.mark.parametrize("scene, formulation", [
    ("reference_top", "auto"), ("reference_top", "quaternion"), ("looping_top", "auto"),
    ("looping_top", "euler-poisson"), ("cuspidal_top", "quaternion"),
    ("free_symmetric", "quaternion"), ("free_symmetric", "euler-poisson")])
def test_error_follows_the_tolerance(scene, formulation):
    """rtol 1e-6 … 1e-12 (atol = rtol/100): the axis and ω (relative to |ω|) within rtol of the
    exact solution (measured 0.004–0.16 rtol), and the error falls with the tolerance (at 1e-12
    at most 1e-4 of the error at 1e-6; measured 1e-6)."""
    errs = []
    for rtol in (1e-6, 1e-8, 1e-10, 1e-12):
        res = derive.simulate(SCENES / f"{scene}.toml", method="taylor", rtol=rtol,
                              atol=rtol * 1e-2, formulation=formulation)
        assert res.method == "taylor"
        errs.append(_error(res))
        assert errs[-1] <= rtol, (rtol, errs[-1])
    assert errs[-1] <= 1e-4 * errs[0]


def test_a_steady_motion_is_one_step():
    """The free symmetric top in Euler angles is a steady precession: every coefficient past the
    first vanishes, and the whole run is one step, exact to round-off."""
    res = derive.simulate(SCENES / "free_symmetric.toml", method="taylor", formulation="euler-angles")
    assert res.nfev == 1
    assert _error(res) < 1e-13


def test_batch_equals_single_runs_and_dense_output_is_the_series():
    """simulate_batch is bit for bit the single runs; output times inside a step come from the
    series (1001 samples, ~100 steps: nfev far below the sample count)."""
    base = tomllib.loads((SCENES / "reference_top.toml").read_text())
    one = derive.simulate(base, method="taylor")
    assert one.nfev < len(one.t) / 5
    variants = [{**base, "initial": {**base["initial"], "beta": b}} for b in (0.8, 0.9, 1.1)]
    batch = derive.simulate_batch(variants, method="taylor")
    for v, r in zip(variants, batch):
        s = derive.simulate(v, method="taylor")
        assert r.method == "taylor"
        np.testing.assert_array_equal(s.axis, r.axis)
        assert s.nfev == r.nfev


# ---------------------------------------------------------------------------------------------
# 5. the hard cases, with method = "taylor"

sys.path.insert(0, str(Path(__file__).resolve().parent))
import test_hard_cases as _hard  # noqa: E402
import test_hard_cases_exact as _hard_exact  # noqa: E402

#: Hard cases that do not apply to the Taylor method, and why.
NOT_APPLICABLE = {
    "test_gauss_legendre_energy_bounded_over_a_million_steps":
        "about the Gauss-Legendre and RK4 fixed-step methods by name",
    "test_gauss_legendre_energy_bounded_while_rk4_drifts_over_two_hundred_thousand_steps":
        "about the Gauss-Legendre and RK4 fixed-step methods by name",
    "test_fast_top_mean_precession_over_a_million_nutations":
        "checks the exact solution alone (no integration)",
    # Its premise is an error that follows the tolerance from rtol 1e-11 to 1e-12; Taylor's is
    # 10-100 times below its tolerance, already within 3x of the round-off floor at 1e-11
    # (axis 1.4e-13 - 2.6e-12, floor ~6e-14): test_nearly_symmetric_body_with_taylor asks the
    # same at rtol 1e-9 and 1e-11.
    "test_nearly_symmetric_body_resolves_a_1e_6_asymmetry":
        "the error is already at the round-off floor at the case's rtol 1e-11",
}


def _hard_cases():
    out = []
    for mod in (_hard, _hard_exact):
        for name, fn in inspect.getmembers(mod, inspect.isfunction):
            if not name.startswith("test_") or name in NOT_APPLICABLE:
                continue
            combos = [{}]
            for mark in getattr(fn, "pytestmark", []):
                if mark.name != "parametrize":
                    continue
                names = [n.strip() for n in mark.args[0].split(",")]
                combos = [{**c, **dict(zip(names, v if len(names) > 1 else (v,)))}
                          for c in combos for v in mark.args[1]]
            for c in combos:
                ident = name + ("[" + ",".join(f"{k}={v}" for k, v in c.items()) + "]" if c else "")
                out.append(pytest.param(fn, c, id=ident))
    return out


@pytest.mark.parametrize("case, kwargs", _hard_cases())
def test_hard_case_with_taylor(case, kwargs, monkeypatch):
    real = derive.simulate

    def simulate(scene, **kw):
        kw.setdefault("method", "taylor")
        return real(scene, **kw)

    monkeypatch.setattr(derive, "simulate", simulate)
    case(**kwargs)


@pytest.mark.parametrize("formulation", ["quaternion", "euler-poisson"])
@pytest.mark.parametrize("I3", [0.4e-3, 1.6e-3], ids=["prolate", "oblate"])
def test_nearly_symmetric_body_with_taylor(I3, formulation):
    """The hard case's body (I2 = I1 (1 + 1e-6), 240 rad of circulation in 20 s) at rtol 1e-9,
    where Taylor's error is what dop853 reaches at 1e-11: ω (relative to |ω|) and the axis within
    1e-9 of free_asymmetric (measured ≤ 8.4e-12 and 1.4e-10), and the axis error falling at least
    5-fold at rtol 1e-11 (measured 20-70 fold: the error is the tolerance's, not a floor)."""
    eps, I1 = 1e-6, 1e-3
    I = (I1, I1 * (1 + eps), I3)
    w0, angles = np.array([3.0, -2.0, 20.0]), (0.3, 0.7, -0.2)
    scene = {"body": {"I1": I[0], "I2": I[1], "I3": I[2]},
             "initial": {"alpha": angles[0], "beta": angles[1], "gamma": angles[2], "omega": list(w0)},
             "simulate": {"t_end": 20.0, "samples": 2001, "method": "taylor"}}
    errs = []
    for rtol in (1e-9, 1e-11):
        res = derive.simulate(scene, formulation=formulation, rtol=rtol, atol=rtol * 1e-2)
        ex = exact.free_asymmetric(*I, w0, res.t, exact.euler_matrix(*angles))
        errs.append((float(np.max(np.abs(res.omega - ex.omega))) / float(np.linalg.norm(w0)),
                     float(np.max(np.abs(res.axis - ex.axis)))))
    assert errs[0][0] <= 1e-9 and errs[0][1] <= 1e-9
    assert errs[1][1] <= errs[0][1] / 5


def test_a_sweep_file_naming_taylor_runs_it(tmp_path):
    """A sweep file whose scene names taylor measures on the Taylor series (once refused: the
    measures read only dop853's dense polynomial; tests/test_sweep_taylor.py checks the values)."""
    scene = (SCENES / "sleeping_top.toml").read_text()
    body = "\n".join(f"[scene.{line[1:]}" if line.startswith("[") else
                     ("scene." + line if line.startswith("title") else line)
                     for line in scene.splitlines())
    spec = tmp_path / "sweep.toml"
    spec.write_text(body.replace("[scene.simulate]", '[scene.simulate]\nmethod = "taylor"')
                    + '\n[vary]\ninitial.beta = { from = 0.1, to = 0.2, num = 2 }\n'
                    + '[measure]\nnames = ["beta_max", "nfev"]\n')
    from derive.sweeps.spec import load

    assert load(str(spec)).method == "taylor"
    res = derive.sweep(str(spec), processes=1)
    assert (res.status == "ok").all() and np.isfinite(res.measures["beta_max"]).all()
    assert (res.measures["beta_max"] >= res.params["initial.beta"]).all()
