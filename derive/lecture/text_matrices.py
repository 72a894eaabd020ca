"""The text's own matrices in products: its names for matrices put in as matrices, and matrices
it names by an axis and an angle.

Takes: values read by `derive.lecture.latex` in which some of the text's names
(non-commuting `latex.Generic` symbols) stand for matrices. Gives:

* `matrices_put` — the value with those names substituted, products multiplied as matrices in
  their written order (``-\\dot{\\mathbf{R}}_3 \\mathbf{R}^T_3``), transposes taken, blocks joined
  (``[\\mathbf{I}_1 \\; \\mathbf{R}_1 \\mathbf{I}_2 \\; …]``);
* `matrix_power` — Mⁿ, M⁻¹ by the adjugate over the determinant;
* the mixin `TextMatrices` of `derive.lecture.notes_check.Checker`, whose `_single_axis_turns`
  reads ``\\mathbf{R}_1(\\phi) \\mathbf{R}_2(\\theta) \\mathbf{R}_3(\\psi)`` as the single-axis turns of the
  text's sequence, and whose `_turn_label` reads the axis and angle a matrix's name gives its
  turn (``\\mathbf{R}_{x'}(\\theta)``), which the matrix written is then held to. A plain name
  applied to two angles in one product (``R_z(\\psi) R_x(\\theta) R_z(\\phi)``) is a turn per angle,
  in the sense the text's own turns have; a name bound to the turn by one angle and applied to
  another is never read as the bound turn (`_turn_at_another_argument` says why it is unchecked),
  unless the text defined it with its argument written, ``C_Z(\\phi) = …``, a function of its angle
  (`_functions_at`). A basis vector right of such matrices is its unit column (`_basis_columns`);
  a matrix named by the three angles that is the sequence's rotation with the first and third
  exchanged is a typo of it (`_angles_exchanged`), and so is a product of three single-axis turns
  that leaves out an angle the name lists (`_angle_left_out`), and a matrix of the three angles that is
  the stated sequence's rotation but for one entry that leaves its column no unit vector
  (`_one_entry_off`); a free letter A, B, C set equal to a 3×3 matrix names it (`_free_letter_named`); a
  new letter set equal to the stated sequence's angular velocity in body or space axes, written out as a
  column of the angles and their rates, holds as that column (`_angular_velocity_column`).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.vocabulary`, :mod:`derive.lecture.written_matrices`,
:mod:`derive.lecture.zero_test`, :mod:`derive.lecture.principal_form`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import itertools
import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.matrix_exp import MatrixExp
from derive.lecture.principal_form import diagonalised
from derive.lecture.vocabulary import Atom
from derive.lecture.written_matrices import Dot, NormSquared, taken
from derive.lecture.zero_test import entry_zero
from derive.symbolic.rotations import trig_reduce


_AT_TIME = re.compile(r"^(\s*\\?[A-Za-z]+(?:\s*_\s*(?:\{[^{}]*\}|\w))?)\s*\(\s*t\s*\)\s*=")
# a name at the time before the product of turns, ``R(t) =``: its argument is no factor
_NAME_OF = re.compile(r"^\s*[^=(){}]+(?:\{[^{}]*\}[^=(){}]*)*\(([^()=]*)\)\s*=")
# a left side that is one name with its arguments listed, ``C(\phi, \theta, \psi) =``


class ShapesApart(lx.NotRead, TypeError):
    """A sum of a matrix and a term that is none (``\\vec{V_b} - R\\,\\vec{V_w}`` with 𝐕_b a
    column the text wrote out and 𝐕_w a name it did not): the reader does not know the term's
    shape, so the statement cannot be read. A `TypeError` too, as SymPy's own sum would raise."""


PUT_NODES = 50000
# the most nodes one putting-in may build (its value, then every product it multiplies out):
# definitions that name one another (o = R V, V = R^T o) multiply their matrices again with every
# round, so without a bound the work grows without end


class TooLarge(lx.NotRead):
    """Putting in the text's definitions builds more than `PUT_NODES` nodes: the reader stops
    there and leaves the statement unchecked, naming the definitions it was putting in."""


