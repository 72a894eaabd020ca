"""A frequency a text defines with its own sign: ``\\Omega \\coloneqq \\frac{I_1 - I_3}{I_1}\\omega_3``.

The free symmetric top's body frequency is written either way round: Ω = ω₃(I₃ − I₁)/I₁ with
ω̇₁ = −Ωω₂, or Ω = ω₃(I₁ − I₃)/I₁ with ω̇₁ = Ωω₂. A definition (≡, ≔) of Ω, Ω₁ or Ω₂ that is the
derived frequency with the opposite sign names the text's own quantity: it is taken as written,
so the displays after it are read with the text's Ω, and a display that uses the other sign is
the one flagged. Any other difference from the derived frequency is judged as before.
"""
from __future__ import annotations


class OwnSign:
    """Mixin of `derive.lecture.notes_check.Checker`: a frequency defined with the opposite sign."""

    def _own_sign(self, line, piece, parsed, forms) -> bool:
        """Take ``Ω ≡ value`` as the text's own when value is minus a derived form; True when taken."""
        if len(parsed.members) != 2 or list(parsed.relations) != ["≡"] or not forms:
            return False
        key, value = parsed.members[0].value, parsed.members[1].value
        val = self._resolve(value, keep=(key,))
        seed = f"{piece}/own-sign"
        targets = [self._resolve(f) for f in forms]
        if any(self._compare(val, f, seed)[0] for f in targets):
            return False
        if not any(self._compare(-val, f, seed)[0] for f in targets):
            return False
        self.ctx.defs[key] = value
        self._add(line, piece, "definition", "holds", "the derived frequency with the opposite sign: the text's "
                  "own sign for its name, kept for the displays after it")
        return True
