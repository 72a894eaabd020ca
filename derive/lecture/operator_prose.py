"""What a text's prose says its operator notation means: D, the orientation matrix, 𝒜, primes, A, B, C.

Takes: the rendered text of a notes file. Gives: `declarations`, the `Declarations` that
`derive.lecture.operator_notation` reads a statement with ("$D$ is the time derivative",
"$\\mathbf{M}$ is the orientation matrix", "$\\mathscr{A}$ turns a vector into the antisymmetric
matrix of the cross product", "primes mark principal-axis components", "$A$, $B$, $C$ are the
principal moments"). A phrase binds the inline symbol right before it, up to the next symbol.
May import: the standard library.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field


@dataclass
class Declarations:
    """What a text says its operator notation means (None or empty: it does not say)."""

    derivative: str | None = None       # the letter of d/dt
    orientation: str | None = None      # the letter of the orientation matrix
    cross: str | None = None            # the letter of 𝒜
    primes_principal: bool = False      # a prime marks principal-axis components
    labels: dict = field(default_factory=dict)   # an axis label → 0, 1, 2 (a, b, c after A, B, C)
    moments: tuple = ()                 # the letters of the principal moments

    @property
    def on(self) -> bool:
        return bool(self.derivative or self.cross) and bool(self.moments)


_INLINE = re.compile(r"(?<![\\$])\$([^$\n]+?)(?<!\\)\$")
_DISPLAY = re.compile(r"\$\$.+?\$\$|\\\[.+?\\\]|\\begin\{(equation|align|gather)\*?\}.+?\\end\{\1\*?\}", re.S)


def _letter(latex: str) -> str | None:
    """The letter of an inline formula that is one symbol (bold, script or plain), else None."""
    m = re.fullmatch(r"\s*(?:\\(?:mathbf|boldsymbol|mathrm|mathscr|mathcal|bm)\s*\{\s*([A-Za-z])\s*\}|([A-Za-z]))\s*", latex)
    return (m.group(1) or m.group(2)) if m else None


def declarations(body: str) -> Declarations:
    """Read what the prose says of D, the orientation matrix, 𝒜, primes and the principal moments."""
    prose = _DISPLAY.sub("\n\n", body)
    out = Declarations()
    for m in _INLINE.finditer(prose):
        letter = _letter(m.group(1))
        if letter is None:
            continue
        after = prose[m.end():m.end() + 80].split("$")[0]
        before = prose[max(0, m.start() - 40):m.start()]
        if re.match(r"\s*(?:is|for|denotes|stands for|,)\s+(?:the\s+)?(?:time\s+)?derivative", after):
            out.derivative = out.derivative or letter
        elif re.match(r"\s*(?:is|denotes|stands for)\s+the\s+orientation(?:\s+matrix)?", after) or \
                re.search(r"orientation matrix\s*$", before):
            out.orientation = out.orientation or letter
        elif re.search(r"antisymmetric matrix|skew[- ]symmetric matrix|cross[- ]product matrix", after):
            out.cross = out.cross or letter
    if re.search(r"primes?\s+(?:mark|denote|indicate)[^.]{0,30}(?:principal|body)", prose, flags=re.I):
        out.primes_principal = True
    listed = re.search(r"\$([A-Z])\$\s*,\s*\$([A-Z])\$\s*,?\s*(?:and\s*)?\$([A-Z])\$\s+(?:are|denote)\s+the\s+principal moments", prose) or \
        re.search(r"principal moments(?: of inertia)?\W{0,12}\$([A-Z])\$\s*,\s*\$([A-Z])\$\s*,?\s*(?:and\s*)?\$([A-Z])\$", prose)
    if listed:
        out.moments = listed.groups()
        out.labels = {x.lower(): k for k, x in enumerate(out.moments)}
        out.labels.update({str(k + 1): k for k in range(3)})
    return out
