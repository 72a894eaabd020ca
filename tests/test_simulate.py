"""Scenes through the whole pipeline: outputs of the contract, effects, formulations, errors."""
import numpy as np
import pytest

import derive
from cli_in_process import derive_main
from compiled_models import compiled_model
from derive.runtime.catalogue import describe
from derive.sim import result, simulation
from derive.symbolic.formulations import REGISTRY
from derive.codegen.render import ROOT

SCENES = ROOT / "scenes"
ARRAYS = {"t": 1, "alpha": 1, "beta": 1, "gamma": 1, "omega": 2, "axis": 2, "energy": 1, "p_alpha": 1, "p_gamma": 1}


def top(**over):
    """A heavy symmetric top scene dict; keyword arguments replace whole tables."""
    scene = {
        "body": {"I1": 1.0, "I3": 0.4},
        "gravity": {"M": 1.0, "g": 9.81, "l": 0.1},
        "initial": {"alpha": 0.0, "beta": 0.6, "gamma": 0.0, "alpha_dot": -0.5, "beta_dot": 0.0, "gamma_dot": 12.0},
        "simulate": {"t_end": 3.0, "samples": 301, "rtol": 1e-11, "atol": 1e-13},
    }
    scene.update(over)
    return {k: v for k, v in scene.items() if v is not None}


run_cli = derive_main


def test_cli_writes_every_output_array(tmp_path):
    out = tmp_path / "out.npz"
    png = tmp_path / "out.png"
    r = run_cli("simulate", str(SCENES / "looping_top.toml"), "-o", str(out), "--plot", str(png))
    assert r.returncode == 0, r.stderr
    data = np.load(out)
    n = len(data["t"])
    for name, ndim in ARRAYS.items():
        assert data[name].ndim == ndim and data[name].shape[0] == n and np.all(np.isfinite(data[name])), name
    assert data["omega"].shape == (n, 3) and data["axis"].shape == (n, 3)
    from derive.sim import plan as plans
    from derive.sim.scene import load_scene

    assert str(data["method"]) == plans.make(load_scene(SCENES / "looping_top.toml")).method  # auto's
    assert str(data["formulation"]) in REGISTRY
    assert int(data["nfev"]) > 0
    assert png.stat().st_size > 10_000 and png.read_bytes()[:4] == b"\x89PNG"


def test_bad_scene_exits_2_with_one_line_and_leaves_no_output(tmp_path):
    scene = tmp_path / "typo.toml"
    import re

    text = (SCENES / "looping_top.toml").read_text()
    scene.write_text(re.sub(r"(?m)^I3\s*=", "I4 =", text, count=1))
    assert "I4 =" in scene.read_text()
    out = tmp_path / "out.npz"
    r = run_cli("simulate", str(scene), "-o", str(out))
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and "I4" in lines[0]
    assert not out.exists()


def test_numerical_failure_exits_3_and_keeps_existing_output(tmp_path):
    """RK4 with a step far beyond its stability limit overflows: exit 3, one line saying where."""
    scene = tmp_path / "unstable.toml"
    scene.write_text((SCENES / "tennis_racket.toml").read_text())
    out = tmp_path / "out.npz"
    out.write_bytes(b"precious")
    r = run_cli("simulate", str(scene), "-o", str(out), "--method", "rk4")
    assert r.returncode == 0, r.stderr  # with its default step RK4 is fine...
    out.write_bytes(b"precious")
    text = scene.read_text().replace("[simulate]", "[simulate]\nh = 5.0", 1)
    scene.write_text(text.replace("t_end =", "t_end = 1000.0 #", 1))
    r = run_cli("simulate", str(scene), "-o", str(out), "--method", "rk4")
    assert r.returncode == 3, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and "t = " in r.stderr
    assert out.read_bytes() == b"precious"


