"""The Taylor method's lanes driver (``<model>_run_taylor`` saving the last time with
``save->lanes``) runs W trajectories at once (W from the CPU it was built for: ``-march=native``), every lane its
own steps. Each trajectory's state, outputs, status and statistics are the scalar final-only
driver's (built with the default flags) bit for bit, failing lanes included, and
``derive.simulate_batch(..., outputs="final")`` with the Taylor method runs it."""
import re

import numpy as np
import pytest
from interrupts import CpuTimer

import derive
from derive.methods.status import Status
from derive.runtime.integrate import ModelKernel
from derive.sim import batch
from derive.symbolic.formulations import OUTPUTS

# the vector and lanes builds are only what they are at derive's own optimisation level
pytestmark = pytest.mark.optimised

BASE = {"body": {"I1": 1.0, "I3": 0.5}, "gravity": {"M": 1.0, "g": 1.0, "l": 1.0},
        "simulate": {"t_end": 3.0, "samples": 5, "rtol": 1e-10, "atol": 1e-12, "method": "taylor"}}


def scenes(n, seed=3, **simulate):
    rng = np.random.default_rng(seed)
    return [{**BASE, "simulate": {**BASE["simulate"], **simulate},
             "initial": {"alpha": float(rng.uniform(-1, 1)), "beta": float(rng.uniform(0.5, 1.2)),
                         "gamma": float(rng.uniform(-1, 1)), "alpha_dot": float(rng.uniform(-0.6, 0.6)),
                         "beta_dot": float(rng.uniform(-0.5, 0.5)), "gamma_dot": float(rng.uniform(3.0, 9.0))}}
            for _ in range(n)]


def kernels(sc, formulation):
    """(plan, description, scalar kernel (the portable build), lanes kernel, driver arguments,
    pole check) of a batch of scenes."""
    bp = batch.batch_plan(sc)
    desc, scalar, args = bp.kernel(formulation, "portable")  # (the plan's own build is not compiled)
    pole = dict(bp.candidates).get(formulation, 0)
    return bp, desc, scalar, ModelKernel.load(desc, bp.method, "lanes"), args, pole


def same(a, b):
    """Both drivers' (out, y, ps, stats) equal bit for bit: the statistics and the parameters of
    every trajectory, the outputs and the state of those that succeeded (a failed one's are
    not written: the caller raises)."""
    assert a[3].tobytes() == b[3].tobytes()
    assert np.array_equal(a[2], b[2], equal_nan=True)
    ok = a[3]["status"] == 0
    for x, y in zip(a[:2], b[:2]):
        assert np.array_equal(x[ok], y[ok])


# a reduced top and the quaternion body in make test (each builds two libraries); the others
# in make test-slow
@pytest.mark.parametrize("formulation", ["reduced-u", "quaternion",
                                         *(pytest.param(f, marks=pytest.mark.slow)
                                           for f in ("reduced", "euler-angles", "euler-poisson"))])
def test_lanes_are_the_scalar_driver_bit_for_bit(formulation):
    sc = scenes(13, formulation=formulation)  # one group and a ragged one on any width
    bp, desc, scalar, native, args, pole = kernels(sc, formulation)
    assert native.lanes in (2, 4, 8) and scalar.lanes == 0 and scalar.has_lanes  # (lanes: native only)
    ps = bp.params(desc)
    want = scalar.simulate_final_batch(bp.inputs, ps, bp.t, args, pole)
    got = native.simulate_lanes_batch(bp.inputs, ps, bp.t, args, pole)
    assert len(set(want[3]["nstep"])) > 3  # the lanes of a group take different steps
    assert (want[3]["status"] == 0).all()
    same(want, got)


# The baseline width (a third -O3 build of the model) of the reduced top in make test, of the
# quaternion body and the others in make test-slow: the lanes' code is the same for every model,
# the widths differ in the vector types it is compiled for.
@pytest.mark.parametrize("formulation", ["reduced-u", *(pytest.param(f, marks=pytest.mark.slow) for f in
                                                        ("quaternion", "reduced", "euler-angles", "euler-poisson"))])
