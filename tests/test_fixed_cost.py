"""The fixed cost of a call (issue 20, item 3): a prepared run builds its Result straight from
the output rows and evaluates the integrals without an ``np.errstate``; ``derive.simulate`` of
a scene equal to a recent one reuses its plan, and never a stale one."""
from __future__ import annotations

import dataclasses
import warnings

import numpy as np
import pytest

import derive
from derive.bench.reference import reference_data
from derive.sim import simulation
from derive.sim.simulation import Result


def _short() -> dict:
    data = reference_data(10.0)
    data["simulate"].update(t_end=1e-3, samples=2)
    return data


def _euler(scale: float) -> dict:
    """A free asymmetric body (Euler's case: the integral |L|²) with moments of ``scale``."""
    return {"body": {"I1": 1.0 * scale, "I2": 2.0 * scale, "I3": 2.5 * scale},
            "initial": {"alpha": 0.1, "beta": 0.8, "gamma": 0.2, "omega": [1.0, 2.0, 3.0]},
            "simulate": {"t_end": 1e-3, "samples": 2}}


def _fields_equal(a: Result, b: Result) -> None:
    for f in dataclasses.fields(Result):
        x, y = getattr(a, f.name), getattr(b, f.name)
        if isinstance(x, np.ndarray):
            assert np.array_equal(x, y), f.name
        elif f.name == "integrals":
            assert x.keys() == y.keys()
            for k in x:
                assert np.array_equal(x[k], y[k]), k
        else:
            assert x == y, f.name


@pytest.mark.parametrize("data", [_short(), _euler(1.0)], ids=["lagrange", "euler"])
def test_the_short_result_has_every_field_a_batch_result_has(data):
    """The compiled path fills the Result's ``__dict__`` itself: the same fields and values as
    the dataclass constructor the batch path calls (``_result``)."""
    res = derive.prepare(data).run()
    assert set(vars(res)) >= {f.name for f in dataclasses.fields(Result)}
    assert res.integrals  # both scenes are integrable cases
    _fields_equal(res, derive.simulate_batch([data])[0])
    _fields_equal(derive.simulate(data), res)


def test_an_overflowing_integral_raises_without_a_warning():
    """|L|² beyond the float range (finite outputs, moments of 1e200): the IntegrationError
    names the integral, and no RuntimeWarning is printed before it, prepared or not."""
    data = _euler(1e200)
    prepared = derive.prepare(data)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for call in (prepared.run, lambda: derive.simulate(data)):
            with pytest.raises(derive.IntegrationError, match="non-finite integral_L_squared"):
                call()


def test_ignoring_leaves_the_callers_error_state_alone():
    before = np.geterr()
    big = np.array([1e300])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert np.isinf(simulation._ignoring(np.multiply, big, big)).all()
    assert np.geterr() == before
    with pytest.warns(RuntimeWarning):
        np.multiply(big, big)


def test_new_numbers_change_the_integral():
    """The integral is the run's own, not a number kept from another scene."""
    a, b = _euler(1.0), _euler(1.0)
    b["initial"]["omega"] = [1.0, 2.0, 3.5]
    ra, rb = derive.simulate(a), derive.simulate(b)
    assert not np.array_equal(ra.integral_L_squared, rb.integral_L_squared)
    assert np.allclose(ra.integral_L_squared, np.sum(ra.L ** 2, axis=1))
    assert np.allclose(rb.integral_L_squared, np.sum(rb.L ** 2, axis=1))


def test_prepared_runs_do_not_share_their_integrals():
    prepared = derive.prepare(_short())
    one, two = prepared.run(), prepared.run()
    (name,) = one.integrals
    assert not np.shares_memory(one.integrals[name], two.integrals[name])
    assert np.array_equal(one.integrals[name], two.integrals[name])
    assert not np.array_equal(prepared.run(initial={"gamma_dot": 5.0}).integrals[name], one.integrals[name])
