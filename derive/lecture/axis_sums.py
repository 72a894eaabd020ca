"""Sums whose range the text writes from 1 to 3 (``\\sum_{a=1}^3``, ``\\sum_{k = 1}^{3}``), over an index of any letter.

Takes: a sum's index and its written range (from `derive.lecture.latex_parser`); an atom of the text's own
and the values the sums around it give their indices (from `derive.lecture.vocabulary`). Gives:

* `range_letters`: the index of a sum that writes its range 1 to 3 is a body axis whatever its letter
  (``a``, ``b``, ``l``), read once per value as i, j, k are;
* `Axis`: such a value (an int), so that only the sums that write their range give their values to
  the text's own symbols: a bare ``\\sum_i`` may run over particles, and keeps its terms as written;
* `summed`: the text's own symbol with its index given that value (``r_a`` → r₁, ``r_a^{(i)}`` →
  r₁⁽¹⁾ inside ``\\sum_{i=1}^3`` too), Kronecker's ``\\delta_{ak}`` its value 1 or 0, each such component
  recorded in the vocabulary's ``summed`` so that `derive.lecture.unlike_terms` gives the components of one
  letter one dimension (a sum of their squares adds them);
* `shares_dimension`: whether a symbol is such a component.

May import: SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

_RANGE = re.compile(r"\{\s*([A-Za-z])\s*=\s*1\s*\}")


class Axis(int):
    """An index's value given by a sum that writes its range 1 to 3."""


def range_letters(index: str, upper, source: str, at: int) -> list[str]:
    """``[letter]`` when the sum's index is one letter written ``{letter = 1}`` at ``source[at:]`` and its upper
    limit is 3, else ``[]``."""
    m = _RANGE.match(source, at)
    return [index] if len(index) == 1 and m and m.group(1) == index and upper == 3 else []


def _value(script: str, env: dict) -> str | None:
    """``script`` with each index a written-range sum binds given its value (a bracketed ``(i)`` too), or None
    when it holds no such index or a letter no sum binds."""
    inner = script[1:-1] if re.fullmatch(r"\([A-Za-z]\)", script) else script
    if not inner or not any(isinstance(env.get(ch), Axis) for ch in inner):
        return None
    if not all(isinstance(env.get(ch), Axis) or not ch.isalpha() for ch in inner):
        return None
    out = "".join(str(env[ch]) if ch in env else ch for ch in inner)
    return f"({out})" if inner is not script else out


def summed(vocab, a, env: dict, generic):
    """The text's own symbol for atom ``a`` under the sums ``env`` (see the module docstring); ``generic`` makes it."""
    sub, sup = _value(a.sub, env), _value(a.sup, env)
    if sub is None and sup is None:
        return generic(a)
    if a.base == "delta" and sub is not None and len(sub) == 2 and sup is None and not a.bold and not a.primes:
        return sp.Integer(int(sub[0] == sub[1]))
    atom = a.with_(sub=a.sub if sub is None else sub, sup=a.sup if sup is None else sup, text="")
    sym = generic(atom)
    vocab.__dict__.setdefault("summed", set()).add(atom.with_(text=""))
    return sym


def shares_dimension(vocab, atom) -> bool:
    """Whether ``atom`` is a component, by one index letter or digit, of a letter whose components a
    written-range sum gave their index (see `summed`): r₁ and r_a beside Σ_{a=1}^3 r_a²."""
    if atom is None or len(atom.sub) != 1:
        return False
    key = atom.with_(sub="", sup="", text="")
    return any(a.with_(sub="", sup="") == key for a in vocab.__dict__.get("summed", ()))
