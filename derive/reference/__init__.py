"""Closed-form references: exact solutions of the free and heavy tops and the elliptic functions
they need, accurate to round-off (for tests and benchmarks; never on the simulate path), and the
orientation matrix of the z-y-z angles in plain NumPy (:mod:`~derive.reference.rotation`), light
enough for the drawing of a motion to import.

May import: nothing else in :mod:`derive`.
"""
