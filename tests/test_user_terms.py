"""Your own body: potentials and torques written in the scene.

The references are independent: the equations of motion written out here by hand (L̇ = τ in the
inertial frame, ṅ = n × ω̃, the dipole's torque m × B) and integrated with SciPy, or closed forms;
never derive against itself. Expressions from a stranger are refused by a whitelist, fast.
"""
import contextlib
import io
import math
import shutil
import time
from importlib import metadata
from pathlib import Path

import numpy as np
import pytest

import compile_once
import derive
from derive import SceneError, cli
from derive.codegen.render import ROOT
from derive.sim.scene import load_scene
from derive.symbolic import expressions as ex

BASE = {
    "body": {"I1": 1.0, "I3": 0.5},
    "initial": {"alpha": 0.0, "beta": 1.0, "gamma": 0.0,
                "alpha_dot": 0.3, "beta_dot": 0.0, "gamma_dot": 4.0},
    "simulate": {"t_end": 2.0, "samples": 21},
}


def scene(**tables) -> dict:
    out = {k: dict(v) for k, v in BASE.items()}
    for k, v in tables.items():
        if isinstance(v, dict) and k in out:
            out[k].update(v)
        else:
            out[k] = v
    return out


def magnet(V="-mu*B*R13", **params):
    return {"name": "magnet", "V": V, "params": params or {"mu": 0.2, "B": 1.5}}


# ---------------------------------------------------------------------------------------------
# safe expressions

HOSTILE = [
    ("-mu2*B*R13", "unknown name 'mu2'"),
    ("__import__('os').system('true')", "attribute access '.system'"),
    ("__import__('os')", "unknown function '__import__'"),
    ("R13.__class__", "attribute access '.__class__'"),
    ("().__class__.__bases__[0]", "subscripts"),
    ("[R13][0]", "subscripts"),
    ("(lambda: 1)()", "calls only the functions"),
    ("eval('1')", "unknown function 'eval'"),
    ("open", "unknown name 'open'"),
    ("9**9**9", "constant power"),
    ("R33**100000", "constant power"),
    ("10**10**10**10", "constant power"),
    ("(" * 300 + "mu" + ")" * 300, "not an expression"),
    ("-" * 990 + "mu", "nested more than"),
    ("+".join(["mu"] * 300), "nested more than"),
    ("mu*" * 400 + "B", "characters long"),
    ("R13 +", "not an expression"),
    ("R13; import os", "not an expression"),
    ("R13 if mu else B", "'if ... else'"),
    ("'text'", "string"),
    ("1e400*mu", "not a finite double"),
    ("sin(R13, R23)", "takes 1 argument"),
    ("mu\u2212B", "ASCII"),
    ("mu @ B", "operator '@'"),
    ("R13/(2 - 2)", "divides by zero"),
    ("mu*sqrt(-1)*R13", "not a real number: sqrt(-1)"),
    ("R13 + log(0)", "not a real number: log(0)"),
    ("exp(1000)*R13", "not a finite double"),
]


@pytest.mark.parametrize("text, what", HOSTILE, ids=[f"hostile{i}" for i in range(len(HOSTILE))])
def test_a_hostile_expression_is_refused_fast_naming_the_key(text, what):
    sc = scene(potential=[magnet(text)])
    t0 = time.perf_counter()
    with pytest.raises(SceneError) as err:
        load_scene(sc)
    assert time.perf_counter() - t0 < 1.0
    message = str(err.value)
    assert message.startswith("<dict>: potential.magnet.V: "), message
    assert what in message
    assert "\n" not in message


def test_the_command_line_refuses_an_unknown_name_with_exit_2_and_one_line(tmp_path):
    path = tmp_path / "top.toml"
    path.write_text('[body]\nI1 = 1.0\nI3 = 0.5\n[[potential]]\nname = "magnet"\n'
                    'V = "-mu2*B*R13"\nparams = { mu = 0.2, B = 1.5 }\n'
                    '[initial]\nalpha = 0.0\nbeta = 1.0\ngamma = 0.0\nomega = [0.0, 0.0, 3.0]\n'
                    '[simulate]\nt_end = 1.0\n')
    out, err = io.StringIO(), io.StringIO()
    t0 = time.perf_counter()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = cli.main(["simulate", str(path), "--out", str(tmp_path / "run.npz")])
    assert time.perf_counter() - t0 < 1.0
    assert rc == 2
    assert err.getvalue() == f"error: {path}: potential.magnet.V: unknown name 'mu2'\n"
    assert out.getvalue() == ""
    assert not (tmp_path / "run.npz").exists()


