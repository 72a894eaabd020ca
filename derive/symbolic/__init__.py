"""Stage 1, the model: rigid-body rotation derived with SymPy from first principles.

Takes: a body (moments, symmetry) and the effects a scene names. Gives: :class:`~derive.symbolic.models.Model`
objects (states, parameters, right-hand side, init and output maps as SymPy expressions), the
Lagrangian quantities of the lecture (ω̃ from the Euler angles, T, L, p_α, p_γ, E, V_eff), the
stability series and the integrable cases.

Modules: ``rotations`` (z-y-z Euler angles, R, ω̃), ``inertia``, ``lagrangian``, ``stability``,
``effects`` (the effects registry), ``effect_sums`` (their potentials and torques summed as
SymPy expressions), ``formulations`` (the formulations registry), ``models``
(build a model from a formulation, a body symmetry and effects), ``integrable`` (integrable
cases and their integrals, classified without SymPy), ``symmetries`` (the integrals a user's terms
leave, by symbolic invariance), ``integral_proofs`` (those integrals
proved along the derived equations).

May import: :mod:`derive.errors` and :mod:`derive.reference` only. Nothing here renders,
compiles or integrates.
"""
