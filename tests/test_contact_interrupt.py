"""Ctrl-C stops a compiled contact run: the phase loop asks the shared runtime's interrupt hook
once per step, the libraries are built with the host's Ctrl-C guard, and an interrupt surfaces
as KeyboardInterrupt (the command line's exit 130, tests/test_cli_robust.py)."""
import tomllib

import pytest

import derive
from derive.codegen.render import ROOT
from derive.contact import driver, reduced
from interrupts import CpuTimer


def long_scene(name: str) -> dict:
    """A shipped contact scene run far longer than a test waits for (three samples)."""
    with open(ROOT / "scenes" / "contact" / f"{name}.toml", "rb") as f:
        data = tomllib.load(f)
    data["simulate"].update(t_end=1e5, samples=3, max_steps=10**12)
    return data


def interrupted(data: dict, request) -> None:
    """Run ``data`` with an interrupt requested after 0.2 s of this thread's CPU: it raises
    KeyboardInterrupt."""
    timer = CpuTimer(0.2, request)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            derive.simulate(data)
    finally:
        timer.cancel()


def test_an_interrupt_stops_the_compiled_phase_driver():
    """The tippe top in the full formulation: contact_simulate stops at its next step."""
    _, lib = driver.library("sphere", "viscous", False)
    interrupted(long_scene("tippe_top"), lib.derive_sigint_request)


def test_an_interrupt_stops_the_reduced_frictionless_loop():
    """The frictionless top in the reduced formulation (the reduced library's own loop)."""
    lib = reduced.kernel("point").lib
    interrupted(long_scene("frictionless_top"), lib.derive_sigint_request)


def test_a_contact_run_after_an_interrupt_runs_to_its_end():
    """The guard clears the request on the way out: the next run is not interrupted."""
    _, lib = driver.library("sphere", "viscous", False)
    interrupted(long_scene("tippe_top"), lib.derive_sigint_request)
    data = long_scene("tippe_top")
    data["simulate"].update(t_end=0.01)
    res = derive.simulate(data)
    assert res.t[-1] == 0.01
