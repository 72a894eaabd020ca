"""The links of an aligned chain: a row ``= C`` after ``= B`` is also the claim B = C.

Gives the mixin `ChainLinks` of `derive.lecture.notes_check.Checker`: `_linked`, which reads a row
that goes on with ``=`` against the member just before it when the row could not be compared with
the chain's left side. May import: the standard library, SymPy, :mod:`derive.lecture.latex`,
:mod:`derive.lecture.statements`, :mod:`derive.lecture.headless_chains`.

A text writes ``R_{XYZ} = R_Z R_Y R_X`` (a name it gives, and a product of names it has not tied
to anything), then ``= [the three matrices written out]``, then ``= [their product]``. Each row
after the first is compared with the left side R_{XYZ}; when the reader cannot compare them (the
left side is the text's new name, its shape unknown), the chain still states that each member
equals the next, and that link — the written-out product against the product of the matrices
written before it — can be checked. The row's verdict is then that link's, said so. A link between
vectors is kept only when it holds: it may rest on the text's set-up said in words (𝐫ᵢ ⊥ 𝛚). A row
whose left side is only a vector the text names (𝐌_{O,i} = 𝐫ᵢ × 𝐅ᵢ = det[…] then ``= mᵢ[…]``) is
read as that link as well, whatever kept it from being read against its left side. A link in names
the text has not tied (the reader cannot say what they stand for) is still a slip where its two
members differ by a number, every component by the same (``\\frac{1}{12}Mb^2\\omega\\frac{1}{\\sqrt{2}}
(-11, 11, 0)`` then ``= \\frac{11}{12}Mb^2\\omega (-1, 1, 0)``, off by √2): no value of those names
makes them equal, short of making both zero. A row the reader took as setting the chain's left side
to its member (``I_{11} = … = \\frac{1}{2}\\frac{M}{abc}[ab^3c + abc^3]`` then ``= \\frac{1}{12}M(b^2 + c^2)``,
each row "a case" of I₁₁) is such a link too: the chain states each member equals the next.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import headless_chains
from derive.lecture import latex as lx
from derive.lecture.statements import top_level

_EQUALS = re.compile(r"(?<![<>!\\])=")
_UNCOMPARED = ("cannot compare its sides", "which the text has not defined", "which the text has not tied",
               "a case or an assumption of the text")

_VECTOR = re.compile(r"\\(?:vec|boldsymbol|bm)\b|\\mathbf\s*\{?\s*[a-z]|\\times|\\hat")

WHY = "the link to the member before it (the chain's left side cannot be compared): "


class ChainLinks:
    """Mixin of the checker. Uses ``self.ctx``, ``self.claims`` and ``_read_once_or_twice``."""

    def _linked(self, line, piece, before, previous, dup, pieces) -> None:
        """Re-read a continuation row against the previous member when its own claims are all
        uncompared, or only set the chain's left side to the row (see the module docstring);
        ``previous`` is the row before it."""
        if previous is None or not re.match(r"\s*=", piece):
            return
        mine = self.claims[before:]
        if not mine or any(c.verdict != "unchecked" for c in mine):
            return
        if not all(any(u in c.why for u in _UNCOMPARED) for c in mine) and not headless_chains.own_head(self.ctx.head or ""):
            return              # a row it could not read, unless its left side is only the text's own name
        member = last_member(previous)
        if member is None or not member.strip():
            return
        head, kept = self.ctx.head, self.claims[before:]
        del self.claims[before:]
        self.ctx.head = member
        try:
            self._read_once_or_twice(line, piece, dup, pieces)
        except Exception:  # noqa: BLE001 - the link is a second reading: when it fails, the first stands
            del self.claims[before:]
        finally:
            self.ctx.head = head
        linked = self.claims[before:]
        factor = None if any(c.verdict != "unchecked" for c in linked) or _VECTOR.search(member + piece) \
            else self._constant_factor(member, piece)
        if factor is not None:          # a link that is off by a number whatever the untied names stand for
            c, names = factor
            self.claims[before:] = [type(kept[0])(line, piece, "identity", "fails", None, WHY + (
                f"it is {sp.latex(c)} times the member before it, whatever {', '.join(names)} stand for"))]
            return
        flagged = any(c.verdict in ("typo", "fails") for c in linked)
        if not any(c.verdict in ("holds", "typo", "fails") for c in linked) or (flagged and _VECTOR.search(member + piece)):
            # a link between vectors may rest on the text's set-up (r ⊥ 𝛚, a fixed axis) said in
            # words: it is kept when it holds, never to flag
            self.claims[before:] = kept
            return
        for c in linked:
            c.why = WHY + c.why


    def _constant_factor(self, member, piece):
        """(c, the names) where the row's first member is the member before it times a number c ≠ 1
        (none of the text's names in it), every component alike, both in the same names; else None."""
        try:
            parsed = lx.parse(member + " " + piece, self.vocab)
        except (lx.NotRead, ArithmeticError, TypeError, ValueError):
            return None
        if len(parsed.members) < 2 or parsed.relations[0] != "=":
            return None
        a, b = (sp.Matrix(m.value) if isinstance(m.value, sp.MatrixBase) else sp.Matrix([m.value])
                for m in parsed.members[:2])
        a, b = a.applyfunc(_cancelled), b.applyfunc(_cancelled)
        names = a.free_symbols
        if a.shape != b.shape or not names or names != b.free_symbols or any(x.has(sp.Integral, sp.Derivative) for x in (*a, *b)):
            return None
        ratios = set()
        for x, y in zip(a, b):
            if (x == 0) != (y == 0):
                return None
            if x != 0:
                ratios.add(sp.nsimplify(sp.simplify(y / x)))
        c = ratios.pop() if len(ratios) == 1 else None
        if c is None or not c.is_number or c == 1 or not c.is_real:
            return None
        return c, sorted(self.tex(x) for x in names)


def _cancelled(x):
    """``x`` with common factors cancelled, so a name that cancels (a in M a b³ c / (a b c)) is in
    neither member; as it is where SymPy cannot cancel it."""
    try:
        return sp.cancel(x)
    except (sp.PolynomialError, TypeError, ValueError):
        return x


def last_member(row: str) -> str | None:
    """The member after a row's last top-level ``=``, or None."""
    eqs = top_level(row, _EQUALS)
    return row[eqs[-1].end():].strip() if eqs else None
