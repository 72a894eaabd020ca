"""Stage 4, the runtime: compile generated C, cache it, load it, and call it.

Takes: a model key (formulation, symmetry, effects) or source files. Gives: the model's
description (:mod:`~derive.runtime.catalogue`: from ``generated/``, or derived once and cached
by a content hash), compiled libraries in the self-healing compile cache
(:mod:`~derive.runtime.cbuild`; the cache folder and what in it is its own:
:mod:`~derive.runtime.cache`), and the ctypes kernels that integrate in one C call
(:mod:`~derive.runtime.integrate` for a (model, method) pair, :mod:`~derive.runtime.kernel`
for any model's sources and its solvers, :mod:`~derive.runtime.splitter`; the one binding of
a run driver and the records it shares with C in :mod:`~derive.runtime.records`).

May import: :mod:`derive.codegen`, :mod:`derive.methods`, :mod:`derive.symbolic`,
:mod:`derive.errors`. The warm path (a model already generated and compiled) imports neither
SymPy nor Jinja2.
"""
