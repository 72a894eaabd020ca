"""What LaTeX spells several ways and every reader reads as one thing: one home for the bold face,
the sign of a definition, a prime and a bracket sized around one token.

Takes and gives nothing at run time: the command names (for the scanners that walk a formula token
by token, and for `derive.lecture.source`'s normaliser) and regular-expression fragments built from
them (to be joined into a reader's own patterns). A bold letter is the same symbol whichever command
sets it: ``\\mathbf{C}``, ``\\boldsymbol{C}``, ``\\bm{C}`` (the bm package), ``\\pmb{C}``, ``\\vb{C}``
(physics), ``\\bold{C}``, ``\\mathbfit{C}`` (unicode-math). A definition is one sign whichever way it
is written: ``\\equiv``, ``\\coloneqq`` (mathtools), ``\\triangleq``, ``\\eqdef``, ``\\defeq`` or
``:=`` typed as two characters. A prime is one mark whether typed ``V'`` or set as a superscript
``V^{\\prime}``, and a round bracket sized with ``\\left``/``\\right`` around one token is the plain
bracket. A reader that matches a shape in a formula before the normaliser has rewritten it (the
rendered text, a display read whole) joins these fragments; after it, the rarer bold spellings are
``\\boldsymbol``, every definition sign is ``\\equiv``, every prime an apostrophe and every such
bracket plain. Three more shapes are spelt here for the same readers: an equation's label that a book's
toolchain writes inside the display, what may follow a sign closing a name (𝐯⁺, 𝐯_rel⁻), and a
superscript that is a word, a label and never a power (``F^{ext}``, ``g^{\text{horizontal}}``).

May import: nothing.
"""
from __future__ import annotations

BOLD_NAMES = ("mathbf", "boldsymbol", "bm")
"""The bold commands a normalised formula keeps as written."""

BOLD_MARK = r"\\(?:" + "|".join(BOLD_NAMES) + ")"
"""A bold command as a normalised formula keeps it (one of `BOLD_NAMES`), without its argument."""

VECTOR_MARK = r"\\(?:vec|" + "|".join(BOLD_NAMES) + ")"
"""A vector's mark as a normalised formula keeps it, an arrow (``\\vec``) or one of `BOLD_NAMES`."""

REWRITTEN_BOLD_NAMES = frozenset({"pmb", "vb", "bold", "mathbfit"})
"""The rarer bold commands, written ``\\boldsymbol`` by the normaliser before any reader sees a formula."""

BOLD = r"\\(?:" + "|".join(BOLD_NAMES + tuple(sorted(REWRITTEN_BOLD_NAMES))) + r")(?![A-Za-z])"
"""A command that sets a letter bold (any of `BOLD_NAMES` or `REWRITTEN_BOLD_NAMES`), without its argument."""

DEFINITION_NAMES = frozenset({"coloneqq", "triangleq", "eqdef", "defeq"})
"""The commands of a definition sign other than ``\\equiv``, written ``\\equiv`` by the normaliser."""

DEFINES = r"(?:\\(?:equiv|" + "|".join(sorted(DEFINITION_NAMES)) + r")(?![A-Za-z])|(?<![:=\\]):\s*=(?![:=]))"
"""A definition sign: ``\\equiv``, one of `DEFINITION_NAMES`, or ``:=`` typed as two characters."""

PRIME_SUPERSCRIPT = (r"(?:(?<=[A-Za-z0-9)\]'|])|(?<=[^{]\}))\s*\^\s*"
                     r"(\\prime(?![A-Za-z])|\{\s*(?:\\prime(?![A-Za-z])\s*)+\})")
"""A superscript of primes only after a symbol, ``V^{\\prime}``, ``x^\\prime``, ``y^{\\prime\\prime}`` (group 1 the
script): the primes ``V'``, ``y''`` as TeX sets them (a pre-superscript ``{}^{\\prime}`` marks no symbol)."""

SIZED_OPEN = r"(?:\\(?:left|[Bb]igg?l?)(?![A-Za-z])\s*)?"
"""What may size an opening bracket, optional: ``\\left``, or by hand ``\\bigl``, ``\\Big``, ``\\biggl`` …"""

SIZED_CLOSE = r"(?:\\(?:right|[Bb]igg?r?)(?![A-Za-z])\s*)?"
"""What may size a closing bracket, optional: ``\\right``, or by hand ``\\bigr``, ``\\Big``, ``\\biggr`` …"""

SIZED_ONE_TOKEN = r"\\left\s*\(\s*([A-Za-z0-9]+|\\[A-Za-z]+)\s*\\right\s*\)"
"""A round bracket sized with ``\\left``/``\\right`` around one letter, number or command (group 1),
``R\\left(t\\right)``: sized to one token it is the plain bracket, a function's argument as ``R(t)``."""

EQUATION_LABEL = r"\{\{\s*numeq\s*\}\}(?:\{[^{}]*\})?|\(\\#eq:[^()\s]*\)"
"""An equation's label as a book's toolchain writes it inside the display, ``{{numeq}}{eq:name}``
(mdbook-numeq) or ``(\\#eq:name)`` (bookdown): a number for the reader of the page, never algebra."""

SIGN_ENDS = (r"\s*(?:$|[-+=<>)\]}|,.;&_]|\\(?:cdot|times|right|[bB]igr?|quad|qquad|[lg]eq?|neq|approx|[,;:!\\)\]])(?![A-Za-z]))")
"""What may follow a superscript sign that closes a name (𝐯⁺ ·, v⁻ =): never a letter, a digit or a
group, which would make it the sign of an exponent written without braces (x^-1)."""

FONT_SIZES = ("tiny", "scriptsize", "footnotesize", "small", "normalsize", "large", "Large", "LARGE", "huge", "Huge")
"""LaTeX's font size switches: ``\\footnotesize{…}`` around a wide matrix only sets how big it prints."""

DIGITS = frozenset("0123456789")
"""The digits a number is written in: ASCII only, since a circled ① or a superscript ² is a digit to
``str.isdigit`` and no number."""

LABEL_WORD = r"\s*(?:\\(?:mathrm|text|rm|mathit)\s*)?\{?\s*[A-Za-z]{3,}\s*\}?\s*"
"""A superscript's group that is one word of three letters or more, upright or not: a label."""
