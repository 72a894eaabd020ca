r"""A product of matrices named by their axes, written out factor by factor.

Takes: the statements of one display (`derive.lecture.statements`), read with the checker's
vocabulary. Gives the mixin `AxisProducts` of `derive.lecture.notes_check.Checker`, whose
`_axis_product` reads a chain such as ::

    R_{zxz} = R_z R_x R_z = [cos γ  sin γ  0; …] [1 0 0; …] [cos α  sin α  0; …]

in which each name of the product says only its axis (x, y, z, or 1, 2, 3 for them) and the
matrix written under it gives the angle. Each written factor is held to the elemental turn about
its name's axis by the one angle its entries are in, every factor in one sense, all passive
(``passive(axis, q)``, the coordinate turn) or all active (``active(axis, q) = passive(axis, q)ᵀ``),
since one letter with two senses would be two matrices. When every factor is that turn, the
chain holds and a name the text sets equal to the product (``R_{zxz}``) is bound to it (also when
the chain goes on to the product multiplied out, a member then left to the rest of the reader). When
they are not, nothing is said: the names alone give no angle, so a factor that is no turn about
its axis is left unchecked rather than judged.

A matrix so bound, written again at its arguments with one of them set (``R_{zxz}(\alpha,
\beta=0, \gamma) = …``), is that matrix with the setting put in (`_at_setting`).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.latex_spaces`, :mod:`derive.lecture.statements`,
:mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.latex_spaces import ONE_SPACE
from derive.lecture.statements import top_level
from derive.symbolic.rotations import trig_reduce

_EQUALS = re.compile(r"(?<![<>!\\])=")
_WRITTEN = re.compile(r"\\begin\{([bpBvV]?matrix)\}(.*?)\\end\{\1\}", re.S)
# between two written factors: spaces and alignment tabs (a quad has cut the statement before this reads it)
_SPACING = re.compile(rf"(?:{ONE_SPACE}|&)*")
_AXES = "123xyz"
_AT = re.compile(r"\s*(?P<name>.+?)\s*\((?P<args>[^()]*)\)\s*=(?P<rest>.*)\Z", re.S)


def _written_factors(text: str) -> list[str] | None:
    """The written matrices of a member that is nothing but their product, or None."""
    blocks, at = [], 0
    for m in _WRITTEN.finditer(text):
        if not _SPACING.fullmatch(text[at:m.start()]):
            return None
        blocks.append(m.group(0))
        at = m.end()
    return blocks if len(blocks) >= 2 and _SPACING.fullmatch(text[at:]) else None


def _axis_names(text: str):
    """The atoms of a member that is a product of names each saying one axis (one letter for
    them all), or None."""
    try:
        toks = lx.scan(text)
    except lx.NotRead:
        return None
    atoms = [t.value for t in toks]
    if len(atoms) < 2 or any(t.kind != "atom" for t in toks):
        return None
    if any(a.sub not in _AXES or a.sup or a.dots or a.primes or a.hat or a.tilde for a in atoms) or \
            len({(a.base, a.bold) for a in atoms}) != 1:
        return None
    return atoms


class AxisProducts:
    """Mixin of the checker. Uses ``self.vocab``, ``self.ctx``, ``self._matrix_name``,
    ``self._add`` and ``self.tex``."""

    def _axis_product(self, line, pieces) -> bool:
        """A display whose chain is ``[X =] A_a A_b … = M_1 M_2 …`` (names by axis, then the
        written factors): checked as the module says. False (the statements read one by one) for
        any other display, or when the written factors are not turns about the named axes."""
        chain = " ".join(p.strip() for p in pieces)
        cuts = top_level(chain, _EQUALS)
        if not cuts or len(cuts) > 3:
            return False
        members, at = [], 0
        for m in cuts:
            members.append(chain[at:m.start()].strip())
            at = m.end()
        members.append(chain[at:].strip())
        # X = A_z A_y A_x = [..][..][..] = [..]: X is bound to the product, the rest read as before
        bound_only = len(members) == 4
        written = _written_factors(members[-2 if bound_only else -1])
        names = _axis_names(members[-3 if bound_only else -2])
        if written is None or names is None or len(written) != len(names):
            return False
        try:
            factors = [lx.parse(w, self.vocab).members for w in written]
        except lx.NotRead:
            return False
        if any(len(f) != 1 or not isinstance(f[0].value, sp.MatrixBase) or f[0].value.shape != (3, 3)
               for f in factors):
            return False
        mats = [sp.Matrix(f[0].value) for f in factors]
        if any(len(m.free_symbols) > 1 for m in mats):
            return False
        axes = ["xyz"[_AXES.index(a.sub) % 3] for a in names]
        turns = self._turns_of_axes(mats, axes)
        if turns is None:
            return False
        sense, angles = turns
        product = mats[0]
        for m in mats[1:]:
            product = product * m
        if len(members) >= 3:
            self._product_bound(members[0], product)
        if bound_only:
            return False
        said = "; ".join(f"{a.text}: about {axis} by {self.tex(q)}" for a, axis, q in zip(names, axes, angles))
        self._add(line, " \\\\ ".join(pieces), "rotation", "holds",
                  f"each written factor the {sense} turn about the axis its name gives ({said})")
        self.settings_only = False
        return True

    def _turns_of_axes(self, mats, axes):
        """(sense, angles) when every matrix is the turn about its axis in one sense, by the one
        angle its entries are in (any angle for the identity, read as a turn by 0); else None."""
        rot = self.d.rot
        for sense, f in (("passive", rot.passive), ("active", rot.active)):
            angles = []
            for m, axis in zip(mats, axes):
                free = sorted(m.free_symbols, key=str)
                q = free[0] if free else sp.Integer(0)
                if not all(trig_reduce(sp.expand(x - y)) == 0 for x, y in zip(m, f(axis, q))):
                    break
                angles.append(q)
            else:
                return sense, angles
        return None

    def _product_bound(self, head, product):
        """``X = (the product)``: a plain name of the text's that it has not defined is the
        product's matrix from here on."""
        try:
            toks = lx.scan(head)
            sym = self.vocab.resolve(toks[0].value) if len(toks) == 1 and toks[0].kind == "atom" else None
        except lx.NotRead:
            return
        if isinstance(sym, lx.Generic) and sym not in self.ctx.defs and sym.is_commutative:
            self._matrix_name(sym, product)

    def _at_setting(self, line, pieces) -> bool:
        """``X(\\alpha, \\beta=0, \\gamma) = …`` with X a matrix the text has bound: the statement
        compared with X at the settings its arguments write (an argument without ``=`` is the
        angle itself); a member that differs fails. False when X is no bound matrix or an argument
        is not read."""
        m = _AT.match(" ".join(p.strip() for p in pieces))
        if m is None or "=" not in m.group("args"):
            return False
        try:
            toks = lx.scan(m.group("name"))
            if len(toks) != 1 or toks[0].kind != "atom":
                return False
            sym = self.vocab.resolve(toks[0].value)
            bound = self.ctx.defs.get(sym)
            if not isinstance(bound, sp.MatrixBase):
                return False
            setting = {}
            for arg in m.group("args").split(","):
                name, eq, value = arg.partition("=")
                if eq:
                    q = lx.parse(name, self.vocab).members
                    v = lx.parse(value, self.vocab).members
                    if len(q) != 1 or len(v) != 1 or not isinstance(q[0].value, sp.Symbol) \
                            or not v[0].value.is_number:
                        return False
                    setting[q[0].value] = v[0].value
            rest = lx.parse(m.group("rest"), self.vocab).members
        except lx.NotRead:
            return False
        target = sp.Matrix(bound).xreplace(setting).applyfunc(trig_reduce)
        said = ", ".join(f"{self.tex(q)} = {self.tex(v)}" for q, v in setting.items())
        for member in rest:
            value = member.value
            if not isinstance(value, sp.MatrixBase) or value.shape != target.shape:
                return False
            if any(trig_reduce(sp.expand(x - y)) != 0 for x, y in zip(value, target)):
                self._add(line, " \\\\ ".join(pieces), "rotation", "fails",
                          f"{self.tex(sym)} at {said} is {self.tex(target)}, not the matrix written",
                          self.tex(target))
                self.settings_only = False
                return True
        self._add(line, " \\\\ ".join(pieces), "rotation", "holds",
                  f"{self.tex(sym)}, the product bound above, at {said}: trig_reduce")
        self.settings_only = False
        return True