def pole_crossing():
    """p_α = p_γ and β̇ toward the pole: the axis sweeps through β = 0 (a sleeping top nodding
    across the vertical). α̇ = I₃γ̇ / (I₁(1 + cos β) − I₃ cos β) makes p_α = p_γ."""
    I1, I3, b0, gd = 1.0, 0.4, 0.3, 10.0
    ad = I3 * gd / (I1 * (1 + np.cos(b0)) - I3 * np.cos(b0))
    return {"body": {"I1": I1, "I3": I3}, "gravity": {"M": 1.0, "g": 9.81, "l": 0.1},
            "initial": {"alpha": 0.0, "beta": b0, "gamma": 0.0, "alpha_dot": ad, "beta_dot": -2.0, "gamma_dot": gd},
            "simulate": {"t_end": 3.0, "rtol": 1e-12, "atol": 1e-14}}


def test_auto_formulation_crosses_the_pole_accurately():
    scene = pole_crossing()
    ref = derive.simulate(scene, formulation="quaternion", rtol=1e-13, atol=1e-15)
    assert np.min(np.hypot(ref.axis[:, 0], ref.axis[:, 1])) < 2e-2  # it does pass (next to) the pole
    res = derive.simulate(scene)
    assert np.max(np.abs(res.axis - ref.axis)) < 1e-9
    assert np.ptp(res.energy) < 1e-10 * abs(res.energy[0])


def test_euler_angles_at_the_pole_refuse_or_stay_right():
    """Asked for explicitly, the Euler-angle formulation either reports the singularity or
    returns a correct trajectory; never a silently wrong one."""
    scene = pole_crossing()
    ref = derive.simulate(scene, formulation="quaternion", rtol=1e-13, atol=1e-15)
    try:
        res = derive.simulate(scene, formulation="euler-angles")
    except derive.IntegrationError as exc:
        assert "singular" in str(exc) or "domain" in str(exc)
    else:
        assert np.max(np.abs(res.axis - ref.axis)) < 1e-8


def test_no_gravity_scene_gets_kernel_without_gravity_parameters():
    res = derive.simulate(top(gravity=None))
    model = describe((res.formulation, True, res.scene.effects))
    assert not {"M", "g", "l"} & set(model.params)
    assert "g" not in (compiled_model(res.formulation, True, (), res.method).param_names)


@pytest.mark.parametrize("formulation", ["reduced", "quaternion", "euler-angles"])
def test_disabling_gravity_equals_zero_g(formulation):
    # dop853: the method whose libraries of these models the suite builds anyway
    off = derive.simulate(top(gravity=None), formulation=formulation, method="dop853")
    zero = derive.simulate(top(gravity={"M": 1.0, "g": 0.0, "l": 0.1}), formulation=formulation,
                           method="dop853")
    assert np.max(np.abs(off.axis - zero.axis)) < 1e-12
    assert np.max(np.abs(off.energy - zero.energy)) < 1e-12 * np.max(np.abs(off.energy))


@pytest.mark.parametrize("formulation", ["quaternion", "euler-angles"])
def test_disabling_damping_equals_zero_c(formulation):
    off = derive.simulate(top(), formulation=formulation)
    zero = derive.simulate(top(damping={"c": 0.0}), formulation=formulation)
    assert np.max(np.abs(off.axis - zero.axis)) < 1e-12


def test_formulations_agree_on_a_looping_top():
    runs = {f: derive.simulate(top(), formulation=f) for f in ("reduced", "quaternion", "euler-angles")}
    ref = runs["quaternion"]
    for f, r in runs.items():
        assert np.max(np.abs(r.axis - ref.axis)) < 1e-8, f
        assert np.max(np.abs(r.omega - ref.omega)) < 1e-7 * np.max(np.abs(ref.omega)), f
        assert np.max(np.abs(np.unwrap(r.alpha) - np.unwrap(ref.alpha))) < 1e-7, f


