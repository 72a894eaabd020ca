"""A chain's members the reader cannot read: checked without them, never as if they were not there.

Takes: a chain ``a = b = c`` parsed with an open vocabulary, some of whose members are written in
names the text has not defined (or cannot combine yet). Gives: the mixin `UnreadMembers` of
`derive.lecture.notes_check.Checker`: `_loose_ends_dropped`, the chain without those members,
`_statement_read`, a statement read with its verdicts marked for the members left out, and
`_identity_then_named`, a chain in untied names whose last member names it with a name of its own,
and `_new_names_set_alike`, a chain of new names ending in a value, each of them defined as it.
May import: :mod:`derive.lecture.comparing`, :mod:`derive.lecture.latex`, SymPy.

A chain states that each member equals the next. With a member left out, the links through it are
not checked: the members on either side of it are not a link the text writes. Each verdict of such
a chain names the members not read. Where no two members left are neighbours in the chain, no link
of it was read: agreement of the members around a gap does not check the chain (``I_1\\dot\\omega_1
= \\zeta_1 = (I_2 - I_3)\\omega_2\\omega_3`` with ζ₁ undefined), and ``holds`` becomes ``unchecked``
naming them; disagreement still shows the chain wrong (it implies every member equals the others).
A new plain name heading a chain at a vector's length (``H = |\\mathbf{H}| = \\sqrt{…}``) names that
length once a link of the chain is judged, as a new name ending a chain at a constant names its head.
"""
from __future__ import annotations

import re

from sympy import Symbol

from derive.lecture import latex as lx
from derive.lecture.comparing import free

_APPLIED = (r"(?<![\\A-Za-z])[A-Za-z](?:_\s*(?:\{[^{}]*\}|[A-Za-z0-9]))?\s*(?:\\left\s*)?"
            r"\((?:[^()]|\([^()]*\))*\)")
_APPLIED_PRODUCT = re.compile(rf"{_APPLIED}\s*(?:\\[,;:!]|\\cdot|\s)*{_APPLIED}")


def applied_names_multiplied(text: str) -> bool:
    """Does ``text`` multiply two names written with arguments (``R(\\hat z, \\alpha) R(\\hat y, \\beta)``,
    ``R_z(\\alpha) R_y(\\beta)``)? Such names are turns and operators as often as numbers, and
    their products need not commute: an identity of them read as numbers is no identity."""
    return bool(_APPLIED_PRODUCT.search(text))


_LENGTH = re.compile(r"(?:\\left\s*)?(?:\||\\l?[vV]ert|\\\|)[^=|]*(?:\||\\r?[vV]ert|\\\|)\s*$")
"""A member written as a vector's length, ``|\\mathbf{H}|``, ``\\lVert …``, ``\\|…\\|``."""
_RELATION_END = re.compile(r"\s*(?:&\s*)?(?:=|\\equiv|\\approx)\s*(?:&\s*)?(?:\\left\s*)?$")


