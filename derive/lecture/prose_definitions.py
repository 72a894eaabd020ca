"""A symbol a text names in running prose, value first: "the rates are named $\\dot\\phi = \\omega_\\phi$".

A definition written symbol first in a sentence ("where $\\Omega = (I_3 - I_1)\\omega_3/I_1$", "with
$u \\equiv \\cos\\theta$") is recorded by the rest of the reader already. Written value first, the
same sentence is a setting (a case: the rate set to ω_φ), which ends with its section; the name is
what carries it into the sections after. The rule rests on the math's shape and its
place, not on the words around it (it reads a Chinese or Spanish sentence as an English one):

* the math is inline and shares its line with words (running prose; a formula alone on its line
  or as a list item of its own is read as a display), and no trigger word made it an assumption;
* it is one relation, a plain ``=``, and nothing else (``\\equiv`` and ``:=`` define their left side);
* its right side is a single symbol (with its sub/superscripts, primes and accents) met nowhere in
  the text's math before, not a quantity the reader knows and not one the front matter names;
* its left side is written only in symbols the text has already used or the reader knows, and
  is not an angle itself (``\\theta = \\theta_0`` holds an angle at a value: a case, not a name).

Such a name is a setting in its section, as before, and from the heading that closes that
section on it is the definition ``X \\equiv value``, recorded as a display's definition is; it is
never judged, and a later display that rests on it and does not hold is left unchecked by the
reader (the slip may be in the sentence). An equation between symbols the text already has binds
nothing, and what is not rendered (code spans, HTML comments) never reaches this reader.
"""
from __future__ import annotations

import re

from derive.lecture import latex as lx
from derive.lecture.latex_spellings import DEFINES
from derive.lecture.source import MATH
from derive.lecture.statements import top_level
from derive.symbolic.rotations import ANGLES

_DEFINES = re.compile(DEFINES + r"|(?<![<>!:\\])=")
_OTHER_RELATION = re.compile(r"\\(?:approx|simeq|sim|neq|ne|geq?|leq?|geqslant|leqslant|ll|gg|propto|to|rightarrow|"
                             r"Rightarrow|implies|iff|Leftrightarrow)(?![A-Za-z])|(?<!\\)[<>]")
_WORD = re.compile(r"[^\W\d_]{2,}")


def _key(atom) -> lx.Atom:
    return atom.with_(text="")


def _atoms(latex: str) -> list | None:
    """The symbols of ``latex``, each as (symbol without its spelling, its spelling), or None if it
    cannot be scanned."""
    try:
        return [(_key(t.value), t.value.text) for t in lx.scan(latex) if t.kind == "atom"]
    except (lx.NotRead, ValueError, IndexError, KeyError, TypeError):
        return None


class ProseDefinitions:
    """The definitions in running prose of one text, read in order (see the module docstring).

    Parameters
    ----------
    body : str
        The rendered text (code and comments blanked).
    angles : tuple of str
        The text's angle names, which the reader knows.
    declared : iterable of str
        The symbols the front matter names (bound by the user, never by the prose).
    """

    def __init__(self, body: str, angles: tuple, declared=()):
        self.body = body
        self.vocab = lx.Vocabulary(angles=tuple(angles))
        self.met: set = set()
        self.scanned_to = 0
        for name in declared:
            self.met.update(k for k, _ in _atoms(str(name)) or ())

    def _meet_until(self, pos: int) -> None:
        """Record the symbols of every math before ``pos`` not yet recorded."""
        for m in MATH.finditer(self.body, self.scanned_to, pos):
            if m.end() > pos:
                break
            raw = next((m.group(g) for g in ("d", "b", "eb", "i") if m.group(g) is not None), "")
            self.met.update(k for k, _ in _atoms(raw) or ())
            self.scanned_to = m.end()

    def definition(self, pos: int, latex: str, line_text: str) -> str | None:
        """``X \\equiv value`` when the inline math at ``pos`` (normalized ``latex``, on the line
        ``line_text``) defines one new symbol X in running prose, else None. Every math before
        ``pos`` counts as met."""
        self._meet_until(pos)
        if not _WORD.search(MATH.sub(" ", line_text)) or _OTHER_RELATION.search(latex):
            return None
        rel = top_level(latex, _DEFINES)
        if len(rel) != 1 or len(_DEFINES.findall(latex)) != 1 or rel[0].group(0) != "=":
            return None
        value, name = latex[:rel[0].start()].strip(), latex[rel[0].end():].strip().rstrip(".,;").strip()
        try:
            toks = lx.scan(name) if value and name else []
        except (lx.NotRead, ValueError, IndexError, KeyError, TypeError):
            return None
        if len(toks) != 1 or toks[0].kind != "atom":
            return None
        key = _key(toks[0].value)
        if key in self.met or _reads(name, self.vocab):
            return None
        others = _atoms(value)
        if _angle(value, self.vocab):
            return None         # "$\\theta = \\theta_0$": an angle held at a value is a case, never a name
        if not others or key in {o for o, _ in others} or \
                not all(o in self.met or _reads(text, self.vocab) for o, text in others):
            return None
        return f"{name} \\equiv {value}"


def carried(names: list, headings: list) -> list:
    """Where each name given in prose starts to hold as a definition: at the heading that ends the
    section it was set in (a heading of its section's level or above), as ``(position, item)``.

    ``names``: ``(position, item)`` in text order; ``headings``: ``(position, level)`` in order.
    Before the first heading, any heading closes the text's opening section."""
    out = []
    for pos, item in names:
        before = [level for at, level in headings if at < pos] or [99]
        end = next((at for at, level in headings if at > pos and level <= before[-1]), None)
        if end is not None:
            out.append((end, item))
    return out


def _angle(value: str, vocab) -> bool:
    """Is ``value`` one of the angles themselves (not a rate)?"""
    try:
        parsed = lx.parse(value, vocab)
    except (lx.NotRead, ValueError, IndexError, KeyError, TypeError):
        return False
    return len(parsed.members) == 1 and parsed.members[0].value in ANGLES


def _reads(name: str, vocab) -> bool:
    """Does the reader know ``name`` without the text (an angle, a rate, a quantity of the lecture)?"""
    try:
        lx.parse(name, vocab)
    except lx.NotRead:
        return False
    except (ValueError, IndexError, KeyError, TypeError):
        return True         # not a plain unknown symbol: never a new name
    return True
