"""The contact laws' extensions: rolling resistance and spin (Contensou) friction, moments ∝ N."""
import copy

import numpy as np
import pytest
from scipy.integrate import simpson

from derive.cli import main
from derive.contact.scene import read
from derive.contact.simulate import run_scene
from derive.errors import SceneError
from test_contact import newton_euler_inertial, reference

TIPPE = {"body": {"I1": 8e-7, "I3": 7e-7}, "gravity": {"M": 0.006, "g": 9.81},
         "contact": {"shape": "sphere", "radius": 0.015, "offset": 0.003, "friction": "coulomb", "mu": 0.3,
                     "regularization": 1e-2},
         "initial": {"beta": 0.1, "omega": [0.0, 0.0, 180.0]}, "simulate": {"t_end": 0.2, "samples": 401}}
PEG = {"body": {"I1": 2e-5, "I3": 1.5e-5}, "gravity": {"M": 0.05, "g": 9.81},
       "contact": {"shape": "sphere", "radius": 0.005, "offset": -0.01, "friction": "coulomb", "mu": 0.3},
       "initial": {"beta": 0.5, "gamma_dot": 150.0}, "simulate": {"t_end": 0.3, "samples": 301}}
ROUTH = {"body": {"I1": 1e-3, "I3": 0.9e-3}, "gravity": {"M": 1.0, "g": 9.81},
         "contact": {"shape": "sphere", "radius": 0.05, "offset": 0.01, "friction": "rolling"},
         "initial": {"beta": 1.0, "alpha_dot": 3.0, "gamma_dot": 5.0},
         "simulate": {"t_end": 0.5, "samples": 501, "rtol": 1e-12, "atol": 1e-14}}


def _with(base, **contact):
    d = copy.deepcopy(base)
    d["contact"].update(contact)
    return d


def _vertical(r):
    """n = Rᵀẑ in body components from the z-y-z angles."""
    b, g = r.beta, r.gamma
    return np.stack([-np.sin(b) * np.cos(g), np.sin(b) * np.sin(g), np.cos(b)], axis=1)


def _jellett(r, sc):
    a = np.array([0.0, 0.0, sc["contact"]["offset"]]) - sc["contact"]["radius"] * _vertical(r)
    inertia = np.array([sc["body"]["I1"], sc["body"]["I1"], sc["body"]["I3"]])
    return np.sum(inertia * r.omega * a, axis=1)


def test_spin_friction_turns_jelletts_integral_toward_zero_at_the_rate_its_moment_gives():
    rs, eps, mu = 1e-3, 1e-2, 0.3
    sc = _with(TIPPE, spin_friction=rs)
    r = run_scene(sc)
    J = _jellett(r, sc)
    assert "jellett" not in r.integrals  # not an integral once the moment acts
    # dJ/dt = τ·a with τ = −μ N r_s σ n and a·n = −z: μ r_s σ N z, σ the spin's regularised sign
    wn = np.sum(r.omega * _vertical(r), axis=1)
    sigma = rs * wn / np.sqrt((rs * wn) ** 2 + eps**2)
    rate = mu * rs * sigma * r.normal_force * r.com[:, 2]
    assert np.all(sigma > 0) and J[0] < 0
    assert np.all(np.diff(np.abs(J)) < 0)  # J < 0 spinning forward: the moment shrinks |J|
    assert J[-1] - J[0] == pytest.approx(simpson(rate, x=r.t), rel=1e-6)
    assert abs(J[-1] - J[0]) > 1e-2 * abs(J[0])
    plain = _jellett(run_scene(TIPPE), TIPPE)
    assert np.max(np.abs(plain - plain[0])) <= 1e-10 * abs(plain[0])


@pytest.mark.parametrize("base,extensions", [
    (TIPPE, {"spin_friction": 1e-3}),
    (TIPPE, {"rolling_resistance": 1e-4}),
    (PEG, {"rolling_resistance": 2e-4, "spin_friction": 1e-3}),   # exact Coulomb: slides, then rolls
    (ROUTH, {"rolling_resistance": 1e-3}),
])
def test_energy_never_rises_with_rolling_resistance_or_spin_friction(base, extensions):
    r = run_scene(_with(base, **extensions))
    plain = run_scene(base)
    assert np.all(np.diff(r.energy) <= 1e-14 * abs(r.energy[0]))
    assert r.energy[-1] < plain.energy[-1] - 1e-6 * abs(plain.energy[0])  # the moment takes energy


def test_rolling_resistance_takes_the_energy_its_moment_s_power_says_while_rolling():
    delta = 1e-3
    r = run_scene(_with(ROUTH, rolling_resistance=delta))
    w, n = r.omega, _vertical(r)
    wt = w - np.sum(w * n, axis=1)[:, None] * n
    power = -delta * r.normal_force * np.linalg.norm(wt, axis=1)  # τ·ω = −δ N |ω_t|
    assert r.energy[-1] - r.energy[0] == pytest.approx(simpson(power, x=r.t), rel=1e-6)
    assert np.max(r.slip_speed) <= 1e-12  # still rolling without slipping
    assert set(r.phase) == {"roll"}


