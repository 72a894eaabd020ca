"""A frame that turns with the body's first two Euler angles but not with its spin.

Texts on tops and rolling wheels often work in the frame of the line of nodes and the symmetry
axis (Resal's frame): it tilts and precesses with the body but does not spin with it, so its
angular velocity is the body's with the third angle and its rate left out (in z-x-z,
ω = (θ̇, φ̇ sin θ, φ̇ cos θ) against the body's ω₁ = φ̇ sin θ sin ψ + θ̇ cos ψ, …). A display that
gives the three components ω₁, ω₂, ω₃ and matches that frame's rates in every one, where the body's
differ, sets the text's ω to that frame's: its rows hold as that frame's angular velocity and, from
there on, the text's ωᵢ stand for those rates (the body's own rate is then the text's other name,
Ω₃ = ω₃ + ψ̇). One component alone, or a triple with any row off, is read as before: an ω₃ without
its ψ̇ is a slip a text can make.

Takes: the statements of one display, the checker's derivation (``self.d``: ω̃ and the sequence's
angles) and context. Gives: the mixin `UnspunFrame` of `derive.lecture.notes_check.Checker`, whose
`_unspun_frame` reads such a display and records the rates in ``self.ctx.defs`` and
``self.ctx.forms_held``.

May import: :mod:`derive.lecture.latex`, SymPy.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import latex as lx


class UnspunFrame:
    """Mixin of the checker: see the module docstring. Uses ``self.vocab``, ``self.d``, ``self.ctx``,
    ``self._resolve``, ``self._compare``, ``self.tex`` and ``self._add``."""

    def _unspun_frame(self, line, pieces) -> bool:
        """The display read as the module says; False (read as before) when it is not of that shape."""
        if len(pieces) != 3 or any(w in self.ctx.defs for w in lx.W):
            return False
        rows, read = {}, lx.parse_all(pieces, self.vocab)
        for piece, parsed in zip(pieces, read or ()):
            members = [m.value for m in parsed.members]
            if len(members) != 2 or parsed.relations != ["="] or members[0] not in lx.W or members[0] in rows:
                return False
            rows[members[0]] = (piece, self._resolve(members[1]))
        if read is None or len(rows) != 3:
            return False
        rot = self.d.rot
        spin = {rot.gamma: 0, rot.gamma_d: 0}
        body = [self._resolve(self.d.forms(w)[0]) for w in lx.W]
        frame = [sp.sympify(b).xreplace(spin) for b in body]
        if not any(f.free_symbols & {rot.gamma, rot.gamma_d} for f in (sp.sympify(v) for _, v in rows.values())) and \
                all(self._compare(rows[w][1], f, f"{line}/unspun/{k}")[0] for k, (w, f) in enumerate(zip(lx.W, frame))) and \
                not all(self._compare(rows[w][1], b, f"{line}/body/{k}")[0] for k, (w, b) in enumerate(zip(lx.W, body))):
            why = (f"the angular velocity of the frame that turns with ${self.tex(rot.alpha)}$ and ${self.tex(rot.beta)}$ "
                   f"but not with the spin ${self.tex(rot.gamma)}$: the body's rates with ${self.tex(rot.gamma)}$ and its "
                   "rate left out (the text's ω is that frame's from here on)")
            for w, (piece, value) in rows.items():
                self._add(line, piece, "definition", "holds", why)
                self.ctx.defs[w] = value
                self.ctx.forms_held[w] = value
            return True
        return False

    def _forms_of(self, key, args=None) -> list:
        """The derived forms of a quantity the text names, its ωᵢ the frame's rates once it set them so."""
        if key in lx.W and key in self.ctx.forms_held:
            return [self.ctx.forms_held[key]]
        return self.d.forms(key, args)
