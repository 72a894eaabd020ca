"""The imaginary unit as a factor: ``\\omega_2 + i\\omega_1``, ``\\dot{u} - \\Omega i u``.

A text that joins two components into one complex quantity writes a lone i multiplying something:
i is then √−1. The i read so stands on its own (not part of a word or a command), outside a
subscript or a superscript (``x_i``, ``\\sum_{i=1}^3``), outside a command's argument (``\\hat{i}``,
``\\mathbf i``, ``\\text{if}``), and beside a factor (a letter, a command that is no relation or
space, a bracket): ``i = 1, 2, 3`` and ``(i)`` keep their i. A formula that also writes a j or a k
so (``x i + y j + z k``, the unit vectors in plain letters), or writes a unit vector î (``\\imath``,
``\\hat{i}``, ``\\mathbf{i}``), keeps its i too: there a lone i is more likely that vector's letter.
A space of any width but a quad between i and its factor sets them apart only (``\\Omega \\, i \\, u``).
An exponent of e is read by `derive.lecture.units`. Takes and gives LaTeX (its macros expanded);
imports nothing of derive but :mod:`derive.lecture.latex_spaces`.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spaces import SPACE

_UNIT_VECTOR_I = re.compile(r"\\imath|\\(?:hat|widehat|vec|mathbf|boldsymbol|bm)\s*\{?\s*i(?![A-Za-z])")
_LONE = re.compile(r"(?<![A-Za-z\\])[ijk](?![A-Za-z])")
_COMMAND_BEFORE = re.compile(r"\\([A-Za-z]+)\s*$")
_COMMAND_AFTER = re.compile(r"\\([A-Za-z]+)")
_SPACE_BEFORE, _SPACE_AFTER = re.compile(SPACE + r"\Z"), re.compile("^" + SPACE)
_NOT_FACTORS = frozenset(
    "quad qquad le leq ge geq neq ne in to equiv approx sim simeq propto text mathrm textrm mbox "
    "operatorname label tag notag nonumber end begin right middle cdots ldots dots forall exists".split())
"""Commands beside which a letter is not multiplied: relations, spaces, words, closings."""
_ARGUMENT_TAKERS = frozenset(
    "hat widehat vec mathbf boldsymbol bm mathit mathbb mathcal mathsf mathrm text textrm mbox "
    "operatorname dot ddot dddot bar overline tilde widetilde check breve acute grave underline".split())
"""Commands whose argument is a name of its own (``\\hat{i}``, ``\\mathbf i``), never √−1."""
_MATH_GROUPS = frozenset(("frac", "dfrac", "tfrac", "sqrt"))


def read(latex: str) -> str:
    """``latex`` with every lone i that multiplies something written ``\\sqrt{-1}``.

    Parameters
    ----------
    latex : str
        One formula as the text writes it.

    Returns
    -------
    str
        The formula, its imaginary unit spelled out; unchanged where no i is read so or where a j
        or a k is a factor as well.
    """
    if _UNIT_VECTOR_I.search(latex):
        return latex
    found = [m.start() for m in _LONE.finditer(latex) if _a_factor(latex, m.start())]
    if not found or any(latex[p] != "i" for p in found):
        return latex
    for p in reversed(found):
        latex = latex[:p] + "\\sqrt{-1}" + latex[p + 1:]
    return latex


def _a_factor(latex: str, p: int) -> bool:
    """The letter at ``p`` is a factor of a product at the top of the formula's math."""
    before, after = _SPACE_BEFORE.sub("", latex[:p]), _SPACE_AFTER.sub("", latex[p + 1:])
    if before.endswith(("_", "^")) or not _in_math_groups(latex, p):
        return False
    command = _COMMAND_BEFORE.search(before)
    if command and command.group(1) in _ARGUMENT_TAKERS:
        return False
    if after[:1] in ("=", ",", "<", ">", ";", ":", "_", "^", "'"):
        return False
    nxt = _COMMAND_AFTER.match(after)
    if nxt and nxt.group(1) in _NOT_FACTORS:
        return False
    prev_factor = bool(before) and (before[-1].isalnum() or before[-1] in ")]}") and \
        not (command and command.group(1) in _NOT_FACTORS)
    next_factor = bool(after) and (after[0].isalpha() or after[0] in "([{" or bool(nxt))
    return prev_factor or next_factor


def _in_math_groups(latex: str, p: int) -> bool:
    """Every brace group around ``p`` is math of the formula's own: a plain group, a fraction's or a
    root's argument; not a script (``_{…}``, ``^{…}``) nor another command's argument."""
    depth_opens = []
    for k, c in enumerate(latex[:p]):
        if c == "{" and (k == 0 or latex[k - 1] != "\\"):
            depth_opens.append(k)
        elif c == "}" and (k == 0 or latex[k - 1] != "\\") and depth_opens:
            depth_opens.pop()
    for k in depth_opens:
        before = latex[:k].rstrip()
        if before.endswith(("_", "^")):
            return False
        command = _COMMAND_BEFORE.search(before)
        if command and command.group(1) not in _MATH_GROUPS:
            return False
    return True
