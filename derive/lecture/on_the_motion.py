"""Statements that hold on the motion the text describes, not as identities: the rates it solved
for, and Lagrange's equations themselves.

Takes: a claim the notes checker (`derive.lecture.notes_check.Checker`) found not to hold as an
identity. Gives: the mixin `OnTheMotion`, which tries two readings a careful reader gives before
calling such a claim wrong —

1. **in this motion**: the text has stated the rates of the motion it studies (``\\dot\\phi =
   M_z/I_1``, kept in ``ctx.motion``); with those put in, the claim holds (``∂L/∂θ = … = 0`` of a
   steady precession);
2. **Lagrange's equation**: claim − derived is ±(d/dt ∂L/∂q̇ − ∂L/∂q) for one coordinate q, with
   the Lagrangian the text uses (``∂L/∂θ = d/dt(∂L/∂θ̇)``): the law of motion, true on every motion.

An angle the text's running text holds at a number (``the nutation angle stays $\\theta =
\\frac{\\pi}{2}$``, kept in ``ctx.held``) is part of that motion too, with no rate: in reading 1 it is put
in with its rate and acceleration zero (``\\omega_1 = \\dot\\phi\\sin\\psi`` of an upright disk). An
angle held at two numbers in one section (``$\\theta = 0$`` or ``$\\pi$``) names cases, and neither is put in.

Either only makes a claim hold; it never flags one. And a third, which judges:

3. **at the angle the text gives**: ``\\tan\\theta = \\frac{I_1\\omega_0}{I_3\\Omega}``, an angle (or its
   tangent, sine or cosine) equal to constants of the text's, is the orientation of its motion
   (kept in ``ctx.angles_stated``); a later relation of the angles alone, with no rates, which is
   no identity, is judged with those angles put in (``\\tan\\alpha = \\frac{I_3}{I_1}\\tan\\theta``
   holds, a step of a chain that breaks it is a slip), the why naming the line it stands on. May import: :mod:`derive.lecture.latex`,
:mod:`derive.lecture.written_rates`, :mod:`derive.lecture.sparse_forms`, :mod:`derive.lecture.zero_test` (its exact screen),
:mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.sparse_forms import free_symbols, trig_zero
from derive.lecture.written_rates import opens_with_rate
from derive.lecture.zero_test import expanded, surely_nonzero
from derive.symbolic.lagrangian import ACCELS
from derive.symbolic.rotations import ANGLES, RATES, trig_reduce


_INVERSE = {sp.tan: sp.atan, sp.sin: sp.asin, sp.cos: sp.acos, sp.cot: sp.acot}
_TRIG_FIRST = re.compile(r"^\s*&?\s*(\\(?:tan|sin|cos|cot)(?![A-Za-z])\s*)?")


def _free(obj) -> set:
    return set(free_symbols(obj)) if hasattr(obj, "free_symbols") else set()


def _trig_zero(d) -> bool:
    """``trig_reduce(d) == 0``, in the sparse ring where d is a polynomial it reads."""
    zero = trig_zero(d, ANGLES)
    return trig_reduce(d) == 0 if zero is None else zero


class OnTheMotion:
    """Mixin of the checker: see the module docstring. Uses ``self.ctx`` (``motion``, ``forms_held``),
    ``self.d``, ``self._resolve``, ``self._unify``, ``self._compare`` and ``self.tex``."""

    def _note_motion(self, line, piece):
        """``\\dot\\phi = M_z/I_1`` (or ``\\frac{d\\phi}{dt} = …``), a rate given by constants and the
        angles: the rate of the motion the text studies, kept as written (read with the names in
        force where it is used)."""
        head = _TRIG_FIRST.sub("", piece)
        angle_first = any(re.match(r"\\?" + re.escape(a.partition("_")[0]) + r"(?![A-Za-z])", head)
                          for a in self.notes.angles)
        rate_first = opens_with_rate(piece)
        try:
            parsed = lx.parse(piece, self.vocab) if rate_first or angle_first else None
        except (lx.NotRead, lx.Words):
            return
        members = [m.value for m in parsed.members] if parsed is not None else []
        if not rate_first:
            self._note_angle(line, members, parsed)
            return
        if len(members) < 2 or members[0] not in RATES or set(parsed.relations) - {"="}:
            return
        value = members[-1]
        try:
            resolved = self._resolve(value)
        except (TypeError, ValueError, AttributeError):
            return
        if any(isinstance(x, lx.Generic) and x.name == "const" for x in _free(value)):
            return                  # "= const" says it is constant, not what it is
        if not _free(resolved) & (set(RATES) | set(ACCELS) | set(lx.W)) and not isinstance(resolved, sp.MatrixBase):
            self.ctx.motion[members[0]] = (value, line)

    def _note_angle(self, line, members, parsed):
        """``\\tan\\theta = \\frac{I_1\\omega_0}{I_3\\Omega}``: an angle of the motion given by constants."""
        if len(members) < 2 or set(parsed.relations) - {"="}:
            return
        head = members[0]
        inverse = _INVERSE.get(type(head)) if isinstance(head, sp.Function) else (lambda x: x)
        angle = head.args[0] if isinstance(head, sp.Function) else head
        if inverse is None or angle not in ANGLES or isinstance(members[-1], sp.MatrixBase):
            return
        try:
            value = self._resolve(members[-1])
        except (TypeError, ValueError, AttributeError):
            return
        if head is angle and not isinstance(value, sp.MatrixBase) and not _free(value) and len(members) == 2 \
                and getattr(self, "_inline", False):
            # running text holding an angle at a number: the motion's, unless a second number makes cases
            held = self.ctx.held.get(angle, (value, line))
            self.ctx.held[angle] = (value, line) if held is not None and sp.simplify(held[0] - value) == 0 else None
            return
        if isinstance(value, sp.MatrixBase) or not _free(value) or \
                _free(value) & (set(ANGLES) | set(RATES) | set(ACCELS) | set(lx.W) | {lx.t}):
            return
        self.ctx.angles_stated[angle] = (inverse(value), line)

    def _at_stated_angles(self, line, piece, kind, value, val, target, parsed, k, keep) -> bool:
        """A relation of the angles alone, no identity, judged at the angles the text gave (item 3 of
        the module docstring); False when it involves an angle the text has not given."""
        used = (_free(val) | _free(target)) & set(ANGLES)
        stated = self.ctx.angles_stated
        if not used or not used <= set(stated) or isinstance(val, sp.MatrixBase):
            return False
        where = ", ".join(f"{self.tex(a)} = {self.tex(stated[a][0])} (line {stated[a][1]})"
                          for a in sorted(used, key=ANGLES.index))
        saved = self.ctx.subs
        self.ctx.subs = {**saved, **{a: stated[a][0] for a in used}}
        try:
            ok, why = self._compare(val, target, f"{piece}/{k}/angles")
            if ok:
                self._confirm(value, parsed)
                self._add(line, piece, kind, "holds", f"{why}, at the angle the text gives ({where})")
                return True
            fix = None if self.judging_only else self._search(value, [target], None, parsed, k, None, None, keep)
        finally:
            self.ctx.subs = saved
        if fix:
            self._add(line, piece, kind, "typo", f"as written, at the angle the text gives ({where}): {why}; "
                      f"one edit ({fix[1]}) makes it hold", fix[0])
        else:
            self._add(line, piece, kind, "fails", f"as written, at the angle the text gives ({where}): {why}")
        return True

    def _on_the_motion(self, val, targets, seed) -> str | None:
        """Why the claim holds on the text's motion (its stated rates, or Lagrange's equation), or None."""
        if isinstance(val, sp.MatrixBase):
            return None
        for f in targets:
            target = self._resolve(f)
            if isinstance(target, sp.MatrixBase):
                continue
            q = self._lagrange_equation(val, target)
            if q is not None:
                return f"Lagrange's equation for {self.tex(q)}: d/dt ∂L/∂{self.tex(q)}̇ = ∂L/∂{self.tex(q)} (true on every motion)"
            held = self._held_motion()
            bare = {x for x in (val, target) if x in RATES}
            if bare and (not held or bare & set(self.ctx.motion)):
                continue            # a rate against the motion's rates would check the text against itself
            motion = {r: self._resolve(v) for r, (v, _) in self.ctx.motion.items()}
            motion.update(held)
            if not motion or not (_free(val) | _free(target)) & (set(motion) | set(lx.W)):
                continue
            a, b = (x.xreplace(self.ctx.subs).xreplace(motion) for x in self._unify([val, target]))
            if self._differs(a, b):
                continue            # `_compare` would not hold: the costly expansion is spared
            a, b = expanded(a), expanded(b)
            # a rate the motion leaves free, unless it cancels only through cos² + sin² = 1
            if any(surely_nonzero(sp.diff(a - b, r)) for r in _free(a - b) & set(RATES) - set(motion)):
                continue
            ok, how = self._compare(a, b, seed + "/motion")
            if ok:
                stated = {**self.ctx.motion, **{q: h for q, h in self.ctx.held.items() if h is not None}}
                where = ", ".join(f"{self.tex(r)} = {self.tex(v)} (line {n})" for r, (v, n) in stated.items())
                return f"{how}, in the motion the text describes ({where})"
        return None

    def _held_motion(self) -> dict:
        """The angles running text holds at a number, with their rates and accelerations zero."""
        out = {}
        for q, held in self.ctx.held.items():
            if held is not None and q in ANGLES:
                k = ANGLES.index(q)
                out.update({q: held[0], RATES[k]: sp.S.Zero, ACCELS[k]: sp.S.Zero})
        return out

    def _differs(self, a, b) -> bool:
        """Whether `_compare` of scalars a and b free of the unit vectors would not hold: their
        difference, unified and put in the section's first case as `_compare` puts it, is proved
        non-zero at an exact point (`zero_test.surely_nonzero`), so its zero test finds it non-zero."""
        if (_free(a) | _free(b)) & set(lx.BASIS):
            return False
        a, b = (self._case_subs(x, self.ctx.cases[0]) for x in self._unify([a, b]))
        return surely_nonzero(a - b)

    def _lagrange_equation(self, val, target):
        """The coordinate q when val − target = ±(d/dt ∂L/∂q̇ − ∂L/∂q), else None."""
        if not (_free(val) | _free(target)) & set(ACCELS):
            return None
        lag = self.ctx.forms_held.get(lx.LAGRANGIAN)
        lag = self._resolve(lag) if lag is not None else self.d.top.lagrangian
        a, b = (x.xreplace(self.ctx.subs) for x in self._unify([val, target]))
        diff = expanded(a - b)
        for q, el in zip(ANGLES, self.d.residuals(lag)):
            el = el.xreplace(self.ctx.subs)
            for sign in (1, -1):
                d = expanded(diff - sign * el)
                if not surely_nonzero(d) and _trig_zero(d):
                    return q
        return None
