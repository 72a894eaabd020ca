"""A vector statement written in one frame's components, every vector and tensor in it labelled so.

Takes: one statement's LaTeX. Gives: `dropped`, the statement without the frame's label and the
label, when every bold symbol in it carries the same subscript naming a frame and the angular
velocity is among them (``\\mathbf I_B\\,\\mathbf{\\dot{\\omega}}_B+\\mathbf\\omega_B\\times\\,\\mathbf
I_B\\,\\mathbf\\omega_B=\\mathbf\\tau_B``), else None.

Why the label may go: a relation among vectors made of products, cross products and the inertia
tensor acting on them holds in one frame's components exactly when it holds in another's (every
term's components turn by the same rotation), and the angular velocity's rate has the same
components seen from the body and from space (its own cross product vanishes). The rate of any
other labelled vector differs between frames (the rate of 𝐋's body components against d𝐋/dt), so
a statement that takes one, or writes d/dt, keeps its label and is not read here.

May import: the standard library, :mod:`derive.lecture.latex_spellings`.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spellings import VECTOR_MARK

_BOLD = (VECTOR_MARK + r"\s*(?:\{(?:[^{}]|\{[^{}]*\})*\}|\\[A-Za-z]+|[A-Za-z])")
_TOKEN = re.compile(r"(?P<sym>\\dot\s*\{\s*" + _BOLD + r"\s*\}|" + _BOLD + r")"
                    r"(?P<label>\s*_\s*(?:\{\s*(?P<b1>[A-Za-z]|\\(?:text|mathrm|rm)\s*\{[A-Za-z]+\})\s*\}"
                    r"|(?P<b2>[A-Za-z])(?![A-Za-z])))?")
_NOT_FRAMES = set("ijknxyz")
"""Subscripts that index a component or a particle, never a frame."""

WHY = " (read in the components of frame {label}: every vector and tensor in it carries that label)"


def dropped(text: str) -> tuple[str, str] | None:
    """``text`` without its frame label, and the label, when it is a vector statement written in
    one frame's components (see the module docstring); None otherwise."""
    if re.search(r"\\frac\s*\{\s*(?:\\mathrm\s*\{?\s*)?d", text) or "\\frac{\\partial" in text:
        return None
    tokens = list(_TOKEN.finditer(text))
    labels = {(m.group("b1") or m.group("b2") or "").replace(" ", "") for m in tokens}
    if len(tokens) < 2 or len(labels) != 1:
        return None
    label = labels.pop()
    if not label or label in _NOT_FRAMES or not any("\\omega" in m.group("sym") for m in tokens):
        return None
    if any("dot" in m.group("sym") and "\\omega" not in m.group("sym") for m in tokens):
        return None
    out, end = [], 0
    for m in tokens:
        out.append(text[end:m.start("label")])
        end = m.end("label")
    out.append(text[end:])
    return "".join(out), label