def test_a_torque_component_is_named_by_its_index_and_may_use_t_and_omega():
    sc = scene(torque=[{"name": "drive", "tau": ["0", "omega1*t", "A*cos(w*t) + B"],
                        "params": {"A": 0.01, "w": 3.0}}])
    with pytest.raises(SceneError, match=r"^<dict>: torque\.drive\.tau\.2: unknown name 'B'$"):
        load_scene(sc)
    # t and omega are the torque's, not the potential's
    with pytest.raises(SceneError, match=r"potential\.magnet\.V: unknown name 't'$"):
        load_scene(scene(potential=[magnet("-mu*B*R13*t")]))


@pytest.mark.parametrize("terms, key, what", [
    ({"potential": {"name": "a", "V": "R33"}}, "potential", "array of tables"),
    ({"potential": [{"V": "R33"}]}, r"potential\[0\]\.name", "missing required key"),
    ({"potential": [{"name": "a b", "V": "R33"}]}, r"potential\[0\]\.name", "letters"),
    ({"potential": [{"name": "a", "V": "R33"}, {"name": "a", "V": "R31"}]}, r"potential\.a",
     "name given twice"),
    ({"potential": [{"name": "a", "V": "R33", "tau": ["0"] * 3}]}, r"potential\.a\.tau",
     "unknown key"),
    ({"potential": [{"name": "a"}]}, r"potential\.a\.V", "missing required key"),
    ({"potential": [{"name": "a", "V": "k*R33", "params": {"k": "1"}}]},
     r"potential\.a\.params\.k", "finite number"),
    ({"potential": [{"name": "a", "V": "R33", "params": {"t": 1.0}}]},
     r"potential\.a\.params\.t", "choose another"),
    ({"potential": [{"name": "a", "V": 3.0}]}, r"potential\.a\.V", "must be a string"),
    ({"torque": [{"name": "a", "tau": ["0", "0"]}]}, r"torque\.a\.tau", "list of 3"),
    ({"torque": [{"name": "a", "frame": "lab", "tau": ["0"] * 3}]}, r"torque\.a\.frame",
     "body"),
])
def test_a_bad_term_table_is_one_line_naming_the_key(terms, key, what):
    with pytest.raises(SceneError, match=rf"^<dict>: {key}: .*{what}"):
        load_scene(scene(**terms))


def test_the_expression_becomes_sympy_from_its_tree():
    import sympy as sp

    mu, B, R13 = sp.symbols("mu B R13")
    parsed = ex.parse("-mu*B*R13 + 0.5*R13**2 + atan2(R13, 1)/2", {"mu", "B", "R13"})
    assert parsed.names == {"mu", "B", "R13"}
    got = ex.to_sympy(parsed, {"mu": mu, "B": B, "R13": R13})
    assert sp.simplify(got - (-mu * B * R13 + R13**2 / 2 + sp.atan2(R13, 1) / 2)) == 0
    # a float that is no short binary fraction stays the double the text denotes
    assert float(ex.to_sympy(ex.parse("0.1", ()), {})) == 0.1


def test_a_scene_with_terms_round_trips_through_to_dict():
    sc = load_scene(scene(potential=[magnet()],
                          torque=[{"name": "drive", "frame": "inertial",
                                   "tau": ["0", "0", "A*cos(w*t)"],
                                   "params": {"A": 0.01, "w": 3.0}}]))
    assert load_scene(sc.to_dict()) == sc
    assert [t.name for t in sc.terms] == ["magnet", "drive"]
    assert len(sc.effects) == 2
    values = sc.param_values()
    assert values[sc.terms[0].model_param("mu")] == 0.2
    assert values[sc.terms[1].model_param("w")] == 3.0


