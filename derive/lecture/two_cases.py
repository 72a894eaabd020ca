"""A formula written with ± (∓) for two cases its prose names just before it: "setting $\\theta=0$
or $\\pi$ … gives" (or ``$\\theta = 0, \\pi$``, ``$\\theta = \\pm\\frac{\\pi}{2}$``), then
``T = … + \\frac12 I_3 (\\dot\\phi \\pm \\dot\\psi)^2``, as texts write the matrix and the kinetic
energy where the Euler angles lock.

The statement is read twice for each pairing of the signs with the cases: the upper signs (± → +,
∓ → −) in the first case named and the lower in the second, then (unless that held) the other way
round, each time with the case set as the text's settings are (from the context just before the statement; the
reader's own state is left as it was). It holds when both signs hold in one pairing (the prose's
order first); it is flagged only when each pairing has a sign that is flagged (then the prose's
order is reported); otherwise it is `unchecked`, saying so.

Gives the mixin `TwoCases` of `derive.lecture.notes_check.Checker` (uses ``_snapshot``,
``_sandbox``, ``_add``, ``self.claims``, ``self.notes``, ``self.vocab``).

A matrix the text has bound (``U = U_1 U_2 U_3``, checked above) set to a matrix with ± is compared
with the bound product at each case, as ``X(\\alpha, \\beta=0, \\gamma) = …`` is
(`derive.lecture.axis_products`).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.notes_claims`,
:func:`derive.symbolic.rotations.trig_reduce`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.notes_claims import Claim
from derive.symbolic.rotations import trig_reduce

_PM = re.compile(r"\\(pm|mp)(?![A-Za-z])")
_OR = r"(?:or|ou|oder|o|或|and|,)"
_TWO = re.compile(r"\$\s*(?P<x>[^$=]+?)\s*=\s*(?P<a>[^$=]+?)\s*\$\s*" + _OR + r"\s*\$\s*(?:(?P=x)\s*=\s*)?(?P<b>[^$=]+?)\s*\$")
"""``$\\theta=0$ or $\\pi$``, ``$\\theta = 0$ or $\\theta = \\pi$``: two cases in two inline maths."""
_ONE = re.compile(r"\$\s*(?P<x>[^$=]+?)\s*=\s*(?P<a>[^$=,]+?)\s*(?:,|\\(?:text|mathrm)\s*\{\s*or\s*\})\s*(?P<b>[^$=,]+?)\s*\$")
"""``$\\theta = 0, \\pi$``, ``$\\theta = 0 \\text{ or } \\pi$``: two cases in one."""
_PLUS_MINUS = re.compile(r"\$\s*(?P<x>[^$=]+?)\s*=\s*\\pm\s*(?P<a>[^$=]+?)\s*\$")
"""``$\\theta = \\pm\\frac{\\pi}{2}$``: the cases +a and −a."""
_DISPLAY_END = re.compile(r"\$\$|\\end\{|\\\]")
_WINDOW = 6
"""Lines of prose before a display searched for its cases."""
FLAGGED = {"typo", "fails"}


def signed(piece: str, upper: bool) -> str:
    """The statement with its upper (± → +, ∓ → −) or its lower signs."""
    return _PM.sub(lambda m: "+" if (m.group(1) == "pm") == upper else "-", piece)


def _zero(d) -> bool:
    """d ≡ 0, sines and cosines of sums expanded first (cos(φ ± ψ) as the texts write it)."""
    return trig_reduce(sp.expand(sp.expand_trig(d))) == 0


def _outcome(claims) -> str:
    verdicts = {c.verdict for c in claims}
    if verdicts & FLAGGED:
        return "flagged"
    return "holds" if "holds" in verdicts else "unchecked"


class TwoCases:
    """Mixin of the checker (see the module docstring)."""

    def _cases_said(self, line):
        """(symbol, its two values, how the prose says them) named in the prose just before the
        display at ``line``, or None."""
        lines = (getattr(self.notes, "body", "") or "").split("\n")
        prose = "\n".join(lines[max(0, line - 1 - _WINDOW):max(0, line - 1)])
        ends = list(_DISPLAY_END.finditer(prose))
        prose = prose[ends[-1].end():] if ends else prose
        found = [(m.start(), m) for pattern in (_TWO, _ONE, _PLUS_MINUS) for m in pattern.finditer(prose)]
        if not found:
            return None
        m = max(found, key=lambda f: f[0])[1]
        try:
            x = lx.parse(m.group("x"), self.vocab).members
            a = lx.parse(m.group("a"), self.vocab).members
            b = a if m.re is _PLUS_MINUS else lx.parse(m.group("b"), self.vocab).members
        except (lx.NotRead, lx.Words, ValueError, TypeError):
            return None
        if len(x) != 1 or len(a) != 1 or len(b) != 1 or not isinstance(x[0].value, sp.Symbol):
            return None
        first, second = a[0].value, (-a[0].value if m.re is _PLUS_MINUS else b[0].value)
        if not (isinstance(first, sp.Expr) and isinstance(second, sp.Expr) and first.is_number and second.is_number) \
                or first == second:
            return None
        return x[0].value, (first, second), m.group(0)

    def _two_cases(self, line, piece, dup, pieces) -> bool:
        """Judge a statement written with ± for the two cases its prose names (False: no ± outside
        its left side, or no such cases)."""
        if "\\pm" not in piece and "\\mp" not in piece:
            return False
        cases = self._cases_said(line)
        if cases is None:
            return False
        symbol, values, said = cases
        readings, outcomes = [], []
        for order in (values, values[::-1]):
            reading = [self._signs_in_case(line, piece, dup, pieces, symbol, upper, value)
                       for upper, value in zip((True, False), order)]
            readings.append((order, reading))
            outcomes.append([_outcome(c) for c in reading])
            if outcomes[-1] == ["holds", "holds"]:
                break                   # the prose's pairing holds: the other is not read
        name = self.tex(symbol)
        pairing = "the upper signs at {0} = {1}, the lower at {0} = {2}"
        chosen = next((k for k, o in enumerate(outcomes) if o == ["holds", "holds"]), None)
        if chosen is None and all("flagged" in o for o in outcomes):
            chosen = 0
        if chosen is None:
            self._add(line, piece, "cases", "unchecked",
                      f"± for the two cases {said} named before it: neither pairing of the signs with them decides it")
            return True
        order, reading = readings[chosen]
        told = pairing.format(name, self.tex(order[0]), self.tex(order[1]))
        for claims in reading:
            for c in claims:
                c.why += f" ({told}, the cases {said}" + (
                    "; flagged in either pairing)" if outcomes[chosen] != ["holds", "holds"] else ")")
            self.claims.extend(claims)
        return True

    def _signs_in_case(self, line, piece, dup, pieces, symbol, upper, value) -> list:
        """The claims of the statement with its upper (lower) signs, the case set."""
        bound = self._bound_at(line, signed(piece, upper), symbol, value)
        if bound is not None:
            return bound
        saved = self._snapshot()
        saved.subs[symbol] = value
        saved.stated[symbol] = f"line {line}, the {'upper' if upper else 'lower'} signs"
        return self._sandbox(saved, line, signed(piece, upper), dup, pieces, judging_only=True)[0]

    def _bound_at(self, line, piece, symbol, value):
        """``X = [a matrix]`` with X a matrix the text has bound: the claims of the written matrix
        against X at the case, or None when the statement is not of that shape."""
        head, eq, rest = piece.partition("=")
        try:
            toks = lx.scan(head.strip())
            if not eq or len(toks) != 1 or toks[0].kind != "atom":
                return None
            bound = self.ctx.defs.get(self.vocab.resolve(toks[0].value))
            if not isinstance(bound, sp.MatrixBase):
                return None
            members = lx.parse(rest, self.vocab).members
        except (lx.NotRead, lx.Words, ValueError, TypeError, KeyError):
            return None
        target = sp.Matrix(bound).xreplace({symbol: value}).applyfunc(trig_reduce)
        if not members or any(not isinstance(m.value, sp.MatrixBase) or m.value.shape != target.shape for m in members):
            return None
        case = f"{self.tex(symbol)} = {self.tex(value)}"
        if any(not _zero(x - y) for m in members for x, y in zip(m.value, target)):
            return [Claim(line, piece, "rotation", "fails",
                          why=f"{head.strip()} at {case} is {self.tex(target)}, not the matrix written")]
        return [Claim(line, piece, "rotation", "holds", why=f"{head.strip()}, the product bound above, at {case}: trig_reduce")]
