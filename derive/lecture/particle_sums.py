"""A sum written with no index over a particle's mass and coordinates: ``\\sum m(y^2 + z^2)``.

Takes: the tokens of one formula (`derive.lecture.vocabulary.scan`) and the position just after a
``\\sum`` that has no subscript. Gives: `over_particles`, which decides whether the sum is one over
the body's particles and, if so, writes the index into its summand. Textbooks write the inertia
tensor's entries as I_xx = Σ m(y² + z²), I_xy = −Σ mxy, the sum over the particles left unindexed as
the integral ∫(y² + z²) dm leaves its mass element: a summand made only of the mass m and the
coordinates x, y, z, none subscripted, is that sum, read as Σᵢ mᵢ(yᵢ² + zᵢ²). A bare sum of anything
else (Σ F_{i,x}, Σ m alone) is not read. May import: :mod:`derive.lecture.vocabulary`.
"""
from __future__ import annotations

from derive.lecture.vocabulary import Tok

_STOPS = ("sum", "quad", "qquad", "int")


def over_particles(toks: list, i: int) -> list | None:
    """``["i"]``, the sum's index, when the summand starting at ``toks[i]`` (up to the next top-level
    +, −, comma, relation or sum) is made of m and x, y, z alone, unsubscripted, with m and a
    coordinate among them: its atoms are then given the index i in ``toks`` (changed in place);
    else None."""
    depth, atoms = 0, []
    for k in range(i, len(toks)):
        t = toks[k]
        if t.kind == "op" and t.value in "({":
            depth += 1
        elif t.kind == "op" and t.value in ")}":
            depth -= 1
            if depth < 0:
                break
        elif depth == 0 and (t.kind == "rel" or t.kind == "op" and t.value in "+-," or
                             t.kind == "cmd" and t.value in _STOPS):
            break
        elif t.kind == "atom":
            atoms.append(k)
        elif t.kind not in ("num", "op"):
            return None
    written = [toks[k].value for k in atoms]
    if not written or not all(_plain(a) for a in written) or {a.base for a in written} <= {"m"} or \
            "m" not in {a.base for a in written}:
        return None
    for k in atoms:
        t = toks[k]
        toks[k] = Tok(t.kind, t.value.with_(sub="i", text=t.value.text + "_i"), t.pos)
    return ["i"]


def _plain(a) -> bool:
    """m, x, y or z with no subscript, superscript, accent, prime or typeface."""
    return a.base in ("m", "x", "y", "z") and not (a.sub or a.sup or a.dots or a.bold or a.hat or a.tilde
                                                    or a.primes or a.mark)
