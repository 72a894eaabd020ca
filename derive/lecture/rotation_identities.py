"""A matrix of sines and cosines equated to another: an identity of rotations, not a condition.

Takes: the two sides of a relation as SymPy values. Gives: `trig_matrices`, whether both are 3×3
matrices whose every symbol stands inside a sine or a cosine. May import: SymPy.

A text that writes out the product of its elemental rotation matrices, ``R_z R_y R_x = [cos β cos γ
…]``, states an identity in its angles, whatever letters it uses for them (α, β, γ of its own). The
reader leaves an equation between a text's own variables unjudged as a condition the text may be
imposing; two rotation matrices equated entry by entry in angles that appear only as arguments of
sines and cosines are no such condition — the text is multiplying matrices, and a slip in an entry
is a slip.
"""
from __future__ import annotations

import sympy as sp


def trig_matrices(val, targets) -> bool:
    """Whether ``val`` and every target are 3×3 matrices whose symbols appear only inside sin and cos."""
    sides = [val, *targets]
    if not all(isinstance(s, sp.MatrixBase) and s.shape == (3, 3) for s in sides):
        return False
    angles = set()
    for s in sides:
        for e in s:
            e = sp.sympify(e)
            trig = e.atoms(sp.sin, sp.cos)
            if (e.subs({f: 0 for f in trig}) if trig else e).free_symbols:
                return False                # a symbol outside every sine and cosine
            angles |= set().union(*(f.free_symbols for f in trig)) if trig else set()
    return bool(angles)
