"""Euler's equation about one named point: the inertia tensor and the torque both labelled by it.

Takes: one statement's LaTeX. Gives: `dropped`, the statement without the point's label and the
label, when it is Euler's equation in vectors taken about one point the text names by a label
(``\\bm{\\tau}_{\\bm{c}} = \\bm{\\omega} \\times (\\mathbf{I}^{\\bm{c}} \\bm{\\omega}) + \\mathbf{I}^{\\bm{c}}
\\frac{d\\bm{\\omega}}{dt}``, ``\\boldsymbol\\tau_{cm} = \\mathbf I_{cm} \\dot{\\boldsymbol\\omega} + …``),
else None.

Why the label may go: the reader's model takes moments about its origin, the point the body turns
about; a tensor and a torque labelled by the centre of mass or by a fixed point (c, cm, CM, com, G,
C, O) are those of the same equation, τ = I ω̇ + ω × I ω holding about either. So the label is
dropped only where every inertia tensor in the statement carries it, the statement has a cross
product and a rate of the angular velocity (the equation's shape), and nothing else carries it: a
statement with two points (𝐈_O = 𝐈_C + …), an unlabelled tensor beside a labelled one, or a
position or velocity of that point (𝐫_c, 𝐯_c, which are not the model's) keeps its labels.

May import: the standard library, :mod:`derive.lecture.latex_spellings`.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spellings import VECTOR_MARK

_LABELS = ("c", "C", "cm", "CM", "com", "G", "O")
_WORD = r"(?:\\(?:text|mathrm|rm)\s*\{\s*([A-Za-z]+)\s*\}|" + VECTOR_MARK + r"\s*\{\s*([A-Za-z]+)\s*\}|([A-Za-z]+))"
_LABEL = r"(?P<label>\s*[_^]\s*(?:\{\s*" + _WORD + r"\s*\}|([A-Za-z])(?![A-Za-z])))"
_FACE = r"(?:" + VECTOR_MARK + r"|\\mathbb|\\mathrm)"
_INERTIA = re.compile(r"(?:" + _FACE + r"\s*\{\s*I\s*\}|" + _FACE + r"\s+I(?![A-Za-z])|(?<![\\A-Za-z])I(?![A-Za-z]))"
                      + _LABEL + "?")
_TORQUE = re.compile(r"(?:" + VECTOR_MARK + r"\s*\{\s*\\(?:tau|Gamma)\s*\}|" + VECTOR_MARK + r"\s*\\(?:tau|Gamma)"
                     r"(?![A-Za-z])|(?<![A-Za-z])\\(?:tau|Gamma)(?![A-Za-z]))" + _LABEL)
_CROSS = re.compile(r"\\times|\\cross(?![A-Za-z])")
_OMEGA_RATE = re.compile(r"\\dot\s*\{?\s*(?:" + VECTOR_MARK + r"\s*\{?\s*)?\\omega|\\frac\s*\{\s*(?:\\mathrm\s*\{\s*d\s*\}|d)"
                         r"\s*(?:" + VECTOR_MARK + r"\s*\{?\s*)?\\omega")

WHY = " (Euler's equation about the point labelled {label}: the tensor and the torque both taken about it)"


def _label(m) -> str:
    """The label a match of `_LABEL` carries, its face (bold, roman) taken off; '' when none."""
    if m.group("label") is None:
        return ""
    return next(g for g in m.groups()[1:] if g)


def dropped(text: str) -> tuple[str, str] | None:
    """``text`` without the point's label on its inertia tensors and torques, and the label, when it
    is Euler's equation about that point (see the module docstring); None otherwise."""
    if not _CROSS.search(text) or not _OMEGA_RATE.search(text):
        return None
    tensors = list(_INERTIA.finditer(text))
    labels = {_label(m) for m in tensors}
    if not tensors or len(labels) != 1 or labels & {""}:
        return None
    label = labels.pop()
    if label not in _LABELS:
        return None
    torques = list(_TORQUE.finditer(text))
    if any(_label(m) in _LABELS and _label(m) != label for m in torques):
        return None                 # 𝛕_O beside 𝐈_C: moments about two points
    marks = sorted(tensors + [m for m in torques if _label(m) == label], key=lambda m: m.start())
    out, end = [], 0
    for m in marks:
        out.append(text[end:m.start("label")])
        end = m.end("label")
    out.append(text[end:])
    rest = "".join(out)
    if re.search(r"[_^]\s*\{?\s*(?:" + VECTOR_MARK + r"\s*\{\s*|\\(?:text|mathrm|rm)\s*\{\s*)?" + re.escape(label)
                 + r"(?![A-Za-z])", rest):
        return None                 # 𝐫_c, 𝐯_c: the point's own position or velocity, not the model's
    return rest, label
