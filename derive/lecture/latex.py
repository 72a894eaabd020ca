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
   ``d\\mathbf{L}/dt`` and ``\\partial L/\\partial\\dot q``) builds SymPy objects directly. What it
   cannot read is handed, with every atom replaced by a placeholder symbol, to SymPy's own LaTeX
   parser (``parse_latex(…, backend="lark")``) — the slow path (a third of a second per formula,
   ambiguous on implicit products), so only for what the fast path refuses. A formula neither
   reads is `NotRead` with the column (1-based, in the formula) where reading stopped.
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

import functools
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
    latex_atoms,
)
from derive.lecture.latex_parser import Member, Parsed, _Parser


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
    except NotRead as err:
        fallback = _lark(latex, toks, vocab)
        if fallback is not None:
            return fallback
        raise err


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


# --- the slow path: SymPy's LaTeX parser (Lark) --------------------------------------------------
def _lark(latex: str, toks: list[Tok], vocab: Vocabulary) -> Parsed | None:
    """Hand the formula to ``sympy.parsing.latex.parse_latex(…, backend="lark")`` with each atom
    replaced by a placeholder ``Z_{k}`` (the vocabulary has already resolved them), and map the
    placeholders back. None when it cannot read it either, or returns an ambiguous reading."""
    pieces, table, last = [], {}, 0
    for k, tok in enumerate(toks):
        if tok.kind == "atom":
            value = vocab.resolve(tok.value)
            if value is None:
                return None
            name = f"Z_{{{k}}}"
            table[sp.Symbol(name)] = value
            pieces.append(latex[last:tok.pos] + f" {name} ")
            last = tok.pos + len(tok.value.text)
    pieces.append(latex[last:])
    text = "".join(pieces)
    for rel in ("\\equiv", "\\approx"):
        text = text.replace(rel, "=")
    text = text.replace("\\left", "").replace("\\right", "")
    result = _lark_reading(text)
    if not isinstance(result, (sp.Basic, sp.MatrixBase)):
        return None                                   # an ambiguous reading (a Lark tree)
    if isinstance(result, sp.core.relational.Relational):
        members = [Member(result.lhs.xreplace(table)), Member(result.rhs.xreplace(table))]
        return Parsed(members, ["="])
    return Parsed([Member(result.xreplace(table))], [])


@functools.lru_cache(maxsize=1024)
def _lark_reading(text: str):
    """SymPy's Lark reading of a formula with placeholders, or None: cached, since the second
    readings of a statement hand the same text over again."""
    try:
        from sympy.parsing.latex import parse_latex
    except ImportError:  # pragma: no cover - lark is a dependency
        return None
    try:
        return parse_latex(text, backend="lark")
    except Exception:  # noqa: BLE001 - any failure of the slow path means "not read"
        return None
