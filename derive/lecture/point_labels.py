"""Points of a body named by capital letters (A, B): their velocities, accelerations and the
vectors between them, as plane-motion texts write them (𝐯_B = 𝐯_A + 𝛚 × 𝐫_AB).

Takes: a bold symbol's letter, subscript and superscript label. Gives: `value`, the symbol's value
under rigid motion with a translating reference point, and `involved`, whether a value rests on
that model. May import: SymPy.

The body moves with a reference point whose velocity 𝐕 and acceleration 𝐀 are free, and turns
with 𝛚 (rate 𝛂). A point X is at 𝛒_X from the reference point, free as well, so

* 𝐫_{XY} = 𝛒_Y − 𝛒_X (from X to Y);
* 𝐯_X = 𝐕 + 𝛚 × 𝛒_X, 𝐚_X = 𝐀 + 𝛂 × 𝛒_X + 𝛚 × (𝛚 × 𝛒_X);
* 𝐯_{YX} = 𝐯_Y − 𝐯_X, 𝐚_{YX} = 𝐚_Y − 𝐚_X (Y relative to X), with the tangential and normal parts
  𝐚_{YX}^t = 𝛂 × 𝐫_{XY} and 𝐚_{YX}^n = 𝛚 × (𝛚 × 𝐫_{XY}).

A relation of these that holds for every 𝐕, 𝐀 and 𝛒 holds for every rigid motion. One that does
not may be the text's choice of its points (an instantaneous centre of velocity taken as A, so
𝐯_B = 𝛚 × 𝐫_AB; a rolling contact at rest): it is never judged wrong here (`involved`). It holds
if one of its points is at rest, or has no acceleration, when it holds with that point as the
reference point and 𝐕 = 𝟎 (or 𝐀 = 𝟎), for every 𝛚, 𝛂 and the other points (`at_rest`): the
instantaneous centre of velocity (of acceleration) as texts take it, `holds if` that, never `fails`.
"""
from __future__ import annotations

import sympy as sp

V = sp.Matrix(sp.symbols("ref_v_x ref_v_y ref_v_z", real=True))      # the reference point's velocity
A = sp.Matrix(sp.symbols("ref_a_x ref_a_y ref_a_z", real=True))      # and acceleration (names no text's vector has)
RESERVED = frozenset("GOCI")
"""Capital letters that name the point moments are taken about (G, O, C) or the inertia (I)."""

WHY = ("relates points of the body named by letters, and does not hold for every motion of them: it may "
       "rest on the text's choice of its points (a point at rest, an instantaneous centre), which the reader "
       "does not know")


AT_REST = ("holds if the {what} of {point} is zero at that instant ({point} an instantaneous centre of {what}, "
           "as texts take a point of the body to write this; the relation does not hold for every point)")


def _rho(label):
    return sp.Matrix(sp.symbols(f"rho_{label}_x rho_{label}_y rho_{label}_z", real=True))


def labels(sub: str) -> tuple | None:
    """The points a subscript names (``B`` → (B,), ``AB`` → (A, B)), or None."""
    if 1 <= len(sub) <= 2 and sub.isalpha() and sub.isupper() and not set(sub) & RESERVED \
            and len(set(sub)) == len(sub):
        return tuple(sub)
    return None


def value(base: str, sub: str, sup: str, w, wd):
    """𝐫, 𝐯 or 𝐚 with a subscript of point letters (and for 𝐚 of two points a label t, τ or n):
    its value, or None when it is not one of these."""
    pts = labels(sub)
    if pts is None or base not in ("r", "v", "a") or (sup and not (base == "a" and len(pts) == 2)):
        return None

    def velocity(x):
        return V + w.cross(_rho(x))

    def acceleration(x):
        return A + wd.cross(_rho(x)) + w.cross(w.cross(_rho(x)))

    if base == "r":
        return _rho(pts[1]) - _rho(pts[0]) if len(pts) == 2 else None
    if len(pts) == 1:
        return velocity(pts[0]) if base == "v" else acceleration(pts[0])
    y, x = pts                                          # 𝐯_{YX}: Y relative to X
    if base == "v":
        return velocity(y) - velocity(x)
    between = _rho(y) - _rho(x)
    parts = {"t": wd.cross(between), "tau": wd.cross(between), "n": w.cross(w.cross(between))}
    return parts[sup] if sup else acceleration(y) - acceleration(x)


def involved(*values) -> bool:
    """Whether any of the values rests on the points' model (its free reference motion or positions)."""
    for v in values:
        free = getattr(v, "free_symbols", set())
        if any(str(s).startswith(("rho_", "ref_")) for s in free):
            return True
    return False


def _points(value) -> set:
    free = set().union(*(x.free_symbols for x in value)) if isinstance(value, sp.MatrixBase) \
        else getattr(value, "free_symbols", set())
    return {str(s).split("_")[1] for s in free if str(s).startswith("rho_")}


def at_rest(claim, derived) -> tuple[str, str] | None:
    """(the point, "velocity" or "acceleration") such that claim − derived vanishes when that point
    is the reference point and its velocity (acceleration) is zero; None when no point does. The
    relation must name another point besides it, so that 𝐯_B = 𝟎 does not hold "if B is at rest"."""
    points = sorted(_points(claim) | _points(derived))
    if len(points) < 2 or not isinstance(claim, sp.MatrixBase) or not isinstance(derived, sp.MatrixBase) \
            or claim.shape != derived.shape:
        return None
    for point in points:
        for what, ref in (("velocity", V), ("acceleration", A)):
            subs = {**{c: 0 for c in _rho(point)}, **{c: 0 for c in ref}}
            if all(sp.expand(x.subs(subs)) == 0 for x in claim - derived):
                return point, what
    return None
