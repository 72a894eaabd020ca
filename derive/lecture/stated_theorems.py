"""Three theorems of a rigid body as texts state them: the parallel-axis theorem (``J_{z'} = J_C +
m d^2``, ``I_O = I_G + M a^2``), König's theorem (``T = \\frac{1}{2} m v_c^2 + \\frac{1}{2} J_C
\\omega^2``, ``T = \\frac{1}{2} m \\mathbf{v}_G^2 + \\frac{1}{2} \\boldsymbol\\omega \\cdot \\mathbf{H}_G``) and
the projection theorem of its velocities (``v_B \\cos\\theta_B = v_A \\cos\\theta_A``).

Takes: a statement of the notes checker (`derive.lecture.notes_check.Checker`) and the claims the
checker gave it. Gives: the mixin `StatedTheorems`, whose ``_stated_theorem`` judges a statement
that is one of the theorems in its standard form, the centre of mass named by a subscript (C, c,
G, cm, CM, com), as every mechanics course writes them:

* **parallel axes**: a moment of inertia (I or J with a subscript naming its axis or point) set
  to the moment of the same letter about the centre of mass plus the mass times a distance
  squared, or the centre of mass's moment set to another minus that term: I_P = I_G + m d², d the
  distance between the parallel axes;
* **König**: the kinetic energy T as that of the mass moving with the centre of mass, ½ m v_G²,
  plus that of the turning about it, ½ I_G ω² (a plane motion, a fixed axis) or ½ 𝛚·𝐇_G (written
  ``\\boldsymbol\\omega\\cdot\\mathbf{H}_G`` or in one bold group, ``\\mathbf{\\omega H_G}``; ``\\bm``, ``\\pmb`` as well); and T = ½ 𝛚·𝐇_P alone,
  about a point P named by a capital, `holds if P is at rest` (a body turning about a fixed point);
* **projection**: two points' speeds times the cosines of the angles (one letter, θ, φ, α or β) their
  velocities make with the line joining them, equal: v_B cos θ_B = v_A cos θ_A (points named by
  capitals, one of a point's two letters allowed in lower case, v_a beside θ_A), as
  (𝐯_B − 𝐯_A)·𝐫_AB = (𝛚 × 𝐫_AB)·𝐫_AB = 0.

Such a statement `holds`, its why naming the theorem, where the checker left it `unchecked` (a
name it records, then uses; symbols it does not tie). Any other form — another sign, power or
factor, a point that is not the centre of mass, a distance written as a sum of squares — is left
to the checker, never flagged here; T about a moving point of the body is judged by
`derive.lecture.moving_point_energy`. The centre of mass may also be named by the paragraph before the
statement: ``I_{A'} = I_A + M d^2`` after "an axis A′ parallel to an axis A through the centre of mass",
``I_1' = I_1 + Ml^2`` after "O′ lies a distance l from the centre of mass" (the unprimed moment the
centre of mass's, the primed one's axis or point the other), ``I_x = I_1 - M R^2`` after moments "moved to
the centre of mass at distance R" (the moments set the centre of mass's). May import: the standard library,
:mod:`derive.lecture.latex_spaces`, :mod:`derive.lecture.moving_point_energy`, :mod:`derive.lecture.shape_moments`.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spaces import SPACE_SYMBOL, TIE
from derive.lecture.moving_point_energy import energy_about_a_point
from derive.lecture.shape_moments import paragraph

_CENTRE = r"(?:C|c|G|cm|CM|com|\\text\{cm\}|\\mathrm\{cm\})"
_SUB = r"(\{[^{}]*(?:\{[^{}]*\}[^{}]*)*\}|[A-Za-z0-9])"
_MOMENT = rf"([IJ])\s*_\s*{_SUB}(\s*\^\s*\{{?\s*\\prime\s*\}}?|')?"
_TERM = r"([mM])\s*(?:\\cdot\s*)?([a-zA-Z])\s*\^\s*\{?\s*2\s*\}?"
_PARALLEL = re.compile(rf"\s*{_MOMENT}\s*=\s*{_MOMENT}\s*([+-])\s*{_TERM}\s*[.,;]?\s*")

_HALF = r"\\frac\s*\{\s*1\s*\}\s*\{\s*2\s*\}\s*"
_SQUARE = r"\s*\^\s*\{?\s*2\s*\}?"
_MOVING = (rf"{_HALF}[mM]\s*(?:\\(?:mathbf|boldsymbol|bm|pmb|vec)\s*\{{?\s*[vV]\s*\}}?|[vV])\s*_\s*{_SUB}{_SQUARE}")
_TURNING = (rf"{_HALF}(?:[IJ]\s*_\s*{_SUB}\s*\\omega{_SQUARE}"
            rf"|\\(?:mathbf|boldsymbol|bm|pmb)\s*\{{\s*\\omega\s*H\s*_\s*{_SUB}\s*\}}"
            rf"|\\(?:mathbf|boldsymbol|bm|pmb)\s*\{{?\s*\\omega\s*\}}?\s*\\cdot\s*\\(?:mathbf|boldsymbol|bm|pmb|vec)\s*\{{?\s*H\s*\}}?\s*_\s*{_SUB})")
_ANGLE = r"\\(?:theta|varphi|phi|alpha|beta)"
_PROJECTION = re.compile(rf"\s*[vV]\s*_\s*\{{?\s*([A-Za-z])\s*\}}?\s*\\cos\s*[({{]?\s*({_ANGLE})\s*_\s*\{{?\s*([A-Za-z])\s*\}}?\s*[)}}]?"
                         rf"\s*=\s*[vV]\s*_\s*\{{?\s*([A-Za-z])\s*\}}?\s*\\cos\s*[({{]?\s*({_ANGLE})\s*_\s*\{{?\s*([A-Za-z])\s*\}}?\s*[)}}]?\s*[.,;]?\s*")
_ABOUT = re.compile(rf"\s*T\s*=\s*{_HALF}(?:\\(?:mathbf|boldsymbol|bm|pmb)\s*\{{\s*\\omega\s*H\s*_\s*\{{?\s*([A-Z])\s*\}}?\s*\}}"
                    rf"|\\(?:mathbf|boldsymbol|bm|pmb)\s*\{{?\s*\\omega\s*\}}?\s*\\cdot\s*\\(?:mathbf|boldsymbol|bm|pmb|vec)\s*\{{?\s*H\s*\}}?\s*_\s*\{{?\s*([A-Z])\s*\}}?)"
                    r"\s*[.,;]?\s*")
_KOENIG = [re.compile(rf"\s*T\s*=\s*{a}\s*\+\s*{b}\s*[.,;]?\s*") for a, b in
           ((_MOVING, _TURNING), (_TURNING, _MOVING))]

PARALLEL = ("the parallel-axis theorem: the moment about an axis is the moment about the parallel axis through "
            "the centre of mass plus the mass times the square of the distance between the axes")
KOENIG = ("König's theorem: the kinetic energy is that of the mass moving with the centre of mass plus that of "
          "the turning about the centre of mass")

PROJECTION = ("the projection theorem of rigid motion: two points' velocities have equal projections on the line "
              "joining them, since the velocity of one relative to the other, 𝛚 × 𝐫_AB, is perpendicular to it")

ABOUT = ("holds if {point} is at rest: the kinetic energy of a body turning about a fixed point {point} is "
         "½ 𝛚·𝐇_{point} (about a moving point it takes the terms of that point's motion as well)")


_SPACING = re.compile(rf"(?<!\\)(?:{SPACE_SYMBOL}|{TIE})")
"""A small space, a control space or a tie between factors (``m \\; v_c^2``, ``\\mathbf{\\omega \\, H_G}``): a space
(the forms above are matched after it, so they take whitespace alone)."""


def _centre(sub: str | None) -> bool:
    return sub is not None and re.fullmatch(rf"\{{?\s*{_CENTRE}\s*\}}?", sub) is not None


def _label(sub: str, prime: str | None) -> str:
    """An axis's or a point's label as written, its prime kept: ``{A'}`` → ``A'``, ``1`` with a prime → ``1'``."""
    label = re.sub(r"\^\s*\{?\s*\\prime\s*\}?", "'", sub.strip("{} "))
    return label + ("'" if prime else "")


def _centre_by_prose(label: str, primed: str, distance: str, prose: str) -> bool:
    """Whether the paragraph before the statement makes ``label``'s moment the centre of mass's, the
    primed one's a distance away: ``an axis \\(A\\) through the centre of mass``, or ``\\(O'\\) lies a
    distance \\(l\\) from the centre of mass`` (the moments with a prime then being about that point)."""
    if primed != label + "'":
        return False
    math = r"(?:\$|\\\()\s*"
    end = r"\s*(?:\$|\\\))"
    through = rf"{math}{re.escape(label)}{end},?\s+(?:passing\s+)?through\s+the\s+cent(?:re|er)\s+of\s+mass"
    away = rf"lies\s+(?:at\s+)?a\s+distance\s+{math}{re.escape(distance)}{end}\s+from\s+the\s+cent(?:re|er)\s+of\s+mass"
    return re.search(through, prose) is not None or re.search(away, prose) is not None


def _moved_to_centre(distance: str, prose: str) -> bool:
    """Whether the paragraph before the statement moves the moments to the centre of mass a distance away
    (``moved to the centre of mass at distance $R$``): the moments it sets are the centre of mass's."""
    math, end = r"(?:\$|\\\()\s*", r"\s*(?:\$|\\\))"
    return re.search(rf"(?:moved|carried|shifted|taken)\s+to\s+the\s+cent(?:re|er)\s+of\s+mass,?\s+(?:at\s+)?"
                     rf"(?:a\s+)?distance\s+{math}{re.escape(distance)}{end}", prose) is not None


def theorem(piece: str, prose: str = "") -> str | None:
    """Why a statement is one of the theorems as written, or None when it is not; ``prose`` is the
    paragraph before it, which may name the centre of mass's axis or point."""
    piece = _SPACING.sub(" ", piece)
    m = _PARALLEL.fullmatch(piece)
    if m is not None:
        letter, sub, prime, other_letter, other_sub, other_prime, sign, _, distance = m.groups()
        if letter == other_letter and _centre(sub) != _centre(other_sub) and (sign == "+") == _centre(other_sub):
            return PARALLEL          # I_P = I_G − m d² and I_G = I_P + m d² are not the theorem
        if letter == other_letter and sign == "+" and not other_prime \
                and _centre_by_prose(_label(other_sub, None), _label(sub, prime), distance, prose):
            return PARALLEL          # I_{A'} = I_A + M d², A the axis the prose puts through the centre of mass
        if letter == other_letter and sign == "-" and _moved_to_centre(distance, prose):
            return PARALLEL          # I_x = I_1 − M R², the moments "moved to the centre of mass at distance R"
        return None
    m = _PROJECTION.fullmatch(piece)
    if m is not None:
        point, angle, at, other, other_angle, other_at = m.groups()
        if point.lower() == at.lower() and other.lower() == other_at.lower() and angle == other_angle \
                and point.lower() != other.lower() and (point + at).lower() != point + at \
                and (other + other_at).lower() != other + other_at:
            return PROJECTION        # v_B cos θ_B = v_A cos θ_A (points by capitals, v_a beside θ_A)
        return None
    m = _ABOUT.fullmatch(piece)
    if m is not None:
        point = m.group(1) or m.group(2)
        return ABOUT.format(point=point)
    for form in _KOENIG:
        m = form.fullmatch(piece)
        if m is not None and all(_centre(g) for g in m.groups() if g is not None):
            return KOENIG
    return None


class StatedTheorems:
    """Mixin of the checker. Uses ``self.claims``, ``self.notes``."""

    def _stated_theorem(self, line, piece, before) -> None:
        """The claims the checker gave ``piece`` (from ``before`` on), all unchecked, replaced by
        one that holds where the statement is one of the theorems (see the module docstring)."""
        why = theorem(piece, paragraph(getattr(self.notes, "body", "") or "", line, lower=False))
        mine = self.claims[before:]
        if not mine or any(c.verdict != "unchecked" for c in mine):
            return
        if why is None and (about := energy_about_a_point(piece)) is not None:
            mine[0].kind, mine[0].verdict, mine[0].why, mine[0].correction = "moving point", *about, None
            del self.claims[before + 1:]
            return
        if why is None:
            return
        kind = {PARALLEL: "parallel axes", KOENIG: "König", PROJECTION: "projection"}.get(why, "fixed point")
        mine[0].kind, mine[0].verdict, mine[0].why, mine[0].correction = kind, "holds", why, None
        del self.claims[before + 1:]
