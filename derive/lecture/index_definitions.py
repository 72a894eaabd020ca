"""A definition over generic indices put in for each instance: ``I_{jh} \\equiv I_j - I_h`` read in ``I_{31}``.

A text that defines a family of quantities once for all its members writes the definition with
index letters in the subscript (``I_{jh} \\equiv I_j - I_h``, ``\\Delta_j \\equiv G^2 - 2 T I_j``,
``R_{ij} = \\delta_{ij}\\cos\\vartheta + \\dots``) and then uses its instances with the indices
given (``I_{31}``, ``\\Delta_1``). `instance` gives an instance's value: the definition's right
side with each of its head's letters replaced by the instance's digit in every subscript it stands
in (``I_j`` becomes ``I_3``, the moment of inertia the vocabulary names), each other index written
twice in a term summed over 1, 2, 3 (`derive.lecture.index_sums.components`). A definition is used
only when its head is one symbol whose subscript is distinct lowercase letters, each of which
stands in a subscript of its right side (so ``T_{rot}`` or ``v_{cm}``, a label, is never read as
over indices); an instance the text defines itself keeps its own definition.

May import: the standard library, SymPy, :mod:`derive.lecture.latex`, :mod:`derive.lecture.index_sums`.
"""
from __future__ import annotations

import functools
import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.index_sums import components

_HEAD = re.compile(r"^(?P<base>[A-Za-z]+)_(?P<sub>[a-z]+)(?P<tail>'*)$")
_INSTANCE = re.compile(r"^(?P<base>[A-Za-z]+)_(?P<sub>[1-3]+)(?P<tail>'*)$")
_SUBSCRIPTED = re.compile(r"^(?P<base>[A-Za-z]+)_(?P<sub>[a-z1-3]+)(?P<tail>'*)$")


def _over_indices(key, value) -> str | None:
    """The head letters of a definition over generic indices, else None."""
    m = _HEAD.match(getattr(key, "name", ""))
    if not m or not isinstance(key, lx.Generic) or len(set(m["sub"])) != len(m["sub"]) or \
            isinstance(value, sp.MatrixBase) or not isinstance(value, sp.Expr):
        return None
    used = set()
    for s in value.free_symbols:
        n = _SUBSCRIPTED.match(s.name)
        if n and isinstance(s, lx.Generic):
            used |= set(n["sub"]) & set(m["sub"])
    return m["sub"] if used == set(m["sub"]) else None


def instance(sym, defs: dict):
    """The value of ``sym`` (``I_31``) by a definition in ``defs`` over generic indices (``I_jh``), else None."""
    m = _INSTANCE.match(getattr(sym, "name", ""))
    if not m or not isinstance(sym, lx.Generic):
        return None
    for key, value in defs.items():
        head = _HEAD.match(getattr(key, "name", ""))
        if not head or (head["base"], head["tail"]) != (m["base"], m["tail"]) or len(head["sub"]) != len(m["sub"]):
            continue
        letters = _over_indices(key, value)
        if letters:
            return _put_in(value, letters, m["sub"])
    return None


@functools.lru_cache(maxsize=4096)
def _put_in(value, letters: str, digits: str):
    """A definition's right side at its head's indices, kept: each reading resolves the same instances again."""
    return components(value, dict(zip(letters, digits)))