def _spent(e, budget, rep):
    """Take ``e``'s nodes from ``budget`` (a one-item list), counting no further than what is left,
    so the count stays cheap; past the budget raise `TooLarge` naming what ``rep`` puts in."""
    budget[0] -= sum(1 for _ in itertools.islice(sp.preorder_traversal(e), budget[0] + 1))
    if budget[0] < 0:
        names = ", ".join(sorted({sp.latex(k) for k in rep}))
        raise TooLarge(f"putting in the text's definitions of {names} builds more than {PUT_NODES} terms "
                       "(definitions that name one another grow without end): the reader stops there")
    return e


def _added(out, a, written):
    """``out + a`` where one side may be a matrix: a zero beside a matrix is dropped; a term the
    reader holds as no matrix beside one raises `ShapesApart`, naming the symbols of ``written``
    (the terms as the text wrote them, before its names were put in)."""
    if isinstance(out, sp.MatrixBase) == isinstance(a, sp.MatrixBase):
        return out + a
    if (out if isinstance(a, sp.MatrixBase) else a) == 0:
        return a if isinstance(a, sp.MatrixBase) else out
    names = ", ".join(sorted({sp.latex(s) for w in written for s in w.free_symbols}))
    raise ShapesApart(f"adds a matrix to a term in {names}, which the reader holds as no matrix "
                      "(the text has not given its shape)")


def matrices_put(e, rep, columns=None, budget=None):
    """``e.xreplace(rep)`` where some of the text's names stand for matrices: rebuilt from the leaves
    up, a product multiplied as matrices in its written order and a transpose taken, since SymPy's
    Mul would take a matrix among its factors for a scalar. A matrix added to a term of no matrix
    shape raises `ShapesApart`. ``columns``: basis vectors that, in a product with matrices, are
    their unit columns, last in the product (`TextMatrices._basis_columns`). ``budget``: the nodes it may
    still build; past `PUT_NODES` in all it raises `TooLarge`."""
    if budget is None:
        budget = [PUT_NODES]
        _spent(e, budget, rep)
    if e in rep:
        return rep[e]
    if isinstance(e, sp.MatrixBase):
        blocks = [[matrices_put(e[i, j], rep, columns, budget) for j in range(e.cols)] for i in range(e.rows)]
        if all(isinstance(b, sp.MatrixBase) for row in blocks for b in row):     # [𝐈₁  R₁𝐈₂  R₁R₂𝐈₃]: a block matrix
            return sp.ImmutableMatrix(sp.Matrix.vstack(*[sp.Matrix.hstack(*row) for row in blocks]))
        return sp.ImmutableMatrix(blocks)
    if not getattr(e, "args", ()):
        return e
    args = [matrices_put(a, rep, columns, budget) for a in e.args]
    if not any(isinstance(a, sp.MatrixBase) for a in args):
        return e.func(*args) if args != list(e.args) else e
    basis = [k for k, a in enumerate(e.args) if a in (columns or {})] if isinstance(e, sp.Mul) else []
    if len(basis) == 1:             # C e_z: the column stands right of the matrices (SymPy put the symbol first)
        args = [a for k, a in enumerate(args) if k != basis[0]] + [columns[e.args[basis[0]]]]
    if isinstance(e, (sp.Mul, sp.Add, lx.MatProduct)):
        out = args[0]
        for k, a in enumerate(args[1:], 1):
            if isinstance(e, sp.Add):
                out = _added(out, a, [w for w, v in zip(e.args[:k + 1], args) if not isinstance(v, sp.MatrixBase)])
            else:
                out = _spent(out * a, budget, rep) if isinstance(a, sp.MatrixBase) or isinstance(out, sp.MatrixBase) \
                    else out * a
    elif isinstance(e, lx.Transposed):
        out = args[0].T
    elif isinstance(e, (Dot, NormSquared)):
        out = taken(e, args)
    elif isinstance(e, sp.Pow) and isinstance(args[0], sp.MatrixBase) and args[0].cols == 1 and args[1] == 2:
        out = (args[0].T * args[0])[0]      # 𝐫² of a column: 𝐫·𝐫, as a vector's square is written
    elif isinstance(e, sp.Pow) and isinstance(args[0], sp.MatrixBase) and args[1].is_integer:
        out = matrix_power(sp.MatPow(sp.ImmutableMatrix(args[0]), args[1], evaluate=False))
    elif e.func is sp.exp and isinstance(args[0], sp.MatrixBase):
        out = MatrixExp(args[0])        # SymPy's Jordan form of a symbolic cubic's roots takes minutes
    else:
        out = e.func(*args)
    return sp.ImmutableMatrix(out) if isinstance(out, sp.MatrixBase) else out


