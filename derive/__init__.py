"""derive: rigid-body rotation, derived symbolically, checked against a lecture, compiled to C.

Conventions throughout: z-y-z Euler angles in the quantum-mechanics convention of the notes
(alpha about the inertial z axis, beta about the intermediate y' axis, gamma about the body 3
axis); the rotation matrix R = Rz(alpha) Ry(beta) Rz(gamma) maps body components to inertial
components (v_inertial = R v_body); omega-tilde are body-frame components; SI units.
"""
from derive import _moved
from derive.errors import CompilerError, IntegrationError, SceneError

_moved.install()  # derive.simulation, derive.scene, …: the old module paths still import

#: The one place the version is written (pyproject.toml reads it; `derive --version` prints it).
__version__ = "0.1.0"

__all__ = ["SceneError", "IntegrationError", "CompilerError", "simulate", "simulate_batch", "sweep"]


def simulate(scene, **overrides):
    """Simulate a scene (a TOML path or a dict shaped like one). See `derive.sim.simulation`."""
    from derive.sim.simulation import simulate as _simulate

    return _simulate(scene, **overrides)


def simulate_batch(scenes, **overrides):
    """Simulate many scenes differing only in numbers, the loop over them in C. See `derive.sim.simulation`."""
    from derive.sim.simulation import simulate_batch as _batch

    return _batch(scenes, **overrides)


def sweep(spec, *, workers=None, scheduler=None, progress=None, **kwargs):
    """Run a parameter sweep (a sweep-file path or a dict shaped like one). See `derive.sweeps.engine`."""
    from derive.sweeps.engine import sweep as _sweep

    return _sweep(spec, workers=workers, scheduler=scheduler, progress=progress, **kwargs)
