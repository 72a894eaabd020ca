"""Stage 5, simulation: a scene file in, a :class:`~derive.sim.result.Result` (and files) out.

Takes: a scene (a TOML path, an example's name, or a dict). Gives: the validated
:class:`~derive.sim.scene.Scene` (:mod:`~derive.sim.scene`: the file read by
:mod:`~derive.sim.reader`, checked by :mod:`~derive.sim.validator` into the types of
:mod:`~derive.sim.scene_types`; examples by name in :mod:`~derive.sim.examples`), what to keep
(:mod:`~derive.sim.saveat`), the numbers a kernel takes (:mod:`~derive.sim.inputs`), the
formulation ``auto`` picks (:mod:`~derive.sim.auto`), the result of one C call
(:mod:`~derive.sim.simulation`; of a batch keeping only the outputs asked for,
:mod:`~derive.sim.batch`), the output files written all or nothing
(:mod:`~derive.sim.outputs`), the plots (:mod:`~derive.sim.plots`), the motion animated as
GIF, MP4 or an offline HTML player (:mod:`~derive.sim.animate`) and the scene format's
reference page (:mod:`~derive.sim.scene_doc`).

May import: :mod:`derive.runtime`, :mod:`derive.codegen`, :mod:`derive.methods`,
:mod:`derive.symbolic`, :mod:`derive.reference` (its NumPy rotation matrix only, off the
closed-form solutions' SciPy), :mod:`derive.errors`.
"""
