"""Relations that do not hold as identities and are no slip either: the orientation a text
chooses (the fixed first axis along 𝐋) and the conditions it imposes.

A mixin of the notes checker (`derive.lecture.notes_check.Checker`): uses ``self.d`` (the
derivation), ``self.ctx`` (the text's context), ``self._resolve``, ``self._compare``,
``self._constants`` and ``self.tex``. Gives `Conditions._oriented` (why a relation holds with
the fixed first axis along 𝐋, or None) and `Conditions._undecidable` (why a relation is a
condition of the text rather than a slip, or None).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.comparing`, :mod:`derive.lecture.rotation_identities`,
:mod:`derive.lecture.primed_functions`,
:mod:`derive.lecture.vocabulary`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import functools

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import primed_functions, rotation_identities
from derive.lecture.comparing import free
from derive.lecture.vocabulary import FREE_NAMES
from derive.symbolic.lagrangian import ACCELS


class Conditions:
    """Mixin of the checker: see the module docstring."""

    def _oriented(self, line, val, targets, seed) -> str | None:
        """Why the claim holds with the fixed first axis along 𝐋 (`derive.lecture.orientation`), or
        None. Tried for a relation of the angles without rates (the text stating its orientation,
        I₁ω₁ = L sin θ sin ψ) and, once one held so, for the relations that follow."""
        rot = self.d.rot
        if self.ctx.orientation is not None and not isinstance(val, sp.MatrixBase):
            val = val.xreplace({lx.p_alpha_sym(): lx.LMAG})       # 𝐋 along the fixed first axis: p = L·ẑ = |𝐋|
        every = free(val).union(*(free(self._resolve(f)) for f in targets))
        if isinstance(val, sp.MatrixBase) or rot.ANGLES[0] in every or not every & set(lx.W) | {lx.LMAG}:
            return None
        stating = every & set(rot.ANGLES[1:]) and not every & (set(rot.RATES) | set(ACCELS))
        if self.ctx.orientation is None and not stating:
            return None
        along = self.d.along
        if not along.ok:
            return None
        for f in targets:
            a, b = along.apply(val), along.apply(self._resolve(f))
            if along.angles_left(a) or along.angles_left(b):
                continue
            ok, how = self._compare(a, b, seed + "/along-L")
            if ok:
                where = f", line {self.ctx.orientation}" if self.ctx.orientation is not None else ""
                self.ctx.orientation = self.ctx.orientation if self.ctx.orientation is not None else line
                return f"{how}, with the fixed first axis along 𝐋 (the orientation the text chooses{where})"
        return None

    def _undecidable(self, written, val, targets) -> str | None:
        """Why a relation that does not hold as an identity is no slip the derivation can name:
        it ties only the text's free variables (ω̃ᵢ, the moments, its own undefined symbols) and so
        is a condition the text imposes; or it ties the angles to ω̃ᵢ without their rates, which
        only the rates connect; or it ties the rates to symbols of a case the text set for ω̃ᵢ
        (ω̃₂ = ω sin α at one instant), a case not imposed on the angles. None when the derivation
        decides it."""
        rot = self.d.rot
        if written and val != 0 and isinstance(written[0], sp.Symbol) and \
                primed_functions.definitions(self.vocab, self.ctx.defs, [written[0]], self.tex):
            return None     # U'(θ) = (its derivative written out) = 0: the rewriting is an identity, only "= 0" a condition
        named = self._constant_named(val, targets)
        if named:
            return named
        rates = set(rot.RATES) | set(ACCELS)
        frames = set(lx.BASIS) | set(lx.PRIMED) | set(lx.INERTIAL)
        variables = rates | set(rot.ANGLES) | set(lx.W)
        case = set().union(*(free(v) for w, v in self.ctx.subs.items() if w in lx.W)) - variables
        every = free(val).union(*(free(self._resolve(f)) for f in targets))
        if every & rates and every & case:
            return ("ties the angles' rates to the values the text set for ω̃ᵢ in a case (an instant, a choice of "
                    "axes): the reader does not put that case into the angles, so it does not decide it")
        if written and isinstance(written[0], sp.Symbol) and written[0] in variables and \
                all(not free(self._resolve(m)) & variables for m in written[1:]):
            return (f"states the value of {self.tex(written[0])} in this motion: a result the derivation does "
                    "not give without solving the motion")
        derived = any(isinstance(x, lx.Quantity) or x in self.ctx.defs or x in rates or x in frames
                      for m in written for x in free(m)) or \
            any(hasattr(m, "has") and (m.has(lx.DT) or m.has(sp.Derivative)) for m in written) or \
            any(primed_functions.definitions(self.vocab, self.ctx.defs, free(m), self.tex) for m in written)
        if not derived and not rotation_identities.trig_matrices(val, [self._resolve(f) for f in targets]):
            return "an equation between the text's variables: a condition it imposes, not an identity"
        every = free(val).union(*(free(self._resolve(f)) for f in targets))
        loose = sorted(self.tex(x) for x in every if isinstance(x, lx.Generic) and x not in self.ctx.defs
                       and x not in self._constants())
        if loose:
            return f"involves {', '.join(loose)}, which the text has not defined"
        turns = isinstance(val, sp.MatrixBase) and (val.shape == (3, 3) or self._turned_column(written, val, targets))
        if not every & rates and every & set(rot.ANGLES) and not turns:
            # (a 3×3 matrix of the angles equated to another is an identity of rotations, decided)
            return ("an equation for the angles with no rates in it (ω̃ᵢ, the momenta and E are independent "
                    "of them there): a condition, such as a turning point or the orientation the text chose")
        return None

    def _turned_column(self, written, val, targets) -> bool:
        """A column that one side writes as a product of the text's own matrices (``C_Z(\\psi)
        C_X(\\theta) \\boldsymbol{e}_z``), equated to columns that all vary with the angles: the
        text multiplies its matrices out, an identity, not a condition. A side constant in the
        angles (``R e_3 = (0, 0, 1)``) may be the orientation the text picks, so it is none."""
        product = any(isinstance(self.ctx.defs.get(x), sp.MatrixBase) and not x.is_commutative
                      for m in written for x in free(m))
        sides = [val, *(self._resolve(f) for f in targets)]
        return product and all(isinstance(v, sp.MatrixBase) and v.shape == (3, 1) and
                               free(v) & set(self.d.rot.ANGLES) for v in sides)

    def _constant_named(self, val, targets) -> str | None:
        """A relation of the body's rates and one constant letter of the text's (A, B, C, δ, ε, φ)
        that no setting or solution has tied (``\\mathbf{J}^2 = I_1^2A^2 + I_3^2\\omega_3^2``, A the
        radius of 𝛚's circle): the relation says what the letter is in this motion, so it names it —
        recorded as its solution (the positive root where only its square is written), then used —
        and is no claim. None when the letter is not alone, or the relation is not linear in it or
        in its square."""
        if len(targets) != 1 or isinstance(val, sp.MatrixBase):
            return None
        target = self._resolve(targets[0])
        if isinstance(target, sp.MatrixBase):
            return None
        every = free(val) | free(target)
        letters = [x for x in every if type(x) is sp.Symbol and x.name in _LETTERS and x not in self.ctx.defs]
        tied = set().union(*(free(v) for v in [*self.ctx.subs.values(), *self.ctx.solutions.values()]))
        if len(letters) != 1 or letters[0] in tied or not every & set(lx.W):
            return None
        x, square = letters[0], sp.Dummy(positive=True)
        for unknown, put in ((square, {x ** 2: square}), (x, {})):
            eq = sp.expand(sp.expand(val - target).xreplace(put))
            if unknown is square and x in free(eq):
                continue            # the letter written otherwise than squared
            poly = sp.Poly(eq, unknown) if eq.has(unknown) else None
            if poly is None or poly.degree() != 1:
                continue
            value = _simplified(-poly.coeff_monomial(1) / poly.coeff_monomial(unknown))
            self.ctx.defs[x] = sp.sqrt(value) if unknown is square else value
            return f"names the text's constant {self.tex(x)} in this motion (recorded, then used)"
        return None


@functools.lru_cache(maxsize=256)
def _simplified(expr):
    """`sp.simplify` of an expression (immutable, so the kept result is the one it would give), kept
    per process: each reading of a text that names a constant by the same relation simplifies the same root."""
    return sp.simplify(expr)


_LETTERS = {name for name in FREE_NAMES.values() if name != "t"}
