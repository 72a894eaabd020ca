"""Stage 3, code generation: a symbolic model through the templates into C and NumPy text.

Takes: a :class:`~derive.symbolic.models.Model` and the method registry. Gives: source files as
``{relative path: text}`` — the model's C header and source, its solver loops
(:mod:`~derive.codegen.solvers`), its splitting solvers (:mod:`~derive.codegen.splitting`), its
NumPy module and its JSON description (:mod:`~derive.codegen.sources`), laid out by the kernel
spec (:mod:`~derive.codegen.kernelspec`: state and parameter layout, CSE, cost). Every file is
rendered through the one Jinja2 environment of :mod:`~derive.codegen.render`, which also knows
where ``templates/``, ``generated/`` and ``scenes/`` live.

May import: :mod:`derive.methods`, :mod:`derive.symbolic`, :mod:`derive.errors`. Nothing here
compiles or runs code.
"""