def test_the_baseline_width_is_the_scalar_driver_bit_for_bit(formulation):
    """The final-only lanes driver built with the default flags (the baseline's narrower width,
    2), on a ragged group and on lanes refilled mid-batch (both ways round): the scalar
    driver's bit for bit."""
    baseline = None
    for sc in (scenes(13, formulation=formulation), spread(37, formulation=formulation, t_end=6.0)):
        bp, desc, scalar, _, args, pole = kernels(sc, formulation)
        baseline = baseline or _lanes_library(desc, "baseline", ["-DDERIVE_LANES"])
        assert baseline.lanes == 2
        ps = bp.params(desc)
        want = scalar.simulate_final_batch(bp.inputs, ps, bp.t, args, pole)
        assert (want[3]["status"] == 0).all() and len(set(want[3]["nstep"])) > 3
        same(want, baseline.simulate_lanes_batch(bp.inputs, ps, bp.t, args, pole))
        rev = bp.inputs[::-1].copy(), ps[::-1].copy()
        same(scalar.simulate_final_batch(*rev, bp.t, args, pole), baseline.simulate_lanes_batch(*rev, bp.t, args, pole))


def _lanes_library(desc, tag: str, flags: list) -> ModelKernel:
    """The model's Taylor library built with the default flags and ``flags`` (a test's own
    build: derive builds the lanes only with -march=native)."""
    from derive.runtime import cbuild

    sources = desc.c_sources()
    unity = f"{desc.name}_taylor_unit.c"
    sources[unity] = "".join(f'#include "{n}"\n' for n in (f"{desc.name}.c", f"{desc.name}_solvers.c",
                                                             f"{desc.name}_taylor.c"))
    flags = [*cbuild.DEFAULT_FLAGS, *flags, "-DDERIVE_SELECT", "-DDERIVE_WITH_TAYLOR"]
    return ModelKernel(desc, "taylor", cbuild.compile_library(f"{desc.name}_taylor_{tag}", sources, unity, flags))


#: A body of user terms whose jet uses every rule the shipped models do not: a power with a
#: non-integer exponent, exp and sqrt (the potential's gradient), log and atan2 (the torque's).
RULES = {"body": {"I1": 1.0, "I3": 0.5},
         "potential": [{"name": "field", "params": {"mu": 0.3},
                        "V": "mu*((2 + R13)**1.5 + exp(0.3*R33) + sqrt(2 + R13*R33))"}],
         "torque": [{"name": "push", "frame": "body", "params": {"mu": 0.1},
                     "tau": ["mu*log(3 + R23)", "mu*atan2(R13, 2 + R33)", "0"]}],
         "simulate": {**BASE["simulate"], "t_end": 2.0}}


# the baseline width of every rule (a second -O3 build of the body) in `make test-slow`; the
# baseline width of the shipped rules is checked in make test by
# test_the_baseline_width_is_the_scalar_driver_bit_for_bit
@pytest.mark.parametrize("width", ["native", pytest.param("baseline", marks=pytest.mark.slow)])
def test_every_rule_of_the_lanes_is_the_scalar_rule_bit_for_bit(width):
    """The lanes' helpers of every rule (written on GNU C's vector types) against the scalar
    driver's, on a user body whose jet has them all, in this CPU's width and the baseline's;
    the products and quotients also as sums side by side in one loop (derive.codegen.taylor
    ._fused)."""
    sc = [{**RULES, "initial": d["initial"]} for d in scenes(11)]
    bp = batch.batch_plan(sc)
    formulation, pole = bp.candidates[0]
    desc, scalar, args = bp.kernel(formulation, "portable")  # (the plan's own build is not compiled)
    source = desc.c_sources()[f"{desc.name}_taylor.c"]
    fused = re.findall(r"s\d+_ ([-+])= ", source)
    assert "+" in fused and "-" in fused  # a product and a quotient among the fused sums
    for rule in ("mul", "sqr", "div", "sqrt", "pow", "exp", "log", "atan2"):
        assert f"tcl_{rule}(n" in source or rule in ("mul", "div"), rule
    ps = bp.params(desc)
    want = scalar.simulate_final_batch(bp.inputs, ps, bp.t, args, pole)
    assert (want[3]["status"] == 0).all() and len(set(want[3]["nstep"])) > 3
    lanes = (ModelKernel.load(desc, bp.method, "lanes") if width == "native"
             else _lanes_library(desc, "baseline", ["-DDERIVE_LANES"]))
    assert lanes.lanes >= 2
    same(want, lanes.simulate_lanes_batch(bp.inputs, ps, bp.t, args, pole))


