"""The contact laws as a registry: the phases each allows (its force, in SymPy, is
:mod:`derive.contact.friction`'s, so that a run reads this registry without SymPy).

u is the velocity of the body's material point at the contact (body components), u_t = u − (u·n) n
its slip (tangential) part, N ≥ 0 the normal force. While sliding the tangential force is

* ``none``      F_t = 0                                   (frictionless plane)
* ``coulomb``   F_t = −μ N d,  d = u_t/|u_t|              (exact; d held from the prediction
                                                          when |u_t| = 0, see phases)
* ``coulomb`` with a regularisation ε:
                F_t = −μ N u_t / √(|u_t|² + ε²)           (smooth, one phase)
* ``viscous``   F_t = −μ u_t                              (μ in N s/m)

and while rolling (``coulomb`` in its stick phase, and ``rolling`` always) F_t is whatever keeps
u = 0, bounded by |F_t| ≤ μ N for Coulomb. The power of the contact force is F·u = F_t·u_t, so
Ė = −μ N |u_t| ≤ 0 (exact Coulomb), −μ N |u_t|²/√(|u_t|² + ε²), −μ |u_t|² while sliding, and
Ė = 0 rolling or frictionless.

Two extensions add a moment about the contact point, proportional to N, in every touching phase
(:data:`EXTENSIONS`; the moment per unit N in SymPy is :mod:`derive.contact.friction`'s):

* ``rolling_resistance = δ`` (m)   τ = −δ N ω_t/|ω_t|,  ω_t = ω − (ω·n) n   (0 when ω_t = 0)
* ``spin_friction = r_s`` (m)      τ = −μ N r_s σ n,  σ = r_s ω_n/√((r_s ω_n)² + ε²)
                                  (ε the scene's regularisation; exact Coulomb: σ = sgn ω_n)

Their power is τ·ω = −δ N |ω_t| − μ N r_s σ ω_n ≤ 0.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Law:
    """A contact law: its registry name, the phases it has, what it models and the scene's
    ``friction`` that selects it (its name when not given)."""

    name: str
    phases: tuple[str, ...]
    description: str
    friction: str = ""

    @property
    def selected_by(self) -> str:
        return self.friction or self.name

    @property
    def slides(self) -> bool:
        return "slide" in self.phases

    @property
    def rolls(self) -> bool:
        return "roll" in self.phases

    @property
    def switches(self) -> bool:
        """Whether sliding and rolling are separate phases joined by events (exact Coulomb)."""
        return self.slides and self.rolls


#: The laws by their registry name; ``[contact] friction`` (and ``regularization``) select one.
LAWS: dict[str, Law] = {law.name: law for law in (
    Law("none", ("slide", "flight"), "frictionless plane"),
    Law("coulomb", ("slide", "roll", "flight"), "Coulomb friction, sliding and rolling joined by events"),
    Law("coulomb_regularized", ("slide", "flight"), "Coulomb friction regularised with ε", "coulomb"),
    Law("viscous", ("slide", "flight"), "viscous friction, force per slip speed μ"),
    Law("rolling", ("roll", "flight"), "rolling without slipping"),
)}


@dataclass(frozen=True)
class Extension:
    """A contact moment a scene may add to its law: its ``[contact]`` key, the name of its length
    in the parameter vector, the frictions it goes with and what it models."""

    key: str
    param: str
    frictions: tuple[str, ...]
    description: str


#: The law extensions by their ``[contact]`` key (each a length ≥ 0; 0 or absent: off).
EXTENSIONS: dict[str, Extension] = {e.key: e for e in (
    Extension("rolling_resistance", "delta", ("coulomb", "viscous", "rolling"),
              "rolling resistance: a moment δN opposing the rolling rate ω_t"),
    Extension("spin_friction", "r_spin", ("coulomb",),
              "spin (Contensou) friction: a moment μ N r_s about the normal opposing the spin ω·n"),
)}


def takes_moments(law: Law) -> bool:
    """Whether some extension goes with ``law`` (its evaluator then carries the moments)."""
    return any(law.selected_by in e.frictions for e in EXTENSIONS.values())
