"""Hard cases that must stay numerically right, each with a numeric requirement.

References: small-oscillation theory from the derived series (stability.py) for the sleeping
and hanging tops, the exact solutions of derive/reference/exact.py where they exist, and conservation
laws for the long runs.
"""
import numpy as np
import pytest

import derive
from derive.symbolic.formulations import REGISTRY

I1, I3, M, G, L = 1.0, 0.4, 1.0, 9.81, 0.1
CRIT = np.sqrt(4 * M * G * L * I1)  # the derived threshold p_γ = 2√(I₁Mgl)


def top_with_equal_momenta(p_gamma, beta0, t_end, samples=2001, l=L, rtol=1e-11, **sim):
    """A symmetric top at β₀ with β̇ = 0 and p_α = p_γ exactly (near β = π: p_α = −p_γ).

    p_α = p_γ needs α̇ = p_γ / (I₁(1 + cos β₀)); near π (cos β₀ ≈ −1) p_α = −p_γ needs
    α̇ = −p_γ / (I₁(1 − cos β₀)). Then γ̇ = p_γ/I₃ − α̇ cos β₀.
    """
    c = np.cos(beta0)
    ad = p_gamma / (I1 * (1 + c)) if c > 0 else -p_gamma / (I1 * (1 - c))
    gd = p_gamma / I3 - ad * c
    return {"body": {"I1": I1, "I3": I3}, "gravity": {"M": M, "g": G, "l": l},
            "initial": {"alpha": 0.0, "beta": beta0, "gamma": 0.0, "alpha_dot": ad, "beta_dot": 0.0, "gamma_dot": gd},
            "simulate": {"t_end": t_end, "samples": samples, "rtol": rtol, "atol": 1e-14 * max(beta0, 1e-300), **sim}}


def small_oscillation_frequency(p_gamma, l=L):
    """Ω² = 2k₂/I₁ with k₂ = p_γ²/(8I₁) − Mgl/2 (the derived series of V_eff about β = 0)."""
    k2 = p_gamma**2 / (8 * I1) - M * G * l / 2
    return np.sqrt(2 * k2 / I1)


@pytest.mark.parametrize("formulation", ["auto", "reduced"])
def test_sleeping_top_at_1e_8_stays_asleep_and_follows_small_oscillation_theory(formulation):
    p = 2.0 * CRIT
    beta0 = 1e-8
    res = derive.simulate(top_with_equal_momenta(p, beta0, 20.0), formulation=formulation)
    if formulation == "auto":  # no coordinate singularity to pass through
        assert not REGISTRY[res.formulation].singular
    Om = small_oscillation_frequency(p)
    # β = |β₀ cos Ωt|: the axis passes through the pole, and the canonical β stays in [0, π]
    # (the reduced chart's β changes sign there; the output reflects it).
    expected = np.abs(beta0 * np.cos(Om * res.t))
    assert np.min(res.beta) >= 0.0
    assert np.max(np.abs(res.beta - expected)) < 1e-6 * beta0
    assert np.max(np.abs(res.beta)) <= beta0 * (1 + 1e-9)
    # The axis never leaves the pole's neighbourhood: no spurious fall.
    assert np.min(res.axis[:, 2]) > np.cos(2 * beta0)


def test_sleeping_top_quaternion_formulation_agrees():
    p = 2.0 * CRIT
    sc = top_with_equal_momenta(p, 1e-8, 20.0)
    a = derive.simulate(sc)
    b = derive.simulate(sc, formulation="quaternion")
    assert np.max(np.linalg.norm(a.axis - b.axis, axis=1)) < 1e-14


def falls(p_gamma, beta0=1e-6, t_end=None):
    """Does a sleeping top at β₀ leave the vertical (|β| > 10 β₀) within t_end?"""
    if t_end is None:
        # Time for 10× growth at the slowest rate we must resolve (|p/crit − 1| = 5e-4): λ = crit √(δ/2)/I₁.
        t_end = 1.5 * np.log(10) / (CRIT * np.sqrt(2.5e-4) / I1)
    res = derive.simulate(top_with_equal_momenta(p_gamma, beta0, t_end, samples=4001, rtol=1e-10))
    return np.max(np.abs(res.beta)) > 10 * beta0


def test_stability_threshold_bracketed_to_1e_3_by_simulation():
    lo, hi = 0.9 * CRIT, 1.1 * CRIT
    assert falls(lo) and not falls(hi)
    while (hi - lo) / CRIT > 1e-3:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if falls(mid) else (lo, mid)
    assert lo <= CRIT <= hi, (lo / CRIT, hi / CRIT)


def test_finite_tilt_shift_is_the_quartic_term():
    """Below threshold the quartic term k₄ > 0 (Mgl/8 at the threshold) catches the fall: started
    at rest next to β = 0, the top swings out only to the turning point k₂β² + k₄β⁴ = 0,
    β_turn = √(−k₂/k₄) ≈ 2√δ for p_γ = (1 − δ)·threshold. So with a finite tilt the observed
    "threshold" depends on how far a top must lean to count as fallen."""
    delta = 0.01
    p = (1 - delta) * CRIT
    k2 = p**2 / (8 * I1) - M * G * L / 2
    k4 = M * G * L / 24 + p**2 / (48 * I1)
    turning = np.sqrt(-k2 / k4)
    growth = CRIT * np.sqrt(delta / 2) / I1
    res = derive.simulate(top_with_equal_momenta(p, 1e-6, 3 * np.log(1e6) / growth, samples=20001, rtol=1e-10))
    # The series is truncated at β⁴: the sixth-order term shifts the turning point by O(β²) ≈ 1%.
    assert abs(np.max(np.abs(res.beta)) / turning - 1) < 0.02


