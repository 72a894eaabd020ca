"""Index notation written out: ``\\delta_{ij}R_{ij} = R_{ii}``, ``n_k\\sin\\vartheta = -\\frac{1}{2}\\varepsilon_{ijk}R_{ij}``.

Gives `components`, one expression in index notation at given values of its free indices, and the
mixin `IndexSums` of `derive.lecture.notes_check.Checker`, whose `_index_identity` judges a chain
in index notation that nothing else ties (and `_identity_whatever` a chain in the text's plain
names, `_links_whatever` the links of one that is not the same throughout). May import: the
standard library, SymPy, :mod:`derive.lecture.latex`, :mod:`derive.lecture.unread_members`,
:mod:`derive.lecture.zero_test`.

A symbol of the text's with a subscript of the index letters i, j, k, l, m, n alone (``x_j``,
``R_{ij}``, ``a'_i``) is a component; in each term of a sum a letter written once is a free
index and a letter written twice is summed over 1, 2, 3 (Einstein's convention); ``\\delta_{ij}``
is Kronecker's delta and ``\\varepsilon_{ijk}`` (``\\epsilon_{ijk}``) the Levi-Civita symbol. A
chain is judged only when every member is read so: no letter three times in a term, no component
inside a function or a denominator, every term of every member with the same free indices (a zero
member aside). Each member is then written out for every value of the free indices, each
component the text's own symbol (``x_1``) or what its definitions make it (``R_{12}`` by the
text's ``R_{ij} = …``); the chain holds when, at every value, the members are the same expression
whatever the components stand for. A chain that does not, its head in the text's own names, has
each link (two neighbouring members) that does so said to hold, and its other links left unchecked:
its members may be related by what the text says in words (an approximation, a definition), never
flagged here.
"""
from __future__ import annotations

import functools
import itertools
import re
from collections import Counter

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.unread_members import applied_names_multiplied
from derive.lecture.zero_test import differs_somewhere, expanded, surely_nonzero

LETTERS = frozenset("ijklmn")
_INDEXED = re.compile(r"^(?P<base>[A-Za-z]+)_(?P<sub>[a-z]+)(?P<tail>'*)$")
_DIGITS = "123"


def indexed(s, letters=LETTERS) -> tuple[str, str, str] | None:
    """(base, index letters, primes) of a component in index notation (``x_j``, ``a_i'``), else None."""
    m = _INDEXED.match(getattr(s, "name", "")) if isinstance(s, lx.Generic) else None
    if not m or not set(m["sub"]) <= letters:
        return None
    return m["base"], m["sub"], m["tail"]


def _letters(term, letters=LETTERS) -> Counter | None:
    """How often each index letter stands in a term's components; None when one stands elsewhere
    than in a factor raised to a positive whole power."""
    counts, seen = Counter(), set()
    for factor in sp.Mul.make_args(term):
        base, exp = factor.as_base_exp()
        parts = indexed(base, letters)
        if parts and exp.is_Integer and exp > 0:
            counts.update({c: int(exp) * n for c, n in Counter(parts[1]).items()})
            seen.add(base)
    if any(indexed(s, letters) for s in term.free_symbols - seen):
        return None
    return counts


def free_indices(expr) -> frozenset | None:
    """The free indices of an expression in index notation, the same in every term; else None."""
    if isinstance(expr, sp.MatrixBase) or not isinstance(expr, sp.Expr):
        return None
    found = set()
    for term in sp.Add.make_args(sp.expand(expr)):
        counts = _letters(term)
        if counts is None or any(n > 2 for n in counts.values()):
            return None
        found.add(frozenset(c for c, n in counts.items() if n == 1))
    return found.pop() if len(found) == 1 else None


@functools.lru_cache(maxsize=None)
def component(base: str, digits: str, tail: str = ""):
    """Kronecker's delta and the Levi-Civita symbol at their indices; the symbol the vocabulary reads
    for ``base_{digits}`` (``I_3`` is the third moment); else the text's own symbol of that name."""
    if base == "delta" and len(digits) == 2 and not tail:
        return sp.KroneckerDelta(int(digits[0]), int(digits[1]))
    if base in ("epsilon", "varepsilon") and len(digits) == 3 and not tail:
        return sp.LeviCivita(*map(int, digits))
    if not tail:
        for latex in (f"{base}_{{{digits}}}", f"\\{base}_{{{digits}}}"):
            try:
                parsed = lx.parse(latex, lx.Vocabulary())
            except lx.NotRead:
                continue
            read = parsed.members[0].value if len(parsed.members) == 1 else None
            if isinstance(read, sp.Symbol) and not isinstance(read, lx.Generic):
                return read
    return lx.Generic(f"{base}_{digits}{tail}", real=True)


