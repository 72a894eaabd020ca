"""The cost of each output sample (issue 20): a prepared run's buffer is not zeroed (only its
stats record is), and what is left in it from before never shows in a result or a status."""
from __future__ import annotations

import numpy as np
import pytest

import derive
import derive.runtime.integrate as integrate
from derive.bench.reference import reference_data

ARRAYS = ("t", "alpha", "beta", "gamma", "omega", "axis", "energy", "p_alpha", "p_gamma", "n", "L")


def _scene(samples: int = 101, **simulate) -> dict:
    data = reference_data(10.0)
    data["simulate"].update(samples=samples, **simulate)
    return data


def _dirty_buffers(monkeypatch):
    """From here on np.empty in the runtime hands out buffers full of NaN (stats record
    included), as memory left over from an earlier run may be."""
    real = np.empty

    def dirty(shape, *args, **kwargs):
        buf = real(shape, *args, **kwargs)
        buf.fill(np.nan)
        return buf

    monkeypatch.setattr(integrate.np, "empty", dirty)


@pytest.mark.parametrize("method", ["dop853", "taylor"])
def test_a_prepared_run_in_a_dirty_buffer_is_simulate_s(monkeypatch, method):
    data = _scene(method=method, formulation="reduced-u")
    direct = derive.simulate(data)
    _dirty_buffers(monkeypatch)
    res = derive.prepare(data).run()
    assert res.nfev == direct.nfev
    for name in ARRAYS:
        assert np.array_equal(getattr(res, name), getattr(direct, name)), name


def test_a_failing_prepared_run_in_a_dirty_buffer_reports_simulate_s_status(monkeypatch):
    data = _scene(max_steps=5)
    with pytest.raises(derive.IntegrationError) as direct:
        derive.simulate(data)
    _dirty_buffers(monkeypatch)
    with pytest.raises(derive.IntegrationError) as prepared:
        derive.prepare(data).run()
    assert str(prepared.value) == str(direct.value)
