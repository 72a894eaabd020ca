"""A run its step budget cannot cover is refused before it starts (derive.methods.costs.least_steps):
exit 3 with one line saying the estimate and how to raise the budget, without integrating; the
estimate is a floor, below the steps every example scene really takes, so no run that would
finish is refused."""
from __future__ import annotations


import pytest
from cli_in_process import derive_main

import derive
import derive.sim.simulation as simulation
from derive.methods import costs
from derive.sim import examples
from derive.sim.inputs import fastest_rate
from derive.sim.scene import load_scene
from small_scenes import HEAVY_TOP

#: The heavy top spun at 1e9 rad/s over 2 s: hopeless under any method at the default budget.
FAST = HEAVY_TOP.replace("gamma_dot = 10.0", "gamma_dot = 1e9").replace("t_end = 0.05", "t_end = 2.0")


@pytest.fixture
def fast_top(tmp_path):
    path = tmp_path / "fast.toml"
    path.write_text(FAST)
    return path


@pytest.mark.parametrize("method", ["scipy-rk45", "scipy-lsoda", "dop853", "taylor", "auto"])
def test_a_top_spun_at_1e9_is_refused_before_any_step(method, fast_top, monkeypatch):
    def never(*args, **kwargs):
        raise AssertionError("integrated a run the budget cannot cover")

    monkeypatch.setattr(simulation, "_solve_scipy", never)
    monkeypatch.setattr(simulation, "_compiled_result", never)
    with pytest.raises(derive.IntegrationError) as err:
        derive.simulate(str(fast_top), method=method)
    message = str(err.value)
    assert "needs at least about" in message and "simulate.max_steps = 1000000" in message
    assert "--max-steps" in message and "\n" not in message


def test_the_command_line_refuses_it_with_exit_3_and_one_line(fast_top):
    proc = derive_main("simulate", fast_top, "--method", "scipy-rk45", "--json")
    assert proc.returncode == 3
    assert proc.stdout == ""
    lines = proc.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {fast_top}: scipy-rk45 needs at least about ")


def test_a_larger_budget_lifts_the_refusal(fast_top):
    scene = load_scene(str(fast_top))
    span = scene.simulate.t_end * fastest_rate(scene)
    floor = costs.least_steps("scipy-rk45", span, 1e-10, 1e-12)
    assert costs.over_budget("scipy-rk45", span, 1e-10, 1e-12, 10**6) is not None
    assert costs.over_budget("scipy-rk45", span, 1e-10, 1e-12, int(floor) + 1) is None


def test_every_tolerance_driven_method_has_a_step_law():
    from derive.methods.registry import REFERENCE_METHODS, compiled_methods, tolerance_driven

    driven = [m for m in compiled_methods() if tolerance_driven(m)] + list(REFERENCE_METHODS)
    assert sorted(driven) == sorted(costs.STEP_LAWS)


#: The examples about a fixed point or free (tops on a table run their own phase loop, derive.contact).
ROTATING = [n for n in examples.names() if examples.path(n).parent != examples.CONTACT]


@pytest.mark.parametrize("name", ROTATING)
@pytest.mark.parametrize("method,per_step", [("dop853", 12), ("taylor", 1)])
def test_the_floor_is_below_the_steps_every_example_takes(name, method, per_step):
    res = derive.simulate(name, method=method)
    s = res.scene.simulate
    floor = costs.least_steps(method, s.t_end * fastest_rate(res.scene), s.rtol, s.atol)
    assert floor <= res.nfev / per_step


@pytest.mark.parametrize("name", ["reference_top", "looping_top", "tennis_racket", "sleeping_top"])
def test_the_floor_is_below_the_steps_scipy_rk45_takes(name):
    res = derive.simulate(name, method="scipy-rk45", t_end=0.2)
    s = res.scene.simulate
    floor = costs.least_steps("scipy-rk45", 0.2 * fastest_rate(res.scene), s.rtol, s.atol)
    assert floor <= res.nfev / 6
