"""Lean batches: ``outputs="final"`` keeps only the (N, …) final arrays, its
work bounded by the chunks' buffers whatever N, with the full batch's numbers at the last sample."""
from __future__ import annotations

import tracemalloc

import numpy as np

import derive
from derive.bench.targets import batch_scenes
from derive.sim import batch

FINAL = ("alpha", "beta", "gamma", "omega", "axis", "energy", "p_alpha", "p_gamma", "n", "L")


def test_final_is_the_full_batch_at_its_last_sample():
    scenes = batch_scenes(12, 2.0)
    full = derive.simulate_batch(scenes)
    final = derive.simulate_batch(scenes, outputs="final")
    assert len(final) == len(full) == 12
    for name in FINAL:
        assert np.array_equal(getattr(final, name), np.array([getattr(r, name)[-1] for r in full])), name
    assert np.array_equal(final.state, np.array([r.state[-1] for r in full]))
    if final.driver == "final":  # straight to the end: no dense-output evaluations
        assert (final.nfev <= np.array([r.nfev for r in full])).all()
    else:
        assert final.nfev.tolist() == [r.nfev for r in full]


def test_a_final_only_batch_of_1000_keeps_its_memory_bounded():
    """Per trajectory only its final arrays (and its validated scene): the peak stays far below
    what the full batch's arrays of 1000 trajectories would take."""
    scenes = batch_scenes(1000, 0.2)
    derive.simulate_batch(scenes[:2], outputs="final")  # compiled and loaded before measuring
    tracemalloc.start()
    try:
        res = derive.simulate_batch(scenes, outputs="final")
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    samples, nout = len(res.t), sum(v.shape[-1] if v.ndim == 2 else 1 for k, v in res.outputs.items() if k != "state")
    full_arrays = 8 * len(scenes) * samples * (nout + res.state.shape[1])
    assert full_arrays > 10 * (batch.CHUNK_BYTES + (8 << 20))  # the bound below means something
    assert peak < batch.CHUNK_BYTES + (8 << 20), peak