def test_conserved_quantities_hold_without_damping_and_energy_falls_with_it():
    res = derive.simulate(top(), formulation="quaternion")
    for q in (res.energy, res.p_alpha, res.p_gamma):
        assert np.ptp(q) < 1e-9 * np.max(np.abs(q))
    damped = derive.simulate(top(damping={"c": 0.05}))
    assert not REGISTRY[damped.formulation].singular  # damping: no Routh reduction, no singular set
    assert np.all(np.diff(damped.energy) < 0)


def test_second_call_reuses_the_compiled_kernel():
    from derive.runtime import catalogue
    from derive.runtime.integrate import ModelKernel

    derive.simulate(top(), method="dop853")  # (auto may weigh another method at another rtol)
    loaded = dict(ModelKernel._cache)
    before = catalogue.cache_info()
    derive.simulate(top(), method="dop853", rtol=1e-9)
    after = catalogue.cache_info()
    assert ModelKernel._cache == loaded  # no new library compiled or loaded
    assert after.misses == before.misses and after.hits > before.hits


@pytest.mark.parametrize("method", ["rk4", "gauss4", "gauss6", "scipy-dop853"])
def test_other_methods_agree_with_dop853(method):
    # the reduced top: the formulation whose libraries of these methods the suite builds anyway
    ref = derive.simulate(top(), formulation="reduced", method="dop853")
    over = {"h": 1e-3} if method in ("rk4", "gauss4", "gauss6") else {}
    sc = top()
    sc["simulate"] = dict(sc["simulate"], **over)
    res = derive.simulate(sc, method=method, formulation="reduced")
    assert res.method == method
    assert np.max(np.abs(res.axis - ref.axis)) < 1e-7


def test_every_example_scene_runs():
    for path in sorted(SCENES.glob("*.toml")):
        res = derive.simulate(path, rtol=1e-8, atol=1e-10)
        assert np.all(np.isfinite(res.axis)), path.name
        assert np.allclose(np.linalg.norm(res.axis, axis=1), 1.0, atol=1e-8), path.name


def test_batch_of_initial_conditions_equals_single_runs():
    """A sweep over the initial tilt in one C call gives, trajectory by trajectory, exactly
    what single runs give (the formulation and the method the batch chose for all)."""
    scenes = []
    for b0 in (0.3, 0.6, 0.9, 1.2):
        sc = top()
        sc["initial"] = dict(sc["initial"], beta=b0)
        scenes.append(sc)
    batch = derive.simulate_batch(scenes)
    assert len(batch) == 4
    for sc, res in zip(scenes, batch):
        single = derive.simulate(sc, formulation=res.formulation, method=res.method)
        np.testing.assert_array_equal(res.axis, single.axis)
        assert res.nfev == single.nfev


def test_batch_refuses_scenes_with_different_effects():
    with pytest.raises(derive.SceneError, match="same effects"):
        derive.simulate_batch([top(), top(gravity=None)])


@pytest.mark.parametrize("name", ["looping_top", "cuspidal_top", "wavy_top", "free_symmetric"])
def test_auto_takes_a_singular_formulation_only_when_the_motion_keeps_clear(name):
    """The example tops keep well away from the poles: auto may take a formulation with a
    singular set, and the simulated β indeed stays clear of 0 and π."""
    from derive.symbolic.formulations import POLE_CLEARANCE

    res = derive.simulate(SCENES / f"{name}.toml")
    if REGISTRY[res.formulation].singular:
        assert np.min(np.sin(res.beta)) > POLE_CLEARANCE


def _tilted_top(beta_dot):
    return {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
            "initial": {"alpha": 0.0, "beta": 0.002, "gamma": 0.0, "alpha_dot": 0.0,
                        "beta_dot": beta_dot, "gamma_dot": 6.0},
            "simulate": {"t_end": 1.0, "samples": 11}}


