"""The checker's convention as the text states it, section by section, and what depends on it.

Takes: the `"convention"` items of `derive.lecture.notes` (a section that states another sequence
or other angle names, `derive.lecture.stated_convention`). Gives: the mixin `SectionConvention` of
`derive.lecture.notes_check.Checker`: `_stated_convention` switches the derivation, the
vocabulary's angles and the LaTeX names of the output from that item on; `_body_rate` is dω̃/dt
in the convention's angles (what a text's Ω̇ written as a column is compared with).

May import: SymPy, :mod:`derive.lecture.notes`, :mod:`derive.lecture.derivation`, :mod:`derive.symbolic`.
"""
from __future__ import annotations

import sympy as sp

from derive.lecture import notes as nt
from derive.lecture.derivation import derivation
from derive.symbolic.lagrangian import ACCELS
from derive.symbolic.rotations import ANGLES, RATES


class SectionConvention:
    """Mixin of the checker (see the module docstring)."""

    def _body_rate(self):
        """dω̃/dt in the angles, their rates and accelerations (the chain rule through q and q̇)."""
        w = self.d.omega
        return w.jacobian(sp.Matrix(ANGLES)) * sp.Matrix(RATES) + w.jacobian(sp.Matrix(RATES)) * sp.Matrix(ACCELS)

    def _stated_convention(self, item, d=None):
        """A section states another convention or other angle names (``item.text``, ``item.symbols``):
        the derivation (``d``, when one of that sequence is at hand), the vocabulary's angles and the
        names for output follow it from here on."""
        self._flush()
        self._place_flushed(len(self.claims))
        self.notes.convention, self.notes.angles = item.text, tuple(item.symbols)
        self.vocab.angles, self.vocab.aliases = tuple(item.symbols), nt.angle_aliases(self.notes)
        self.d = d or derivation(item.text)
        self.derivations.append(self.d)
        self.vocab.axial = "xyz".index(self.d.conv.axes[2])
        if self.vocab.vertical:
            self.vocab.vertical = tuple(self.d.conv.matrix().T[:, 2])
        self.__dict__.pop("names", None)        # the LaTeX names of the angles, built again
