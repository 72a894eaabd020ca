"""A prepared run binds its C call once (buffer layout, pointers, converted arguments) and gives
the same numbers, statuses and exceptions as ``derive.simulate``, run after run."""
from __future__ import annotations

import copy

import numpy as np
import pytest
from interrupts import CpuTimer

import derive
from derive.bench.reference import reference_data

ARRAYS = ("t", "alpha", "beta", "gamma", "omega", "axis", "energy", "p_alpha", "p_gamma", "n", "L")


def _short() -> dict:
    data = reference_data(10.0)
    data["simulate"].update(t_end=1e-3, samples=2)
    return data


def _same(a, b):
    assert (a.method, a.formulation, a.nfev, a.model) == (b.method, b.formulation, b.nfev, b.model)
    for name in ARRAYS:
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert a.integrals.keys() == b.integrals.keys()
    for k in a.integrals:
        assert np.array_equal(a.integrals[k], b.integrals[k]), k
    assert np.array_equal(a.state, b.state)


def test_repeated_prepared_runs_are_simulate_bit_for_bit():
    """Every run is simulate's result, in arrays of its own."""
    data = _short()
    prepared = derive.prepare(data)
    direct = derive.simulate(data)
    runs = [prepared.run() for _ in range(4)]
    for res in runs:
        _same(res, direct)
    assert not np.shares_memory(runs[0].beta, runs[1].beta)
    assert not np.shares_memory(runs[0].state, runs[-1].state)


def test_new_values_after_repeated_runs_are_not_the_old_ones():
    data = _short()
    prepared = derive.prepare(data)
    for _ in range(3):
        prepared.run()
    changed = copy.deepcopy(data)
    changed["initial"]["beta"] = 0.9
    changed["gravity"]["M"] = 0.6
    _same(prepared.run(initial={"beta": 0.9}, params={"M": 0.6}), derive.simulate(changed))
    _same(prepared.run(), derive.simulate(data))  # and the prepared numbers again, untouched


def test_a_failing_prepared_run_raises_what_simulate_raises_every_time():
    data = reference_data(10.0)
    data["simulate"].update(max_steps=5)
    with pytest.raises(derive.IntegrationError) as direct:
        derive.simulate(data)
    prepared = derive.prepare(data)
    for _ in range(2):
        with pytest.raises(derive.IntegrationError) as again:
            prepared.run()
        assert str(again.value) == str(direct.value)


def test_the_pole_check_of_a_short_output_is_simulate_s():
    """A start near the pole in the Euler-angle formulation: the list path of the pole check
    (short outputs) refuses it as simulate does."""
    data = _short()
    data["simulate"].update(formulation="euler-angles", rtol=1e-12, atol=1e-14)
    data["initial"].update(beta=1e-4, alpha_dot=0.0, beta_dot=0.0)
    with pytest.raises(derive.IntegrationError, match="coordinate singularity") as direct:
        derive.simulate(data)
    with pytest.raises(derive.IntegrationError) as prepared:
        derive.prepare(data).run()
    assert str(prepared.value) == str(direct.value)


def test_an_interrupt_stops_a_long_prepared_run():
    """A prepared run is guarded: the kernel's interrupt flag, set from
    another thread as a SIGINT sets it, stops the loop and surfaces as KeyboardInterrupt."""
    data = reference_data(10.0)
    data["simulate"].update(t_end=1e7, samples=3, rtol=1e-13, atol=1e-15, max_steps=10**12)
    prepared = derive.prepare(data)
    kernel = prepared.plan.candidates[0].kernel
    if kernel._run.guard is None:
        pytest.skip("the kernel was loaded outside the main thread: no guard")
    request = kernel.lib.derive_sigint_request
    timer = CpuTimer(0.2, request)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            prepared.run()
    finally:
        timer.cancel()
