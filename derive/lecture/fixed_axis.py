"""Rotation about a fixed axis, as a text sets it up: ``\\vec\\omega = \\omega \\hat k``.

Takes: one statement's LaTeX. Gives: `setting`, the axis (0, 1, 2) a statement sets the angular
velocity (and the angular acceleration) along, and `off_axis`, the substitution that puts the
model's 𝛚 and 𝛂 on that axis. May import: the standard library, :mod:`derive.lecture.latex_spellings`, SymPy, :mod:`derive.lecture.
vector_algebra_model` (its symbols), :mod:`derive.lecture.latex_spaces`.

A text on a body turning about a fixed axis writes 𝛚 = ω k̂ (𝛂 = α k̂): a bold angular velocity set
equal to a plain scalar times a unit vector. That is the text's set-up, not a claim the derivation
could check, and it changes what later statements mean: the plain ω is then the signed rate about
the axis (not |𝛚|), the off-axis components vanish, and a plain distance r may be measured from
the axis as well as from the origin (``L_z = ω Σ m_i r_i²`` with r_i ⊥ z). The reader records the
axis, reads ω and α as the components along it, sets the others to zero when it compares, and
tries both readings of r (`derive.lecture.algebra_claims`).
"""
from __future__ import annotations

import re

from derive.lecture import vector_algebra_model as va
from derive.lecture.latex_spaces import SPACE
from derive.lecture.latex_spellings import BOLD_MARK, VECTOR_MARK

_UNIT = r"\\hat\s*\{?\s*(?:" + BOLD_MARK + r"\s*\{?\s*)?(?P<axis>[ijkxyz])\s*\}?\s*\}?"
_BOLD = VECTOR_MARK + r"\s*\{?\s*\\(?P<vec>omega|alpha)\s*\}?"
# the scalar rate and the unit vector side by side, or with a centred dot (a product with a scalar)
_ONE = re.compile(r"^\s*" + _BOLD + r"\s*=\s*\\(?P<scalar>omega|alpha)" + SPACE + r"(?:\\cdot(?![A-Za-z])" + SPACE + r")?"
                  + _UNIT + r"\s*$")
AXIS = {"i": 0, "j": 1, "k": 2, "x": 0, "y": 1, "z": 2}

WHY = ("the text's set-up: the body turns about a fixed axis, 𝛚 (and 𝛂) along it — an assumption, "
       "not a claim (recorded: later, ω and α are the rates about that axis, the other components zero)")


def setting(text: str) -> int | None:
    """The axis a statement ``\\vec\\omega = \\omega \\hat k`` (or ``\\vec\\alpha = \\alpha \\hat k``) sets the
    rotation about, or None."""
    m = _ONE.match(text)
    if m is None or m.group("vec") != m.group("scalar"):
        return None
    return AXIS[m.group("axis")]


_PLAIN_OMEGA = re.compile(r"(?<!\\vec)(?<!\\mathbf\{)(?<!\\boldsymbol\{)(?<!\\bm\{)(?<!\\hat\{)\\omega(?![A-Za-z])(?!\s*_)(?!\s*\})")
_OMEGA_RATE = re.compile(r"\\frac\s*\{\s*(?:\\mathrm\s*\{\s*d\s*\}|\\mathrm\s*d|d)\s*\\omega\s*\}|\\dot\s*\{?\s*\\omega(?![A-Za-z])(?!\s*\}?\s*_)")
"""The rate of a plain ω, dω/dt or ω̇ (a rate, not a component): it implies the axis as ω does."""
_PLAIN_ALPHA = re.compile(r"(?<!\\vec)(?<!\\mathbf\{)(?<!\\boldsymbol\{)(?<!\\bm\{)(?<!\\hat\{)\\alpha(?![A-Za-z])(?!\s*_)(?!\s*\})")
"""A plain α, the angular acceleration as a rate about one axis (J_z α)."""
_COMPONENT = re.compile(r"(?<![\\A-Za-z])(?:L|J|I|H)\s*_\s*\{?\s*(?P<axis>[xyz])\s*\}?(?![A-Za-z_{])")


def implied(text: str) -> int | None:
    """The axis a statement's own words imply, ``L_z = \\omega \\sum_i m_i r_i^2``: a component of the
    angular momentum or a moment of inertia about one axis (L_z, J_z) beside a plain ω (a rate, not
    a component; or its rate, dω/dt, ω̇ or a plain α) — the only reading in which they are related is
    a rotation about that axis. None
    when the statement names no such component or no plain ω, or more than one axis."""
    if not (_PLAIN_OMEGA.search(text) or _OMEGA_RATE.search(text) or _PLAIN_ALPHA.search(text)):
        return None
    axes = {m.group("axis") for m in _COMPONENT.finditer(text)}
    return AXIS[axes.pop()] if len(axes) == 1 else None


def off_axis(axis: int) -> dict:
    """The model's 𝛚 and 𝛂 components off the axis, set to zero."""
    return {s: 0 for k, s in enumerate([*va.W, *va.WD]) if k % 3 != axis}


def plain_r(text: str) -> bool:
    """Whether a statement writes a plain distance r (``r``, ``r_i``, ``r_i^2``), not a bold vector."""
    return re.search(r"(?<![\\A-Za-z])r(?![A-Za-z])", re.sub(VECTOR_MARK + r"\s*\{?\s*r\b", "", text)) \
        is not None
