"""Where a contact law has no consistent continuation: the phases it would take contradict."""
import numpy as np
import pytest

from derive.contact import driver
from derive.contact.kernel import OUTPUTS
from derive.contact.scene import read
from derive.contact.simulate import initial_state, kernel, params
from derive.errors import IntegrationError

O = {n: i for i, n in enumerate(OUTPUTS)}
KNOCKED = {"body": {"I1": 2e-5, "I3": 1.5e-5}, "gravity": {"M": 0.05, "g": 9.81},
           "contact": {"shape": "sphere", "radius": 0.005, "offset": -0.01, "friction": "rolling"},
           "initial": {"beta": 0.5, "gamma_dot": 150.0, "beta_dot": 40.0}}


def test_a_rolling_peg_reaching_n_zero_with_a_tangential_force_has_no_phase_to_go_on_in():
    sc = read(KNOCKED)
    p, k = params(sc), kernel(sc.shape, sc.law)
    go = dict(restitution=0.0, rtol=sc.rtol, atol=sc.atol, max_steps=sc.max_steps)
    with pytest.raises(IntegrationError, match=r"more than 20 phase switches by t = 0\.0437484"):
        driver.run(sc.shape, sc.law, p, None, initial_state(sc), np.array([0.0, 0.05]), max_switches=20, **go)
    # just before: rolling, N falling to zero while the no-slip force is larger than the weight
    run = driver.run(sc.shape, sc.law, p, None, initial_state(sc), np.array([0.0, 0.0437484]), **go)
    assert [s.event for s in run.switches] == ["landing"] and run.phase[-1] == 1
    y = run.y[-1].copy()
    o = k.outputs(1, y, p, np.zeros(3))
    assert 0 < o[O["N"]] < 1e-5 and np.linalg.norm(o[O["ft_x"]:O["ft_z"] + 1]) > 2 * 0.05 * 9.81
    # the flight from there presses into the table: neither rolling (N < 0) nor flying can go on
    y[9:13] = o[O["z"]:O["vz"] + 1]
    h, f = 1e-6, (lambda s: k.rhs(2, s, p, np.zeros(3)))
    for _ in range(100):
        k1 = f(y); k2 = f(y + h / 2 * k1); k3 = f(y + h / 2 * k2); k4 = f(y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    assert k.outputs(2, y, p, np.zeros(3))[O["gap"]] < -1e-10
