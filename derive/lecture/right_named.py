"""A new name a text introduces on the right of a definition sign: ``p_\\psi \\equiv I_1 a``.

Takes: a relation the notes checker could not tie to the derivation (`derive.lecture.textnames`),
its members and the one symbol of the text's that nothing ties (``loose``). Gives: `defines`, which
reads a definition sign (``\\equiv``, every spelling of it written so by the normaliser) between a
quantity the reader knows and an expression of the one new symbol as the definition of that symbol:
the relation solved for it, uniquely, is recorded (the text's own symbol, ``a = p_ψ/I₁``) and used
in the displays after it, as ``X \\equiv …`` with X new on the left is. A text writes so when it
names a constant after the fact ("define $p_\\psi \\equiv I_1 a$ and $p_\\phi \\equiv I_1 b$"). An
equals sign is not read so (a relation between a known and a new quantity may be a claim the text
makes about its own symbol), nor is a relation the symbol stands in on both sides or not solvable
for it alone.

May import: SymPy.
"""
from __future__ import annotations

import sympy as sp


def defines(checker, line, piece, members, rels, loose) -> bool:
    """Is the relation ``X \\equiv f(a)`` (or ``f(a) \\equiv X``) with ``a`` the one loose symbol and X
    free of it? Then ``a`` is recorded as the solution, and the statement is no claim."""
    if rels != ["≡"] or len(loose) != 1 or len(members) != 2:
        return False
    (a,) = loose
    sides = [checker._resolve(m) for m in members]
    holding = [k for k, side in enumerate(sides) if a in getattr(side, "free_symbols", set())]
    if len(holding) != 1:
        return False
    known = members[1 - holding[0]]
    try:
        solutions = sp.solve(sp.Eq(known, members[holding[0]]), a, dict=True)
    except (NotImplementedError, TypeError, ValueError):
        return False
    if len(solutions) != 1 or a in sp.sympify(solutions[0].get(a, a)).free_symbols:
        return False
    checker.ctx.defs[a] = solutions[0][a]
    checker._add(line, piece, "new symbol", "unchecked",
                 f"defines the text's symbol {checker.tex(a)} by a definition sign (recorded, then used)")
    return True
