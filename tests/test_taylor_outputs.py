"""The Taylor method's outputs from the series: the model's output map is part of the
Taylor decomposition, and the whole-simulation driver evaluates every output at every sample
from its own series (Horner), not by the output map on the evaluated state.

The reference is the output map itself: ``<model>_outputs_at`` (the compiled ``<model>_observables``
with the canonical angles, what every other method's driver writes) applied to the states the
same run wrote. Both are truncations of the same solution: they agree to the tolerance, and to
round-off when the tolerance is at round-off.
"""
from __future__ import annotations

import tomllib

import numpy as np
import pytest
import sympy as sp

import derive
from derive.codegen.jet import decompose, series_safe
from derive.codegen.kernelspec import KernelSpec
from derive.codegen.render import ROOT
from derive.codegen.sources import shipped_keys
from derive.methods.status import Status
from derive.symbolic.models import build

SCENES = ROOT / "scenes"


def _prepared(scene, formulation, rtol, samples=None):
    data = tomllib.loads((SCENES / f"{scene}.toml").read_text())
    sim = dict(data.get("simulate", {}), method="taylor", rtol=rtol, atol=rtol * 1e-2,
               formulation=formulation)
    if samples is not None:
        sim["samples"] = samples
    data["simulate"] = sim
    plan = derive.prepare(data).plan
    return plan, plan.candidates[0]


def _run(scene, formulation, rtol):
    plan, c = _prepared(scene, formulation, rtol)
    out, y, p, st = c.kernel.simulate(plan.inputs, c.params, plan.t, c.args, c.pole_check)
    assert st["status"] == Status.OK
    return out, c.kernel.outputs_at(plan.t, y, p), st


def _column_error(out, ref):
    """Per output: the largest difference over the run, relative to the output's size."""
    scale = np.maximum(np.max(np.abs(ref), axis=1), 1.0)
    return np.max(np.abs(out - ref), axis=1) / scale


CASES = [("reference_top", "euler-angles"), ("reference_top", "reduced"),
         ("looping_top", "reduced"), ("looping_top", "quaternion"),
         ("looping_top", "euler-poisson"), ("tennis_racket", "auto")]


@pytest.mark.parametrize("scene, formulation", CASES)
def test_outputs_from_the_series_are_the_output_map_of_the_states(scene, formulation):
    """At rtol 1e-13 every output within 1e-12 of the output map applied to the written states
    (relative to the output's size, at least 1); at rtol 1e-8 within the tolerance."""
    out, ref, _ = _run(scene, formulation, 1e-13)
    assert np.all(_column_error(out, ref) <= 1e-12), _column_error(out, ref)
    out, ref, _ = _run(scene, formulation, 1e-8)
    assert np.all(_column_error(out, ref) <= 1e-8), _column_error(out, ref)


def test_the_reference_top_outputs_do_come_from_the_series():
    """Not the output map: cos β (output nutation axis_z) differs from cos of the written β in
    the last digits somewhere (a truncation of the composed series is not the map of the
    truncated state), while agreeing to the tolerance."""
    out, ref, _ = _run("reference_top", "euler-angles", 1e-8)
    assert (out[8] != ref[8]).any()


def test_a_single_sample_is_the_output_map():
    plan, c = _prepared("reference_top", "euler-angles", 1e-10)
    t = plan.t[:1].copy()
    out, y, p, st = c.kernel.simulate(plan.inputs, c.params, t, c.args, c.pole_check)
    assert st["status"] == Status.OK and st["nstep"] == 0
    np.testing.assert_array_equal(out, c.kernel.outputs_at(t, y, p))


def test_batch_is_the_single_runs_bit_for_bit():
    plan, c = _prepared("looping_top", "euler-angles", 1e-9)
    ins = np.array([plan.inputs, plan.inputs])
    ps = np.array([c.params, c.params])
    bo, by, _, bst = c.kernel.simulate_batch(ins, ps, plan.t, c.args, c.pole_check)
    out, y, _, st = c.kernel.simulate(plan.inputs, c.params, plan.t, c.args, c.pole_check)
    np.testing.assert_array_equal(bo[1], out)
    np.testing.assert_array_equal(by[1], y)
    assert bst[1]["nstep"] == st["nstep"]


@pytest.mark.parametrize("scene, formulation", [("reference_top", "auto"), ("looping_top", "euler-angles"),
                                               ("tennis_racket", "auto")])
def test_a_samples_numbers_do_not_depend_on_the_other_samples(scene, formulation):
    """The same run (same t0 and t_end: the same steps) asked for every sample and for every
    third one and the last: the common samples bit for bit, states and outputs but the three
    angles (their unwrapping reads the samples between). The map of a step's samples runs over
    a whole number of vectors, writing made-up samples where later ones go (rewritten by their
    own steps): a sample left as made up, or one made of another block's numbers, differs."""
    plan, c = _prepared(scene, formulation, 1e-9, samples=1001)
    out, y, p, st = c.kernel.simulate(plan.inputs, c.params, plan.t, c.args, c.pole_check)
    keep = np.r_[np.arange(0, len(plan.t) - 1, 3), len(plan.t) - 1]
    t = np.ascontiguousarray(plan.t[keep])
    sub, ys, _, st2 = c.kernel.simulate(plan.inputs, c.params, t, c.args, c.pole_check)
    assert st["status"] == st2["status"] == Status.OK and st["nstep"] == st2["nstep"]
    np.testing.assert_array_equal(ys, y[keep])
    np.testing.assert_array_equal(sub[3:], out[3:, keep])


def test_which_outputs_have_a_series():
    """sin, cos, exp of controlled states have a series (a column); of a cyclic angle (α, γ:
    the step does not follow them) they are computed at each sample from the state (a pair per
    angle, ``trig``); the quaternion's atan2 angles and square roots are evaluated from the
    state."""
    euler = build(*shipped_keys()["heavy_top"])
    d = decompose(KernelSpec.of(euler), outputs=True)
    beta = euler.states[1]
    assert len(d.columns) == 2 and len(d.pointwise) == 18
    exprs = [e for _, e in d.pointwise]
    assert not any(e.has(sp.sin(beta)) or e.has(sp.cos(beta)) for e in exprs)
    alpha, gamma = euler.states[0], euler.states[2]
    assert d.trig == [0, 2]  # sin and cos of α and γ, per sample
    assert not any(e.has(sp.cos(gamma)) or e.has(sp.sin(alpha)) for e in exprs)
    assert any(e.has(sp.Symbol("tvc1")) for e in exprs)  # cos γ: read from the pair
    quat = build(*shipped_keys()["euler_poisson_sym_gravity"])
    assert decompose(KernelSpec.of(quat), outputs=True).columns == []
    x, y = quat.states[:2]
    assert series_safe(quat, sp.sin(x) * y ** 2 + sp.exp(y))
    assert not series_safe(quat, sp.sqrt(x ** 2 + y ** 2))
    assert not series_safe(quat, sp.Piecewise((x, y > 0), (y, True)))