def test_hanging_top_near_pi_stays_hanging():
    """Centre of mass below the pivot (β ≈ π, l > 0): stable for any spin; p_α = −p_γ exactly."""
    p = 0.3 * CRIT
    eps = 1e-8
    res = derive.simulate(top_with_equal_momenta(p, np.pi - eps, 20.0))
    assert not REGISTRY[res.formulation].singular
    assert np.max(res.beta) <= np.pi  # canonical angles, even where the motion crosses the pole
    dev = np.pi - np.abs(res.beta)
    # Small oscillation about π: V_eff ≈ const + (p²/(8I₁) + Mgl/2)(β − π)²; start at rest ⇒ |β − π| ≤ ε.
    assert np.max(np.abs(dev)) <= eps * (1 + 1e-6)
    assert np.max(res.axis[:, 2]) < -np.cos(2 * eps)
    assert np.ptp(res.energy) < 1e-12 * abs(res.energy[0])


def _relative_energy_errors(t_end, method):
    """|E(t) − E(0)| / |E(0)| of the reduced top, whose α and γ grow without bound, at h = 0.01."""
    sc = {"body": {"I1": I1, "I3": I3}, "gravity": {"M": M, "g": G, "l": L},
          "initial": {"alpha": 0.0, "beta": 0.8, "gamma": 0.0, "alpha_dot": 0.0, "beta_dot": 0.0, "gamma_dot": 6.0},
          "simulate": {"t_end": t_end, "samples": 2001, "formulation": "reduced", "h": 1e-2}}
    r = derive.simulate(sc, method=method)
    return np.abs(r.energy - r.energy[0]) / abs(r.energy[0])


def test_gauss_legendre_energy_bounded_while_rk4_drifts_over_two_hundred_thousand_steps():
    """2·10⁵ steps (h = 0.01): Gauss–Legendre keeps the energy error bounded (order 4: at its
    truncation level, the same in the first and the last tenth; order 6: at round-off), while
    RK4 at the same step drifts secularly, already far above order 4's level."""
    g6 = _relative_energy_errors(2e3, "gauss6")
    assert np.max(g6) < 1e-14
    g4 = _relative_energy_errors(2e3, "gauss4")
    n = len(g4)
    assert np.max(g4) < 1e-11
    assert np.max(g4[-n // 10:]) < 1.5 * np.max(g4[: n // 10])  # no drift
    rk = _relative_energy_errors(2e3, "rk4")
    assert rk[-1] > 500 * np.max(g4)
    assert rk[-1] > 5 * np.max(rk[: n // 10])  # secular growth


@pytest.mark.slow
def test_gauss_legendre_energy_bounded_over_a_million_steps():
    """10⁶ steps (h = 0.01) on the reduced top, whose α and γ grow without bound: Gauss–Legendre
    keeps the energy error bounded (order 4: at its truncation level, the same in the first and
    the last tenth; order 6: at round-off), while RK4 at the same step drifts secularly."""
    g6 = _relative_energy_errors(1e4, "gauss6")
    assert np.max(g6) < 1e-14
    g4 = _relative_energy_errors(1e4, "gauss4")
    n = len(g4)
    assert np.max(g4) < 1e-11
    assert np.max(g4[-n // 10:]) < 1.5 * np.max(g4[: n // 10])  # no drift
    rk = _relative_energy_errors(1e4, "rk4")
    assert rk[-1] > 1000 * np.max(g4)
    assert rk[-1] > 5 * np.max(rk[: n // 10])  # secular growth


def test_damped_top_energy_decreases_monotonically():
    sc = top_with_equal_momenta(2 * CRIT, 0.3, 20.0)
    sc["damping"] = {"c": 0.02}
    res = derive.simulate(sc)
    assert not REGISTRY[res.formulation].singular  # damping: no Routh reduction to check a range
    assert np.all(np.diff(res.energy) < 0)
    # dE/dt = −c|ω̃|² along the motion (the damping torque's power)
    dEdt = np.gradient(res.energy, res.t)
    expected = -0.02 * np.sum(res.omega**2, axis=1)
    assert np.max(np.abs(dEdt[5:-5] - expected[5:-5])) < 1e-3 * np.max(np.abs(expected))


@pytest.mark.parametrize("beta0, p_factor", [(1e-8, 2.0), (np.pi - 1e-8, 0.3)],
                         ids=["sleeping", "hanging"])
def test_tiny_motions_keep_their_relative_accuracy(beta0, p_factor):
    """A motion of size 1e-8 about a pole (the sleeping top above its threshold, the hanging
    top), rtol 1e-11, atol 1e-13, t ∈ [0, 30]: the axis's horizontal components against the
    exact solution to ≤ 1e-13 absolute, ≤ 1e-5 of the motion. (The reduced chart, which
    passes through the pole in β, reaches only ~3e-13 here; auto takes a formulation without
    a singular set, whose state carries the small components themselves.)"""
    from derive.reference import exact

    sc = top_with_equal_momenta(p_factor * CRIT, beta0, 30.0, rtol=1e-11)
    sc["simulate"]["atol"] = 1e-13
    res = derive.simulate(sc)
    i = sc["initial"]
    ex = exact.heavy_top(I1, I3, M, G, L, i["alpha"], i["beta"], i["gamma"], i["alpha_dot"],
                         i["beta_dot"], i["gamma_dot"], res.t)
    motion = np.max(np.abs(ex.axis[:, :2]))
    err = np.max(np.abs(res.axis[:, :2] - ex.axis[:, :2]))
    assert 0.5e-8 < motion < 2e-8
    assert err <= 1e-13 and err <= 1e-5 * motion
