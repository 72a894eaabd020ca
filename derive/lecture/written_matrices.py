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
``pmatrix`` column), and for names the text set to such columns `named_dot` (a `Dot` of two),
`squared_column` (`NormSquared`, r² beside the column 𝐫), `taken` (either once the columns are put in),
`numbers_set` and `columns_only` (statements the scalar reader keeps from the vector readers).

May import: :mod:`derive.lecture.vocabulary`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture.vocabulary import NotRead, scan


def outer(a, b, after=None):
    """a ⊗ b = a bᵀ of two written columns; `NotRead` for anything else (``after``: the token
    after b, for the column)."""
    if not all(isinstance(v, sp.MatrixBase) and v.cols == 1 for v in (a, b)):
        raise NotRead("an outer product (⊗) of what is not two written columns", after.pos + 1 if after else None)
    return sp.ImmutableMatrix(sp.Matrix(a) * sp.Matrix(b).T)


_UNIT_LETTERS = ("e", "i", "j", "k", "u", "imath", "jmath")
"""Letters texts give the unit vectors of a frame: three numbers for them depend on the frame meant."""


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
    𝐞_Z = (0, 0, 1) and then 𝐞_Z = C 𝐞_z in the moving frame): not read as a name's components,
    unless they are the whole right side of a bold letter of the text's that names no unit vector of
    a frame (`_set_alone`: ``{\bf n} = (0, 0, 1)``, an axis the text then dots with its own vectors)."""
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
                return commas == 2 and (symbolic or _set_alone(toks, i, k)) and not _is(after, "op", "_") \
                    and not _is(after, "op", "^")
        elif depth == 1 and _is(t, "op", ","):
            commas += 1
        symbolic = symbolic or t.kind not in ("num", "op")
    return False


def _set_alone(toks, i: int, close: int) -> bool:
    """Whether the bracket from ``toks[i]`` to ``toks[close]`` is all that the statement sets a bold
    letter to, ``{\\bf n} = (0, 0, 1)``: the letter no frame's unit vector (𝐞, 𝐢, 𝐣, 𝐤, 𝐮 or hatted)."""
    before = [t for t in toks[:i] if not (t.kind == "op" and t.value in "{}")]
    if len(before) != 2 or not _is(before[1], "rel", "=") or not _is(before[0], "atom"):
        return False
    a = before[0].value
    return a.bold and a.base not in _UNIT_LETTERS and not (a.hat or a.sub or a.sup or a.dots or a.primes) \
        and all(t.kind == "op" and t.value in ".,}" for t in toks[close + 1:])


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


class Dot(sp.Function):
    """a · b of two bold names the text set to written matrices, taken once the names are put in
    (`taken`): the dot product of two columns (``{\\bf r} \\cdot {\\bf n}``), which SymPy would multiply
    as matrices, and the matrix product otherwise (``\\{\\boldsymbol\\lambda_\\psi\\} \\cdot …``), kept in
    its place in a product as the names are."""

    is_commutative = False

    def _latex(self, printer):
        return rf"{printer._print(self.args[0])} \cdot {printer._print(self.args[1])}"


class NormSquared(sp.Function):
    """r² of a plain letter whose bold twin the text set to a written column: 𝐫·𝐫, as texts write
    r² for |𝐫|², once the column is put in (`taken`); the plain letter squared when the bold one
    is no column there."""

    is_commutative = True

    def _latex(self, printer):
        return f"{printer._print(self.args[1])}^{{2}}"


def _column(v) -> bool:
    return isinstance(v, sp.MatrixBase) and v.shape == (3, 1)


def taken(e, args):
    """A `Dot` or `NormSquared` with its names put in (``args``): the dot product of two columns,
    the product of anything else."""
    if isinstance(e, NormSquared) and not _column(args[0]):
        return args[1] ** 2
    a, b = (args[0], args[0]) if isinstance(e, NormSquared) else args
    if not _column(a) or not _column(b):
        return a * b            # matrices (or a matrix and a column): their product, as before
    return sp.trigsimp(sp.expand((a.T * b)[0, 0]))       # cos² + sin² of polar components: 1


def _named_column(x) -> bool:
    """A name the text set to a written matrix (the reader's non-commuting symbol for it)."""
    return isinstance(x, sp.Symbol) and x.is_commutative is False


def named_dot(a, b, otherwise):
    """a · b: a `Dot` when both are names the text set to written matrices, bold or plain (a homework's
    ``v \\cdot v`` of its column v), else ``otherwise(a, b)``."""
    return Dot(a, b) if _named_column(a) and _named_column(b) else otherwise(a, b)


def squared_column(base, exp, vocab):
    """base ** exp, or `NormSquared` for r² of a plain letter (no index, accent or script) whose bold
    twin is a name the text set to a written matrix."""
    atom = vocab.generic.get(base) if exp == 2 and isinstance(base, sp.Symbol) else None
    if atom is None or atom.bold or atom.sub or atom.sup or atom.dots or atom.primes or atom.hat or atom.mark:
        return base ** exp
    twin = next((s for s, a in vocab.generic.items() if a == atom.with_(bold=True) and _named_column(s)), None)
    return NormSquared(twin, base) if twin is not None else base ** exp


def numbers_set(text: str) -> bool:
    """Whether ``text`` sets a bold letter to three written numbers, ``{\\bf n} = (0, 0, 1)``
    (`_set_alone`): the scalar reader's written column, not a vector statement."""
    try:
        toks = scan(text)
    except NotRead:
        return False
    i = next((k for k, t in enumerate(toks) if _is(t, "op", "(")), None)
    return i is not None and _is(toks[-1], "op", ")") and components_follow(toks, i) and \
        all(t.kind in ("num", "op") for t in toks[i:])


def columns_only(text: str, vocab, defs) -> bool:
    """Whether every bold letter ``text`` writes (one at least) is a name the text set to a written
    column, ``{\\bf r} \\cdot {\\bf n} = z`` after both were written out: the scalar reader's."""
    try:
        bold = [t.value.with_(text="") for t in scan(text) if t.kind == "atom" and t.value.bold]
    except NotRead:
        return False
    names = [next((s for s, a in vocab.generic.items() if a == atom and _named_column(s)), None) for atom in bold]
    return bool(names) and all(n is not None and _column(defs.get(n)) for n in names)
