"""The one C driver per method and its ``derive_saveat``: what a save selects (every sample or
the last, states from given starts or the init map's start with the outputs, one trajectory or
a batch) comes out of the same integration, and a save the method cannot make is refused."""
import ctypes

import numpy as np
import pytest

import derive
from derive.bench.reference import reference_data
from derive.methods.status import Status
from derive.runtime.records import STATS_DTYPE, SaveAt, saveat

_VP = ctypes.c_void_p


@pytest.fixture(scope="module")
def top():
    """The reduced-u top's dop853 library: (run driver, kernel, driver arguments, inputs, p, t)."""
    data = reference_data(2.0)
    data["simulate"].update(samples=11, method="dop853", formulation="reduced-u")
    plan = derive.prepare(data).plan
    c = plan.candidates[0]
    fn = c.kernel.lib[f"{c.desc.name}_run_dop853"]  # (a fresh function object: no argtypes)
    fn.restype = ctypes.c_int
    conv = [ty(v) for ty, v in zip((ctypes.c_double, ctypes.c_double, ctypes.c_double, ctypes.c_long),
                                   c.args)]
    return fn, c.kernel, conv, np.ascontiguousarray(plan.inputs, dtype=np.float64), c.params, plan.t


def _run(top, save, n_batch, ins, ps):
    fn, k, conv, _, _, t = top
    n = 1 if save.final else t.shape[0]
    width = k.nin if save.outputs else k.ny
    ins = np.ascontiguousarray(np.broadcast_to(ins, (n_batch, width)), dtype=np.float64)
    ps = np.array(np.broadcast_to(ps, (n_batch, k.np)), dtype=np.float64, order="C")
    y = np.full((n_batch, n, k.ny), np.nan)
    out = np.full((n_batch, k.nout, n), np.nan)
    st = np.zeros(max(n_batch, 1), STATS_DTYPE)
    rc = fn(ctypes.byref(save), ctypes.c_long(n_batch), _VP(ins.ctypes.data), _VP(ps.ctypes.data),
            *conv, _VP(y.ctypes.data), _VP(out.ctypes.data), _VP(st.ctypes.data))
    return rc, y, out, ps, st


def test_every_save_of_one_trajectory_comes_from_the_same_integration(top):
    """The grid with outputs; the same start given as a state (states alone, the same bits); the
    last time alone (the grid's last state bit for bit); a batch of three (each row the single
    run's)."""
    _, k, _, inputs, p, t = top
    rc, y, out, pd, st = _run(top, saveat(t), 1, inputs, p)
    assert rc == 0 and np.isfinite(out).all() and st[0]["nstep"] > 0
    rc_s, y_s, _, _, _ = _run(top, saveat(t, outputs=False), 1, y[0, 0], pd[0])
    assert rc_s == 0 and np.array_equal(y_s, y)
    rc_f, y_f, _, _, st_f = _run(top, saveat(t, final=True), 1, inputs, p)
    assert rc_f == 0 and np.array_equal(y_f[0, 0], y[0, -1]) and st_f[0]["nstep"] == st[0]["nstep"]
    rc_b, y_b, out_b, _, st_b = _run(top, saveat(t), 3, inputs, p)
    assert rc_b == 0 and all(np.array_equal(y_b[b], y[0]) and np.array_equal(out_b[b], out[0])
                             for b in range(3))
    assert list(st_b["nfev"]) == [st[0]["nfev"]] * 3


def test_a_save_the_driver_cannot_make_is_refused_as_bad_arguments(top):
    """The last time alone from given states (no such save), and a negative batch size."""
    _, k, _, inputs, p, t = top
    rc, *_ = _run(top, saveat(t, final=True, outputs=False), 1, np.zeros(k.ny), p)
    assert rc == Status.BAD_ARGS
    fn, _, conv, *_ = top
    assert fn(ctypes.byref(saveat(t)), ctypes.c_long(-1), None, None, *conv, None, None, None) == Status.BAD_ARGS
    assert fn(None, ctypes.c_long(1), None, None, *conv, None, None, None) == Status.BAD_ARGS


def test_the_saveat_record_has_the_c_layout():
    """The ctypes mirror of derive_saveat: a pointer, a long and four ints, in that order."""
    names = [f[0] for f in SaveAt._fields_]
    assert names == ["t_out", "n_out", "final", "outputs", "pole_check", "lanes"]
    assert SaveAt.n_out.offset == ctypes.sizeof(ctypes.c_void_p)
    assert ctypes.sizeof(SaveAt) == ctypes.sizeof(ctypes.c_void_p) + ctypes.sizeof(ctypes.c_long) + 4 * 4
