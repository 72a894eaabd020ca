"""A display quantified over an index: ``\\forall i \\in \\mathbb{Z}_3: I_i\\dot\\Omega_i = \\Omega_{i+1}(I_{i+1} - I_{i-1})\\Omega_{i-1}``.

A text that writes Euler's equations (or any statement about the body axes) once for all three
axes opens it with a quantifier over the index: ``\\forall i \\in \\mathbb{Z}_3`` (the index taken
modulo three, so that ``i+1`` and ``i-1`` run cyclically: 2 and 3 for i = 1, 3 and 1 for i = 2, 1
and 2 for i = 3) or ``\\forall i \\in \\{1, 2, 3\\}``. The display states its three instances, each
index put in its subscripts (``_i``, ``_{i}``, ``_{i+1}``, ``_{i-1}``). Left as written when the
index stands anywhere but in a subscript (a coefficient, a sum's bound), or when the set is
``\\{1, 2, 3\\}`` and a subscript shifts it (i+1 = 4 is no axis there). Takes and gives LaTeX
normalised by `derive.lecture.source` (``\\mathbb`` written ``\\mathrm``), spaced by any of
`derive.lecture.latex_spaces`'s spaces; imports nothing of derive but that module.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spaces import ONE_SPACING, SPACE

_QUANTIFIER = re.compile(r"^\s*\\forall" + SPACE + r"(?P<i>[ijk])" + SPACE + r"\\in" + SPACE +
                         r"(?P<set>\\mathrm\s*\{\s*Z\s*\}\s*_\s*\{?\s*3\s*\}?|\\\{\s*1\s*,\s*2\s*,\s*3\s*\\\})"
                         + SPACE + r":(?:&|" + ONE_SPACING + r"|\\\\)*")


def instances(body: str) -> list[str]:
    """The statements ``body`` makes for each value of its quantified index.

    Parameters
    ----------
    body : str
        One display's LaTeX, its environments stripped.

    Returns
    -------
    list of str
        The three instances (i = 1, 2, 3), the quantifier dropped; ``[body]`` where no quantifier
        opens it or it cannot be put so.
    """
    m = _QUANTIFIER.match(body)
    if not m:
        return [body]
    rest, i, cyclic = body[m.end():], m.group("i"), "Z" in m.group("set")
    shifted = re.compile(r"_\s*\{\s*" + i + r"\s*([+-])\s*1\s*\}")
    if shifted.search(rest) and not cyclic:
        return [body]
    plain = re.compile(r"_\s*(?:\{\s*" + i + r"\s*\}|" + i + r"(?![A-Za-z]))")
    out = []
    for v in (1, 2, 3):
        one = shifted.sub(lambda s: "_{" + str((v + (1 if s.group(1) == "+" else -1) - 1) % 3 + 1) + "}", rest)
        one = plain.sub("_{" + str(v) + "}", one)
        if re.search(r"(?<![A-Za-z\\])" + i + r"(?![A-Za-z])", one):
            return [body]                 # the index outside a subscript: not a statement per axis
        out.append(one)
    return out
