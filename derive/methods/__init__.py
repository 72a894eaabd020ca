"""Stage 2, the integration methods as data (the numbered contract a method provides).

Takes: nothing from a scene. Gives: the method registry (:mod:`~derive.methods.registry`:
a tableau plus a driver each, ``DEFAULT_METHOD``, the SciPy references), the exact rational
Butcher tableaux (:mod:`~derive.methods.tableaux`), the Lie–Poisson splitting schemes
(:mod:`~derive.methods.splitting`), the one status enum shared by C and Python
(:mod:`~derive.methods.status`) and what a run costs before it starts
(:mod:`~derive.methods.costs`: auto's choice, the floor on a run's steps).

A new method adds a tableau (or a splitting scheme) and one registry entry: numbers, not logic.

May import: :mod:`derive.symbolic` (which formulations and effects a method can run),
:mod:`derive.errors`.
"""