class UnreadMembers:
    """Mixin of the checker. Uses ``self.claims``, ``self._statement``, ``self._constants``,
    ``self._new_name``, ``self._resolve``, ``self._members_kept``, ``self.vocab``, ``self._text``,
    ``self.ctx``, ``self._mark_defined``, ``self._add`` and ``self.tex``."""

    unread: tuple | None = None
    """(the members kept, the written form of each member left out) of the statement being read."""
    chain_names: tuple = ()
    """(a lone new symbol ending the chain, the chain's first member): the text naming that quantity."""

    def _loose_ends_dropped(self, parsed):
        """A chain ``a = b = G(u)`` whose end is a lone symbol the text has not defined yet (it
        names the expression, as G(u) is defined on the next line), or with a member written in
        names the text has not defined: checked without it (the members left out recorded)."""
        members = [m.value for m in parsed.members]
        if len(members) < 3 or not set(parsed.relations) <= {"=", "≡"}:
            return parsed
        known = self._constants()

        def unread(m):      # a member in names the text has not defined (or cannot combine yet)
            try:
                return any(self._new_name(x) and x not in known for x in free(self._resolve(m)))
            except (TypeError, ValueError, AttributeError):
                return True

        loose = [k for k, m in enumerate(members) if self._new_name(m) or k and unread(m)]
        if not loose and unread(members[0]) and not self._new_name(members[0]) and not unread(members[1]):
            loose = [0]     # tan β = tan(α − θ) = …, β named only in words: the steps after it are claims

        def matrices_unread(m):     # in bold names the text has not defined yet (its matrices, given further on)
            names = {x for x in free(self._resolve(m)) if self._new_name(x) and x not in known}
            return bool(names) and all(getattr(self.vocab.generic.get(x), "bold", False) for x in names)

        if loose and any(k and matrices_unread(members[k]) for k in loose) and self._read_in_vectors():
            return None         # ½ 𝛚·𝐈·𝛚 beside scalars: a member in the text's bold names is the vector reader's
        if loose and loose[0] == 0 and len(loose) > 1 and self._new_name(members[0]) and \
                len(members) - len(loose) >= 1 and all(matrices_unread(members[k]) for k in loose[1:]):
            loose = loose[1:]   # X = (matrices given further on) = (names it has): X is the member it can read
        if not loose or len(members) - len(loose) < 2 or 0 in loose and loose != [0]:
            return parsed
        kept = [k for k in range(len(members)) if k not in loose]
        self.unread = (kept, [self._written_member(parsed, k) for k in loose])
        # ``p_φ = ∂L/∂φ̇ = … = S_z = const``: a lone new symbol before "= constant" names the first member
        ends = {k: self._written_member(parsed, k) for k in loose if k >= len(members) - 2}
        tail = [k for k, w in ends.items() if "(" not in w and "const" in (w if k == len(members) - 1 else
                                                                          str(members[-1]))]
        self.chain_names = [(members[k], members[0]) for k in tail if isinstance(members[k], Symbol)
                            and self._new_name(members[k]) and loose == tail]
        if loose == [0] and isinstance(members[0], Symbol) and self._new_name(members[0]) and \
                _LENGTH.match(self._written_member(parsed, 1).rstrip(".,;")):
            self.chain_names = [(members[0], members[1])]   # ``H = |𝐇| = √(…)``: a new head names the length
        return self._members_kept(parsed, kept)

    def _identity_then_named(self, line, piece, members, loose) -> bool:
        """``R = (R − S) + S = d + S`` in names the text has not tied: its last member brings in a name
        of its own (d, which the text goes on to define) and names the chain, the links before it an
        identity whatever the names stand for; True when such a chain was recorded so."""
        if len(members) < 3:
            return False
        toks = lx.scan(getattr(self, "_text", ""))
        last = max((k for k, t in enumerate(toks) if t.kind == "rel"), default=0)
        written = {t.value.base + (f"_{t.value.sub}" if t.value.sub else "") for t in toks[:last] if t.kind == "atom"}
        own = {x for x in free(self._resolve(members[-1])) & loose if str(x) not in written}   # not written before it
        if len(own) != 1 or not self._identity_whatever(members[:-1]):
            return False
        names = ", ".join(sorted(self.tex(x) for x in loose - own))
        self._add(line, piece, "identity", "holds", f"an identity whatever {names} stand for (expand); the last "
                  f"member names the chain with {self.tex(next(iter(own)))}, the text's own (a definition)")
        self.settings_only = False
        return True

    def _read_in_vectors(self) -> bool:
        """The statement being read, read whole by the vector reader (`_vectors`); False when it cannot."""
        at = getattr(self, "_reading_at", None)
        return at is not None and self._vectors(at[0], at[1], getattr(self, "_text", at[1]))

    def _written_member(self, parsed, k) -> str:
        """The member ``k`` of a chain as the text writes it (from its position in the statement)."""
        text = getattr(self, "_text", "")
        start = parsed.members[k].pos
        end = parsed.members[k + 1].pos if k + 1 < len(parsed.members) else len(text)
        written = _RELATION_END.sub("", text[start:end]).strip() if isinstance(start, int) and \
            isinstance(end, int) and 0 <= start < end <= len(text) else ""
        short = written and "\n" not in written and len(written) <= 80 and written.count("{") == written.count("}")
        return written if short else f"member {k + 1} of the chain"

    def _statement_read(self, line, piece, dup, pieces):
        """`_statement`, its verdicts then marked for the chain's members it could not read."""
        outer, self.unread, self.chain_names = self.unread, None, []
        outer_at, self._reading_at = getattr(self, "_reading_at", None), (line, piece)
        start = len(self.claims)
        try:
            self._statement(line, piece, duplicate=dup, pieces=pieces)
            if self.unread is not None:
                self._unread_marked(start, *self.unread, line, piece)
            read = any(c.verdict in ("holds", "typo", "fails") for c in self.claims[start:])
            for name, first in self.chain_names if read else ():
                self.ctx.defs.setdefault(name, first)     # the text's name for the quantity, from here on
        finally:
            self.unread, self.chain_names, self._reading_at = outer, [], outer_at

    def _unread_marked(self, start, kept, written, line, piece):
        names = ", ".join(written)
        linked = any(b - a == 1 for a, b in zip(kept, kept[1:]))
        for c in self.claims[start:]:
            if c.verdict == "holds" and not linked:
                c.verdict, c.correction = "unchecked", None
                c.why = (f"{names} not read, and every link of the chain passes through it: "
                         f"the members around it agree ({c.why}), which does not check the links")
                if not getattr(self, "_rereading_later", False):     # its names may be defined further on
                    self.deferred.append((c, line, piece, self._snapshot()))
            elif c.verdict in ("holds", "typo", "fails"):
                c.why += f" (checked without {names}, not read: its links are unchecked)"

    def _new_names_set_alike(self, line, piece, members, rels) -> bool:
        """``a_1 = a_2 = a_3 = b/2``: a chain of names the text has not defined, ending in a value in
        other names, defines each of them as that value (as ``a_1 = b/2`` defines one)."""
        names, value = members[:-1], members[-1]
        if len(members) < 3 or set(rels) - {"=", "≡"} or len(set(names)) < len(names) \
                or not all(self._new_name(m) for m in names) or free(value) & set(names):
            return False
        for m in names:
            self.ctx.defs[m] = value
            self._mark_defined(m)
        self.settings_only = False
        self._add(line, piece, "new symbol", "unchecked", f"defines the text's symbols "
                  f"{', '.join(self.tex(m) for m in names)} as {self.tex(value)} (recorded, then used)")
        return True

