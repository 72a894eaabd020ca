"""Closed-form references: exact solutions of the free and heavy tops and the elliptic functions
they need, accurate to round-off (for tests and benchmarks; never on the simulate path).

May import: nothing else in :mod:`derive`.
"""
