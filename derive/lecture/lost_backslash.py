"""A symbol's command typed without its backslash in a display that writes the command itself.

Takes: a statement of a display and the display's whole LaTeX. Gives: the mixin `LostBackslash`, which
calls the statement a `typo` where it writes the letters of a symbol's command of four letters or more
(``theta``, ``infty``, ``omega``, ``hbar``) as a word of its own, without the backslash, while the same
display writes that command with it (``\\cos\\theta … + \\sin theta``, ``\\lim_{N\\to\\infty} … \\lim_{N \\to
infty}``): TeX sets those letters as a product, where the display's own spelling shows the symbol is
meant. The correction puts the backslash back. Its sibling, a sum's index typed after a symbol without its
underscore (``\\mathbf{ r}\\alpha`` where the display writes ``\\mathbf{r}_{\\alpha}``), is read here too
(`lost_underscore`): a `typo`, corrected by the subscript.

Left alone: words in a text command (``\\text{…}``, ``\\mathrm{…}``, ``\\operatorname{…}``, a label), a
word that is the whole of a subscript or superscript (``I_{theta}``, a label the text may name by a word),
a word inside a longer run of letters, names of two or three letters (``phi``, ``psi``, ``eta``: a text's
own product of letters may spell them), and every display that never writes the command. A statement
another reader already flagged keeps its verdicts. May import: derive.lecture.lost_underscore.
"""
from __future__ import annotations

import re

from derive.lecture import lost_underscore

NAMES = ("alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "theta", "vartheta", "iota",
         "kappa", "lambda", "sigma", "upsilon", "omega", "varphi", "Gamma", "Delta", "Theta", "Lambda", "Sigma",
         "Omega", "infty", "hbar", "nabla", "partial", "imath", "jmath")
"""Commands of four letters or more whose letters are never a product a text means."""
_WORD = re.compile(r"(?<![\\A-Za-z])(" + "|".join(NAMES) + r")(?![A-Za-z])")
_TEXT_COMMAND = re.compile(r"\\(?:text\w*|math(?:rm|it|sf|tt|bf|cal|frak|bb)|operatorname|mbox|hbox|label|tag|ref|eqref|"
                           r"begin|end)\s*\*?\s*\{[^{}]*\}")
_WHOLE_INDEX = re.compile(r"[_^]\s*(?:\{\s*(" + "|".join(NAMES) + r")\s*\}|(" + "|".join(NAMES) + r")(?![A-Za-z]))")


def lost(piece: str, latex: str) -> list[str]:
    """The commands ``piece`` writes without their backslash that ``latex`` (its display) writes with it."""
    text = _WHOLE_INDEX.sub(lambda m: " " * len(m.group(0)), _TEXT_COMMAND.sub(lambda m: " " * len(m.group(0)), piece))
    found = dict.fromkeys(m.group(1) for m in _WORD.finditer(text))
    return [w for w in found if re.search(r"\\" + w + r"(?![A-Za-z])", latex)]


def restored(piece: str, words: list[str]) -> str:
    """``piece`` with the backslash put back before each of ``words`` where it stands as a word of its own."""
    spans = {m.start() for m in _WORD.finditer(_WHOLE_INDEX.sub(lambda m: " " * len(m.group(0)),
             _TEXT_COMMAND.sub(lambda m: " " * len(m.group(0)), piece))) if m.group(1) in words}
    return "".join(("\\" if k in spans else "") + ch for k, ch in enumerate(piece))


class LostBackslash:
    """Mixin of the checker: uses ``self._add`` and ``self.claims``."""

    def _lost_backslash(self, line, piece, latex, before) -> None:
        """A typo where the statement writes a command's letters bare that its display writes as the command."""
        if any(c.verdict in ("typo", "fails") for c in self.claims[before:]):
            return
        words = lost(piece, latex)
        if not words:
            self._lost_underscore(line, piece, latex, before)
            return
        if all(c.verdict == "unchecked" for c in self.claims[before:]):
            del self.claims[before:]
        names = ", ".join(words)
        self._add(line, piece, "symbol", "typo",
                  f"writes the letters {names} without the backslash, which TeX sets as a product of letters, where "
                  f"the same display writes the symbol \\{words[0]}: its backslash lost", restored(piece, words))

    def _lost_underscore(self, line, piece, latex, before) -> None:
        """A typo where the statement writes a sum's index bare after a symbol its display writes indexed."""
        spans = lost_underscore.lost(piece, latex)
        if not spans:
            return
        if all(c.verdict == "unchecked" for c in self.claims[before:]):
            del self.claims[before:]
        self._add(line, piece, "symbol", "typo",
                  f"writes the sum's index \\{spans[0][1]} after a symbol without its underscore, which TeX sets as a "
                  f"factor, where the same display writes that symbol with the index as its subscript: its underscore lost",
                  lost_underscore.restored(piece, spans))