# ---------------------------------------------------------------------------------------------
# the physics, against independent references

def _R_zyz(a, b, c):
    """R = Rz(a) Ry(b) Rz(c), body → inertial, written out here (not derive's)."""
    def rz(x):
        return np.array([[math.cos(x), -math.sin(x), 0], [math.sin(x), math.cos(x), 0], [0, 0, 1]])

    ry = np.array([[math.cos(b), 0, math.sin(b)], [0, 1, 0], [-math.sin(b), 0, math.cos(b)]])
    return rz(a) @ ry @ rz(c)


def _rigid_body(I, torque, R0, w0, t_out):
    """I ω̃̇ = (I ω̃) × ω̃ + τ̃(t, R, ω̃),  Ṙ = R [ω̃]ₓ, integrated with SciPy's DOP853 at tight
    tolerances: the reference the user terms are checked against."""
    from scipy.integrate import solve_ivp

    I = np.asarray(I, float)

    def f(t, y):
        w, R = y[:3], y[3:].reshape(3, 3)
        tau = torque(t, R, w)
        wdot = (np.cross(I * w, w) + tau) / I
        W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        return np.concatenate([wdot, (R @ W).ravel()])

    sol = solve_ivp(f, (t_out[0], t_out[-1]), np.concatenate([w0, R0.ravel()]), t_eval=t_out,
                    method="DOP853", rtol=1e-12, atol=1e-14)
    assert sol.success
    return sol.y[:3].T, sol.y[3:].T.reshape(-1, 3, 3)


def test_a_dipole_in_a_uniform_horizontal_field_follows_the_hand_written_equations():
    """V = −μ B x̂·(R ê₃) = −μ B R13: a dipole μ along body axis 3 in a field B along the
    inertial x axis. Reference: τ̃ = μ ê₃ × B̃, B̃ = Rᵀ B x̂ = B (R11, R12, R13)."""
    mu, B = 0.2, 1.5
    sc = scene(potential=[magnet("-mu*B*R13", mu=mu, B=B)],
               initial={"alpha": 0.4, "beta": 1.0, "gamma": 0.3},
               simulate={"t_end": 3.0, "samples": 31})
    res = derive.simulate(sc)
    I = (1.0, 1.0, 0.5)

    def torque(t, R, w):
        return np.cross([0.0, 0.0, mu], B * R[0, :])

    ini = load_scene(sc).initial
    w, R = _rigid_body(I, torque, _R_zyz(ini.alpha, ini.beta, ini.gamma), np.array(ini.omega),
                       res.t)
    np.testing.assert_allclose(res.omega, w, atol=1e-8)
    np.testing.assert_allclose(res.axis, R[:, :, 2], atol=1e-8)
    # conservative: T + V is conserved, with V = −μ B R13 computed here from the reference R
    T = 0.5 * np.einsum("ij,j,ij->i", w, I, w)
    np.testing.assert_allclose(res.energy, T - mu * B * R[:, 0, 2], atol=1e-8)
    assert np.ptp(res.energy) < 1e-9


@pytest.mark.parametrize("method", ["auto", "dop853", "taylor"])
def test_a_drive_torque_about_axis_3_of_a_body_at_rest_has_its_closed_form(method):
    """τ̃ = (0, 0, A cos ωt) on a body at rest: ω̃₁ = ω̃₂ = 0 stay (Euler's equations), and
    ω̃₃ = A sin(ωt)/(ω I₃), γ = γ₀ + A (1 − cos ωt)/(ω² I₃), the axis fixed. Every method: the
    Taylor jet must carry the time's series (a user term's t is a real symbol, matched by
    name; once it was taken for a constant, cos(ωt) frozen over each step)."""
    A, wd, I3 = 0.05, 3.0, 0.5
    sc = scene(torque=[{"name": "drive", "frame": "body", "tau": ["0", "0", "A*cos(w*t)"],
                        "params": {"A": A, "w": wd}}],
               initial={"alpha": 0.2, "beta": 0.7, "gamma": 0.1, "alpha_dot": 0.0,
                        "gamma_dot": 0.0},
               simulate={"t_end": 4.0, "samples": 41, "method": method})
    res = derive.simulate(sc)
    t = res.t
    if method == "taylor":  # a batch's Taylor driver too
        end = derive.simulate_batch([sc, sc], outputs="final")
        np.testing.assert_allclose(end.omega[:, 2], A * np.sin(wd * t[-1]) / (wd * I3), atol=1e-10)
    np.testing.assert_allclose(res.omega[:, 2], A * np.sin(wd * t) / (wd * I3), atol=1e-10)
    np.testing.assert_allclose(res.omega[:, :2], 0.0, atol=1e-12)
    np.testing.assert_allclose(res.gamma, 0.1 + A * (1 - np.cos(wd * t)) / (wd**2 * I3),
                               atol=1e-9)
    np.testing.assert_allclose(res.axis, np.tile(res.axis[0], (len(t), 1)), atol=1e-12)


