"""derive: rigid-body rotation, derived symbolically, checked against a lecture, compiled to C.

Conventions throughout: z-y-z Euler angles in the quantum-mechanics convention of the notes
(alpha about the inertial z axis, beta about the intermediate y' axis, gamma about the body 3
axis); the rotation matrix R = Rz(alpha) Ry(beta) Rz(gamma) maps body components to inertial
components (v_inertial = R v_body); omega-tilde are body-frame components; SI units.
"""
from .errors import CompilerError, IntegrationError, SceneError

#: The one place the version is written (pyproject.toml reads it; `derive --version` prints it).
__version__ = "0.1.0"

__all__ = ["SceneError", "IntegrationError", "CompilerError", "simulate", "simulate_batch", "sweep"]


def simulate(scene, **overrides):
    """Simulate a scene (a TOML path or a dict shaped like one). See `derive.simulation`.

    Parameters
    ----------
    scene : str, os.PathLike or dict
        A scene file, or a dict shaped like one (generated/scene-format.md).
    **overrides
        Values of the scene's ``[simulate]`` table (``method``, ``rtol``, ``atol``, ...).

    Returns
    -------
    Result
        The arrays of the output file as attributes (generated/outputs.md): ``t``, ``alpha``,
        ``beta``, ``gamma``, ``omega``, ``axis``, ``energy``, ``p_alpha``, ``p_gamma``, ``n``,
        ``L``, and ``method``, ``formulation``, ``nfev``. ``integrals`` maps the name of the
        extra first integral of the scene's integrable case, if any, to its array (also the
        attribute and npz key ``integral_<name>``), the same name ``derive analyze`` gives:
        ``L_squared`` (|L|², free body), ``L_1``/``L_2``/``L_3`` (the component of L along the
        symmetry axis of a Lagrange top), ``L_dot_rc`` (spherical body), ``kovalevskaya``,
        ``goryachev_chaplygin`` (only for a state on L·n = 0).

    Raises
    ------
    SceneError
        Bad input (the one-line message the command line prints, exit 2 there).
    IntegrationError
        Numerical failure (exit 3 there).
    """
    from .simulation import simulate as _simulate

    return _simulate(scene, **overrides)


def simulate_batch(scenes, **overrides):
    """Simulate many scenes differing only in numbers, the loop over them in C. See `derive.simulation`."""
    from .simulation import simulate_batch as _batch

    return _batch(scenes, **overrides)


def sweep(spec, *, workers=None, scheduler=None, progress=None, **kwargs):
    """Run a parameter sweep (a sweep-file path or a dict shaped like one). See `derive.sweeps`."""
    from .sweeps import sweep as _sweep

    return _sweep(spec, workers=workers, scheduler=scheduler, progress=progress, **kwargs)
