"""LaTeX as physicists write it, read into SymPy through a whitelist: never ``eval``, never ``sympify``.

A formula goes through three steps:

1. **Scanning** (`scan`): the physics notation is recognised token by token — decorated symbols
   (``\\dot``, ``\\ddot``, ``\\tilde``/``\\widetilde``, ``\\hat``, ``\\mathbf``/``\\boldsymbol``/``\\vec``)
   with their subscripts, superscripts and primes become one *atom* each; spacing commands,
   ``\\left``/``\\right`` and ``[ ]`` used as parentheses are normalised; ``\\equiv``, ``\\approx``,
   ``\\ge``, ``\\le``, ``\\neq`` are relations; anything else that is a command is refused by
   name.
2. **Parsing** (`parse`): a recursive-descent parser (`derive.lecture.latex_parser`) over those
   tokens (sums, products, implicit products, powers, ``\\frac``, ``\\sqrt``, sin/cos/tan with or without parentheses, sums
   ``\\sum_i`` over body axes 1..3, ``pmatrix``/``bmatrix`` matrices and column vectors,
   ``d\\mathbf{L}/dt`` and ``\\partial L/\\partial\\dot q``) builds SymPy objects directly. A
   formula it cannot read is `NotRead` with the column (1-based, in the formula) where reading
   stopped. There is no second parser behind it: SymPy's own LaTeX parser reads ``\\times`` as a
   commutative product and an implicit product ambiguously, which is not a reading to judge a
   formula by.
3. **Vocabulary** (`Vocabulary`, in `derive.lecture.vocabulary` with the scanner): every atom is looked up among the derivation's quantities and
   their usual spellings: the Euler angles of the notes' convention and their rates, ω̃ᵢ (also
   written ωᵢ), I₁ I₂ I₃ (Iᵢ in sums), M g l, p_α p_γ, Ω Ω₁ Ω₂, the unit vectors ê₁ ê₂ ê₃, ê′ᵢ,
   ê⁰ᵢ, and the named quantities T, L (Lagrangian), **L** (angular momentum), E, E′, V_eff, **ω**.
   An atom outside it is `Unknown` (``unknown symbol X``).

Named quantities are returned as `Quantity` symbols (the checker substitutes what they stand
for); the others are the derivation's own SymPy symbols (`derive.symbolic`), so a parsed formula
can be compared with a derived one directly.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.symbolic.lagrangian import p_alpha, p_gamma  # noqa: F401  (latex.p_alpha, as the checker reads it)
from derive.lecture.vocabulary import (  # noqa: F401  (the reader's names, used as latex.X across the package)
    W,
    WD,
    BASIS,
    PRIMED,
    INERTIAL,
    Omega,
    Omega1,
    Omega2,
    TAU,
    t,
    Quantity,
    DT,
    Transposed,
    MatProduct,
    Generic,
    quantity,
    T_,
    LAGRANGIAN,
    LVEC,
    ENERGY,
    EPRIME,
    VEFF,
    OMEGA_VEC,
    W_PRIMED,
    LMAG,
    DLDT,
    DLDT_BODY,
    MOMENTUM,
    QUANTITY_LATEX,
    NotRead,
    Unknown,
    Words,
    FUNCTIONS,
    Tok,
    scan,
    Vocabulary,
    p_alpha_sym,
    p_gamma_sym,
)
from derive.lecture.latex_parser import Parsed, _Parser
from derive.lecture.variations import delta_a_quantity
from derive.lecture.vocabulary import DECORATIONS, GREEK

BODY_COMPONENTS = "body components"
"""The key of `Vocabulary.readings` under which the components of the angular momentum a statement
writes together (L₁ and L₃) are all Iᵢω̃ᵢ, the axial one too, not p of the third angle."""


def parse(latex: str, vocab: Vocabulary | None = None) -> Parsed:
    """Read one formula (possibly a chain a = b = c, a ≈ b, a ≥ b) into SymPy members.

    Raises `NotRead` (with ``why`` = "cannot parse at column N: …", "unknown symbol X" or "words,
    not a formula").
    """
    vocab = vocab or Vocabulary()
    toks = scan_cells(latex)
    try:
        return _Parser(toks, vocab, latex).chain()
    except Unknown:
        raise
    except (sp.ShapeError, TypeError, ValueError, ZeroDivisionError, AttributeError) as err:
        raise NotRead(f"cannot combine its parts ({type(err).__name__}: {str(err)[:80]})") from None


def parse_all(pieces, vocab: Vocabulary) -> list[Parsed] | None:
    """Each statement of a display read by :func:`parse`; None when any of them does not read (a
    display-level rule then leaves the display to the statement-by-statement reading)."""
    out = []
    for piece in pieces:
        try:
            out.append(parse(piece, vocab))
        except (NotRead, Words, ArithmeticError, TypeError, ValueError, KeyError):
            return None
    return out


def scan_cells(latex: str) -> list[Tok]:
    """`scan`, with the '&' of matrix rows kept as entry separators (elsewhere '&' is alignment)."""
    toks = scan(latex)
    # Re-scan for '&' positions inside matrix environments.
    out, depth = [], 0
    amp = [m.start() for m in re.finditer(r"(?<!\\)&", latex)]
    amp_iter = iter(amp)
    pending = next(amp_iter, None)
    for tok in toks:
        while pending is not None and pending < tok.pos:
            if depth:
                out.append(Tok("op", "&", pending))
            pending = next(amp_iter, None)
        if tok.kind == "begin":
            depth += 1
        elif tok.kind == "end":
            depth -= 1
        out.append(tok)
    return out


def latex_atoms(latex: str, vocab: Vocabulary) -> set:
    """The derivation symbols the atoms of a formula stand for (unknown atoms left out)."""
    out = set()
    try:
        toks = scan(latex)
    except NotRead:
        return out
    for tok in toks:
        if tok.kind == "atom":
            try:
                v = vocab.resolve(tok.value)
            except NotRead:
                continue
            if isinstance(v, sp.Symbol):
                out.add(v)
    return out


def delta_quantity(body: str) -> bool:
    """Whether a text writes δ alone, as its own quantity, so that δx is δ times x (`derive.lecture.variations`)."""
    return delta_a_quantity(body, GREEK | DECORATIONS.keys())
