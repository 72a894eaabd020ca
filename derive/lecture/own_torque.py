"""A vector of the text's own as the torque: ``\\vec{M_{cm}} = I\\dot{\\vec\\omega} + \\vec\\omega \\times (I\\vec\\omega)``.

A text names the moment about the centre of mass in its own letter (𝐌, 𝐍, 𝐓, 𝐌_cm) and writes
Euler's equation in vectors with it alone on one side. As a symbol of the text's entering a
component of Euler's equation alone is that component of the torque, a vector of the text's
alone on one side of Euler's equation in vectors — the other side has the body's inertia
tensor I, the rate of 𝛚 and a cross product — is the torque τ = d𝐋/dt; that side is judged
against d𝐋/dt. A vector alone beside anything else (𝐚 = 𝛚̇ × 𝐫 + …, 𝐅 = m𝐚, or 𝐍 = I𝛂, a law a
text may set for a fixed axis) is not read so.

Takes: a reading of `derive.lecture.vector_algebra_model` (members with their generic vectors,
their source spans, whether they have a rate). Gives `sides` (which member is the text's torque
and which the equation's other side) and `judged` (the verdict and why).

May import: :mod:`derive.lecture.latex_spellings`, :mod:`derive.lecture.vector_algebra_model`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import vector_algebra_model as va
from derive.lecture.latex_spellings import VECTOR_MARK

_BOLD = VECTOR_MARK + r"\s*\{?\s*"
_INERTIA = re.compile(r"(?<![\\A-Za-z])I(?![A-Za-z])|" + _BOLD + r"I(?![A-Za-z])|\\mathbb\s*\{?\s*I(?![A-Za-z])")
_CROSS = re.compile(r"\\times|×|\\cross")
_OMEGA_RATE = re.compile(r"\\dot\s*\{?\s*" + _BOLD + r"\\omega|" + _BOLD + r"\\dot\s*\{?\s*\\omega|\\frac\s*\{\s*d\s*" + _BOLD + r"\\omega|"
                         + _BOLD + r"\\alpha(?![A-Za-z])")


def sides(reading, ref: int, k: int) -> tuple[int, int] | None:
    """(the member that is the text's torque, the other) among members ``ref`` and ``k`` of a
    reading with no free index: one a single vector of the text's and nothing else, the other
    with no vector of the text's, a rate of 𝛚, the inertia tensor and a cross product written;
    None otherwise."""
    if reading.free or len(reading.members) != 1:
        return None
    first = reading.members[0]
    for own, other in ((ref, k), (k, ref)):
        a, b = first[own], first[other]
        if a.atom is None or not (a.atom.bold or a.atom.text.startswith("\\vec")) or len(a.generics) != 1:
            continue
        written = reading.source[b.start:b.end]
        if not b.generics and b.rated and not b.law and _INERTIA.search(written) and _OMEGA_RATE.search(written) \
                and _CROSS.search(written):
            return own, other
    return None


def judged(reading, own: int, other: int, why: str, where, off_axis=None) -> tuple[str, str]:
    """The other side against d𝐋/dt of the reading's system: ``holds`` or ``fails`` (``where``
    says which component differs; ``off_axis`` puts the fixed axis a text set)."""
    first = reading.members[0]
    name = reading.source[first[own].start:first[own].end].strip()
    d = va.difference(first[other].value, va.torque(reading.model))
    if d is not None and off_axis is not None:
        d = va.difference(d.subs(off_axis), 0 * d)
    said = f"the text's {name} read as the torque, alone on its side of an equation of motion"
    if d is None:
        return "unchecked", f"cannot compare its sides: their shapes differ ({said})"
    if all(x == 0 for x in d):
        return "holds", f"{why}: {said}: exact (expand)"
    return "fails", f"as written: {where(d)} ({why}; {said})"


def added(reading, ref: int, k: int) -> str | None:
    """The text's one vector as the torque where it is a term beside the others
    (``I\\dot{\\boldsymbol\\omega} = -\\boldsymbol\\omega \\times I\\boldsymbol\\omega + \\mathbf{M}``): the members
    of a reading with no free index differ by ±𝐆 and the rest, the statement writes the inertia
    tensor, a rate of 𝛚 and a cross product, and with 𝐆 = τ = d𝐋/dt the difference is zero.
    The name of the vector taken for the torque when it holds so, else None (a vector of the
    text's may be a force, or a torque the text defines otherwise: nothing is flagged)."""
    if reading.free or len(reading.members) != 1:
        return None
    first = reading.members[0]
    names = first[ref].generics | first[k].generics
    written = reading.source
    if len(names) != 1 or first[ref].law or first[k].law or not (
            _INERTIA.search(written) and _OMEGA_RATE.search(written) and _CROSS.search(written)):
        return None
    name = next(iter(names))
    own = va.generic_components(name)
    d = va.difference(first[k].value, first[ref].value)
    if not isinstance(d, sp.MatrixBase) or d.shape != (3, 1):
        return None
    slope = d.jacobian(own)
    if slope not in (sp.eye(3), -sp.eye(3)):
        return None
    torque = va.torque(reading.model)
    return name if all(va.difference(x, 0) == 0 for x in d.xreplace(dict(zip(own, torque)))) else None