def test_a_constant_inertial_torque_makes_L_grow_linearly():
    """τ⁰ = (τx, 0, τz) fixed in space: L⁰(t) = L⁰(0) + τ⁰ t, so ẑ·L = p_α grows as
    L⁰_z(0) + τz t and |L̃|² = |L⁰(0) + τ⁰ t|² (a rotation keeps the length)."""
    tx, tz = 0.3, -0.2
    sc = scene(body={"I1": 1.0, "I2": 0.8, "I3": 0.5},
               torque=[{"name": "push", "frame": "inertial", "tau": ["tx", "0", "tz"],
                        "params": {"tx": tx, "tz": tz}}],
               simulate={"t_end": 3.0, "samples": 31})
    res = derive.simulate(sc)
    ini = load_scene(sc).initial
    I = np.array([1.0, 0.8, 0.5])
    L0 = _R_zyz(ini.alpha, ini.beta, ini.gamma) @ (I * np.array(ini.omega))
    L = L0 + np.outer(res.t, [tx, 0.0, tz])
    np.testing.assert_allclose(res.p_alpha, L[:, 2], atol=1e-9)
    np.testing.assert_allclose(np.sum(res.L**2, axis=1), np.sum(L**2, axis=1), atol=1e-8)


@pytest.mark.parametrize("formulation", [
    "auto", "quaternion",
    # each formulation is a model derived and compiled on a cold cache: the rest run with -m slow
    pytest.param("euler-poisson", marks=pytest.mark.slow),
    pytest.param("euler-angles", marks=pytest.mark.slow),
    pytest.param("reduced", marks=pytest.mark.slow),
])
def test_a_potential_restating_gravity_gives_the_gravity_trajectory(formulation):
    grav = {"M": 1.2, "g": 9.81, "l": 0.1}
    a = derive.simulate(scene(gravity=grav), formulation=formulation)
    b = derive.simulate(scene(potential=[{"name": "g", "V": "M*g*l*R33", "params": grav}]),
                        formulation=formulation)
    assert a.formulation == b.formulation
    for key in ("axis", "omega", "energy", "p_alpha", "p_gamma", "beta"):
        np.testing.assert_allclose(getattr(b, key), getattr(a, key), atol=1e-9, rtol=0,
                                   err_msg=key)


# ---------------------------------------------------------------------------------------------
# batches and sweeps over a term's params

def test_a_batch_of_one_user_body_equals_its_single_runs():
    scenes = [scene(potential=[magnet("-mu*B*R13", mu=mu, B=1.5)]) for mu in (0.1, 0.3)]
    batch = derive.simulate_batch(scenes)
    assert batch[0].model == batch[1].model
    for sc, res in zip(scenes, batch):
        single = derive.simulate(sc, formulation=res.formulation)
        np.testing.assert_array_equal(res.axis, single.axis)
        np.testing.assert_array_equal(res.energy, single.energy)