def test_failing_lanes_say_so_per_trajectory_while_the_others_finish():
    sc = scenes(11, formulation="reduced-u", t_end=6.0)
    bp, desc, scalar, native, args, pole = kernels(sc, "reduced-u")
    ps = bp.params(desc)
    steps = scalar.simulate_final_batch(bp.inputs, ps, bp.t, args, pole)[3]["nstep"]
    budget = int(np.median(steps))  # the step budget spent by about half of them
    args = list(args)
    args[-1] = budget
    inputs = bp.inputs.copy()
    inputs[4, 8] = np.nan  # a start that is not finite (the init map says so)
    inputs[7, 8] = 1e200  # a spin whose series overflow in the lane's first step
    want = scalar.simulate_final_batch(inputs, ps, bp.t, args, pole)
    got = native.simulate_lanes_batch(inputs, ps, bp.t, args, pole)
    same(want, got)
    st = want[3]
    assert st["status"][4] == st["status"][7] == Status.NONFINITE
    assert st["nfev"][4] == 0 and st["nfev"][7] == 1  # the init map; the lane's first step
    assert (st["status"] == Status.MAX_STEPS).sum() >= 2
    assert (st["status"] == 0).sum() >= 3


def spread(n, seed=5, **simulate):
    """Scenes whose step counts differ several fold (spins from slow to fast): lanes finish at
    very different times, so the lanes take the batch's next trajectories mid-way through their
    neighbours'."""
    sc = scenes(n, seed=seed, **simulate)
    spins = np.random.default_rng(seed).uniform(0.5, 40.0, n)
    return [{**d, "initial": {**d["initial"], "gamma_dot": float(w)}} for d, w in zip(sc, spins)]


@pytest.mark.parametrize("formulation", ["reduced-u", "quaternion"])
def test_lanes_refilled_mid_batch_are_the_scalar_driver_bit_for_bit(formulation):
    sc = spread(37, formulation=formulation, t_end=6.0)
    bp, desc, scalar, native, args, pole = kernels(sc, formulation)
    ps = bp.params(desc)
    want = scalar.simulate_final_batch(bp.inputs, ps, bp.t, args, pole)
    steps = want[3]["nstep"]
    assert (want[3]["status"] == 0).all()
    assert steps.max() > 4 * steps.min()  # a lane takes several trajectories while another runs one
    same(want, native.simulate_lanes_batch(bp.inputs, ps, bp.t, args, pole))
    # (the baseline width: test_the_baseline_width_is_the_scalar_driver_bit_for_bit)
    # the batch the other way round: each trajectory in another lane, beside other neighbours
    rev = bp.inputs[::-1].copy(), ps[::-1].copy()
    same(scalar.simulate_final_batch(*rev, bp.t, args, pole), native.simulate_lanes_batch(*rev, bp.t, args, pole))


def test_lanes_refilled_after_failures_and_budgets_are_the_scalar_driver_bit_for_bit():
    """Failing starts, lanes failing in their first step and lanes out of steps among trajectories
    of very different lengths: every lane that stops takes the next trajectory, whatever stopped
    it, and each trajectory's status and statistics are the scalar driver's."""
    sc = spread(41, formulation="reduced-u", t_end=6.0)
    bp, desc, scalar, native, args, pole = kernels(sc, "reduced-u")
    ps = bp.params(desc)
    steps = scalar.simulate_final_batch(bp.inputs, ps, bp.t, args, pole)[3]["nstep"]
    args = list(args)
    args[-1] = int(np.percentile(steps, 70))
    inputs = bp.inputs.copy()
    inputs[[2, 3, 17], 8] = np.nan  # starts that are not finite: never loaded
    inputs[[0, 9, 10, 30], 8] = 1e200  # lanes whose series overflow in their first step
    want = scalar.simulate_final_batch(inputs, ps, bp.t, args, pole)
    st = want[3]
    assert (st["status"] == Status.MAX_STEPS).sum() >= 5
    assert (st["status"] == 0).sum() >= 15
    assert (st["nfev"][[2, 3, 17]] == 0).all() and (st["nfev"][[0, 9, 10, 30]] == 1).all()
    same(want, native.simulate_lanes_batch(inputs, ps, bp.t, args, pole))
    baseline = _lanes_library(desc, "baseline", ["-DDERIVE_LANES"])
    same(want, baseline.simulate_lanes_batch(inputs, ps, bp.t, args, pole))


def test_a_batch_of_failed_starts_loads_no_lane():
    sc = scenes(11, formulation="reduced-u")
    bp, desc, scalar, native, args, pole = kernels(sc, "reduced-u")
    inputs = bp.inputs.copy()
    inputs[:, 8] = np.nan
    want = scalar.simulate_final_batch(inputs, bp.params(desc), bp.t, args, pole)
    assert (want[3]["status"] == Status.NONFINITE).all()
    same(want, native.simulate_lanes_batch(inputs, bp.params(desc), bp.t, args, pole))


