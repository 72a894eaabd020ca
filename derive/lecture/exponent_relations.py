"""An equals sign typed inside a bracket of an exponential's exponent.

Takes: a statement of a display. Gives: the mixin `ExponentRelations`, which calls the statement `fails` where
the exponent of e (``e^{…}``, ``\\mathrm{e}^{…}``) holds a round bracket with an equals sign between two
terms, ``e^{-i(\\alpha = \\gamma)/2}``: an exponent is a value, so a relation cannot stand inside it, and the
statement is no formula as written (the sign meant, − or + beside = on the keyboard, cannot be told, so no
correction is given).

Left alone: an equals sign in a subscript or a sum's limits (``e^{\\sum_{k=1}^n a_k}``), one at the top of
the exponent outside any bracket, a bracket after a function or a derivative of its own, a power of anything
but e, and a statement another reader already flagged. May import: nothing of derive's.
"""
from __future__ import annotations

import re

_BASE = re.compile(r"(?<![\\A-Za-z])(?:\\mathrm\s*\{\s*e\s*\}|e)\s*\^\s*\{")


def _group(s: str, k: int, open_: str, close: str) -> int | None:
    """The index of the bracket closing the one at ``s[k]``, or None."""
    depth = 0
    for j in range(k, len(s)):
        if s[j] == open_ and s[j - 1] != "\\":
            depth += 1
        elif s[j] == close and s[j - 1] != "\\":
            depth -= 1
            if depth == 0:
                return j
    return None


def _relation(inner: str) -> bool:
    """Whether ``inner`` (a bracket's content) has a bare = between two terms, outside its own groups and scripts."""
    depth = 0
    for j, ch in enumerate(inner):
        if ch in "({[" and inner[j - 1:j] != "\\":
            depth += 1
        elif ch in ")}]" and inner[j - 1:j] != "\\":
            depth -= 1
        elif ch == "=" and depth == 0 and inner[j - 1:j] not in ("<", ">", "!", ":", "=") and inner[j + 1:j + 2] != "=":
            return bool(inner[:j].strip()) and bool(inner[j + 1:].strip())
    return False


def relations(piece: str) -> list[str]:
    """The brackets, as written, of exponents of e in ``piece`` that hold an equals sign between two terms."""
    out = []
    for m in _BASE.finditer(piece):
        end = _group(piece, m.end() - 1, "{", "}")
        if end is None:
            continue
        body = piece[m.end():end]
        for b in re.finditer(r"\(", body):
            if re.search(r"(?:[_^]\s*|\\[A-Za-z]+\s*|[A-Za-z]\s*)$", body[:b.start()]) and \
                    not re.search(r"(?<![\\A-Za-z])i\s*$|\\sqrt\s*\{-1\}\s*$", body[:b.start()]):
                continue                # f(t = 0), \omega(t=0), x_(…): a function's argument, not a factor
            close = _group(body, b.start(), "(", ")")
            if close is not None and _relation(body[b.start() + 1:close]):
                out.append(body[b.start():close + 1])
    return out


class ExponentRelations:
    """Mixin of the checker: uses ``self._add`` and ``self.claims``."""

    def _exponent_relation(self, line, piece, before) -> None:
        """Fails where an exponent of e holds a bracket with an equals sign in it."""
        if any(c.verdict in ("typo", "fails") for c in self.claims[before:]):
            return
        found = relations(piece)
        if not found:
            return
        if all(c.verdict == "unchecked" for c in self.claims[before:]):
            del self.claims[before:]
        self._add(line, piece, "symbol", "fails",
                  f"writes an equals sign inside the exponent of e, {found[0]}: an exponent is a value, so no "
                  "relation can stand there (a sign, − or +, mistyped); it is no formula as written")
