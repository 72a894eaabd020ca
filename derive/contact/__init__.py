"""Tops on a table: a rigid body touching the horizontal plane z = 0 under gravity.

Takes: a scene with a ``[contact]`` table (a dict, read by :mod:`derive.sim`'s TOML reader and
handed over), or the description of a body and its contact (shape, radius, offset, law).
Gives: the equations of motion derived with SymPy from that description
(:mod:`~derive.contact.geometry`: the shapes and the contact point a(n);
:mod:`~derive.contact.laws`: the contact laws as a registry, their forces in
:mod:`~derive.contact.friction`; :mod:`~derive.contact.equations`: Newton–Euler with the
normal force solved from the height constraint and the rolling force from the no-slip
condition), the integrals each case has and the analysis of its steady states
(:mod:`~derive.contact.integrals`, :mod:`~derive.contact.analysis`), the phase right-hand sides,
event functions and monitors as C (:mod:`~derive.contact.sources`, ``templates/contact/``,
written by ``make derive`` into ``generated/contact/``; :mod:`~derive.contact.layout`: the
names and the shared C), the compiled evaluators (:mod:`~derive.contact.kernel`), the
event-driven integration of the phases slide, roll and flight — in C by the phase driver
(:mod:`~derive.contact.driver`, the compiled method's one call), with its switch rules stated
and kept as the ``scipy-dop853`` reference in :mod:`~derive.contact.phases` (a second sphere,
the tippe top's stem, switched to at a located event) — the frictionless plane
reduced by its symmetries (:mod:`~derive.contact.reduced`: p_α and p_γ held as parameters), the
validated scene (:mod:`~derive.contact.scene`) and the result (:mod:`~derive.contact.simulate`).

Two sides: a run (scene, kernel, driver, phases, reduced, simulate, prepared) reads the generated C and
imports neither SymPy nor SciPy; the derivation (geometry, friction, equations, integrals,
analysis, sources) is SymPy, reached from a run only through
:func:`derive.contact.kernel.text` when a file of ``generated/contact/`` is missing. SciPy
loads only for the ``scipy-dop853`` reference stepper.

May import: :mod:`derive.runtime` (compile and load), :mod:`derive.codegen` (the Jinja2
environment), :mod:`derive.methods` (the stepper's registry name), :mod:`derive.symbolic` (the
z-y-z rotation, the gravity table's name), :mod:`derive.errors`. :mod:`derive.sim` hands a
contact scene over (its TOML reader, example names, output files).
"""