def test_a_refused_start_stops_the_lanes_batch_as_the_scalar_one():
    """A pole check that refuses a start: status RANGE, so the batch's next formulation runs."""
    sc = scenes(6, formulation="reduced-u")
    bp, desc, scalar, native, args, _ = kernels(sc, "reduced-u")
    inputs = bp.inputs.copy()
    inputs[3, 1] = 0.05  # beta near the pole: reduced-u's check refuses it
    got = native.simulate_lanes_batch(inputs, bp.params(desc), bp.t, args, 1)
    want = scalar.simulate_final_batch(inputs, bp.params(desc), bp.t, args, 1)
    assert want[3]["status"][3] == Status.RANGE
    assert got[3][3:].tobytes() == want[3][3:].tobytes()  # the refusal and the rest, as there


def test_simulate_batch_runs_the_lanes_for_the_taylor_method():
    sc = scenes(10, formulation="reduced-u", samples=41)
    full = derive.simulate_batch(sc)
    fin = derive.simulate_batch(sc, outputs="final")
    assert fin.driver == "lanes" and fin.method == "taylor"
    for name, _ in OUTPUTS:
        assert np.array_equal(fin.outputs[name], np.array([getattr(r, name)[-1] for r in full])), name
    assert np.array_equal(fin.state, np.array([r.state[-1] for r in full]))
    assert np.array_equal(fin.nfev, [r.nfev for r in full])


def test_a_lanes_library_without_the_lanes_runs_the_scalar_final_driver(monkeypatch):
    """The lanes are written on GNU C's vector types: a compiler without them builds the lanes'
    library with no lanes driver (``lanes`` 0), and the batch runs the scalar final-only driver,
    with the same numbers."""
    sc = scenes(10, formulation="reduced-u", samples=41)
    lanes = derive.simulate_batch(sc, outputs="final")
    bp, desc, _, native, _, _ = kernels(sc, "reduced-u")
    monkeypatch.setattr(native, "lanes", 0)  # (the kernel the batch loads: one per build)
    fin = derive.simulate_batch(sc, outputs="final")
    assert lanes.driver == "lanes" and fin.driver == "final"
    assert np.array_equal(fin.state, lanes.state) and np.array_equal(fin.nfev, lanes.nfev)


def test_a_failing_lane_is_named_as_the_full_batch_names_it():
    sc = scenes(9, formulation="reduced-u", max_steps=12)
    with pytest.raises(derive.IntegrationError) as full:
        derive.simulate_batch(sc)
    with pytest.raises(derive.IntegrationError) as fin:
        derive.simulate_batch(sc, outputs="final")
    assert str(fin.value) == str(full.value)


def test_an_interrupt_stops_the_lanes():
    """The interrupt flag, polled once per step of a group, set from another thread as a SIGINT
    sets it: KeyboardInterrupt."""
    sc = scenes(16, formulation="reduced-u", t_end=1e7, rtol=1e-13, atol=1e-15, max_steps=10**12)
    bp, desc, _, native, args, pole = kernels(sc, "reduced-u")
    if native._run.guard is None:
        pytest.skip("the kernel was loaded outside the main thread: no guard")
    timer = CpuTimer(0.2, native.lib.derive_sigint_request)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            native.simulate_lanes_batch(bp.inputs, bp.params(desc), bp.t, args, pole)
    finally:
        timer.cancel()


