"""Letters a text gives the components of a known vector by writing them as its column.

Takes: the members of one statement read by `derive.lecture.latex` and the checker (its
definitions and its test for a name the text has not defined). Gives: `named`, which records
``\\boldsymbol{\\omega} = \\begin{bmatrix} p \\\\ q \\\\ r \\end{bmatrix}`` (or the column first) as
p, q, r := ω̃₁, ω̃₂, ω̃₃ — the body rates of the aerospace texts, named so — and says so; later
formulas in p, q, r are then checked as formulas in the angular velocity's components.
May import: SymPy, :mod:`derive.lecture.latex`.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import latex as lx


def named(checker, members) -> str | None:
    """Why the statement ``vector = column of new letters`` defines those letters (recorded in
    ``checker.ctx.defs``), or None when it is not one: two members, both columns of three, one
    of distinct letters the text has not defined, the other of the derivation's own quantities."""
    if len(members) != 2 or not any(isinstance(m, sp.MatrixBase) for m in members):
        return None
    members = [_column(checker._resolve(m)) for m in members]
    if not all(isinstance(m, sp.MatrixBase) and m.shape == (3, 1) for m in members):
        return None
    for known, letters in (members, members[::-1]):
        if len(set(letters)) == 3 and all(checker._new_name(x) for x in letters) and all(
                isinstance(x, sp.Symbol) and not isinstance(x, lx.Generic) for x in known):
            for letter, value in zip(letters, known):
                checker.ctx.defs[letter] = value
                checker._mark_defined(letter)
            checker.settings_only = False
            return (f"defines the text's symbols {', '.join(checker.tex(x) for x in letters)} as the components "
                    f"{', '.join(checker.tex(x) for x in known)} (recorded, then used)")
    return None


def _column(value):
    """A vector as its column: a written one as it stands, 𝛚 = ω̃₁𝐞₁ + ω̃₂𝐞₂ + ω̃₃𝐞₃ as (ω̃₁, ω̃₂, ω̃₃)."""
    if isinstance(value, sp.MatrixBase):
        return value
    value = sp.expand(value)
    column = sp.Matrix([value.coeff(e) for e in lx.BASIS])
    return column if sp.expand(value - sum(c * e for c, e in zip(column, lx.BASIS))) == 0 else value
