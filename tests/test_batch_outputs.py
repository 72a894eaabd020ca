"""`derive.simulate_batch(scenes, outputs=...)` keeps only what is asked for:
the numbers are bit for bit those of the full batch, and only the arrays asked for are
allocated (the compiled loop runs in chunks whose work arrays are reused)."""
import tracemalloc

import numpy as np
import pytest

import derive
from derive.sim import batch as sim_batch
from derive.symbolic.formulations import OUTPUTS

DEFAULT_CHUNK_BYTES = sim_batch.CHUNK_BYTES

BASE = {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
        "simulate": {"t_end": 1.0, "samples": 51, "rtol": 1e-10, "atol": 1e-12}}


def scenes(n, seed=5, **simulate):
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        out.append({**BASE, "simulate": {**BASE["simulate"], **simulate},
                    "initial": {"alpha": 0.0, "beta": float(rng.uniform(0.6, 1.0)), "gamma": 0.0,
                                "alpha_dot": float(rng.uniform(-0.6, -0.2)), "beta_dot": float(rng.uniform(0.1, 0.5)),
                                "gamma_dot": float(rng.uniform(5.0, 7.0))}})
    return out


@pytest.fixture(autouse=True)
def small_chunks(monkeypatch):
    """Chunks of 3 trajectories: several chunks and a ragged last one in every test."""
    monkeypatch.setattr(sim_batch, "CHUNK_BYTES", 3 * 8 * 51 * (sum(w for _, w in OUTPUTS) + 6))


def test_final_outputs_are_the_last_sample_of_the_full_batch_bit_for_bit():
    sc = scenes(8, method="dop853")  # (the Taylor lanes: tests/test_taylor_lanes.py)
    full = derive.simulate_batch(sc)
    fin = derive.simulate_batch(sc, outputs="final")
    assert len(fin) == 8 and fin.final and fin.method == full[0].method
    assert fin.formulation == full[0].formulation and fin.model == full[0].model
    for name, width in OUTPUTS:
        got = fin.outputs[name]
        assert got.shape == ((8,) if width == 1 else (8, width)), name
        want = np.array([getattr(r, name)[-1] for r in full])
        assert np.array_equal(got, want), name
    assert np.array_equal(fin.state, np.array([r.state[-1] for r in full]))
    # straight to the end: the same steps, none of dop853's dense-output evaluations
    assert fin.driver == "final" and fin.method == "dop853"
    assert (fin.nfev <= np.array([r.nfev for r in full])).all()
    assert np.array_equal(fin.t, full[0].t)


def test_named_outputs_are_the_full_series_bit_for_bit():
    sc = scenes(7)
    full = derive.simulate_batch(sc)
    sel = derive.simulate_batch(sc, outputs=("beta", "axis", "state"))
    assert set(sel.outputs) == {"beta", "axis", "state"}
    assert sel.beta.shape == (7, 51) and sel.axis.shape == (7, 51, 3) and sel.state.shape[:2] == (7, 51)
    assert np.array_equal(sel.beta, np.array([r.beta for r in full]))
    assert np.array_equal(sel.axis, np.array([r.axis for r in full]))
    assert np.array_equal(sel.state, np.array([r.state for r in full]))
    with pytest.raises(AttributeError):
        sel.energy  # noqa: B018 - not asked for, not there


def test_a_fixed_step_batch_keeps_its_outputs_too():
    sc = scenes(4, method="rk4", h=1e-3)
    full = derive.simulate_batch(sc)
    fin = derive.simulate_batch(sc, outputs="final")
    assert np.array_equal(fin.omega, np.array([r.omega[-1] for r in full]))
    assert fin.driver == "full"  # its samples set its steps: the full grid
    assert np.array_equal(fin.nfev, [r.nfev for r in full])


def test_bad_outputs_are_refused_with_one_line_naming_the_key():
    for bad in ("everything", ("beta", "spin"), 3, ()):
        with pytest.raises(derive.SceneError, match="outputs") as exc:
            derive.simulate_batch(scenes(2), outputs=bad)
        assert "\n" not in str(exc.value)
    assert derive.simulate_batch([], outputs="final") is None


def test_a_failed_trajectory_is_named_as_in_the_full_batch():
    sc = scenes(5, max_steps=5)  # the step budget is spent in the first trajectory
    with pytest.raises(derive.IntegrationError) as full:
        derive.simulate_batch(sc)
    with pytest.raises(derive.IntegrationError) as fin:
        derive.simulate_batch(sc, outputs="final")
    assert str(fin.value) == str(full.value)


def test_a_final_only_batch_of_1000_allocates_its_outputs_not_the_trajectories(monkeypatch):
    """1000 trajectories of 1001 samples: the full batch maps ~200 MB of outputs and states; the
    final-only one its (1000, ·) arrays and the chunks' work arrays (a loose structural bound)."""
    monkeypatch.setattr(sim_batch, "CHUNK_BYTES", DEFAULT_CHUNK_BYTES)
    sc = scenes(1000, t_end=0.2, samples=1001, rtol=1e-6, atol=1e-8)
    derive.simulate_batch(sc[:2], outputs="final")  # compile and load outside the measurement
    tracemalloc.start()
    try:
        fin = derive.simulate_batch(sc, outputs="final")
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    full_bytes = 1000 * 1001 * 8 * (sum(w for _, w in OUTPUTS) + fin.state.shape[1])
    assert full_bytes > 150e6
    assert peak < 20e6, peak  # ~4 MB of reused work arrays + ~0.2 MB of results
    assert fin.beta.shape == (1000,) and np.isfinite(fin.energy).all()