def matrix_power(e):
    """M^n of a matrix the text wrote; M⁻¹ by the adjugate over the determinant, both in their
    canonical trigonometric form (a rotation's determinant reduces to 1)."""
    m, n = sp.ImmutableMatrix(e.args[0]), int(e.args[1])
    if n >= 0:
        return m ** n
    det = trig_reduce(m.det())
    if det == 0:
        return e
    return sp.ImmutableMatrix((m.adjugate() / det).applyfunc(trig_reduce)) ** (-n)


def _angle_swapped(piece, old, new) -> str | None:
    """The statement as written with the angle ``old`` of its right side put as ``new`` (the
    correction in the text's own layout), or None when the right side does not spell it so."""
    at = piece.find("=")
    spelled = re.compile(re.escape(old) + r"(?![A-Za-z])")
    if at < 0 or not spelled.search(piece, at):
        return None
    return piece[:at] + spelled.sub(lambda _: new, piece[at:])


class TextMatrices:
    """Mixin of the checker. Uses ``self.d`` (the derivation), ``self.vocab``, ``self.ctx``,
    ``self._matrix_name``, ``self._add`` and ``self.tex``."""

    def _turn_label(self, text: str):
        """``\\mathbf{R}_{x'}(\\theta) = …``: the axis (x, y, z; a primed axis is the same one in its
        own frame, and 1, 2, 3 stand for x, y, z) and the angle a matrix's written name gives its
        turn, or None when the left side is no such name."""
        try:
            toks = lx.scan(text)
        except lx.NotRead:
            return None
        if len(toks) < 5 or [t.kind for t in toks[:5]] != ["atom", "op", "atom", "op", "rel"] or \
                (toks[1].value, toks[3].value) != ("(", ")"):
            return None
        name, arg = toks[0].value, toks[2].value
        axis = name.sub.replace("'", "").strip("{} ")
        axis = axis.lower() if axis in ("X", "Y", "Z") else axis        # C_Y(φ): the axis Y of the fixed frame is y
        if axis not in ("1", "2", "3", "x", "y", "z") or name.sup or name.dots:
            return None
        try:
            angle = self.vocab.resolve(arg)
        except lx.NotRead:
            return None
        if angle not in self.d.rot.ANGLES:
            return None
        self.__dict__.setdefault("functions_of", {})[name.with_(text="")] = (angle, arg.text)   # the turn as its angle's function
        return "xyz"["123xyz".index(axis) % 3], angle

    def _turn_at_another_argument(self, text: str) -> str | None:
        """``R_z(\\psi)`` where ``R_z`` is bound to the turn by φ: why the statement is not read (the
        bound matrix would stand in for a turn by another angle), or None when every bound turn's
        name is applied to the angle it is bound at, or to none."""
        try:
            toks = lx.scan(text)
        except lx.NotRead:
            return None
        self._functions_at(toks)
        angles = set(self.d.rot.ANGLES)
        for k in range(len(toks) - 2):
            a, o, g = toks[k:k + 3]
            if a.kind != "atom" or (o.kind, o.value) != ("op", "(") or (g.kind == "atom" and g.value.bold):
                continue            # 𝐀(𝐁) is a product of the text's matrices
            try:
                sym = self.vocab.resolve(a.value)
            except lx.NotRead:
                continue
            bound = self.ctx.defs.get(sym) if isinstance(sym, lx.Generic) else None
            if not isinstance(bound, sp.MatrixBase) or bound.shape != (3, 3) or self._bound_at_argument(a, g):
                continue
            free = set(bound.free_symbols)
            if len(free) != 1 or not free <= angles:
                continue
            (at,) = free
            close = next((j for j in range(k + 2, len(toks)) if (toks[j].kind, toks[j].value) == ("op", ")")), None)
            if close == k + 3 and g.kind == "atom":
                try:
                    if self.vocab.resolve(g.value) == at:
                        continue
                except lx.NotRead:
                    pass
            arg = text[o.pos + 1:toks[close].pos].strip() if close is not None else text[o.pos + 1:].strip()
            return (f"{self.tex(sym)} is the turn by {self.tex(at)}; its turn by {arg} is not read "
                    f"(the turn by {self.tex(at)} would stand in for it)")
        return None

    def _bound_at_argument(self, a, g) -> bool:
        """``R_1(\\theta)`` where the sequence's product wrote ``R_1`` with its argument and the name at
        this argument is bound to its turn (by :meth:`_functions_at`)."""
        if g.kind != "atom" or a.value.with_(text="") not in self.__dict__.get("argument_turns", {}):
            return False
        return self.vocab._generic(a.value.with_(sup=f"({g.value.text})")) in self.ctx.defs

    def _functions_at(self, toks):
        """``C_Z(\\psi)`` where the text defined ``C_Z(\\phi) = …`` with its argument written: a
        function of its angle, so at another angle of the sequence it is the matrix with φ put as
        ψ, and the name at that argument is bound so. A name bound without its argument
        (``R_z = …`` in φ) is that matrix at φ only: ``R_z(\\phi)`` is bound to it, ``R_z(\\psi)``
        left as it is."""
        known = self.__dict__.get("functions_of", {})
        for k in range(len(toks) - 3):
            a, o, g, c = toks[k:k + 4]
            if a.kind != "atom" or g.kind != "atom" or (o.kind, o.value, c.kind, c.value) != ("op", "(", "op", ")"):
                continue
            try:
                arg = self.vocab.resolve(g.value)
                at, spelled = known.get(a.value.with_(text=""), (None, None))
                bound = self.ctx.defs.get(self.vocab._generic(a.value.with_(sup=f"({spelled})")) if spelled
                                          else self.vocab.resolve(a.value))
            except lx.NotRead:
                continue
            if spelled is None and a.value.with_(text="") in self.__dict__.get("argument_turns", {}):
                at = self.__dict__["argument_turns"][a.value.with_(text="")]
                if arg == at:
                    continue
            elif spelled is None and isinstance(bound, sp.MatrixBase) and set(bound.free_symbols) == {arg}:
                at = arg                  # R_z(φ) after R_z = (the turn by φ): that turn
            elif arg == at:
                continue
            if arg not in self.d.rot.ANGLES or not isinstance(bound, sp.MatrixBase) or bound.shape != (3, 3) \
                    or set(bound.free_symbols) != {at}:
                continue
            sym = self.vocab._generic(a.value.with_(sup=f"({g.value.text})"))
            if sym not in self.ctx.defs and sym.is_commutative:
                self._matrix_name(sym, sp.Matrix(bound).xreplace({at: arg}))

    def _single_axis_turns(self, text: str) -> str:
        """``\\mathbf{R}_1(\\phi) \\mathbf{R}_2(\\theta) \\mathbf{R}_3(\\psi)``: matrices named by an axis (1, 2, 3
        or x, y, z) and applied to one angle each are the single-axis turns; the sense, passive or
        active for all of them, is the one whose product is the sequence's R or its transpose. Each
        name is bound to its turn (used bare from then on), and the text is read without the
        arguments. The text unchanged when the factors are no such product."""
        try:
            toks = lx.scan(text)
        except lx.NotRead:
            return text
        rot, found = self.d.rot, self._turn_factors(toks)
        if found is None:
            return text
        # one name at two angles (R_z(ψ) R_x(θ) R_z(φ)): each name-and-argument is its own turn, which
        # the reader keeps for a plain name (R_z(ψ) is read as that); a bold name drops its argument
        at_arguments = len({f[0].text for f in found}) != 3
        if at_arguments and any(f[0].bold for f in found):
            return text
        R = self.d.conv.matrix()
        for sense in (rot.passive, rot.active):
            turns = [sp.Matrix(sense(axis, angle)) for _, axis, angle, _, _, _ in found]
            product = turns[0] * turns[1] * turns[2]
            if any(all(rot.trig_reduce(x - y) == 0 for x, y in zip(product, target)) for target in (R, R.T)):
                break
        else:
            return text
        self._product_named(toks, found[0][3], product)
        if at_arguments:
            self._turns_at_arguments(found, sense)
            return _AT_TIME.sub(r"\1 =", text, count=1)
        for (atom, _, angle, start, end, _), turn in zip(reversed(found), reversed(turns)):
            sym = self.vocab.resolve(atom)
            if isinstance(sym, lx.Generic) and sym not in self.ctx.defs and sym.is_commutative:
                self._matrix_name(sym, turn)
                # written with its argument, the name is its angle's function (R_1(θ) later is R_1 at θ)
                self.__dict__.setdefault("argument_turns", {})[atom.with_(text="")] = angle
            text = text[:start] + text[end:]
        return _AT_TIME.sub(r"\1 =", text, count=1)

    def _turn_factors(self, toks):
        """The three factors ``name_axis(angle)`` of a product of single-axis turns by three different
        angles of the sequence, each (atom, axis, angle, start, end, argument atom), or None."""
        found = []
        for k in range(len(toks) - 3):
            a, o, g, c = toks[k:k + 4]
            if a.kind != "atom" or a.value.sub not in ("1", "2", "3", "x", "y", "z") or a.value.sup or \
                    a.value.dots or (o.kind, o.value) != ("op", "(") or g.kind != "atom" or (c.kind, c.value) != ("op", ")"):
                continue
            try:
                angle = self.vocab.resolve(g.value)
            except lx.NotRead:
                continue
            if angle in self.d.rot.ANGLES:
                found.append((a.value, "xyz"["123xyz".index(a.value.sub) % 3], angle, o.pos, c.pos + 1, g.value))
        return found if len(found) == 3 and len({f[2] for f in found}) == 3 else None

    def _product_named(self, toks, at, product):
        """``R = R_3(\\theta_1) R_1(\\theta_2) R_3(\\theta_3) = …``: the plain name the text sets equal to
        the product of the turns (a name it has not defined) is that product from here on. Only in a
        chain: ``R = (the turns)`` alone is read as a rotation R and checked as one."""
        if sum(1 for t in toks if t.kind == "rel") < 2:
            return
        before = [t for t in toks if t.pos < at]
        if before[-2:-1] and before[-1].kind == "atom":       # "R = R_3(…)": the first turn's letter is before[-1]
            before = before[:-1]
        if len(before) < 2 or before[0].kind != "atom" or before[-1].kind != "rel" or before[-1].value != "=":
            return
        inner = before[1:-1]
        if inner and [(t.kind, t.value) for t in inner] not in ([("op", "("), ("atom", inner[1].value), ("op", ")")],):
            return                        # R(t) = …: a name with its argument, else nothing
        try:
            sym = self.vocab.resolve(before[0].value)
        except lx.NotRead:
            return
        if isinstance(sym, lx.Generic) and sym not in self.ctx.defs and sym.is_commutative:
            self._matrix_name(sym, product)

    def _turns_at_arguments(self, found, sense):
        """Bind each plain name-at-argument of ``found`` (``R_z(\\psi)``, read as its own name) the text
        has not defined to its turn, in the sense of those it has defined (all passive or all
        active), else in ``sense``, the one whose product is the sequence's R; nothing when the
        defined ones disagree on the sense."""
        rot = self.d.rot
        syms = [self.vocab._generic(atom.with_(sup=f"({arg.text})")) for atom, *_, arg in found]
        learned = []
        for sym, (_, axis, angle, *_) in zip(syms, found):
            if sym in self.ctx.defs:
                bound = sp.Matrix(self.ctx.defs[sym])
                learned.append({f for f in (rot.passive, rot.active) if bound.shape == (3, 3) and
                                all(trig_reduce(x - y) == 0 for x, y in zip(bound, f(axis, angle)))})
        if learned:
            agreed = set.intersection(*learned)
            if len(agreed) != 1:
                return        # a bound matrix that is no turn of its axis, or senses that disagree
            (sense,) = agreed
        for sym, (_, axis, angle, *_) in zip(syms, found):
            if sym not in self.ctx.defs and sym.is_commutative:
                self._matrix_name(sym, sp.Matrix(sense(axis, angle)))

    def _turn_by_another_angle(self, line, piece, m, axis, angle) -> bool:
        """The matrix of a turn named ``R_x(θ)`` written in another angle: the named turn with the
        angle of the entries swapped is a typo of it (the name and the entries disagree on one
        angle); any other matrix is left unchecked, since the name alone decides nothing."""
        rot = self.d.rot
        (other,) = m.free_symbols
        swapped = m.xreplace({other: angle})
        for kind, f in (("passive", rot.passive), ("active", rot.active)):
            target = sp.Matrix(f(axis, angle))
            if all(trig_reduce(x - y) == 0 for x, y in zip(swapped, target)):
                self._turn_meant = target
                self._add(line, piece, "rotation", "typo",
                          f"the {kind} turn about {axis} by {self.tex(other)}, but its name says the turn "
                          f"by {self.tex(angle)}: the entries must be in {self.tex(angle)}",
                          _angle_swapped(piece, self.tex(other), self.tex(angle)) or self.tex(target))
                return True
        self._add(line, piece, "rotation", "unchecked",
                  f"named the turn about {axis} by {self.tex(angle)}, but written in {self.tex(other)} only, "
                  f"and no turn by {self.tex(angle)} with that angle swapped")
        return True

    def _angles_exchanged(self, line, piece, m, named) -> bool:
        """``C(\\phi, \\theta, \\psi) = [a matrix]`` that is one of the rotations ``named`` (R, Rᵀ)
        with the first and third angles exchanged, or that but for one entry: a typo of that
        rotation, when the text states its sequence and the angles' names and the matrix's name lists
        the three angles in the sequence's order, so that the text itself says which angle turns
        first. False (nothing said) for any other matrix or name."""
        notes = self.notes
        angles = tuple(self.d.rot.ANGLES)
        if not notes.convention_stated or not ("angles" in notes.declared or notes.angles_stated) or \
                self._angles_listed(getattr(self, "_text", piece)) != angles:
            return False
        first, third = angles[0], angles[2]
        for what, right in named.items():
            target = sp.Matrix(right).xreplace({first: third, third: first})
            off = [k for k in range(9) if not entry_zero(m[k] - target[k])]
            if len(off) > 1:
                continue
            sign = f", and the entry in row {off[0] // 3 + 1}, column {off[0] % 3 + 1} written otherwise" if off else ""
            self._turn_meant = sp.Matrix(right)        # the products after it use the matrix meant
            self._add(line, piece, "rotation", "typo",
                      f"{what} with {self.tex(first)} and {self.tex(third)} exchanged{sign}: the text's "
                      f"sequence turns by {self.tex(first)} first, and its name lists the angles so",
                      self.tex(sp.Matrix(right)))
            return True
        return False

    def _one_entry_off(self, line, piece, m, named) -> bool:
        """A matrix of the three angles that is one of the rotations ``named`` (R, Rᵀ of the sequence the
        text states) but for one entry whose column is then no unit vector: no rotation at all, so a typo of
        that rotation, and the products after it use the rotation meant. False (nothing said) where the
        text states no sequence, more than one entry is off, or the column stays a unit vector."""
        if not self.notes.convention_stated:
            return False
        for what, right in named.items():
            right = sp.Matrix(right)
            off = [k for k in range(9) if not entry_zero(m[k] - right[k])]
            if len(off) != 1:
                continue
            row, col = divmod(off[0], 3)
            if entry_zero(sum(m[r, col] ** 2 for r in range(3)) - 1):
                continue
            self._turn_meant = right
            self._add(line, piece, "rotation", "typo",
                      f"{what} but for the entry in row {row + 1}, column {col + 1}, which leaves that column "
                      "no unit vector: the matrix written is no rotation", self.tex(right))
            return True
        return False

    def _angular_velocity_column(self, line, piece, m) -> bool:
        """A column of the angles and their rates, in a text that states its sequence, that is the
        sequence's angular velocity in body axes (vect(Rᵀ Ṙ)) or in space axes (vect(Ṙ Rᵀ)): it `holds` as
        that column. Nothing is said of any other column (the text's letter may name anything)."""
        if not self.notes.convention_stated or m.shape != (3, 1):
            return False
        for what, target in (("body", self.d.omega), ("space", self.d.conv.omega_space())):
            if all(entry_zero(sp.expand(x - y)) for x, y in zip(m, target)):
                self._add(line, piece, "definition", "holds",
                          f"the stated sequence's angular velocity in {what} axes, written out in its angles' rates")
                return True
        return False

    def _angle_left_out(self, text: str):
        """``R(\\phi, \\theta, \\psi) = R_z(\\psi) R_y(\\theta) R_x(\\psi)``: a name listing the sequence's three
        angles set equal to a product of three turns named by an axis, one angle each, that leaves a listed
        angle out and turns by another twice. Whatever the turns' sense, such a product does not depend on
        the angle left out, so it is a typo: ("typo", why); None for any other statement."""
        listed, m = self._angles_listed(text), _NAME_OF.match(text)
        if listed is None or len(set(listed)) != 3 or not set(listed) <= set(self.d.rot.ANGLES):
            return None
        try:
            toks = lx.scan(text[m.end():])
        except lx.NotRead:
            return None
        if len(toks) != 12 or not all(
                a.kind == "atom" and a.value.sub in ("1", "2", "3", "x", "y", "z") and not a.value.sup and not a.value.dots
                and (o.kind, o.value, c.kind, c.value) == ("op", "(", "op", ")") and g.kind == "atom"
                for a, o, g, c in (toks[k:k + 4] for k in range(0, 12, 4))):
            return None
        try:
            turns = [self.vocab.resolve(toks[k + 2].value) for k in range(0, 12, 4)]
        except lx.NotRead:
            return None
        if len(set(turns)) != 2 or not set(turns) < set(listed):
            return None
        (out,) = set(listed) - set(turns)
        twice = next(a for a in turns if turns.count(a) == 2)
        return ("typo", f"the product turns by {self.tex(twice)} twice and never by {self.tex(out)}, which its "
                        f"name lists: it does not depend on {self.tex(out)}")

    def _angles_listed(self, text: str):
        """The symbols a left side ``N(a, b, c) =`` lists as its name's arguments, or None."""
        m = _NAME_OF.match(text)
        if m is None:
            return None
        try:
            toks = [lx.scan(a) for a in m.group(1).split(",")]
            return tuple(self.vocab.resolve(t[0].value) if len(t) == 1 and t[0].kind == "atom" else None
                         for t in toks)
        except lx.NotRead:
            return None

    def _basis_columns(self, value) -> dict:
        """The basis vectors of ``value`` the text has not defined, each as its unit column: a bold
        𝐞 with the subscript x, y, z (either case) or 1, 2, 3. In a product with a matrix such a
        vector can only be the column of its components in its own frame, (1, 0, 0) for 𝐞_x."""
        out = {}
        for s in value.free_symbols if hasattr(value, "free_symbols") else ():
            atom = self.vocab.generic.get(s) if isinstance(s, lx.Generic) else None
            if s in lx.BASIS:
                k = lx.BASIS.index(s)
            elif atom is not None and atom.base == "e" and atom.bold and atom.sub in tuple("xyzXYZ") and \
                    not (atom.sup or atom.dots or atom.primes or atom.hat or atom.tilde or atom.mark):
                k = "xyz".index(atom.sub.lower())
            else:
                continue
            if s not in self.ctx.defs and s not in self.ctx.subs:
                out[s] = sp.ImmutableMatrix([int(j == k) for j in range(3)])
        return out

    def _free_letter_named(self, sym, value):
        """``C = [a 3×3 matrix]``, ``C(\\phi, \\theta, \\psi) = …``: a letter the reader holds only as a
        free constant (A, B, C) set equal to a square matrix is the text's name for that matrix, as
        ``R = …`` is; the letter is that name from here on. Any other side is returned as it is."""
        if type(sym) is not sp.Symbol or sym.name not in ("A", "B", "C") or \
                not isinstance(value, sp.MatrixBase) or value.shape != (3, 3):
            return sym
        atom = Atom(sym.name)
        self.vocab.defined[atom] = self.vocab._generic(atom)
        return self.vocab.defined[atom]

    def _free_letter_moved(self, sym, mat, atom):
        """A free letter named as a matrix (`_free_letter_named`) and now bound to ``mat``: the letter
        stands for the matrix from here on, and the text's names it defined before as the letter or
        its transpose (``R = C^T``, read while C was a free constant) are defined by the matrix."""
        if self.vocab.defined.get(atom) != sym:
            return
        self.vocab.defined[atom] = mat
        free = sp.Symbol(atom.base, real=True)
        for name, v in list(self.ctx.defs.items()):
            if v in (free, lx.Transposed(free)):
                self.ctx.defs[name] = v.xreplace({free: mat})

    def _matrix_again(self, line, piece, sym, written) -> bool:
        """``R = [a matrix]`` for a name the text has bound to a 3×3 matrix already: a text that
        writes each rotation in turn as R names a new matrix, not the old one again. Re-bound (and
        checked as the rotation it is) when it is one of the rotations of the text's angles, or when
        it is in other angles than the bound one (a matrix of θ after one of φ is no claim about
        that one); True when so handled. The same angles and no rotation: False, it is compared."""
        old = self.ctx.defs.get(sym) if isinstance(sym, lx.Generic) else None
        if self._column_anew(line, piece, sym, old, written):
            return True
        # R(φ, θ, ψ) = [a matrix] where R was defined before as no matrix: the angles' matrix, named anew
        anew = old is not None and not isinstance(old, sp.MatrixBase) and \
            self._angles_listed(getattr(self, "_text", piece)) == tuple(self.d.rot.ANGLES)
        if not anew and (not isinstance(old, sp.MatrixBase) or old.shape != (3, 3)):
            return False
        value = self._resolve(written)
        if not isinstance(value, sp.MatrixBase) or value.shape != (3, 3):
            return False
        if anew:
            self._turn_meant = None
            if self._rotation(line, piece, sp.Matrix(value)):
                self._matrix_name(sym, value if self._turn_meant is None else self._turn_meant)
                return True
            return False
        if self._rotation(line, piece, sp.Matrix(value), self._turn_label(getattr(self, "_text", piece))):
            self.ctx.defs[sym] = sp.ImmutableMatrix(value)
            return True
        if (why := diagonalised(old, value)) is not None:
            return self._add(line, piece, "identity", "holds", why) or True
        if value.free_symbols == old.free_symbols:
            return False
        self.ctx.defs[sym] = sp.ImmutableMatrix(value)
        self._add(line, piece, "new symbol", "unchecked",
                  f"defines the text's matrix {self.tex(sym)} anew, in other angles (recorded, then used)")
        return True

    def _column_anew(self, line, piece, sym, old, written) -> bool:
        """``𝛀 = (a, b, c)``, a written column, for a name the text set before as no matrix through a
        bold letter it never wrote out (``𝛀 = ω𝐧``, 𝐧 an axis named in words): the name is the column
        from here on; its earlier value, in a vector of unknown components, is not compared with it."""
        if old is None or sp.Matrix(written).shape != (3, 1) or sym not in self.vocab.generic:
            return False
        if isinstance(old, sp.MatrixBase):
            return self._column_again(line, piece, sym, old, written)
        unwritten = [self.tex(s) for s in getattr(old, "free_symbols", ()) if s not in self.ctx.defs and
                     getattr(self.vocab.generic.get(s), "bold", False)]
        if not unwritten:
            return False
        self._matrix_name(sym, self._resolve(written))
        self._add(line, piece, "new symbol", "unchecked",
                  f"defines the text's vector {self.tex(sym)} by its components (recorded, then used); its value "
                  f"before, through {', '.join(sorted(unwritten))}, which the text does not write out, is not compared")
        return True

    def _column_again(self, line, piece, sym, old, written) -> bool:
        """``{\\bf n} = (1, 0, 0)`` after ``{\\bf n} = (0, 0, 1)`` (another axis), a column of numbers then
        written out in angles (the fixed axis in a moving basis), or a written column set again in a later
        section (``{\\bf r}`` in spherical after cylindrical coordinates, another body): the name that
        column from here on, not compared with the old one. A column of symbols set again to symbols
        in its own section is compared as before (False)."""
        value = self._resolve(written)
        numbers = lambda col: all(sp.sympify(x).is_number for x in col)  # noqa: E731
        if old.shape != (3, 1) or not isinstance(value, sp.MatrixBase) or sp.Matrix(value) == sp.Matrix(old) or \
                sym in self.ctx.columns and not numbers(value) and not numbers(old):
            return False
        self.ctx.defs[sym] = sp.ImmutableMatrix(value)
        self.ctx.columns.add(sym)
        self._add(line, piece, "new symbol", "unchecked",
                  f"defines the text's vector {self.tex(sym)} anew by its components (a new case or body; recorded, then used)")
        return True
