"""Frames a text names with letters of its own, and the brackets it labels with them.

Takes: the rendered text of a notes file (`learned`), then one normalised formula and what `learned`
gave (`relabelled`). Gives: the text's frame letters, each the inertial or the body frame as its prose
names it ("an inertial frame $S_0$ that coincides with the body frame $S$"), and the formula with its
brackets labelled by them written as the frame readers read a rate seen from a frame:
``[\\dot{\\bm{A}}]_{S_0}`` and ``\\left(\\frac{d\\bm{A}}{dt}\\right)_{S_0}`` as
``\\left(\\frac{d \\bm{A}}{dt}\\right)_{space}``, ``[\\dot{\\bm{A}}]_{S}`` as the same rate in the body,
and ``[\\bm{A}]_{S}``, a vector in the body frame's components, as ``\\bm{A}`` (every vector is read in
body components). A vector bracketed with the inertial frame's letter keeps its label: its components
there are not its body ones, so its statement stays unread. A letter the prose names as both frames
names neither.

May import: the standard library, :mod:`derive.lecture.latex_spaces`, :mod:`derive.lecture.latex_spellings`.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spaces import SPACE
from derive.lecture.latex_spellings import VECTOR_MARK

_INERTIAL = r"inertial|space-fixed|space|fixed|laboratory|lab|non-rotating|stationary"
_BODY = r"body-fixed|body|rotating|moving|co-rotating"
# the frame's kind right before "frame" (or "reference frame"), then its letter in inline math; a kind
# never read off the end of a hyphenated word ("non-inertial", "body-fixed")
_NAMED = re.compile(r"(?<![\w-])(?P<kind>" + _INERTIAL + "|" + _BODY + r")\s+(?:reference\s+)?frame\s+"
                    r"(?:of\s+reference\s+)?\$\s*(?P<label>[A-Za-z](?:\s*_\s*(?:\{\s*[A-Za-z0-9]\s*\}|[A-Za-z0-9]))?)\s*\$",
                    re.I)
_BODY_KIND = re.compile(r"(?:" + _BODY + r")$", re.I)

_VEC = VECTOR_MARK + r"\s*(?:\{(?:[^{}]|\{[^{}]*\})*\}|\\[A-Za-z]+|[A-Za-z])"
_D = r"(?:\\mathrm\s*\{\s*d\s*\}|d)" + SPACE
# a label braced whole, its own index braced or not (``_{S_0}``, ``_{S_{0}}``), or one letter
_LABEL = r"\s*_\s*(?P<label>\{(?:[^{}]|\{[^{}]*\})*\}|[A-Za-z])"


def _bracketed(inner: str) -> re.Pattern:
    """``inner`` in a round or square bracket, plain or sized, closed by its own kind and labelled."""
    return re.compile(r"(?:\\left\s*)?(?:(?P<o_round>\()|\[)\s*" + inner + r"\s*(?:\\right\s*)?(?(o_round)\)|\])" + _LABEL)


_DOT_RATE = _bracketed(r"\\dot\s*(?:\{\s*(?P<v1>" + _VEC + r")\s*\}|(?P<v2>" + _VEC + r"))")
_FRAC_RATE = _bracketed(r"\\frac\s*\{\s*" + _D + r"(?P<v>" + _VEC + r")\s*\}\s*\{\s*" + _D + r"t\s*\}")
_VECTOR = _bracketed(r"(?P<v>" + _VEC + r")")


def _key(label: str) -> str:
    """A label as one spelling: ``S_{0}``, ``S_0`` and ``{S_0}`` alike."""
    return re.sub(r"[\s{}]", "", label)


def learned(body: str) -> dict[str, str]:
    """The text's frame letters (`_key` spellings) → ``space`` or ``body``, as its prose names them."""
    said: dict[str, set] = {}
    for m in _NAMED.finditer(body):
        kind = "body" if _BODY_KIND.match(m.group("kind")) else "space"
        said.setdefault(_key(m.group("label")), set()).add(kind)
    return {label: kinds.pop() for label, kinds in said.items() if len(kinds) == 1}


def relabelled(latex: str, frames: dict[str, str]) -> str:
    """``latex`` with its brackets labelled by the text's frame letters written as the frame readers
    read them (see the module docstring); as it is when ``frames`` is empty."""
    if not frames:
        return latex

    def rate(m):
        frame = frames.get(_key(m.group("label")))
        if frame is None:
            return m.group(0)
        found = m.groupdict()
        vector = found.get("v") or found.get("v1") or found.get("v2")
        return r"\left(\frac{d " + vector + r"}{dt}\right)_{" + frame + "}"

    def vector(m):
        return m.group("v") if frames.get(_key(m.group("label"))) == "body" else m.group(0)

    latex = _FRAC_RATE.sub(rate, latex)
    latex = _DOT_RATE.sub(rate, latex)
    return _VECTOR.sub(vector, latex)