def test_a_sweep_varies_a_potential_param_as_a_single_run_does():
    """A sweep over potential.magnet.mu: each point's largest tilt (the sweep's dense output)
    is that of derive.simulate with the same mu, sampled finely (by DOP853, the sweep's method,
    whose library the single runs of this body share), and differs between points."""
    from derive.sweeps.spec import load
    from derive.sweeps.engine import sweep

    base = scene(potential=[magnet("-mu*B*R13", mu=0.2, B=1.5)],
                 simulate={"t_end": 2.0, "samples": 2})
    spec = {"scene": base, "vary": {"potential.magnet.mu": {"values": [0.1, 2.0]}},
            "measures": ["beta_max"]}
    table = sweep(spec, processes=1)
    assert list(table.status) == ["ok", "ok"]
    got = table.measures["beta_max"]
    assert abs(got[1] - got[0]) > 1e-2
    for i, mu in enumerate((0.1, 2.0)):
        assert table.params["potential.magnet.mu"][i] == mu
        single = derive.simulate(scene(potential=[magnet("-mu*B*R13", mu=mu, B=1.5)],
                                       simulate={"t_end": 2.0, "samples": 4001}), method="dop853")
        assert got[i] == pytest.approx(single.beta.max(), abs=1e-6)
    with pytest.raises(SceneError, match=r"vary\.potential\.magnet\.nu: .*no param 'nu'"):
        load({**spec, "vary": {"potential.magnet.nu": {"values": [0.1]}}})
    with pytest.raises(SceneError, match=r"vary\.torque\.magnet\.mu: .*no \[\[torque\]\]"):
        load({**spec, "vary": {"torque.magnet.mu": {"values": [0.1]}}})


# ---------------------------------------------------------------------------------------------
# conserved quantities found by symmetry, and seen in the trajectories

def _symmetries(sc):
    from derive.symbolic.symmetries import symmetries

    s = load_scene(sc)
    return symmetries(s.effects, s.symmetric)


@pytest.mark.parametrize("V, p_alpha, p_gamma", [
    ("-mu*B*R33", True, True),          # dipole on axis 3, field vertical: both
    pytest.param("-mu*B*R13", False, True, marks=pytest.mark.slow),  # field horizontal: axis 3 only
    ("-mu*B*R31", True, False),         # dipole across axis 3, field vertical: about z only
    ("mu*B*cos(beta)**2", True, True),  # a function of the tilt alone, written in the angles
    pytest.param("mu*B*sin(alpha)", False, True, marks=pytest.mark.slow),
])
def test_conserved_momenta_are_found_by_symmetry_and_hold_in_the_trajectory(V, p_alpha, p_gamma):
    sc = scene(potential=[magnet(V, mu=0.4, B=1.5)], simulate={"t_end": 3.0, "samples": 61})
    found = _symmetries(sc)
    assert (found["p_alpha"], found["p_gamma"], found["energy"]) == (p_alpha, p_gamma, True)
    res = derive.simulate(sc, formulation="quaternion")
    drift = {k: np.ptp(getattr(res, k)) for k in ("p_alpha", "p_gamma", "energy")}
    assert drift["energy"] < 1e-9
    for k, conserved in (("p_alpha", p_alpha), ("p_gamma", p_gamma)):
        assert (drift[k] < 1e-9) if conserved else (drift[k] > 1e-4), (k, drift[k])


def test_a_torque_breaks_the_energy_and_what_it_acts_along():
    sc = scene(torque=[{"name": "spin", "tau": ["0", "0", "0.1"]}])
    found = _symmetries(sc)
    assert not found["energy"] and not found["p_gamma"] and not found["p_alpha"]
    assert "does work" in found["why"]["energy"]
    # a torque about the inertial vertical breaks p_alpha alone (and the energy)
    sc = scene(torque=[{"name": "z", "frame": "inertial", "tau": ["0", "0", "0.1"]}],
               body={"I1": 1.0, "I2": 1.0, "I3": 0.5})
    found = _symmetries(sc)
    assert (found["energy"], found["p_alpha"], found["p_gamma"]) == (False, False, False)
    # a horizontal inertial torque leaves p_alpha = ẑ·L
    sc = scene(torque=[{"name": "x", "frame": "inertial", "tau": ["0.1*cos(t)", "0", "0"]}])
    found = _symmetries(sc)
    assert found["p_alpha"] and not found["energy"]
    res = derive.simulate(sc)
    assert np.ptp(res.p_alpha) < 1e-9 and np.ptp(res.energy) > 1e-4


