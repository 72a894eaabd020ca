"""A display with no relation that writes out the one before it.

A text that defines a name (``F_g = R_{i \\rightarrow b} [0, 0, mg]^T``) often goes on "written
out:" with a display that is only an expression, the name's value with the products done. Such a
display states ``name = expression``: it holds when the expression is the value the text defined
the name as (with the text's matrices and definitions put in). One that is not is left
`unchecked` naming why (the expression may be something else the prose introduces), never judged
wrong.

Takes: the checker (``claims``, ``ctx.defs``, ``_resolve``, ``_compare``, ``_add``, ``tex``).
Gives: the mixin `WrittenOut`.

May import: :mod:`derive.lecture.latex`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import latex as lx


class WrittenOut:
    """Mixin of the checker: see the module docstring."""

    def _written_out(self, line, piece, parsed) -> bool:
        """The expression ``parsed`` (one member) against the name the display before it defined.
        True when a claim was added."""
        if len(parsed.members) != 1 or not self.claims or not self.ctx.defs:
            return False
        last = self.claims[-1]
        name = next(reversed(self.ctx.defs))
        if last.kind not in ("new symbol", "weight") or last.line >= line or not isinstance(name, lx.Generic) or \
                self.tex(name) not in last.why:
            return False
        try:
            value, bare = self._resolve(self.ctx.defs[name]), self._resolve(parsed.members[0].value)
        except (TypeError, ValueError, AttributeError, lx.NotRead):
            return False
        shapes = [v.shape if isinstance(v, sp.MatrixBase) else None for v in (value, bare)]
        if shapes[0] != shapes[1]:
            return False
        ok, how = self._compare(bare, value, f"{piece}/written-out")
        if ok:
            self._add(line, piece, "identity", "holds",
                      f"writes out {self.tex(name)} as the display before defined it (line {last.line}): {how}")
        else:
            self._add(line, piece, "identity", "unchecked",
                      f"read as {self.tex(name)} (line {last.line}) written out, it does not agree ({how}); "
                      "the prose may introduce something else")
        return True
