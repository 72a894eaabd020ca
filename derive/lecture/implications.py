"""A display's conclusion after ⇒ that solves the equation before it for one of its names
(``v - V = \\frac{2}{5}v \\implies v = \\frac{5}{7}V``, ``bMR\\dot\\omega = \\frac{2}{5}MR^2\\dot\\omega
\\implies b = \\frac{2}{5}R``).

Takes: the statements of one display (`derive.lecture.statements.statements`), the last of them the
conclusion after ``\\Rightarrow`` (or ``\\implies``) and the one before it the premise, both read by
the scanner (`derive.lecture.latex.parse`). Gives the mixin `Implications` of
`derive.lecture.notes_check.Checker`. The conclusion ``x = e`` is judged as algebra on the symbols
as written, whatever they mean: it `holds` when one link of the premise's chain, a polynomial in x
of degree one or two, has e among its roots; it `fails` when every link that holds x gives roots
other than e in exactly e's names (``5V/3`` for ``5V/7``), none of those names set or defined
by the text (a relation the text stated would be a premise the display leaves unsaid). A root in
other names (a name dropped, a small angle's sine left out), a premise with no x, a conclusion
in names the premise lacks, anything but ``=`` leave the conclusion to the other rules, unchanged.

May import: sympy, :mod:`derive.lecture.latex`, :mod:`derive.lecture.statements`.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.statements import statements

_ARROW = "\\Rightarrow"


def _members(text, vocab):
    """The members of an equation or a chain of them as SymPy expressions; None where it is not one."""
    try:
        parsed = lx.parse(text, vocab)
    except (lx.NotRead, lx.Words, ValueError, TypeError):
        return None
    values = [m.value for m in parsed.members]
    if len(values) < 2 or set(parsed.relations) != {"="} or \
            not all(isinstance(v, sp.Expr) and not isinstance(v, sp.MatrixBase) for v in values):
        return None
    return [sp.sympify(v) for v in values]


def _roots(a, b, x):
    """The roots in x of a = b where it is a polynomial of degree one or two in x; None otherwise."""
    num = sp.numer(sp.together(sp.expand(a - b)))
    if not num.has(x):
        return None
    try:
        poly = sp.Poly(num, x)
    except sp.PolynomialError:
        return None
    if poly.degree() not in (1, 2) or any(c.has(x) for c in poly.all_coeffs()):
        return None
    return list(sp.roots(poly, x, multiple=True)) or None


def _same(r, e) -> bool:
    return sp.simplify(r - e) == 0


class Implications:
    """Mixin of the checker. Uses ``self.vocab``, ``self.ctx``, ``self.claims`` and ``self.tex``."""

    def _implied(self, pieces, k, latex):
        """(verdict, why) of the display's last statement as the conclusion of the one before it, or
        None where it is not one the rule decides. Taken before the conclusion is read, which may set
        its name."""
        if not (k == len(pieces) - 1 > 0 and _ARROW in latex):
            return None
        before, after = latex.rsplit(_ARROW, 1)
        if statements(after) != [pieces[k]] or statements(before)[-1:] != [pieces[k - 1]]:
            return None
        said, premise = _members(pieces[k], self.vocab), _members(pieces[k - 1], self.vocab)
        if said is None or premise is None or len(said) != 2 or not isinstance(said[0], sp.Symbol):
            return None
        x, e = said
        names = set().union(*(m.free_symbols for m in premise)) - {x}
        if e.has(x) or not e.free_symbols <= names:
            return None
        found = []
        for i in range(len(premise)):
            for j in range(i + 1, len(premise)):
                roots = _roots(premise[i], premise[j], x)
                if roots is None:
                    continue
                if any(_same(r, e) for r in roots):
                    return "holds", f"solves the equation before ⇒ for {self.tex(x)} (its root {self.tex(e)})"
                found.append(roots)
        told = set(self.ctx.subs) | set(self.ctx.defs)
        if not found or names & told or any(r.free_symbols != e.free_symbols for roots in found for r in roots):
            return None
        worked = ", ".join(self.tex(r) for r in found[0])
        return "fails", (f"does not follow from the equation before ⇒: solved for {self.tex(x)} it gives "
                         f"{worked}, not {self.tex(e)} (one of the two is wrong)")

    def _judge_implied(self, verdict, start):
        """Put the conclusion's verdict on its claims from ``start`` when none of them is judged."""
        added = self.claims[start:]
        if verdict is None or not added or any(c.verdict != "unchecked" for c in added):
            return
        for c in added:
            c.kind, (c.verdict, c.why) = "implication", verdict
