"""Stage 6, export: a scene's model and method as code that runs without derive.

Takes: a scene (a TOML path, an example's name, or a dict) and optionally a method. Gives: the
model that scene runs (:mod:`~derive.export.bundle`: the plan's candidate that actually runs,
its parameters named as in the scene, the driver's settings), written out as

* a self-contained folder (:mod:`~derive.export.folder`): the model's C99 sources and solvers,
  a ``Makefile`` (``example``, a static and a shared library), a ``README.md``, the JSON
  description, the NumPy module and ``example.c``, which runs the scene and prints one JSON line
  with the numbers of ``derive simulate --json`` and the output file's last sample;
* an FMI 2.0 FMU (:mod:`~derive.export.fmu`): model exchange (the right-hand side) and
  co-simulation (the generated solver stepping between communication points), compiled with
  the C compiler alone and zipped.

May import: :mod:`derive.sim` and every stage below it, :mod:`derive.errors`.
"""