# ---------------------------------------------------------------------------------------------
# derive analyze for the user's body

def test_analyze_finds_the_compass_equilibria_of_a_dipole_with_their_closed_forms():
    """V = −μB R13 (a compass needle along body axis 3, field along x): rest at V = −μB
    (axis 3 along +x) is stable, with small oscillations λ = ±i√(μB/I₁), ±i√(μB/I₂) about the
    two axes across the needle; V = +μB is unstable with λ = ±√(μB/I₁), ±√(μB/I₂). Both are
    circles of equilibria (V does not change as the needle spins about itself)."""
    mu, B, I1, I2 = 0.2, 1.5, 1.0, 0.8
    sc = scene(body={"I1": I1, "I2": I2, "I3": 0.5}, potential=[magnet("-mu*B*R13", mu=mu, B=B)])
    a = derive.analyze(sc)
    data = a.to_json()
    assert data["case"] == "general" and not data["dissipative"]
    assert [i["name"] for i in data["integrals"]] == ["energy", "n_squared"]
    assert [i["name"] for i in data["not_conserved"]] == ["p_alpha", "p_gamma"]
    assert "not invariant about the vertical" in data["not_conserved"][0]["why"]
    eqs = sorted(data["equilibria"], key=lambda e: e["values"]["V"])
    assert [e["stable"] for e in eqs] == [True, False]
    assert [e["values"]["family"] for e in eqs] == [1, 1]
    for e, sign in zip(eqs, (-1, 1)):
        assert e["values"]["V"] == pytest.approx(sign * mu * B, rel=1e-9)
        assert e["values"]["n"][2] == pytest.approx(0.0, abs=1e-7)  # axis 3 horizontal (along ±x)
        lam = [complex(*z) for z in e["eigenvalues"] if abs(complex(*z)) > 1e-6]
        rates = [math.sqrt(mu * B / I1), math.sqrt(mu * B / I2)]
        expect = [s * (1j if sign < 0 else 1) * r for r in rates for s in (1, -1)]
        np.testing.assert_allclose(sorted(lam, key=lambda z: (z.real, z.imag)),
                                   sorted(expect, key=lambda z: (z.real, z.imag)), atol=1e-7)
    text = a.to_markdown()
    assert "potential `magnet`" in text and "not conserved" in text


def test_analyze_of_a_driven_body_lists_no_energy_integral_and_no_rest_equilibria():
    sc = scene(torque=[{"name": "drive", "tau": ["0", "0", "A*cos(w*t)"],
                        "params": {"A": 0.01, "w": 3.0}}])
    data = derive.analyze(sc).to_json()
    assert [i["name"] for i in data["integrals"]] == ["n_squared"]
    assert "does work" in data["not_conserved"][0]["why"] and data["dissipative"] is True
    assert data["equilibria"] == []


def test_the_figure_of_a_driven_body_does_not_call_its_energy_change_an_error():
    pytest.importorskip("matplotlib")
    from derive.sim import plots

    # the documented driven body (its model is the one the energy summary and plot tests run)
    res = derive.simulate(str(ROOT / "docs" / "own-body" / "magnetic_top.toml"), t_end=0.5, samples=101)
    fig = plots.figure(res)
    titles = {ax.get_label(): ax.get_title() for ax in fig.axes}
    assert "not conserved: torque 'drive' does work" in titles["energy"]
    assert "error" not in titles["energy"]
    assert "not conserved" in titles["momenta"] and "potential 'magnet'" in titles["momenta"]
    import matplotlib.pyplot as plt

    plt.close(fig)


