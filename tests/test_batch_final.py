"""The final-only batch driver: ``derive.simulate_batch(scenes,
outputs="final")`` on a formulation whose α and γ are states integrates each trajectory straight
to the end (``<model>_run_<method>`` saving the last time), with the full batch's last sample bit
for bit where the full path's unwrapping of the angles did not fire; the others keep the full
grid."""
import tracemalloc

import numpy as np
import pytest

import derive
from derive.symbolic.formulations import OUTPUTS, REGISTRY

BASE = {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
        "simulate": {"t_end": 3.0, "samples": 41, "rtol": 1e-10, "atol": 1e-12}}


def scenes(n, seed=11, **simulate):
    rng = np.random.default_rng(seed)
    return [{**BASE, "simulate": {**BASE["simulate"], **simulate},
             "initial": {"alpha": float(rng.uniform(-1, 1)), "beta": float(rng.uniform(0.5, 1.2)),
                         "gamma": float(rng.uniform(-1, 1)), "alpha_dot": float(rng.uniform(-0.6, 0.6)),
                         "beta_dot": float(rng.uniform(-0.5, 0.5)), "gamma_dot": float(rng.uniform(3.0, 9.0))}}
            for _ in range(n)]


def _unwrap_quiet(full):
    """Rows where the full path's unwrapping moved nothing at the last sample: α and γ there
    within π of the sample before (whole turns were not added)."""
    a = np.array([r.alpha[-2:] for r in full])
    c = np.array([r.gamma[-2:] for r in full])
    return (np.abs(np.diff(a, axis=1)[:, 0]) < np.pi) & (np.abs(np.diff(c, axis=1)[:, 0]) < np.pi)


@pytest.mark.parametrize("formulation", ["reduced-u", "reduced", "euler-angles"])
@pytest.mark.parametrize("method", ["dop853", "taylor"])
def test_final_driver_is_the_full_batch_last_sample_bit_for_bit(formulation, method):
    sc = scenes(6, formulation=formulation, method=method)
    full = derive.simulate_batch(sc)
    fin = derive.simulate_batch(sc, outputs="final")
    pole_loss = REGISTRY[formulation].pole_loss
    assert fin.driver == ("full" if pole_loss else "lanes" if method == "taylor" else "final"), fin.driver
    assert fin.formulation == formulation and fin.method == method
    quiet = _unwrap_quiet(full)
    assert quiet.all()  # these scenes do not test the exception
    for name, _ in OUTPUTS:
        want = np.array([getattr(r, name)[-1] for r in full])
        assert np.array_equal(fin.outputs[name], want), name
    assert np.array_equal(fin.state, np.array([r.state[-1] for r in full]))
    nfev = np.array([r.nfev for r in full])
    if method == "taylor" or fin.driver == "full":  # one expansion a step either way; the same call
        assert np.array_equal(fin.nfev, nfev)
    else:  # the same steps without dop853's dense-output evaluations
        assert (fin.nfev < nfev).all()


def test_formulations_with_angles_from_atan2_keep_the_full_grid():
    sc = scenes(3, formulation="quaternion")
    fin = derive.simulate_batch(sc, outputs="final")
    assert fin.driver == "full"
    full = derive.simulate_batch(sc)
    assert np.array_equal(fin.alpha, np.array([r.alpha[-1] for r in full]))


@pytest.mark.parametrize("method, driver", [("dop853", "final"), ("taylor", "lanes")])
def test_the_final_driver_allocates_no_samples(method, driver):
    """A grid of 400001 samples: the full path would need a chunk of 400001 x (18 + 4) doubles
    (~70 MB) per trajectory; the final drivers (DOP853's, the Taylor lanes) only the grid itself
    and the (N, .) results."""
    sc = scenes(3, samples=400001, rtol=1e-8, atol=1e-10, method=method)
    derive.simulate_batch(sc[:1], outputs="final", samples=11)  # compiled and loaded outside
    tracemalloc.start()
    try:
        fin = derive.simulate_batch(sc, outputs="final")
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert fin.driver == driver
    assert peak < 20e6, peak  # the grid (3.2 MB) and its copies, not 70 MB of samples
    assert np.isfinite(fin.energy).all()


def test_a_failing_trajectory_is_named_as_the_full_batch_names_it():
    sc = scenes(4, max_steps=8)
    with pytest.raises(derive.IntegrationError) as full:
        derive.simulate_batch(sc)
    with pytest.raises(derive.IntegrationError) as fin:
        derive.simulate_batch(sc, outputs="final")
    assert str(fin.value) == str(full.value)
