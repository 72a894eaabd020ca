"""A partial derivative of names the text has not tied: ``\\frac{\\partial \\Omega_3}{\\partial \\dot\\psi}``.

Takes: the expression under ``\\partial`` (the text's definitions already put in), the variable and
order, and the checker (its ``ctx.defs``, ``_constants``, ``vocab`` and ``claims``).
Gives: `partial`, the derivative, noting the untied names it took for constants, and the mixin
`UntiedPartials`, whose `_untied_partials_unjudged` leaves unchecked a display's flags that rest on them.

May import: :mod:`derive.lecture.vocabulary`, SymPy.

SymPy takes a symbol it knows nothing of for a constant, so ∂Ω₃/∂ψ̇ is 0 and the text's ``= 1``
would be a slip, while Ω₃ may well be φ̇ cos θ + ψ̇ in a column the reader did not take for its
definition. The derivative is still taken so (a relation that holds with the names constant, as
Lagrange's equation d/dt ∂R/∂θ̇ − ∂R/∂θ = 0 in a Routhian R the text has not written out, stays
read), but a flag in a display where an untied name dropped out of a derivative is no finding: the
reader cannot say what the name is. A name that survives the differentiation (m of ∂(m ψ̇²/2)/∂ψ̇ =
m ψ̇) is kept a constant, and the rate of the variable's own coordinate (ẋ of ∂/∂x) is independent
of it, as Lagrange's equations take it.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture.vocabulary import Generic

_FLAGS = ("typo", "fails")


def partial(expr, var, n, checker):
    """∂ⁿexpr/∂varⁿ with the text's untied names constant; those that drop out are noted on the checker."""
    out = sp.diff(expr, var, n)
    if not isinstance(expr, sp.Expr):
        return out              # a matrix of the text's: its entries are read where they are written
    kept = checker._constants() | set(checker.ctx.defs) | out.free_symbols | {var}
    lost = {s for s in expr.free_symbols
            if isinstance(s, Generic) and s not in kept and not _same_coordinate(s, var, checker.vocab)}
    # a trial reading without the names the prose gave (``vocab.names_off``) is no reading of the display's
    if lost and not getattr(checker.vocab, "names_off", False):
        checker.partials_lost = getattr(checker, "partials_lost", set()) | lost
    return out


def _same_coordinate(s, var, vocab) -> bool:
    """ẋ and x (or x and ẋ): the text's coordinate and its rate, independent in ∂/∂x and ∂/∂ẋ."""
    if not isinstance(var, Generic):
        return False
    base_s, base_v = vocab.undotted(s), vocab.undotted(var)
    return (base_s[0] if base_s else s) == (base_v[0] if base_v else var)


class UntiedPartials:
    """Mixin of the checker: see the module docstring. Uses ``self.claims``, ``self.tex`` and
    ``partials_lost`` (set by `partial`)."""

    def _untied_partials_unjudged(self, start):
        """The display's typo and fails on a partial derivative that took an untied name for a constant:
        unchecked, naming the names (the notes reset after each display)."""
        lost, self.partials_lost = getattr(self, "partials_lost", set()), set()
        if not lost:
            return
        names = ", ".join(sorted(self.tex(s) for s in lost))
        for c in self.claims[start:]:
            if c.verdict in _FLAGS and "partial" in c.latex:
                c.why = (f"a partial derivative of {names}, which the text has not tied to the derivation "
                         f"and the reader could only hold constant there: no finding (so read: {c.why})")
                c.verdict, c.correction = "unchecked", None
