"""``derive simulate --json`` tells drift from work: ``energy_change`` = E(t_end) − E(0) for every
run, ``energy_drift`` (the integration's error) only where the physics conserves the energy;
a damped or driven run's change of energy is the work its torques did, not a drift."""
from __future__ import annotations

import json

import numpy as np
import pytest

import derive
from derive import cli
from derive.codegen.render import ROOT
from derive.sim import plots

MAGNETIC = str(ROOT / "docs" / "own-body" / "magnetic_top.toml")


def summary(res) -> dict:
    return json.loads(json.dumps(cli.simulate_summary(res, 0.0)))  # what --json prints


def test_a_conservative_run_reports_its_drift_and_its_change():
    res = derive.simulate("looping_top", t_end=0.5, samples=51)
    s = summary(res)
    E = res.energy
    assert s["energy_drift"] == float(np.max(np.abs(E - E[0])) / abs(E[0]))
    assert s["energy_drift_relative"] is True
    assert s["energy_change"] == float(E[-1] - E[0])


def test_a_damped_run_reports_the_work_done_not_a_drift():
    res = derive.simulate("damped_top", t_end=2.0, samples=2001)
    s = summary(res)
    assert s["energy_drift"] is None and s["energy_drift_relative"] is None
    assert s["energy_change"] == float(res.energy[-1] - res.energy[0]) < 0
    # the change is the work the damping did (trapezoid rule on the samples)
    assert s["energy_change"] == pytest.approx(-plots.work_against_damping(res)[-1], rel=1e-4)


def test_a_driven_run_reports_the_work_done_not_a_drift():
    res = derive.simulate(MAGNETIC, t_end=0.5, samples=101)
    s = summary(res)
    assert s["energy_drift"] is None
    assert s["energy_change"] == float(res.energy[-1] - res.energy[0]) != 0.0


def test_the_command_line_prints_both_keys(capsys):
    assert cli.main(["simulate", "damped_top", "--t-end", "0.2", "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["energy_drift"] is None and s["energy_change"] < 0