def test_an_interrupt_after_refills_says_so_per_trajectory(monkeypatch):
    """The interrupt flag set while lanes that failed in their first step have taken the batch's
    next trajectories: those failures are the scalar driver's, every trajectory loaded and still
    running says INTERRUPTED, and so does every one not yet loaded (the call returns the status:
    no guard, so no KeyboardInterrupt)."""
    sc = scenes(40, formulation="reduced-u", t_end=1e7, rtol=1e-13, atol=1e-15, max_steps=10**12)
    bp, desc, scalar, native, args, pole = kernels(sc, "reduced-u")
    inputs = bp.inputs.copy()
    # trajectories whose series overflow in their first step, their lanes refilled at once (one
    # of them a refill itself): loaded whatever the width
    early = [0, 1, 2, native.lanes + 1]
    inputs[early, 8] = 1e200
    ps = bp.params(desc)
    want = scalar.simulate_final_batch(inputs[early], ps[early], bp.t, args, pole)[3]
    monkeypatch.setattr(native._run, "guard", None)
    timer = CpuTimer(0.2, native.lib.derive_sigint_request)
    timer.start()
    try:
        st = native.simulate_lanes_batch(inputs, ps, bp.t, args, pole)[3]
    finally:
        timer.cancel()
        native.lib.derive_sigint_guard(0)  # (clears the flag)
    for name in want.dtype.names:  # (field by field: a fancy index copies no padding)
        assert np.array_equal(st[early][name], want[name], equal_nan=True), name
    rest = np.setdiff1d(np.arange(len(sc)), early)
    assert (st["status"][rest] == Status.INTERRUPTED).all()
    assert (st["nfev"][rest[:native.lanes]] > 0).all()  # the lanes that ran, refills included
    assert (st["nfev"][rest[native.lanes:]] == 0).all()


def test_the_width_is_the_cpus():
    """W from the instruction sets of the build (-march=native for the lanes' library): 8 with
    AVX-512, 4 with AVX, else 2; the default build (x86-64 baseline or another CPU) its own."""
    from derive.runtime import cbuild

    sc = scenes(2, formulation="reduced-u")
    _, _, scalar, native, _, _ = kernels(sc, "reduced-u")
    macros = cbuild.native_macros(tuple(cbuild.compiler()))
    want = 8 if "__AVX512F__" in macros else 4 if "__AVX__" in macros else 2
    assert native.lanes == want
    assert scalar.lanes <= native.lanes


@pytest.mark.parametrize("formulation", [pytest.param("quaternion", marks=pytest.mark.slow), "reduced-u"])
def test_the_avx2_width_is_bit_for_bit_too(formulation):
    """W = 4 (AVX, here AVX2 with FMA instructions available) on a CPU that would build 8: the
    lanes' library built with the lanes' flags but -mavx2 -mfma instead of -march=native gives the
    scalar driver's numbers (no fused multiply-add slips in: the quaternion's init map is where
    gcc's straight-line vectoriser once fused one)."""
    from derive.runtime import cbuild

    if "__AVX2__" not in cbuild.native_macros(tuple(cbuild.compiler())):
        pytest.skip("this CPU has no AVX2")
    sc = scenes(11, formulation=formulation)
    bp, desc, scalar, _, args, pole = kernels(sc, formulation)
    avx2 = _lanes_library(desc, "avx2", ["-mavx2", "-mfma",
                                          *(f for f in cbuild.NATIVE_FLAGS if f != "-march=native")])
    assert avx2.lanes == 4
    ps = bp.params(desc)
    same(scalar.simulate_final_batch(bp.inputs, ps, bp.t, args, pole),
         avx2.simulate_lanes_batch(bp.inputs, ps, bp.t, args, pole))


# the reduced top, the Euler-angle top and the quaternion body in make test (their portable builds
# are the lanes tests'); heavy_top_reduced and Euler-Poisson, two -O3 builds each of their own,
# in make test-slow
@pytest.mark.parametrize("formulation", ["reduced-u", "euler-angles", "quaternion",
                                         *(pytest.param(f, marks=pytest.mark.slow) for f in ("reduced", "euler-poisson"))])
def test_the_vector_build_is_the_portable_one_bit_for_bit(formulation):
    """A Taylor method's single runs use the vector build (this CPU's width for the output map
    over a step's block of samples); every sample's outputs, the states, the parameters and the
    statistics are the portable build's bit for bit (samples many to a step: blocks of 16)."""
    sc = scenes(6, samples=401, formulation=formulation)
    bp = batch.batch_plan(sc)
    desc, kernel, args = bp.kernel(formulation)
    pole = dict(bp.candidates).get(formulation, 0)
    vector = ModelKernel.load(desc, bp.method, "vector")
    assert kernel is vector  # the build a Taylor method's plan runs in
    portable = ModelKernel.load(desc, bp.method, "portable")
    ps = bp.params(desc)
    got = vector.simulate_batch(bp.inputs, ps, bp.t, args, pole)
    want = portable.simulate_batch(bp.inputs, ps, bp.t, args, pole)
    same(want, got)
    for i in range(len(sc)):  # and one at a time (the prepared run's call)
        one = vector.simulate(bp.inputs[i], ps[i], bp.t, args, pole)
        np.testing.assert_array_equal(one[0].view(np.uint64), want[0][i].view(np.uint64))
