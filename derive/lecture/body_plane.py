"""A body the text puts in a coordinate plane: ``$z = 0$`` in its prose before a statement on the body.

Takes: one statement's LaTeX. Gives: `setting`, the axis (0, 1, 2) a bare ``x = 0``, ``y = 0`` or
``z = 0`` sets to zero, and `in_plane`, the substitution that puts the model's mass points in that
plane. May import: the standard library, :mod:`derive.lecture.vector_algebra_model` (its symbols).

A lamina's theorems hold only for a body in a plane: I_zz = I_xx + I_yy (the perpendicular-axis
theorem) is false of a body in general and true of one whose points all have z = 0, which a text
says in words around a bare ``$z = 0$``. The reader records the plane (for the section it is set in)
and, where a statement on the body fails for generic mass points, reads it again with the points in
that plane (`derive.lecture.algebra_claims`): it holds there if that reading holds.
"""
from __future__ import annotations

import re

from derive.lecture import vector_algebra_model as va

_BARE = re.compile(r"^\s*(?P<axis>[xyz])\s*=\s*0\s*$")
AXIS = {"x": 0, "y": 1, "z": 2}

WHY = "for a body in the plane {axis} = 0 the text sets (every mass point's {axis} zero)"


def setting(text: str) -> int | None:
    """The axis a bare ``z = 0`` (or ``x = 0``, ``y = 0``) sets to zero, or None."""
    m = _BARE.match(text)
    return AXIS[m.group("axis")] if m else None


def in_plane(axis: int) -> dict:
    """The model's mass points' coordinate along ``axis``, set to zero."""
    return {p[axis]: 0 for p in (va.R0, *va.RK)}
