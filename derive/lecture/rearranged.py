"""An equation and the same equation solved for one of its terms, joined by an arrow.

Takes: one statement's LaTeX (``F_{O_z} - mg = ma_{cm_z} \\rightarrow F_{O_z} = ma_{cm_z} + mg``).
Gives: `check`, the verdict on the step the arrow claims — that the second equation is the first
rearranged (moved terms, a common factor) — or None when the statement is no such pair. The first
equation is the text's (a law or a setting it applies); what is checked is that the second says the
same, whatever the symbols stand for: (L₁ − R₁) = c (L₂ − R₂) for a non-zero number c. A second
equation in the same symbols that differs from the first by one term moved across the = with its
sign kept fails; any other second equation is a consequence the reader does not judge here.

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.statements`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.statements import top_level

_ARROW = re.compile(r"\\(?:rightarrow|longrightarrow|Longrightarrow|to)(?![A-Za-z])")


def _equation(part: str):
    vocab = lx.Vocabulary()
    vocab.open = True              # every letter the text's own: the step is checked whatever they mean
    parsed = lx.parse(part, vocab)
    if parsed.relations != ["="] or any(isinstance(m.value, sp.MatrixBase) for m in parsed.members):
        raise lx.NotRead("not one equation between scalars")
    return sp.expand(parsed.members[0].value - parsed.members[1].value)


def check(text: str) -> tuple[str, str] | None:
    """("holds" | "fails", why) for ``A = B \\rightarrow C = D``, else None."""
    arrows = top_level(text, _ARROW)
    if not arrows:
        return None
    first, second = text[:arrows[0].start()], text[arrows[0].end():]
    try:
        d1, d2 = _equation(first), _equation(second)
    except (lx.NotRead, TypeError, ValueError, AttributeError):
        return None
    if d2 == 0 or d1 == 0:
        return None
    ratio = sp.cancel(d1 / d2)
    if ratio.is_number and ratio != 0:
        return "holds", "the equation after the arrow is the one before it rearranged (the same equation)"
    if d1.free_symbols != d2.free_symbols:
        return None                 # a consequence in other symbols (ω̇ = 0 → ω = const): not a rearrangement
    for gap in (sp.expand(d1 - d2), sp.expand(d1 + d2)):
        if len(sp.Add.make_args(gap)) == 1:       # one term moved across the = without its sign changed
            return "fails", (f"the equation after the arrow is the one before it with the term "
                             f"{sp.sstr(gap / 2)} moved across the = without changing its sign")
    return None
