r"""Cases the text names that the reader does not apply: a flag there would rest on the case left out.

A sentence's own special case (``… $\cos\theta = 0$, where $\omega_z = \dot\phi$``): the inline
relation after "where", "when", "if" is read without it, and a flag it gets is left unchecked.

A case the text sets by its constants of the motion alone, as ``L^2 = 2I_3T`` in running text: a
relation written in the prose between the quantities the reader knows as constants of the motion
(T the kinetic energy, E, |𝐋|, the text's L, and a name the text defined by the rates, its L_z or
its spin n) and the body's parameters (I₁, I₂, I₃, M, g, l, and a letter the text tied to nothing,
its A or C), with no variable of the motion in it, is no identity (``L_z = Cn``, a top started
upright): it picks the motions that have those constants —
"in the limit L² = 2I₃T", "at the other end, L² = 2I₁T", "case 3, L² = 2I₂T" (or a range of them,
"case 1, 2I₂T < L² ≤ 2I₃T"). The reader does not
impose such a case (it would have to restrict the motion itself), so the relation is a setting of
the text, never flagged, and a statement after it that the reader would flag is left unchecked,
saying the case it may hold in — up to the section's end, another case, or a statement of the motion
that holds as read without it (the text has gone back to the general motion; a closed form that
solves the text's own equation does not count). Nothing that holds changes. Where the case gives one
of the angles' rates on its motions, a flagged statement that vanishes there holds in the case
instead (`derive.lecture.case_imposed`).

Gives the mixin `ConstantCases` of the checker (`derive.lecture.notes_check.Checker`).
May import: :mod:`derive.lecture.case_imposed`, :mod:`derive.lecture.latex`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import case_imposed
from derive.lecture import latex as lx
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3, Mass, g, l
from derive.symbolic.rotations import ANGLES, RATES

_PARAMETERS = frozenset((I1, I2, I3, Mass, g, l))
CASE_LEAD = re.compile(r"\s*,?\s*(?:where|when|whenever|if|in which case)\s*", re.I)
"""The prose between an inline case and the inline relation it governs."""
FLAGGED = ("typo", "fails")


_ORDER = {"<", ">", "≤", "≥"}


def of_constants_only(parsed, own=frozenset(), letters=frozenset()) -> bool:
    """A relation ``=`` of two members, or a chain of inequalities (a range, ``2I_2T < L^2 \\le
    2I_3T``), built from named quantities (at least one) and the body's parameters and numbers only:
    no variable of the motion. A name of the text's counts as a named quantity when it is in ``own``
    (the text defined it by the rates: its L_z, its spin n) and as a parameter when it is in
    ``letters`` (a letter it never tied to anything, its A or C)."""
    if parsed is None or not (len(parsed.members) == 2 and parsed.relations == ["="]
                              or len(parsed.members) >= 2 and set(parsed.relations) <= _ORDER):
        return False
    syms = set()
    for m in parsed.members:
        value = m.value
        if not isinstance(value, sp.Basic) or isinstance(value, sp.MatrixBase) or m.args:
            return False
        syms |= value.free_symbols
    quantities = {s for s in syms if isinstance(s, lx.Quantity) or s in own}
    return bool(quantities) and syms <= quantities | _PARAMETERS | letters


class ConstantCases:
    """Mixin of the checker: see the module docstring. Uses ``self.claims``, ``self.ctx`` and
    ``self.vocab``."""

    def _cases_not_applied(self, item, start):
        """After a display or inline relation is read (its claims from ``start``): the sentence's
        own case, then a case of the constants (`_constant_case`)."""
        lead = item.lead or ""
        self._in_case = item.kind == "inline" and (CASE_LEAD.fullmatch(lead) is not None or (
            getattr(self, "_in_case", False) and re.fullmatch(r"\s*(?:,|and|,\s*and)\s*", lead) is not None))
        if self._in_case:
            for c in self.claims[start:]:
                if c.verdict in FLAGGED:
                    c.verdict, c.correction = "unchecked", None
                    c.why = ("stated in a sentence for the case it names just before (\"…, where\"), "
                             f"which the reader does not apply: as read without it, {c.why}")
            return
        self._constant_case(item, start)

    def _constant_case(self, item, start):
        """After a display or inline relation is read (its claims from ``start``): a flagged inline
        relation of constants alone becomes the section's case; a flagged statement read while a
        case holds is left unchecked."""
        claims = self.claims[start:]
        # an equation of constants is a case when the reader flags it, a range when it is not judged
        if item.kind == "inline" and claims and all(c.verdict in FLAGGED or c.kind == "inequality"
                                                    and c.verdict == "unchecked" for c in claims):
            try:
                parsed = lx.parse(item.latex, self.vocab)
            except lx.NotRead:
                parsed = None
            if of_constants_only(parsed, *self._named_constants(parsed)):
                for c in claims:
                    c.kind, c.verdict, c.correction = "setting", "unchecked", None
                    c.why = ("a case of the text's constants of the motion (the motions that have them), "
                             "which the reader does not impose")
                self.ctx.constant_case = (item.line, item.latex.strip())
                return
        case = self.ctx.constant_case
        if case is None:
            return
        if any(c.verdict == "holds" and c.kind != "solution" for c in claims):
            # a statement of the motion that holds without it: the case is left (a closed form
            # solving the text's own equation says nothing of the general motion)
            self.ctx.constant_case = None
            return
        zero = case_imposed.rates_zero(self, case[1])
        for c in claims:        # a rate set to zero that the case itself sets to zero: it holds there
            if c.kind == "setting" and c.verdict == "unchecked" and zero and self._set_rates(c.latex) <= zero:
                c.verdict, c.correction = "holds", None
                c.why = (f"holds in the case {case[1]} the text sets at line {case[0]}: under "
                         f"{self._orderings_text()} it is a sum of squares of the rates of one sign")
        flagged = [c for c in claims if c.verdict in FLAGGED]
        imposed = case_imposed.in_case(self, flagged[0].latex, case[1]) if flagged else None
        for c in claims:
            if c.verdict in FLAGGED and imposed:
                c.verdict, c.correction = "holds", None
                c.why = f"holds in the case {case[1]} the text sets at line {case[0]}, imposed: {imposed}"
            elif c.verdict in FLAGGED:
                c.verdict, c.correction = "unchecked", None
                c.why = (f"stated in the case {case[1]} the text sets at line {case[0]}, which the reader "
                         f"does not impose: as read without it, {c.why}")

    def _set_rates(self, latex: str) -> frozenset:
        """The body rates ω̃ᵢ a statement ``\\omega_1 = \\omega_2 = 0`` sets to zero (none if it is not one)."""
        try:
            parsed = lx.parse(latex, self.vocab)
        except lx.NotRead:
            return frozenset({None})
        *rates, last = [m.value for m in parsed.members]
        ok = set(parsed.relations) == {"="} and last == 0 and rates and all(r in lx.W for r in rates)
        return frozenset(rates) if ok else frozenset({None})

    def _named_constants(self, parsed) -> tuple:
        """The text's names in ``parsed`` that stand for quantities of the motion (defined by an
        expression in the rates, as L_z = A\\dot\\varphi\\sin^2\\vartheta + Cn\\cos\\vartheta) and its
        letters tied to nothing (A, C): the quantities and parameters of `of_constants_only`."""
        if parsed is None:
            return frozenset(), frozenset()
        syms = set().union(*(m.value.free_symbols for m in parsed.members if isinstance(m.value, sp.Basic)))
        mine = {s for s in syms if isinstance(s, lx.Generic)}
        rates = set(RATES) | set(lx.W)
        own = {s for s in mine if s in self.ctx.defs and isinstance(self.ctx.defs[s], sp.Basic)
               and self._resolve(self.ctx.defs[s]).free_symbols & rates}
        motion = rates | set(ANGLES) | set(ACCELS) | set(lx.WD) | {lx.t}
        plain = {s for s in syms if not isinstance(s, (lx.Quantity, lx.Generic)) and s not in motion}
        return frozenset(own), frozenset({s for s in mine - own if s not in self.ctx.defs} | plain)

