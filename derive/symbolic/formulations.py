"""Formulations of the equations of motion: a registry, one entry per formulation.

Numbered contract of an entry (in the manner of ``scipy.integrate._ivp.base.OdeSolver``):

1. ``name``: how scenes and the command line name it (``simulate.formulation``).
2. its builder, under ``name`` in :data:`derive.symbolic.models.BUILDERS`: derives its
   :class:`~derive.symbolic.models.Model` (state, parameters, right-hand side, the init map from the
   scene's ``INPUT_NAMES`` to the state, the output map from the state to the output arrays).
   The builder is called only when a model has not been generated yet; the warm path loads the
   generated description instead (:mod:`derive.runtime.catalogue`).
3. ``applicable(scene) -> str | None``: None if the formulation can represent the scene, else
   the reason it cannot (shown to a user who asked for it).
4. ``singular``: True when the coordinates have a singular set (sin β = 0): ``auto`` takes such
   a formulation only when the derived β range keeps clear of it (:mod:`derive.sim.auto`).
5. ``needs_routh``: True when the formulation is exact only for conserved p_α, p_γ (the reduced
   top): it takes their values from the init map, as parameters.
6. ``pole_check``: the pole check every run of the formulation carries, whoever chose it (1:
   the motion keeps |sin β| ≥ its ``clearance``), or 0: only the one ``auto`` gives it. The
   reduced-u form cannot follow the axis through a pole (u = ±1 is a turning point of u while
   the axis goes through, and α would have to jump by π), so it refuses such a motion even when
   asked for by name.
7. ``clearance``: the |sin β| its pole check keeps (``POLE_CLEARANCE`` unless the formulation
   loses accuracy nearer a pole: reduced-u's ``REDUCED_U_CLEARANCE``), rendered into its C
   ``pole_clear`` and its Routh checks.
8. ``pole_loss``: True when its accelerations lose accuracy as eps/sin²β near a pole (the
   Euler-angle mass matrix): a trajectory that came closer than the tolerance allows is refused.
9. ``angle_states``: True when α and γ are states of the model, continuous along the motion
   (not read back from a rotation by atan2): the angles of the last sample then need only β's
   canonical range, not the unwrapping from sample to sample, and a batch that keeps the last
   sample only integrates straight to the end (:mod:`derive.sim.batch`).

``auto`` (see :mod:`derive.sim.auto`) tries the applicable formulations in order of the cost of
their right-hand side (the kernel spec's weighted operation count, stored with the generated
model), and takes the first whose derived β range allows it.

Nothing here imports SymPy.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

from derive.symbolic import effects as fx

#: The inputs of every model's init map: the scene's initial orientation and angular velocity
#: (ω̃ always; the Euler-angle rates where the scene gave them, with rates_given = 1).
INPUT_NAMES = ("alpha", "beta", "gamma", "omega1", "omega2", "omega3",
               "alpha_dot", "beta_dot", "gamma_dot", "rates_given")

#: The output file's arrays that every model computes in C, with their widths, in order.
OUTPUTS = (("alpha", 1), ("beta", 1), ("gamma", 1), ("omega", 3), ("axis", 3), ("energy", 1),
           ("p_alpha", 1), ("p_gamma", 1), ("n", 3), ("L", 3))

#: |sin β| at which the Euler-angle maps lose their accuracy: closer than this to a pole,
#: a formulation with a singular set is not chosen by auto, nor started by the scene.
POLE_CLEARANCE = 1e-3

#: reduced-u's own clearance: its axis error is δu / |sin β| (β and the axis come from
#: u = cos β), and near a pole its steps shrink (at |sin β| = 0.002 and rtol 1e-12, 14,434
#: right-hand sides against 1,088 for "reduced", and 30× the error); |sin β| ≥ 0.1 bounds the
#: amplification by 10.
REDUCED_U_CLEARANCE = 0.1


def _no_damping_axisymmetric(scene) -> str | None:
    effects = fx.lookup(scene.effects)
    bad = [e.name for e in effects if not (e.conservative and e.axisymmetric)]
    if bad:
        return (f"needs conserved p_alpha and p_gamma, but the effect {bad[0]!r} "
                f"does not conserve them")
    return None


#: The |sin β₀| a start of a singular Euler-angle formulation needs: (rates given, ω given).
#: With ω given the init map divides by sin β₀ to find the Euler rates.
EULER_START = (1e-9, POLE_CLEARANCE)


def _starts_clear(scene, name: str) -> str | None:
    if abs(math.sin(scene.initial.beta)) < EULER_START[1] and not scene.initial.has_rates:
        return (f"{name!r} is singular at sin(beta) = 0 and initial.beta = "
                f"{scene.initial.beta:g} with omega given starts there; use 'quaternion' or 'auto'")
    if abs(math.sin(scene.initial.beta)) < EULER_START[0]:
        return (f"{name!r} is singular at sin(beta) = 0 and initial.beta = "
                f"{scene.initial.beta:g} starts there; use 'quaternion' or 'auto'")
    return None


def _euler_angles(scene) -> str | None:
    return _starts_clear(scene, "euler-angles")


def _reduced(scene) -> str | None:
    if not scene.symmetric:
        return (f"'reduced' needs a symmetric body (I1 == I2) so that p_gamma is conserved; "
                f"got I1 = {scene.body.I1:g}, I2 = {scene.body.I2:g}")
    return _no_damping_axisymmetric(scene) or _starts_clear(scene, "reduced")


def _reduced_u(scene) -> str | None:
    if not scene.symmetric:
        return (f"'reduced-u' needs a symmetric body (I1 == I2) so that p_gamma is conserved; "
                f"got I1 = {scene.body.I1:g}, I2 = {scene.body.I2:g}")
    if abs(math.sin(scene.initial.beta)) < REDUCED_U_CLEARANCE:
        # u = cos beta cannot represent a motion at a pole (see pole_check in the contract).
        return (f"'reduced-u' needs |sin(beta)| >= {REDUCED_U_CLEARANCE:g} all along and "
                f"initial.beta = {scene.initial.beta:g} starts closer to a pole; use 'reduced' "
                f"or 'auto'")
    return _no_damping_axisymmetric(scene)


def _always(scene) -> str | None:
    return None


@dataclass(frozen=True)
class Formulation:
    """One formulation (see the module docstring for the contract)."""

    name: str
    description: str
    applicable: Callable
    singular: bool = False
    needs_routh: bool = False
    pole_check: int = 0
    clearance: float = POLE_CLEARANCE  # the |sin β| its pole check keeps (see routh_checks)
    pole_loss: bool = False
    angle_states: bool = False
    #: The |sin β₀| below which ``applicable`` refuses a start, as (rates given, ω given): what
    #: of ``applicable`` depends on the initial state, for starts checked many at once
    #: (:func:`starts_accepted`; a prepared batch).
    start_clearance: tuple = (0.0, 0.0)


#: Cheapest first for a typical body (the shipped heavy top: reduced-u 149, euler-angles 205,
#: reduced 246 operation units): the order in which ``auto`` tries formulations whose model the
#: package does not ship (a user's body).
REGISTRY: dict[str, Formulation] = {f.name: f for f in (
    Formulation("reduced-u", "u = cos beta and its rate with conserved p_alpha, p_gamma, E': "
                "u'' = f'(u)/2 from the Routh polynomial, alpha and gamma as quadratures; "
                "symmetric body, axisymmetric conservative effects", _reduced_u,
                singular=True, needs_routh=True, pole_check=1, clearance=REDUCED_U_CLEARANCE,
                angle_states=True, start_clearance=(REDUCED_U_CLEARANCE, REDUCED_U_CLEARANCE)),
    Formulation("euler-angles", "(alpha, beta, gamma) and their rates; singular at sin(beta) = 0",
                _euler_angles, singular=True, pole_loss=True, angle_states=True,
                start_clearance=EULER_START),
    Formulation("reduced", "beta alone with conserved p_alpha, p_gamma; symmetric body, "
                "axisymmetric conservative effects", _reduced, singular=True,
                needs_routh=True, angle_states=True, start_clearance=EULER_START),
    Formulation("quaternion", "unit quaternion and body omega; no coordinate singularity", _always),
    Formulation("euler-poisson", "angular momentum L, vertical n and x-axis e in body axes; no "
                "coordinate singularity", _always),
)}

def starts_accepted(name: str, sin_beta0, rates_given: bool):
    """Per start, whether formulation ``name`` takes it: |sin β₀| at least its
    ``start_clearance`` (the part of ``applicable`` that depends on the initial state; the
    rest, the body and the effects, is the scene's). ``sin_beta0``: an array of |sin β₀|."""
    return sin_beta0 >= REGISTRY[name].start_clearance[0 if rates_given else 1]


#: The formulation that takes every body and every effect (no singular set): what the analysis
#: derives its equations from.
UNIVERSAL = "euler-poisson"

#: Scene spelling: "auto" plus the registry.
CHOICES = {"auto": "let derive choose from the body, the effects and the initial state",
           **{name: f.description for name, f in REGISTRY.items()}}

#: Names of the models committed to generated/ whose name the C contract fixes.
SPECIAL_NAMES = {
    ("euler", False, ()): "euler_free",
    ("euler-angles", True, ("gravity",)): "heavy_top",
    ("reduced", True, ("gravity",)): "heavy_top_reduced",
    ("quaternion", False, ("gravity_general", "damping")): "rigid_body",
}


def model_name(formulation: str, symmetric: bool, effects) -> str:
    """The model's name (its C prefix): ``<formulation>_<sym|asym>_<effects…>``, or one of the
    contract's names (``heavy_top``, …)."""
    effects = tuple(e.name for e in fx.lookup(effects))
    special = SPECIAL_NAMES.get((formulation, symmetric, effects))
    if special:
        return special
    return "_".join([formulation.replace("-", "_"), "sym" if symmetric else "asym", *effects])
