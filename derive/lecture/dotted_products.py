"""A dot over more than one symbol, ``\\dot{\\vartheta\\cos\\varphi}``: the time derivative of what
it covers.

Takes: a formula's text at a ``\\dot`` or ``\\ddot`` and the scanner's parts (`derive.lecture.vocabulary`
passes its own, so this module imports none of derive's). Gives: `rate_of_product`, the tokens of
``(\\frac{d}{dt}(…))`` (``d^2/dt^2`` for ``\\ddot``), which the parser reads as the rate of the
covered product, so a text that dots a product where it meant one factor's rate is judged as it
wrote it. A dot over one symbol, however decorated, is left to the scanner. May import: the
standard library.
"""
from __future__ import annotations

import re

_COVERED = ("atom", "num", "op", "cmd")
_SEPARATORS = (",", "|", "\\\\")


def rate_of_product(s: str, i: int, after: int, name: str, reader):
    """The tokens of the rate of what a dot covers, and the index after it.

    Parameters
    ----------
    s : str
        The formula.
    i : int
        Where ``\\dot`` (or ``\\ddot``, ``name``) starts.
    after : int
        The index after the command's name.
    name : str
        ``"dot"`` or ``"ddot"``.
    reader : tuple
        The scanner's ``(group, atom_at, scan, Tok, NotRead)``.

    Returns
    -------
    tuple of (list, int), or None
        None where the dot covers one symbol, no braced group, or what the scanner cannot read.
    """
    group, atom_at, scan, tok, not_read = reader
    if not re.match(r"\s*\{", s[after:]):
        return None
    inner, j = group(s, after + len(s[after:]) - len(s[after:].lstrip()))
    body = inner.strip()
    try:
        if not body or atom_at(body, 0)[1] >= len(body):
            return None
        covered = scan(body)
    except not_read:
        return None
    if any(t.kind not in _COVERED or t.kind == "op" and t.value in _SEPARATORS for t in covered):
        return None
    start = s.index(body, after)
    order = "" if name == "dot" else "^2"
    head = [tok(t.kind, t.value, i) for t in scan(rf"(\frac{{d{order}}}{{dt{order}}}(")]
    return head + [tok(t.kind, t.value, t.pos + start) for t in covered] + [tok("op", ")", j - 1)] * 2, j