def test_routh_check_agrees_with_the_exact_turning_points():
    """auto's compiled Routh check (f(±u_c) < 0) says "clear of the top pole" exactly when the
    exact solution's upper turning point (`derive.reference.exact`, the cubic's roots) keeps
    |sin β| ≥ POLE_CLEARANCE: scanned across the boundary by the initial β̇ (moving toward
    the pole)."""
    from derive.sim import auto
    from derive.reference import exact
    from derive.symbolic.formulations import POLE_CLEARANCE

    verdicts = []
    for beta_dot in -np.linspace(0.0, 0.02, 41):
        sc = simulation.load_scene(_tilted_top(beta_dot))
        i = sc.initial
        info = exact.heavy_top(1.0, 0.5, 1.0, 1.0, 1.0, i.alpha, i.beta, i.gamma, i.alpha_dot,
                               i.beta_dot, i.gamma_dot, [0.0]).info
        y_lo = info["y_roots"][0]  # y = sin²(β/2) at the turning point nearest β = 0
        beta_min = 2 * np.arcsin(np.sqrt(max(y_lo, 0.0)))
        exact_clear = np.sin(beta_min) > POLE_CLEARANCE
        verdicts.append(exact_clear)
        assert auto._clear(sc, "euler-angles", "dop853") == exact_clear, beta_dot
    assert any(verdicts) and not all(verdicts)  # the scan crosses the boundary


def test_nonfinite_output_is_reported_by_the_compiled_check():
    """Finite states whose outputs overflow (energy = I ω²/2 beyond the float range): the C
    driver's output check stops with NONFINITE_OUTPUT and names the first bad output; single
    and batch runs alike, and a normal batch beside it passes."""
    import derive
    from derive.errors import IntegrationError

    huge = {"body": {"I1": 1e300, "I3": 1e300},
            "initial": {"alpha": 0.0, "beta": 0.5, "gamma": 0.0, "omega": [0.0, 0.0, 1e5]},
            "simulate": {"t_end": 1e-6, "samples": 3}}
    with pytest.raises(IntegrationError, match=r"t = 0: non-finite energy in the output"):
        derive.simulate(huge)
    fine = {**huge, "body": {"I1": 1.0, "I3": 1.0}}
    with pytest.raises(IntegrationError, match=r"non-finite energy in the output"):
        derive.simulate_batch([fine, huge])
    assert np.isfinite(derive.simulate_batch([fine, fine])[1].energy).all()


def test_pole_loss_check_from_the_extremes_equals_the_rule_on_every_sample():
    """result._check_pole reads only the smallest and largest canonical β (sin is concave
    on [0, π]); it must refuse exactly the trajectories whose smallest |sin β| over the samples
    has sin²β < eps/rtol, single and batched (_pole_suspects)."""
    from derive.runtime import catalogue
    from derive.errors import IntegrationError

    desc = catalogue.describe(("euler-angles", True, ("gravity",)))
    rng = np.random.default_rng(3)
    eps, rtol = np.finfo(float).eps, 1e-10
    t = np.linspace(0.0, 1.0, 200)
    rows, refused = [], []
    for _ in range(300):
        lo, hi = np.sort(rng.uniform(0.0, np.pi, 2))
        lo *= rng.choice([1.0, 1e-2, 1e-3, 1e-4, 1e-6])
        hi = np.pi - (np.pi - hi) * rng.choice([1.0, 1e-2, 1e-3, 1e-4, 1e-6])
        beta = rng.uniform(lo, hi, t.size)
        beta[rng.integers(t.size)], beta[rng.integers(t.size)] = lo, hi
        want = float(np.min(np.abs(np.sin(beta)))) ** 2 < eps / rtol
        try:
            result._check_pole(desc, t, beta, rtol)
            got = False
        except IntegrationError:
            got = True
        assert got == want, (lo, hi)
        rows.append(beta)
        refused.append(want)
    suspects = result._pole_suspects(desc, np.array(rows), rtol)
    assert (suspects == np.array(refused)).all() and any(refused) and not all(refused)
