"""A determinant set to zero that the text rewrites by one row (or column) operation: the secular
equation ``\\begin{vmatrix} … \\end{vmatrix} = 0`` of a body's inertia tensor, then the same
determinant with one row replaced by that row less another ("taking row 1 from row 2").

Takes: the statements of a text, each a determinant between bars alone on one side and 0 on the
other, its entries read by the scanner (`derive.lecture.latex.parse`). Gives the mixin
`DeterminantSteps` of `derive.lecture.notes_check.Checker`, whose ``_row_step`` keeps each such
determinant and judges a later one of the same size that differs from the latest kept one in
exactly one row, or in exactly one column, all other entries the same: it is that determinant
rewritten, so the two determinants must be equal up to a non-zero number (adding a multiple of
another row keeps it, a swap changes its sign, a number scales it). It `holds` when their ratio
is a number, and `fails` when it is not, the earlier determinant taken as written. A later
determinant that differs in two rows or more, or in its size, is a new equation and is not judged.

May import: sympy, :mod:`derive.lecture.latex`.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx

_ALONE = re.compile(r"\s*\\begin\{vmatrix\}(?P<body>.*)\\end\{vmatrix\}\s*=\s*0\s*$", re.S)


def _matrix(piece, vocab):
    """The square matrix between bars of ``|…| = 0``, or None where the statement is not that."""
    m = _ALONE.match(piece)
    if m is None or "vmatrix" in m["body"]:
        return None
    try:
        parsed = lx.parse("\\begin{pmatrix}" + m["body"] + "\\end{pmatrix}", vocab)
    except (lx.NotRead, lx.Words, ValueError, TypeError):
        return None
    value = parsed.members[0].value if len(parsed.members) == 1 else None
    if not isinstance(value, sp.MatrixBase) or value.rows != value.cols or value.rows < 2 or \
            not all(isinstance(x, sp.Expr) and x.is_commutative for x in value):
        return None
    return sp.Matrix(value)


def _one_line_changed(new, old):
    """'row i' or 'column j' when new and old differ in exactly that line and nowhere else; else None."""
    same = [[sp.expand(new[i, j] - old[i, j]) == 0 for j in range(new.cols)] for i in range(new.rows)]
    rows = [i for i in range(new.rows) if not all(same[i])]
    cols = [j for j in range(new.cols) if not all(same[i][j] for i in range(new.rows))]
    if len(rows) == 1 and len(cols) > 1:
        return f"row {rows[0] + 1}"
    if len(cols) == 1 and len(rows) > 1:
        return f"column {cols[0] + 1}"
    return None


class DeterminantSteps:
    """Mixin of the checker. Uses ``self.vocab``, ``self.claims`` and ``self.tex``."""

    def _row_step(self, line, piece, start):
        """Judge ``|B| = 0`` against the text's latest ``|A| = 0`` when B is A with one row or column
        rewritten and the statement's claims from ``start`` are all unchecked; keep B for the next."""
        new = _matrix(piece, self.vocab)
        if new is None:
            return
        kept = self.__dict__.setdefault("_determinants", [])
        old = kept[-1] if kept else None
        kept.append((line, new))
        added = self.claims[start:]
        if old is None or old[0] >= line or old[1].shape != new.shape or not added or \
                any(c.verdict != "unchecked" for c in added):
            return
        changed = _one_line_changed(new, old[1])
        if changed is None:
            return
        before, after = (sp.expand(m.det(method="berkowitz")) for m in (old[1], new))
        if before == 0:
            return
        ratio = sp.cancel(after / before)
        if ratio.is_number and ratio != 0:
            verdict = "holds", f"the determinant of line {old[0]} with its {changed} rewritten: the same up to the factor {self.tex(ratio)}"
        else:
            verdict = "fails", (f"the determinant of line {old[0]} with its {changed} rewritten, but not by adding a multiple of "
                                f"the others: it works out to {self.tex(sp.factor(after))}, not a number times "
                                f"{self.tex(sp.factor(before))}")
        for c in added:
            c.kind, (c.verdict, c.why) = "determinant", verdict