def components(expr, env: dict):
    """``expr`` at the indices ``env`` (letter → digit), each other letter written twice in a term summed
    over 1, 2, 3; None when a term is not index notation (a letter unbound and not repeated, a component
    in a function)."""
    letters = LETTERS | set(env)
    total = sp.S.Zero
    for term in sp.Add.make_args(sp.expand(expr)):
        counts = _letters(term, letters)
        if counts is None:
            return None
        summed = sorted(c for c in counts if c not in env)
        if any(counts[c] != 2 for c in summed) or len(summed) > 4:
            return None
        comps = [s for s in term.free_symbols if indexed(s, letters)]
        for digits in itertools.product(_DIGITS, repeat=len(summed)):
            at = {**env, **dict(zip(summed, digits))}
            rep = {}
            for s in comps:
                base, sub, tail = indexed(s, letters)
                rep[s] = component(base, "".join(at.get(c, c) for c in sub), tail)
            total += term.xreplace(rep)
    return total


class IndexSums:
    """Mixin of the checker. Uses ``_resolve``, ``_calculus``, ``_add``."""

    def _index_identity(self, line, piece, members, rels) -> bool:
        """A chain in index notation whose members are the same at every value of its free indices
        (see the module docstring): holds; else its links that are, each said so; anything else is
        left to the other readings."""
        if not set(rels) <= {"=", "≡"} or not any(indexed(s) for m in members for s in getattr(m, "free_symbols", ())):
            return False
        free = self._same_in_index(members)
        if free is not None:
            over = f", free {', '.join(free)} each of 1, 2, 3" if free else ""
            self._add(line, piece, "identity", "holds", "an identity in index notation whatever its components stand "
                      f"for (each index written twice in a term summed over 1, 2, 3{over})")
            return True
        links = [k for k in range(len(members) - 1) if self._same_in_index(members[k:k + 2]) is not None]
        if len(members) < 3 or not links or not self._own_head(members):
            return False
        self._links_held(line, piece, members, links, "identities in index notation whatever the components stand "
                         "for (each index written twice in a term summed over 1, 2, 3)")
        return True

    def _links_whatever(self, line, piece, members, rels) -> bool:
        """A chain of three or more members in names the text has not tied, not the same throughout,
        whose head is in the text's own names and whose last links are identities whatever the names
        stand for: those links hold, said so; the links before them (a law, a definition the text
        states in words) are left unchecked. False otherwise."""
        if len(members) < 3 or not set(rels) <= {"=", "≡"}:
            return False
        links = [k for k in range(len(members) - 1) if self._identity_whatever(members[k:k + 2])]
        if not links or links != list(range(links[0], len(members) - 1)) or not self._own_head(members):
            return False            # an identity before a link it does not pass may lead into a slip
        loose = sorted({self.tex(x) for k in links for m in members[k:k + 2]
                        for x in getattr(self._resolve(m), "free_symbols", ()) if isinstance(x, lx.Generic)})
        self._links_held(line, piece, members, links, f"identities whatever {', '.join(loose)} stand for (expand)"
                         if loose else "identities (expand)")
        return True

    def _own_head(self, members) -> bool:
        """Whether a chain's head is in names of the text's own: a quantity the derivation knows (the
        energy E) restated in another theory's names (ħ) is not the text's algebra to pass link by link."""
        return any(isinstance(x, lx.Generic) for x in getattr(self._resolve(members[0]), "free_symbols", ()))

    def _links_held(self, line, piece, members, links, how) -> None:
        """The claims of a chain some of whose links (``k``: member k+1 = member k+2) hold ``how``."""
        said = lambda ks: " and ".join(f"{k + 1} = {k + 2}" for k in ks)  # noqa: E731
        left = [k for k in range(len(members) - 1) if k not in links]
        self._add(line, piece, "identity", "holds", f"the chain's links {said(links)} (its members counted from its "
                  f"left side) are {how}")
        self._add(line, piece, "unknown", "unchecked", f"the chain's links {said(left)} are not read as identities "
                  "whatever its names stand for: the text's words (a law, an approximation, a definition) may "
                  "relate them")

    def _same_in_index(self, members) -> list | None:
        """The free indices (sorted) of members that are the same at every value of them; None when
        they are not, or are not all index notation with like free indices."""
        frees = [None if m == 0 else free_indices(m) for m in members]
        if any(f is None and m != 0 for f, m in zip(frees, members)) or len({f for f in frees if f is not None}) != 1:
            return None
        free = sorted(next(f for f in frees if f is not None))
        for digits in itertools.product(_DIGITS, repeat=len(free)):
            env = dict(zip(free, digits))
            written = [components(m, env) for m in members]
            if any(w is None for w in written):
                return None
            first, *others = [self._resolve(w) for w in written]
            if any(isinstance(v, sp.MatrixBase) for v in (first, *others)) or \
                    any(differs_somewhere(o, first, "whatever") or expanded(o - first) != 0 for o in others):
                return None
        return free

    def _identity_whatever(self, members) -> bool:
        """Every member the same expression whatever the text's undefined names stand for."""
        try:
            first = self._calculus(self._resolve(members[0]))
            others = (self._calculus(self._resolve(m)) for m in members[1:])
            return not applied_names_multiplied(getattr(self, "_text", "")) and all(
                not surely_nonzero(d) and not differs_somewhere(o, first, "whatever") and expanded(d) == 0
                for o, d in ((o, o - first) for o in others))
        except TypeError:           # a matrix of the text's beside names it has not defined
            return False