def test_a_warm_run_of_a_user_body_imports_no_sympy(tmp_path):
    """Validation reads the expressions with ast alone; the model comes from the compile
    cache: a second process runs the body without SymPy. Both processes use a cache of this
    test's own, so that nothing another test does to the shared cache can change the second
    run's path. The first process's cache is a function of the package, its libraries and the
    body: it is kept for exactly these (``compile_once.once``, which runs the first process
    again after any change to one), and the second process runs on a copy of it."""
    import json
    import os
    import subprocess
    import sys

    root = Path(__file__).resolve().parents[1]
    sc = scene(potential=[magnet()], torque=[{"name": "drive", "tau": ["0", "0", "A*cos(w*t)"],
                                              "params": {"A": 0.01, "w": 3.0}}])
    code = ("import json, sys, derive; "
            "derive.simulate(json.loads(sys.argv[1]), formulation='quaternion'); "
            "print([m for m in ('sympy', 'jinja2') if m in sys.modules])")

    def run(cache: Path) -> subprocess.CompletedProcess:
        out = subprocess.run([sys.executable, "-c", code, json.dumps(sc)], capture_output=True, text=True,
                             env=dict(os.environ, DERIVE_CACHE=str(cache)), timeout=300)
        assert out.returncode == 0, out.stderr
        return out

    def first(work: Path) -> None:
        assert "sympy" in run(work / "cache").stdout  # the first derived it (with SymPy) ...

    inputs = compile_once.files_under(root / "derive", root / "templates", root / "generated")
    what = ["a user body derived", json.dumps(sc), sys.version,
            *(f"{dist} {metadata.version(dist)}" for dist in ("numpy", "sympy", "jinja2")),
            repr(sorted((k, v) for k, v in os.environ.items() if k.startswith("SYMPY_")))]
    shutil.copytree(compile_once.once(what, inputs, first) / "cache", tmp_path / "cache", symlinks=True)
    second = run(tmp_path / "cache")
    assert second.stdout.strip() == "[]", second.stderr  # ... the second did not


def test_a_sweep_task_registers_the_terms_a_fresh_worker_does_not_know():
    """A Dask worker is a fresh process: only the built-in effects are registered there. The
    task carries the terms and registers them before it loads the model."""
    from derive.runtime import catalogue
    from derive.sweeps import measures as ms
    from derive.sweeps.spec import load
    from derive.sweeps.tasks import run_chunk
    from derive.symbolic import effects

    base = scene(potential=[magnet("-mu*B*R13", mu=0.2, B=1.5)],
                 simulate={"t_end": 1.0, "samples": 2})
    sp = load({"scene": base, "vary": {"potential.magnet.mu": {"values": [0.1, 0.4]}},
               "measures": ["beta_max"]})
    name = sp.terms[0].effect
    args = (sp.key, sp.method, sp.inputs, sp.ps, np.array([0.0, 1.0]), ms.driver_args(sp.method, 1e-10, 1e-12, 10**6),
            ms.config_of(("beta_max",), {}))
    expected = run_chunk(*args)
    effects.unregister(name)  # as in a fresh worker
    catalogue.clear_memory()
    try:
        with pytest.raises(KeyError):
            catalogue.describe(sp.key)
        got = run_chunk(*args, None, sp.terms)
        assert name in effects.REGISTRY
        np.testing.assert_array_equal(got[0], expected[0])
    finally:
        catalogue.clear_memory()


def test_a_bodys_effects_do_not_depend_on_which_terms_this_process_registered_first():
    """A term's effect is registered when a scene first names it, so registration order is the
    process's history; the order of a model's effects (and with it its name, its parameter
    layout and the first reason a plot gives) must not be: built-in effects first, then the
    user's terms by kind (potentials, then torques) and content. A fresh process must find the
    model this one made."""
    import json
    import subprocess
    import sys

    from derive.sim.scene import load_scene

    drive = {"name": "drive", "tau": ["0", "0", "A*cos(w*t)"], "params": {"A": 0.02, "w": 2.0}}
    load_scene(scene(torque=[drive]))  # the torque's effect registered first, alone
    sc = scene(potential=[magnet("-mu*B*R13", mu=0.3, B=1.1)], torque=[drive])
    effects = load_scene(sc).effects
    kinds = [name.split("_")[0] for name in effects]
    assert kinds == ["potential", "torque"], effects
    code = ("import json, sys; from derive.sim.scene import load_scene; "
            f"print(json.dumps(load_scene(json.loads({json.dumps(json.dumps(sc))})).effects))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert tuple(json.loads(out.stdout)) == effects
