"""Matrices as texts write them between the formula reader's tokens: the outer and the cross product
of two written columns, ``[v_1; v_2; v_3] \\otimes [w_1; w_2; w_3]`` and ``… \\times …``, and a written
matrix labelled by the frame its components are in, ``\\begin{bmatrix} … \\end{bmatrix}_A``, and a vector's three components
written in a row between round brackets, ``\\boldsymbol\\Omega = (\\omega \\sin\\alpha, 0, \\omega \\cos\\alpha)``.

Takes: the operands `derive.lecture.latex_parser` has read (for a cross product, the parser itself, to
read the second), and its tokens after a written matrix.
Gives: `outer` (a bᵀ; `NotRead` when the operands are not two columns), `cross` (a × b of two written
columns, ``[\\omega_1; \\omega_2; \\omega_3] \\times [I_1\\omega_1; I_2\\omega_2; I_3\\omega_3]`` in Euler's
equations in matrix form; `NotRead` for anything else) and `frame_label` (how many
tokens the label takes, 0 when there is none; a statement whose matrices are labelled with two
frames raises `NotRead`, since two frames' components are not comparable entry by entry),
`components_follow` and `components` (the column of a bracketed triple, as the reader reads a written
``pmatrix`` column).

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


def cross(parser, a, env):
    """a × b of two written columns, the parser at the ``\\times`` (b its next operand); anything else
    is the vector reader's, `NotRead` as before: a cross product of the text's vectors or names."""
    if not (isinstance(a, sp.MatrixBase) and a.shape == (3, 1)):
        parser.fail("vector products (×) are not read")
    at = parser.peek()
    parser.i += 1
    b = parser.operand(env)
    if not (isinstance(b, sp.MatrixBase) and b.shape == (3, 1)):
        parser.fail("vector products (×) are not read", at)
    return sp.ImmutableMatrix(sp.Matrix(a).cross(sp.Matrix(b)))


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


def components_follow(toks, i: int) -> bool:
    """Whether the round bracket at ``toks[i]``, an operand of its own (not after a name, whose
    arguments it would list), holds exactly three entries
    cut by two commas at its own depth (``(a, b, c)``, a vector's components) and no subscript
    follows it: a pair or a longer list is an interval, a point or a state, not a 3-vector. Three
    numbers alone, ``(0, 0, 1)``, are a direction in whichever frame the prose means (a text sets
    𝐞_Z = (0, 0, 1) and then 𝐞_Z = C 𝐞_z in the moving frame): not read as a name's components."""
    if not _is(toks[i] if i < len(toks) else None, "op", "(") or i > 0 and toks[i - 1].kind == "atom":
        return False                    # 𝐑_{lG}(−α, −β, −γ): a name's arguments, not a vector
    depth, commas, symbolic = 0, 0, False
    for k in range(i, len(toks)):
        t = toks[k]
        if t.kind == "op" and t.value in "([{":
            depth += 1
        elif t.kind == "op" and t.value in ")]}":
            depth -= 1
            if depth == 0:
                after = toks[k + 1] if k + 1 < len(toks) else None
                return commas == 2 and symbolic and not _is(after, "op", "_") and not _is(after, "op", "^")
        elif depth == 1 and _is(t, "op", ","):
            commas += 1
        symbolic = symbolic or t.kind not in ("num", "op")
    return False


def components(parser, env):
    """The column of the bracketed triple at the parser's position (`components_follow`), each entry
    one value read by ``parser.expr`` (a vector or a matrix among them: `NotRead`)."""
    parser.take("op", "(")
    entries = []
    for close in (",", ",", ")"):
        entry = parser.expr(env)
        if isinstance(entry, sp.MatrixBase):
            parser.fail("a vector's component that is itself a matrix")
        entries.append(entry)
        parser.take("op", close)
    return sp.Matrix(entries)
