r"""Products of turns written by their axis and angle, read as identities of every angle.

Texts on rotations (quantum mechanics' z-y-z Euler angles among them) write a turn by the axis it
turns about and its angle, ``R({\hat z}, \alpha)``, ``R(\hat{y}, \beta)`` or ``R_z(\alpha)``, and
rewrite products of such turns without ever writing the matrices out: ``R(\hat z,\alpha)
R(\hat y,\beta) R(\hat z,-\alpha) R(\hat z,\gamma) R(\hat z,\alpha) = R(\hat z,\alpha) R(\hat y,\beta)
R(\hat z,\gamma)`` (turns about one axis commute, a turn and its opposite cancel).

Takes: the claims the checker has made (in the order of the text). Gives the mixin
`AxisAngleTurns` of `derive.lecture.notes_check.Checker`, whose `_axis_angle_turns` pass (run after
every statement has been read) reads a statement left unchecked whose every member is a product of
such turns, each about the coordinate axis x, y or z (a small letter, unprimed: a capital or a primed
axis is one the text has moved) by an angle that is one letter or its negative. A link of a chain
written on from the member before it (``= …``) is read with that member. The statement holds when
its members are equal for every value of the angles; the turns are exact rational rotations (cos
and sin of each angle from a rational half-angle tangent), two draws. An identity of every angle
holds whichever way the text's turns turn (active or passive: the passive turns are the active ones
at the opposite angles), so the sense is not asked. A statement that is not such an identity is left
as it was, never flagged: the text's letters may be particular angles, or its axes moved ones.

May import: SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

_AXIS = r"\\hat\s*\{?\s*([xyz])\s*\}?"
_ANGLE = r"(-?)\s*(\\[A-Za-z]+|[A-Za-z])"
_OPEN, _CLOSE = r"(?:\\left\s*)?\(", r"(?:\\right\s*)?\)"    # a bracket the same however it is sized
_TURN = re.compile(r"\s*R\s*(?:_\s*\{?\s*([xyz])\s*\}?\s*" + _OPEN + r"\s*" + _ANGLE + r"\s*" + _CLOSE
                   + r"|" + _OPEN + r"\s*\{?\s*" + _AXIS + r"\s*\}?\s*,\s*" + _ANGLE + r"\s*" + _CLOSE + ")")
"""One turn: ``R_z(\\alpha)`` or ``R({\\hat z}, -\\alpha)`` (axis, sign, angle in groups 1-3 or 4-6)."""
_SPACING = re.compile(r"\\[,;:! ]|\\quad|\\qquad|~")
_DRAWS = ((sp.Rational(1, 3), sp.Rational(-2, 5), sp.Rational(3, 7), sp.Rational(5, 2)),
          (sp.Rational(-4, 9), sp.Rational(2, 11), sp.Rational(-7, 3), sp.Rational(1, 6)))
"""Two draws of the angles' half-angle tangents (as many as the letters a statement may hold)."""
WHY = ("an identity of every angle {angles}: the products of turns about the coordinate axes, each by its "
       "angle, are equal at exact rational rotations (two draws; either sense of turning)")


def _turn(axis: str, tan_half) -> sp.Matrix:
    """The turn about ``axis`` by the angle whose half-angle tangent is ``tan_half`` (exact)."""
    c, s = (1 - tan_half ** 2) / (1 + tan_half ** 2), 2 * tan_half / (1 + tan_half ** 2)
    i, j = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}[axis]
    m = sp.eye(3)
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def _factors(member: str) -> list | None:
    """The turns of a member, each (axis, sign, angle), or None when the member is anything else."""
    text, out, k = _SPACING.sub(" ", member).strip(), [], 0
    while k < len(text):
        m = _TURN.match(text, k)
        if m is None:
            return None if text[k:].strip() else out or None
        axis, sign, angle = (m.group(1), m.group(2), m.group(3)) if m.group(1) else m.group(4, 5, 6)
        out.append((axis, sign == "-", angle))
        k = m.end()
    return out or None


def _members(latex: str) -> list[str]:
    """The members of a statement between its top-level ``=`` (none inside brackets)."""
    out, depth, start = [], 0, 0
    for k, ch in enumerate(latex):
        depth += {"(": 1, "{": 1, "[": 1, ")": -1, "}": -1, "]": -1}.get(ch, 0)
        if ch == "=" and depth == 0:
            out.append(latex[start:k])
            start = k + 1
    return out + [latex[start:]]


def identity_of_every_angle(members: list[list]) -> bool:
    """Whether products of turns (each member's (axis, negated, angle) in order) are all equal at
    every value of the angles: equal at two draws of exact rational rotations."""
    angles = sorted({a for f in members for _, _, a in f})
    if len(angles) > len(_DRAWS[0]):
        return False
    for draw in _DRAWS:
        tan = dict(zip(angles, draw))
        values = []
        for factors in members:
            m = sp.eye(3)
            for axis, negated, angle in factors:
                m = m * _turn(axis, -tan[angle] if negated else tan[angle])
            values.append(m)
        if any(v != values[0] for v in values[1:]):
            return False
    return True


class AxisAngleTurns:
    """Mixin of the checker. Uses ``self.claims``."""

    def _axis_angle_turns(self):
        """Read the unchecked statements that are products of turns by axis and angle (module docstring)."""
        previous = None
        for claim in self.claims:
            latex = claim.latex.strip()
            members = _members(latex)
            if latex.startswith("=") and previous is not None and previous[0] == claim.line:
                members = [previous[1]] + members[1:]
            previous = (claim.line, members[-1])
            if claim.verdict != "unchecked" or len(members) < 2 or "\\neq" in latex:
                continue
            factors = [_factors(m) for m in members]
            if any(f is None for f in factors) or not identity_of_every_angle(factors):
                continue
            angles = sorted({a for f in factors for _, _, a in f})
            claim.kind, claim.verdict = "identity", "holds"
            claim.why = WHY.format(angles=", ".join(angles))