@pytest.mark.parametrize("base", [TIPPE, PEG, ROUTH])
def test_extensions_set_to_zero_run_bit_for_bit_as_the_plain_law(base):
    plain = run_scene(base).arrays()
    zero = run_scene(_with(base, rolling_resistance=0.0, **({"spin_friction": 0.0}
                                                              if base["contact"]["friction"] == "coulomb" else {})))
    got = zero.arrays()
    assert set(got) == set(plain)
    for k, v in plain.items():
        assert np.array_equal(got[k], v), k


def test_the_moments_move_the_sliding_tippe_top_as_an_independent_integration_does():
    delta, rs, t_end = 2e-4, 1e-3, 0.1
    r = run_scene(_with(TIPPE, rolling_resistance=delta, spin_friction=rs),
                  t_end=t_end, samples=2, rtol=1e-12, atol=1e-14)
    def integrate():
        sol = newton_euler_inertial(1e-2, t_end, delta=delta, rs=rs)
        return sol.t[-1], sol.y[:, -1]

    t_last, y = reference("newton-euler-with-moments", (1e-2, t_end, delta, rs), integrate)
    R, w = y[:9].reshape(3, 3), y[9:12]
    assert t_last == t_end
    assert r.axis[-1] == pytest.approx(R[:, 2], abs=1e-9)
    assert r.omega[-1] == pytest.approx(R.T @ w, rel=1e-8, abs=1e-7)
    plain = run_scene(TIPPE, t_end=t_end, samples=2, rtol=1e-12, atol=1e-14)
    assert np.max(np.abs(plain.axis[-1] - R[:, 2])) > 1e-6  # the moments make a difference


@pytest.mark.parametrize("contact,key", [
    ({"spin_friction": -1e-3}, "contact.spin_friction"),
    ({"rolling_resistance": -1e-4}, "contact.rolling_resistance"),
    ({"rolling_resistance": "1e-4"}, "contact.rolling_resistance"),
    ({"spin_friction": float("inf")}, "contact.spin_friction"),
    ({"friction": "viscous", "regularization": None, "spin_friction": 1e-3}, "contact.spin_friction"),
    ({"friction": "rolling", "mu": None, "regularization": None, "spin_friction": 1e-3}, "contact.spin_friction"),
    ({"friction": "none", "mu": None, "regularization": None, "rolling_resistance": 1e-4},
     "contact.rolling_resistance"),
    ({"friction": "none", "mu": None, "regularization": None, "spin_friction": 0.0}, "contact.spin_friction"),
])
def test_a_bad_extension_names_its_key(contact, key):
    d = _with(TIPPE, **contact)
    d["contact"] = {k: v for k, v in d["contact"].items() if v is not None}
    with pytest.raises(SceneError, match=rf": {key}: "):
        read(d, "top.toml")


def test_the_command_line_refuses_spin_friction_without_friction_with_exit_2(tmp_path, capsys):
    path = tmp_path / "top.toml"
    path.write_text('[body]\nI1 = 8e-7\nI3 = 7e-7\n[gravity]\nM = 0.006\ng = 9.81\n'
                    '[contact]\nshape = "sphere"\nradius = 0.015\noffset = 0.003\nfriction = "none"\n'
                    'spin_friction = 0.001\n[initial]\nbeta = 0.1\n', encoding="utf-8")
    assert main(["simulate", str(path), "-o", str(tmp_path / "out.npz")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "contact.spin_friction" in err[0]
    assert not (tmp_path / "out.npz").exists()


def test_an_export_of_a_top_with_both_extensions_takes_their_lengths_as_parameters():
    from derive.export import contact as ce
    from derive.export.contact_fmu import variables

    b = ce.bundle((_with(TIPPE, rolling_resistance=2e-4, spin_friction=1e-3), "top.toml"))
    params = {v.name: float(v.start) for v in variables(b) if v.causality == "parameter"}
    assert params["contact.rolling_resistance"] == 2e-4 and params["contact.spin_friction"] == 1e-3
    files = ce.files(b.scene)
    assert "`contact.spin_friction`" in files["README.md"]
    assert {"contact_model.inc", "contact_sphere.inc"} <= set(files)
    assert [n for n, _ in ce.integral_outputs(b.scene)] == []  # no integral once a moment acts
    viscous = _with(TIPPE, friction="viscous")
    del viscous["contact"]["regularization"]
    plain = ce.bundle((viscous, "top.toml"))
    names = {v.name for v in variables(plain)}
    assert "contact.rolling_resistance" in names and "contact.spin_friction" not in names
