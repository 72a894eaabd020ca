"""The derivative of a function the text defined, written with primes: ``U'(\\theta)``, ``U''(\\theta)``.

Takes: the checker's vocabulary (its atoms), the text's definitions and the symbols of a claim.
Gives: `definitions`, each primed symbol → the derivative of the text's own definition of the
unprimed one with respect to the argument it is written at.

May import: the standard library, SymPy.

A heavy top's effective potential ``U(\\theta) = ...`` is followed by its slope ``U'(\\theta) = ...``
(the steady-precession condition) and its curvature ``U''(\\theta_0)`` (the nutation frequency).
The reading is sound only where the argument is one of the free symbols of that definition, so the
derivative is the one the text means; anything else stays the text's own symbol.
"""
from __future__ import annotations

import re

import sympy as sp

# a statement that opens with a primed function at an argument: U'(\theta) = ..., V''_{eff}(x) = ...
_LEADS = re.compile(r"^\s*(?:\\[A-Za-z]+|[A-Za-z])(?:_\{[^{}]*\}|_\\?[A-Za-z0-9]+)?\s*'+\s*(?:_\{(?:[^{}]|\{[^{}]*\})*\}|_\\?[A-Za-z0-9]+)?\s*(?:\\left)?\(")

# d/dθ, d²/dθ², ∂/∂x written as an operator in a variable other than t: the reader takes d for a factor there
_OPERATOR = re.compile(r"\\[dt]?frac\s*\{\s*(?:\\mathrm\{d\}|d|\\partial)[^{}]*\}\s*\{\s*(?:\\mathrm\{d\}|d|\\partial)\s*(?!t\s*\})")


def operator_in_other_variable(piece: str) -> bool:
    """Does the statement write a derivative in a variable other than time (``\\frac{d}{d\\theta}``)?"""
    return bool(_OPERATOR.search(piece))


def leads(piece: str) -> bool:
    """Does the statement open with a primed function at an argument (``U'(\\theta) = ...``)?
    Its members are then the calculus of the text's own definition, true or false whatever the
    text's names mean."""
    return bool(_LEADS.match(piece))


def definitions(vocab, defs: dict, syms, tex) -> dict:
    """X'(q) → d/dq of the text's X(q), for the primed symbols in ``syms``.

    Parameters
    ----------
    vocab : Vocabulary
        The checker's vocabulary (``generic`` maps a symbol to its written atom).
    defs : dict
        The text's definitions so far (symbol → value).
    syms : iterable
        The symbols of the claim.
    tex : callable
        Symbol → its LaTeX, to find the argument among the definition's free symbols.

    Returns
    -------
    dict
        Primed symbol → the derivative of the unprimed definition.
    """
    rep = {}
    for s in syms:
        atom = vocab.generic.get(s)
        if atom is None or not atom.primes or s in defs or not atom.sup.startswith("("):
            continue
        base = vocab._symbol_of(atom.with_(primes=0))
        if base is None or base not in defs or isinstance(defs[base], sp.MatrixBase):
            continue
        value = defs[base]
        arg = atom.sup[1:-1].strip() if atom.sup.endswith(")") else ""
        q = [x for x in value.free_symbols if tex(x).replace(" ", "") == arg.replace(" ", "")]
        if len(q) != 1:
            continue
        rep[s] = sp.diff(value, q[0], atom.primes)
    return rep
