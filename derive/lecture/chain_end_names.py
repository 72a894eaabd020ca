"""A name the text defines at the end of a chain, by a factor it shares with the member before.

Takes: a display's LaTeX read by `derive.lecture.latex`. Gives the mixin `ChainEndNames` of
`derive.lecture.notes_check.Checker`, whose `_named_at_chain_end` reads
``L_z = \\omega \\sum_i m_i r_i^2 = J_z \\omega`` — a chain whose last member is a name of the text's
met there for the first time times a factor of the member before it — as the definition
J_z = Σᵢ mᵢ rᵢ² (the member before divided by that factor), recorded for the displays after it.
Nothing is judged here: the chain's own claims are read as before. The definition is kept in the
text's LaTeX as well (``\\frac{B}{c}``, c the last member with the name put to 1), which
`put_in` writes in place of the name in a later statement, so that the readers of vectors and
sums over particles read J_z as the text defined it, not as the z component of a vector 𝐉.

May import: the standard library, :mod:`derive.lecture.latex`, :mod:`derive.lecture.latex_spaces`,
:mod:`derive.lecture.statements`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.latex_spaces import SPACE
from derive.lecture.statements import top_level

_EQUALS = re.compile(r"(?<![<>!\\])=")
_END_PUNCTUATION = re.compile(r"(?:\s|(?<!\\)[,.;])+$")
"""The punctuation that ends a display's sentence (``… = J_z \\omega,``): no part of its last member."""


class ChainEndNames:
    """Mixin of the checker. Uses ``self.vocab`` and ``self.ctx``."""

    def _named_at_chain_end(self, latex: str, line: int = 0) -> None:
        """Record ``N = B / c`` for a chain ``… = B = N c`` (N a new name of the text's, c ≠ 1 a
        factor whose symbols B has, B free of N); nothing for any other display."""
        latex = _END_PUNCTUATION.sub("", latex)
        try:
            parsed = lx.parse(latex, self.vocab)
        except lx.NotRead:
            return
        members = parsed.members
        if len(members) < 3 or set(parsed.relations) != {"="}:
            return
        last, before = sp.sympify(members[-1].value), sp.sympify(members[-2].value)
        if not isinstance(last, sp.Mul) or isinstance(before, sp.MatrixBase):
            return
        earlier = set().union(*(sp.sympify(m.value).free_symbols for m in members[:-1]))
        new = [s for s in last.free_symbols - earlier
               if isinstance(s, lx.Generic) and s.is_commutative and s not in self.ctx.defs]
        if len(new) != 1 or not last.has(new[0]):
            return
        (name,) = new
        factor = sp.cancel(last / name)
        if factor.has(name) or factor == 1 or not factor.free_symbols or \
                not factor.free_symbols <= before.free_symbols:
            return
        value = sp.cancel(before / factor)
        if value.has(name) or sp.expand(value * factor - before) != 0 or \
                not value.free_symbols.isdisjoint(factor.free_symbols):
            return
        self.ctx.defs[name] = value
        self._latex_of(latex, members, name, line)

    def _latex_of(self, latex, members, name, line) -> None:
        """Keep ``name ↦ (line, \\frac{B}{c})`` in the text's LaTeX, when the chain's members and the
        name's spelling in its last member can be told."""
        cuts = top_level(latex, _EQUALS)
        if len(cuts) != len(members) - 1:
            return
        before = latex[cuts[-2].end():cuts[-1].start()].strip()
        last = latex[cuts[-1].end():].strip()
        try:
            toks = lx.scan(last)
        except lx.NotRead:
            return
        for k, tok in enumerate(toks):
            if tok.kind != "atom":
                continue
            end = toks[k + 1].pos if k + 1 < len(toks) else len(last)
            spelled = re.sub(SPACE + "$", "", last[tok.pos:end])   # J_z \, \omega: the space is no part of the name
            try:
                if sp.sympify(lx.parse(spelled, self.vocab).members[0].value) != name:
                    continue
            except lx.NotRead:
                continue
            factor = last[:tok.pos] + " 1 " + last[tok.pos + len(spelled):]
            self.__dict__.setdefault("chain_end_latex", {})[spelled] = (line, f"\\frac{{{before}}}{{{factor}}}")
            return


def put_in(text: str, names: dict, line: int | None) -> str:
    """The statement with each name defined at a chain's end on an earlier line written as its
    definition, bracketed (the statement unchanged when it has none of them); ``line`` None: every
    name, wherever it was defined."""
    for spelled, (at, value) in names.items():
        if line is not None and at >= line:
            continue
        pattern = r"(?<![A-Za-z\\])" + _spelling(spelled) + r"(?![A-Za-z0-9_{'])"
        text = re.sub(pattern, lambda _: r"\left(" + value + r"\right)", text)
    return text


_ONE_TOKEN_SCRIPT = re.compile(r"(?P<base>.*?)\s*_\s*(?:\{\s*(?P<braced>\\[A-Za-z]+|[A-Za-z0-9])\s*\}|(?P<bare>\\[A-Za-z]+|[A-Za-z0-9]))",
                               re.S)


def _spelling(spelled: str) -> str:
    """A pattern for a name as written anywhere: its one-token index braced or not (``J_{z}`` is
    ``J_z``, the same symbol), spaces allowed around the ``_``."""
    m = _ONE_TOKEN_SCRIPT.fullmatch(spelled)
    if m is None:
        return re.escape(spelled).replace("_", r"\s*_\s*")
    index = re.escape(m["braced"] or m["bare"])
    return re.escape(m["base"]) + r"\s*_\s*(?:\{\s*" + index + r"\s*\}|" + index + ")"
