"""Matrices as texts write them between the formula reader's tokens: the outer product of two
written columns, ``[v_1; v_2; v_3] \\otimes [w_1; w_2; w_3]``, and a written matrix labelled by the
frame its components are in, ``\\begin{bmatrix} … \\end{bmatrix}_A``.

Takes: the operands `derive.lecture.latex_parser` has read, and its tokens after a written matrix.
Gives: `outer` (a bᵀ; `NotRead` when the operands are not two columns) and `frame_label` (how many
tokens the label takes, 0 when there is none; a statement whose matrices are labelled with two
frames raises `NotRead`, since two frames' components are not comparable entry by entry).

May import: :mod:`derive.lecture.vocabulary`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture.vocabulary import NotRead


def outer(a, b, after=None):
    """a ⊗ b = a bᵀ of two written columns; `NotRead` for anything else (``after``: the token
    after b, for the column)."""
    if not all(isinstance(v, sp.MatrixBase) and v.cols == 1 for v in (a, b)):
        raise NotRead("an outer product (⊗) of what is not two written columns", after.pos + 1 if after else None)
    return sp.ImmutableMatrix(sp.Matrix(a) * sp.Matrix(b).T)


def _is(tok, kind, value=None) -> bool:
    return tok is not None and tok.kind == kind and (value is None or tok.value == value)


def frame_label(toks, i: int, frames: set) -> int:
    """The number of tokens of a frame's label at ``toks[i]`` after a written matrix (``_A``,
    ``_{A}``: one capital letter), 0 when there is none; the label is added to ``frames``, the
    labels met in this statement, and a second one raises `NotRead`."""
    get = lambda k: toks[k] if k < len(toks) else None  # noqa: E731
    if not _is(get(i), "op", "_"):
        return 0
    braced = _is(get(i + 1), "op", "{")
    letter = get(i + 2) if braced else get(i + 1)
    if not _is(letter, "atom") or not re.fullmatch(r"[A-Z]", letter.value.text) or \
            (braced and not _is(get(i + 3), "op", "}")):
        return 0
    frames.add(letter.value.text)
    if len(frames) > 1:
        raise NotRead(f"components in two frames ({', '.join(sorted(frames))}) compared", letter.pos + 1)
    return 4 if braced else 2
