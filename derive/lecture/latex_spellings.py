"""What LaTeX spells several ways and every reader reads as one thing: one home for the bold face
and for the sign of a definition.

Takes and gives nothing at run time: the command names (for the scanners that walk a formula token
by token, and for `derive.lecture.source`'s normaliser) and regular-expression fragments built from
them (to be joined into a reader's own patterns). A bold letter is the same symbol whichever command
sets it: ``\\mathbf{C}``, ``\\boldsymbol{C}``, ``\\bm{C}`` (the bm package), ``\\pmb{C}``, ``\\vb{C}``
(physics), ``\\bold{C}``, ``\\mathbfit{C}`` (unicode-math). A definition is one sign whichever way it
is written: ``\\equiv``, ``\\coloneqq`` (mathtools), ``\\triangleq``, ``\\eqdef``, ``\\defeq`` or
``:=`` typed as two characters. A reader that matches a shape in a formula before the normaliser has
rewritten it (the rendered text, a display read whole) joins these fragments; after it, the rarer
bold spellings are ``\\boldsymbol`` and every definition sign is ``\\equiv``.

May import: nothing.
"""
from __future__ import annotations

BOLD_NAMES = ("mathbf", "boldsymbol", "bm")
"""The bold commands a normalised formula keeps as written."""

REWRITTEN_BOLD_NAMES = frozenset({"pmb", "vb", "bold", "mathbfit"})
"""The rarer bold commands, written ``\\boldsymbol`` by the normaliser before any reader sees a formula."""

BOLD = r"\\(?:" + "|".join(BOLD_NAMES + tuple(sorted(REWRITTEN_BOLD_NAMES))) + r")(?![A-Za-z])"
"""A command that sets a letter bold (any of `BOLD_NAMES` or `REWRITTEN_BOLD_NAMES`), without its argument."""

DEFINITION_NAMES = frozenset({"coloneqq", "triangleq", "eqdef", "defeq"})
"""The commands of a definition sign other than ``\\equiv``, written ``\\equiv`` by the normaliser."""

DEFINES = r"(?:\\(?:equiv|" + "|".join(sorted(DEFINITION_NAMES)) + r")(?![A-Za-z])|(?<![:=\\]):\s*=(?![:=]))"
"""A definition sign: ``\\equiv``, one of `DEFINITION_NAMES`, or ``:=`` typed as two characters."""
