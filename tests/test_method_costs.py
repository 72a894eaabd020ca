"""The cost model behind ``method = "auto"`` (derive.methods.costs): its shape, and that a plan
of an auto scene takes the method it names. Whether its choices are the faster ones is
measured by ``derive bench`` (derive.bench.autochoice), never timed here."""
from __future__ import annotations

import math

import pytest

from derive.methods import costs
from derive.methods.taylor import METHODS as TAYLOR

WORK = costs.Work(rhs_cost=200.0, jet_weight=40.0, output_cost=150.0, ny=6, n_out=18,
                  samples=1001, span=120.0)


def test_dop853_steps_grow_as_the_eighth_root_of_the_tolerance():
    quiet = WORK._replace(samples=0)
    ratio = costs.cost("dop853", quiet, 1e-12, 1e-14) / costs.cost("dop853", quiet, 1e-4, 1e-6)
    assert ratio == pytest.approx(1e8 ** (1 / 8))


def test_taylor_steps_fall_and_jets_grow_with_the_order():
    quiet = WORK._replace(samples=0)
    p_lo, p_hi = TAYLOR["taylor"].order(1e-6, 0), TAYLOR["taylor"].order(1e-12, 0)
    assert p_hi > p_lo
    lo, hi = costs.cost("taylor", quiet, 1e-6, 1e-8), costs.cost("taylor", quiet, 1e-12, 1e-14)
    steps = lambda p: 1 + costs.A / p  # noqa: E731
    jet = lambda p: (costs.TAYLOR_UNIT * (quiet.jet_weight * p * p / 2 + 2 * quiet.ny * p)  # noqa: E731
                     + costs.TAYLOR_STEP)
    assert hi / lo == pytest.approx(steps(p_hi) * jet(p_hi) / (steps(p_lo) * jet(p_lo)))
    assert steps(p_hi) < steps(p_lo)


def test_a_model_without_a_taylor_kernel_runs_dop853():
    none = WORK._replace(jet_weight=0.0)
    assert math.isinf(costs.cost("taylor", none, 1e-12, 1e-14))
    assert costs.choose(none, 1e-12, 1e-14) == "dop853"


def test_the_choice_moves_to_taylor_as_the_tolerance_tightens():
    # with these weights dop853 wins loose and taylor tight (the model's intended shape: a fixed
    # step count against one growing like eps^(-1/8)); the crossing is where the costs meet
    chosen = [costs.choose(WORK, eps, eps / 100) for eps in (1e-3, 1e-6, 1e-9, 1e-12, 1e-15)]
    assert chosen == sorted(chosen, key=costs.CHOICES.index)  # never back to dop853
    for eps in (1e-3, 1e-9, 1e-15):
        costs_ = {m: costs.cost(m, WORK, eps, eps / 100) for m in costs.CHOICES}
        assert costs.choose(WORK, eps, eps / 100) == min(costs_, key=costs_.get)


def test_an_auto_plan_runs_the_method_the_cost_model_picks():
    from derive.sim import plan as plans
    from derive.sim.scene import load_scene

    sc = load_scene("reference_top")
    pl = plans.make(sc)
    assert len(pl.candidates) > 1  # reduced-u, then the fallbacks
    assert pl.method == pl.candidates[0].method
    assert all(c.method == plans.auto_method(sc, c.desc) for c in pl.candidates)
    named = plans.make(load_scene("reference_top", method="dop853"))
    assert named.method == "dop853"


def test_a_sample_costs_the_output_map_and_a_share_of_its_horner_scheme():
    quiet = WORK._replace(samples=0)
    p = TAYLOR["taylor"].order(1e-10, 0)
    extra = costs.cost("taylor", WORK, 1e-10, 1e-12) - costs.cost("taylor", quiet, 1e-10, 1e-12)
    assert extra == pytest.approx(WORK.samples * (costs.TAYLOR_SAMPLE * WORK.ny * p
                                                  + costs.TAYLOR_OUTPUT * WORK.output_cost))
    assert 0 < costs.TAYLOR_SAMPLE <= 1 and 0 < costs.TAYLOR_OUTPUT <= 1
    extra_rk = costs.cost("dop853", WORK, 1e-10, 1e-12) - costs.cost("dop853", quiet, 1e-10, 1e-12)
    assert extra_rk == pytest.approx(WORK.samples * (7 * WORK.ny + WORK.output_cost))
