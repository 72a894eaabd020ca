"""Kane's vector notation as the vector-algebra reader takes it (`derive.lecture.vector_algebra_model`).

Texts in the tradition of Kane and Levinson (multibody dynamics courses, sympy.physics.mechanics)
write a vector with a bar, a unit vector with a hat, a dyadic with a breve, and label a position
by the two points it joins: ``\\bar{r}^{P_i/O}`` is the position of particle Pᵢ relative to the
point O, ``\\breve{I}^{S/O}`` the inertia dyadic of the set S about O, ``\\breve{U}`` the unit
dyadic. `rewrite` brings such a statement to the bold notation the reader knows:

* ``\\bar{r}^{P_i/O}`` (a point with the sum's index) → ``\\mathbf{r}_{i}``; ``\\bar{r}^{P/O}``,
  ``\\bar{r}^{P(\\tau)/O}`` (one point, or the point of an integral) → ``\\mathbf{r}``;
* ``\\bar{X}``, ``\\bar{X}_a`` (no label) → ``\\mathbf{X}``, ``\\mathbf{X}_{a}``;
* ``\\hat{n}_a`` (a unit vector named by a letter other than x, y, z, i, j, k) → ``\\mathbf{n}_{a}``,
  a vector of the text's;
* ``{}^A\\bar{\\omega}^B`` (B's angular velocity in A) → ``\\boldsymbol{\\omega}``; a frame's left
  superscript ``{}^A`` on a vector is dropped (one frame per statement);
* ``\\breve{U}`` → the unit tensor; ``\\breve{I}^{S/O}`` about the point the positions are taken from
  → the inertia tensor of the body (or set), ``\\mathbf{I}_{system}``; ``\\breve{I}^{B_o/O}`` beside the
  position ``\\bar{r}^{B_o/O}`` of the same point (its index no sum's) → ``\\mathbf{I}`` and ``\\mathbf{r}``,
  the one particle at that point.

A statement with positions from two points, or dyadics with two labels (the parallel axis
theorem's ``\\breve{I}^{B/O} = \\breve{I}^{B/B_o} + \\breve{I}^{B_o/O}``), is left as written, so it is
not read: the reader's points are all taken from one origin and it has one body.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spaces import SPACE

_LABEL = (r"\^\s*\{\s*([A-Za-z])\s*(?:_\s*\{?\s*([A-Za-z])\s*\}?|\(\s*\\tau\s*\))?\s*/\s*"
          r"([A-Za-z](?:\s*_\s*\{?\s*[a-z0-9]\s*\}?)?)\s*\}")
_POSITION = re.compile(r"\\bar\s*\{\s*([A-Za-z])\s*\}\s*" + _LABEL)
_DYADIC = re.compile(r"\\breve\s*\{\s*([A-Za-z])\s*\}\s*" + _LABEL)
_BAR = re.compile(r"\\bar\s*\{\s*([A-Za-z])\s*\}(?!\s*\^)(?:\s*_\s*\{?\s*([A-Za-z])\s*\}?)?")
_UNIT = re.compile(r"\\hat\s*\{\s*([a-hl-wA-Z])\s*\}\s*_\s*\{?\s*([A-Za-z])\s*\}?")
_UNIT_DYADIC = re.compile(r"\\breve\s*\{\s*U\s*\}")
# a frame's prescript spaced off its vector ({}^A \, \bar H); never across a quad, which ends its statement
_FRAME = re.compile(r"\^\s*\{?\s*[A-Z]\s*\}?" + SPACE + r"(?=\\bar\s*\{)")
_ANGULAR_VELOCITY = re.compile(r"\\bar\s*\{\s*\\omega\s*\}\s*\^\s*\{?\s*[A-Z]\s*\}?")
_KANE = re.compile(r"\\bar\s*\{\s*[A-Za-z]\s*\}\s*\^\s*\{(?:[^{}]|\{[^{}]*\})*/|\\breve\s*\{")
"""A labelled position or a dyadic, its point's index braced or not (``\\bar{r}^{S_o/O}``, ``\\bar{r}^{S_{o}/O}``)."""


def kane(text: str) -> bool:
    """Whether a statement is written in Kane's notation (a labelled position or a dyadic)."""
    return bool(_KANE.search(text))


def rewrite(text: str, known: bool = False) -> str:
    """The statement in bold vectors (see the module docstring); unchanged when not in Kane's notation
    (a labelled position or a dyadic in it, or ``known``: the text has written one before)."""
    if not (known or kane(text)):
        return text
    origins = {m.group(4) for m in _POSITION.finditer(text)}
    labels = {m.group(0).split("^", 1)[1].replace(" ", "") for m in _DYADIC.finditer(text)}
    frames = set(re.findall(r"\^\s*\{?\s*([A-Z])\s*\}?\s*\\bar", text))
    if len(origins) > 1 or len(labels) > 1 or len(frames) > 1:
        return text          # positions or dyadics about two points: the reader takes all from one

    dyadic_points = {m.group(2, 3) for m in _DYADIC.finditer(text)}
    summed = set(re.findall(r"\\sum_\s*\{?\s*([a-z])", text))

    def position(m):
        letter, point, index, origin = m.groups()
        if index and index not in summed and (point, index) in dyadic_points:
            index = None     # 𝐫^{B_o/O} beside the dyadic 𝐈^{B_o/O}: the one particle at B_o, not a sum's point
        return r"\mathbf{" + letter + "}" + ("_{" + index + "}" if index else "")

    position_points = {m.group(2, 3) for m in _POSITION.finditer(text)}

    def dyadic(m):
        letter, point, index, origin = m.groups()
        if origins and origin not in origins:
            return m.group(0)
        if (point, index) in position_points:
            return r"\mathbf{" + letter + "}"      # about a point whose position is written: that particle's
        return r"\mathbf{" + letter + "}_{system}"  # 𝐈^{B/O}, 𝐈^{S/O}: the body's, or the set's

    text = _FRAME.sub("", text)             # {}^A: the frame a vector is seen in (one frame per statement)
    text = _ANGULAR_VELOCITY.sub(r"\\boldsymbol{\\omega}", text)    # {}^A\bar{\omega}^B: the body's, in A
    text = _POSITION.sub(position, text)
    text = _UNIT_DYADIC.sub(r"\\mathrm{I}", text)
    text = _DYADIC.sub(dyadic, text)
    text = _UNIT.sub(lambda m: r"\mathbf{" + m.group(1) + "}_{" + m.group(2) + "}", text)
    return _BAR.sub(lambda m: r"\mathbf{" + m.group(1) + "}" + ("_{" + m.group(2) + "}" if m.group(2) else ""), text)
