"""The lecture: its formulas checked against the derivation, and its analysis done for any body.

Takes: the derivation (:mod:`derive.symbolic`). Gives: the claims of the lecture on rigid-body
motion (:mod:`~derive.lecture.claims`, each with where it stands in the notes and its meaning,
written with the symbols of :mod:`~derive.lecture.slides`), their verdicts
(:mod:`~derive.lecture.verify`: holds, typo with the corrected form, fails; against the derived
quantities of :mod:`~derive.lecture.targets`, by the zero test of :mod:`~derive.lecture.zero_test`) and
the reports ``generated/lecture-verification.md`` and ``generated/derivation.md``
(:mod:`~derive.lecture.report`). The lecture's formulas are the thing checked, never used.
``derive analyze`` (:mod:`~derive.lecture.analysis`) does the lecture's analysis — energies,
equations, cyclic coordinates, integrals, relative equilibria and their stability — for a
scene's own body, evaluated at the scene's numbers (the derived expressions in
:mod:`~derive.lecture.closed_forms`, the equilibria in :mod:`~derive.lecture.equilibria`).

May import: :mod:`derive.sim` (a scene, for the analysis) and the stages below it,
:mod:`derive.errors`.
"""
