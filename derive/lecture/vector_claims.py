"""Statements in vectors for the notes checker: sums over particles, the inertia tensor, frame
derivatives (read by `derive.lecture.vectors`, with a single-edit search of the LaTeX for a
correction), the torque-free d𝐋/dt = 0 written out in components, Newton's law with the inertial
derivative (`vectors.newton`), a weight rotated into body axes (``F_g = R_{i→b} [0, 0, mg]^T``) and
a position's inertial rate as the body velocity turned (ṙᵢ = R𝐕_b).

Gives the mixin `VectorStatements` of `derive.lecture.notes_check.Checker`.

May import: :mod:`derive.lecture.latex_spellings`, :mod:`derive.lecture.latex`, :mod:`derive.lecture.vectors` (and its
:mod:`~derive.lecture.vector_models`, :mod:`~derive.lecture.vector_parser`),
:mod:`derive.lecture.comparing`, :mod:`derive.symbolic.rotations` (the angles),
:mod:`derive.symbolic.lagrangian` (the principal moments), SymPy.
"""
from __future__ import annotations

import re
from dataclasses import replace

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.latex_spaces import SPACE
from derive.lecture import vector_models as vm
from derive.lecture import vectors as vc
from derive.lecture.comparing import Mismatch, column, free
from derive.lecture.vector_models import is_quantity
from derive.lecture.vector_parser import LAW
from derive.symbolic.lagrangian import I1, I2, I3
from derive.symbolic.rotations import ANGLES
from derive.lecture.latex_spellings import BOLD_MARK, VECTOR_MARK


_VECTOR_LEFT = re.compile(r"\s*(?:\\frac\s*\{\s*d\s*)?" + VECTOR_MARK + r"\s*\{")
_BODY_AXIS = re.compile(r"\\hat\s*\{\s*" + BOLD_MARK + r"\s*\{\s*e\s*_\s*\{?\s*[123]")
_OMEGA_LEFT = re.compile(r"\s*" + VECTOR_MARK + r"\s*(?:\{\s*\\omega\s*\}|\\omega(?![A-Za-z]))\s*=(?!=)")
_UNIT_E = (r"\\(?:widehat|hat)\s*\{\s*(?:" + VECTOR_MARK + r"\s*\{\s*e\s*(?:_\s*\{?\s*(?P<a>[123])\s*\}?)?\s*\}"
           r"(?:\s*_\s*\{?\s*(?P<c>[123])\s*\}?)?|e)\s*\}(?:\s*_\s*\{?\s*(?P<b>[123])\s*\}?)?")
_MOMENTUM_LEFT = re.compile(r"\s*" + VECTOR_MARK + r"\s*(?:\{\s*L\s*\}|L(?![A-Za-z]))\s*=(?!=)")
_ALONG_AXIS = re.compile(r"\s*(?P<sign>[+-]?)\s*(?P<coef>\\?[A-Za-z]+(?:\s*_\s*(?:\{[^{}]*\}|[A-Za-z0-9]))?)" + SPACE + _UNIT_E)
"""A term ``\\omega_1 \\widehat{\\mathbf{e}}_1``, ``\\lambda \\hat{\\mathbf{e}}_2``: one symbol along a body axis."""
_SUM = re.compile(r"[^\s{(^_]\s*[+-]")
"""A sum of terms written out: a + or − after a term (not a sign in front)."""


def _axis(m) -> int:
    """The body axis (1, 2, 3) of a term `_ALONG_AXIS` matched, 0 where it names none."""
    return int(m.group("a") or m.group("b") or m.group("c") or 0)


class VectorStatements:
    """Mixin of the checker. Uses ``self.vocab``, ``self.d``, ``self.ctx``, ``self._add``,
    ``self._resolve`` and ``self.judging_only``."""

    def _body_axes_first(self, line, piece, text) -> bool:
        """``\\vec{H} = I_1\\omega_1\\hat{\\boldsymbol{e_1}} + …``: a vector on the left written out
        along the body axes ê_i is the vector reader's, before the scalar one reads its letters as
        scalars (False when it is not such a statement, or that reader cannot read it)."""
        if self._angular_velocity_along_axes(line, piece, text) or self._momentum_along_axes(line, piece, text):
            return True
        if not (_VECTOR_LEFT.match(text) and _BODY_AXIS.search(text)):
            return False
        return self._vectors(line, piece, text)

    def _angular_velocity_along_axes(self, line, piece, text) -> bool:
        """``\\boldsymbol{\\omega} = \\omega_1 \\widehat{\\mathbf{e}}_1 + \\lambda \\widehat{\\mathbf{e}}_2 + \\mu
        \\widehat{\\mathbf{e}}_3``: the angular velocity written along the body's principal axes, one
        symbol per axis, states its components. An axis left out has ω̃ᵢ = 0 (a spin about ê₁, a
        case of the text); a symbol of the text's that it has not defined names ω̃ᵢ, its dot ω̃̇ᵢ, from
        here on (a disturbance's λ, μ), as ω̃ᵢ itself does. Not a claim: `unchecked`, saying what it sets."""
        head = _OMEGA_LEFT.match(text)
        if head is None:
            return False
        rest, coefs = text[head.end():].strip().rstrip(".,;").strip(), {}
        while rest:
            m = _ALONG_AXIS.match(rest)
            if m is None or m.group("sign") == "-" or (not m.group("sign") and coefs):
                return False
            k = _axis(m) - 1
            if k < 0 or k in coefs:
                return False
            coefs[k], rest = m.group("coef"), rest[m.end():].strip()
        named, said = {}, []
        for k, coef in coefs.items():
            try:
                tok = lx.scan(coef)
                value = lx.parse(coef, self.vocab).members[0].value
            except lx.NotRead:
                return False
            if value == lx.W[k]:
                continue
            if len(tok) != 1 or tok[0].kind != "atom" or not isinstance(value, lx.Generic) or \
                    value in self.ctx.defs or value in self.ctx.subs:
                return False            # a known symbol, one the text defined, or an expression: not a name
            named[k] = tok[0].value
        for k in range(3):
            if k in named:
                atom = named[k]
                self.vocab.defined[atom.with_(text="")] = lx.W[k]
                self.vocab.defined[atom.with_(text="", dots=1)] = lx.WD[k]
                said.append(f"{self.tex(lx.W[k])} = {coefs[k]}")
            if k not in coefs:
                self.ctx.subs[lx.W[k]] = sp.S.Zero
                self.ctx.subs[lx.WD[k]] = sp.S.Zero
                self.ctx.stated[lx.W[k]] = f"line {line}"
                said.append(f"{self.tex(lx.W[k])} = 0")
            elif any(self.ctx.subs.get(x) == 0 for x in (lx.W[k], lx.WD[k])):
                self.ctx.subs.pop(lx.W[k], None)        # a component a spin about another axis had set to zero
                self.ctx.subs.pop(lx.WD[k], None)
        if not said:
            return False
        self._add(line, piece, "setting", "unchecked",
                  f"the angular velocity along the body's principal axes: {', '.join(said)} (a case of the text, "
                  "its names for the components from here on), not a claim")
        return True

    def _momentum_along_axes(self, line, piece, text) -> bool:
        """``\\mathbf{L} = L_2 \\widehat{\\mathbf{e}_2}``: the angular momentum written as its own components
        along some of the body's principal axes, as an example sets the axes by it. It says the other
        components are zero in the text's case, which the reader does not model: not a claim, `unchecked`."""
        head = _MOMENTUM_LEFT.match(text)
        if head is None:
            return False
        rest, axes = text[head.end():].strip().rstrip(".,;").strip(), []
        while rest:
            m = _ALONG_AXIS.match(rest)
            k = _axis(m) if m else 0
            if not k or m.group("sign") == "-" or k in axes or \
                    not re.fullmatch(rf"L\s*_\s*(?:\{{\s*{k}\s*\}}|{k})", m.group("coef")):
                return False
            axes.append(k)
            rest = rest[m.end():].strip()
        if not axes or len(axes) == 3:
            return False
        zero = " = ".join(f"L_{k}" for k in (1, 2, 3) if k not in axes)
        self._add(line, piece, "setting", "unchecked",
                  f"the angular momentum along the body's principal axes: {zero} = 0 in the text's case (the axes "
                  "chosen by it), not a claim")
        return True

    def _vectors(self, line, piece, text) -> bool:
        """A statement in vectors, tensors, sums over particles or frame derivatives
        (`derive.lecture.vectors`): each member against the first, a single-edit search of the
        LaTeX for a correction. False when that reader cannot read it either."""
        if self._position_rate(line, piece, text):
            return True
        self.vocab.open = False          # the vector reader knows its own symbols (m_p, I_ij, r_p)
        try:
            reading = vc.read(text, self.vocab, self.d, self.ctx.vec_model)
        except lx.NotRead:
            return False
        finally:
            self.vocab.open = True
        if set(reading.relations) - {"=", "≡"}:
            return False
        first = reading.members[0]
        before = getattr(self, "_vec_last", (None, None))
        previous = before[1] if before[0] == line else None     # the row before, in this display only
        self._vec_last = (line, reading.source[first[-1].start:first[-1].end].strip())
        continued = re.match(r"\s*&?\s*(=|\\equiv)", piece) is not None
        if previous and continued and vc.reference(reading, len(first) - 1) is None:
            try:    # a row "&= …" of a chain that opened with a vector of the text's: against the row before
                reading = vc.read(previous + " " + piece, self.vocab, self.d, self.ctx.vec_model)
            except lx.NotRead:
                pass
            first = reading.members[0]
        self.ctx.head = reading.source[:first[0].end].strip() if not continued else self.ctx.head
        put = {s: v for comps, value in self.ctx.vectors.values() for s, v in zip(comps, value)}
        for row in reading.members if put and reading.model == "frame" else ():
            for m in row:                 # the text's vectors it has defined (𝐅 = m d𝐕/dt): what it defined them as
                m.value = m.value.xreplace(put) if hasattr(m.value, "xreplace") else m.value
        written = [m.value for m in first if hasattr(m.value, "has")]
        equal = {k: v for k, v in self.ctx.subs.items() if k in (I1, I2, I3)}
        # 𝐋 beside I₁, I₂, I₃, or in a text that has set its principal moments equal (I₁ = I₂)
        if reading.model == "frame" and ({I1, I2, I3} <= set().union(*(free(v) for v in written)) or
                                         equal and any(v.has(*vm.L_B) for v in written)):
            principal = vm.Model("frame", self.d).principal_rigid()     # 𝐋 beside I₁, I₂, I₃: principal axes,
            principal.update(vm.principal_tensor())                     # and the plain I their diagonal tensor
            for row in reading.members:
                for m in row:
                    m.value = m.value.xreplace(principal) if hasattr(m.value, "xreplace") else m.value
        if reading.model == "frame" and any(m.value.has(*vm.RIGID) for m in first if hasattr(m.value, "has")):
            rigid = vm.Model("frame", self.d).rigid()     # the text's tensor written: 𝐋 = I𝛚 of the rigid body
            for row in reading.members:
                for m in row:
                    m.value = m.value.xreplace(rigid) if hasattr(m.value, "xreplace") else m.value
        for row in reading.members if equal else ():
            for m in row:                 # the text's I₁ = I₂: its vectors' moments are equal as its scalars' are
                m.value = m.value.xreplace(equal) if hasattr(m.value, "xreplace") else m.value
        if reading.model == "particle":
            self.ctx.vec_model = "particle"
        if len(first) == 1:
            self._missing_relation(line, piece, reading)
            return True
        quantity = first[0].atom is not None and is_quantity(first[0].atom)
        kind = "kinematics" if reading.model == "frame" else ("definition" if quantity else "identity")
        where = f" for {', '.join(reading.free)} = 1, 2, 3" if reading.free else ""
        for k in range(1, len(first)):
            if first[k].value is LAW or first[0].value is LAW:
                if not (self._past_the_law(line, piece, reading, k, kind) or
                        self._law_written_out(line, piece, reading, k, kind)):
                    self._add(line, piece, "law", "unchecked", "the law of motion d𝐋/dt = τ: where the derivation "
                              "starts (Euler's equations are it in body axes), not a consequence of it")
                continue
            ref = vc.reference(reading, k)
            if ref is None and k == 1 and self._defines_vector(reading):
                law = vc.newton(reading, self.d)
                if law is not None:
                    self._add(line, piece, "law", *law)
                    continue
                self._add(line, piece, "definition", "unchecked", f"defines the text's vector "
                          f"{next(iter(vc.generics(first[0].value)))} (recorded, then used)")
                continue
            if ref is None:
                self._add(line, piece, kind, "unchecked", "relates the text's own vector "
                          f"{', '.join(sorted(vc.generics(first[k].value) ^ vc.generics(first[0].value)))} "
                          "to others: nothing ties it to the derivation")
                continue
            ok, how = vc.holds(reading, k, f"{piece}/{k}", ref)
            if ok:
                self._add(line, piece, kind, "holds", f"{vc.WHY[reading.model]}{where}: {how}")
                continue
            if not reading.free and self._vector_eom(reading.members[0][0].value, reading.members[0][k].value):
                self._add(line, piece, "equation of motion", "holds", "in components, each row is Euler's equation "
                          "for that component (Iᵢ ω̃̇ᵢ − ((Iω̃)×ω̃)ᵢ = τᵢ, the torque's components as the text names them)")
                continue
            if "not a vector" in how or " against a " in how:
                self._add(line, piece, kind, "unchecked", f"cannot compare its sides as read: {how}")
                continue
            untied = sorted({str(x) for x in getattr(first[k].value, "free_symbols", ()) if str(x) in ("A", "B", "C")})
            if untied:          # diag(A, B, C) for the inertia tensor: the text naming its moments
                self._add(line, piece, kind, "unchecked", f"involves {', '.join(untied)}, which the text has not "
                          "tied to the derivation (a definition of them?)")
                continue
            carried = _carried_by_the_body(reading, k, ref, piece)
            if carried:
                self._add(line, piece, kind, "unchecked", f"holds if the text's vector {carried} is fixed in the body "
                          "(its body components constant), which the derivation does not know of it: the text's "
                          "set-up of that vector, not a claim")
                continue
            fix = None if self.judging_only else self._vector_fix(reading, k, piece)
            if fix:
                self._add(line, piece, kind, "typo", f"as written: {how}; one edit ({fix[1]}) makes it hold "
                          f"({vc.WHY[reading.model]})", fix[0])
            else:
                self._add(line, piece, kind, "fails", f"as written: {how} ({vc.WHY[reading.model]}{where})")
        return True

    def _past_the_law(self, line, piece, reading, k, kind) -> bool:
        """``𝐍 = (d𝐋/dt)_space = (d𝐋/dt)_body + 𝛚 × 𝐋``: a chain headed by the torque states the law in
        its first link; each member after the next is checked against the one before it, and the
        link is kept when it holds (False otherwise: the law's verdict stands for it)."""
        first = reading.members[0]
        if k < 2 or reading.free or first[0].value is not LAW or LAW in (first[k].value, first[k - 1].value):
            return False
        ok, how = vc.holds(reading, k, f"{piece}/law{k}", k - 1)
        if ok:
            self._add(line, piece, kind, "holds", f"{vc.WHY[reading.model]}: against the member before it "
                      f"(the chain's head is the torque, its first link the law of motion): {how}")
        return ok

    def _law_written_out(self, line, piece, reading, k, kind) -> bool:
        """``𝐋_C = {}^B d𝐇_C/dt + 𝛚 × 𝐇_C``, ``𝐋_C = [I]𝛚̇ + 𝛚 × [I]𝛚``: the torque equal to a sum that
        writes out the angular momentum's inertial rate is the law with the transport theorem, so
        the sum is checked against (d𝐋/dt)_inertial and kept when it holds (False otherwise, a rate
        written alone being the law itself)."""
        first = reading.members[0]
        if reading.model != "frame" or reading.free or len(first) != 2 or k != 1 or \
                [m.value is LAW for m in first].count(True) != 1:
            return False
        j = 1 if first[0].value is LAW else 0
        if not _SUM.search(reading.source[first[j].start:first[j].end]):
            return False
        model = vm.Model("frame", self.d)
        rate = model.derivative(vm.L_B, "inertial")
        value = first[j].value
        if hasattr(value, "has") and value.has(*vm.RIGID):
            rate = rate.xreplace(model.rigid())     # the text's tensor written: 𝐋 = I𝛚 of the rigid body
        law = [[replace(m, value=rate) if m.value is LAW else m for m in row] for row in reading.members]
        ok, how = vc.holds(replace(reading, members=law), k, f"{piece}/law", 0)
        if ok:
            self._add(line, piece, kind, "holds", f"{vc.WHY[reading.model]}: against the angular momentum's "
                      f"inertial rate, the torque's by the law of motion: {how}")
        return ok

    def _vector_eom(self, a, b) -> bool:
        """``I\\dot{\\boldsymbol\\omega} + \\boldsymbol\\omega \\times (I\\boldsymbol\\omega) = \\boldsymbol\\tau`` as
        columns: component i of a − b a non-zero constant multiple of Euler's equation i (with the
        torque's component τᵢ when the text writes one)."""
        if not all(isinstance(v, sp.MatrixBase) and v.shape == (3, 1) for v in (a, b)):
            return False
        r = [sp.expand(self._resolve(e).xreplace(self.ctx.subs)) for e in (a - b)]
        if not any(free(e) & set(lx.WD) for e in r):
            return False
        euler = self.d.euler(self.ctx.subs)
        dyn = set(lx.W) | set(lx.WD) | set(lx.TAU)
        for i in range(3):
            target = euler[i] - lx.TAU[i] if free(r[i]) & set(lx.TAU) else euler[i]
            q = sp.cancel(sp.together(r[i] / target)) if target != 0 else None
            if q is None or q == 0 or free(q) & dyn:
                return False
        return True

    def _missing_relation(self, line, piece, reading):
        """A display of vectors with no relation: when exactly one of its top-level signs + written
        as = makes it hold (``d𝐯/dt|ᵢ + d𝐯/dt|_b + 𝛚 × 𝐯``), the relation was typed as a sign: a typo,
        corrected in the text's own LaTeX."""
        src = reading.source
        found = []
        for n, k in enumerate(_top_level_plus(src)):
            try:
                again = vc.read(src[:k] + "=" + src[k + 1:], self.vocab, self.d, self.ctx.vec_model)
            except lx.NotRead:
                continue
            if len(again.members[0]) == 2 and vc.reference(again, 1) == 0 and vc.holds(again, 1, f"{piece}/rel{k}")[0]:
                found.append(n)
        mine = _top_level_plus(piece)
        if len(found) == 1 and len(mine) == len(_top_level_plus(src)):
            k = mine[found[0]]
            self._add(line, piece, "kinematics", "typo", "no relation as written; with one '+' read as '=' it holds "
                      f"({vc.WHY[reading.model]})", correction=_evaluated_at((piece[:k] + "=" + piece[k + 1:]).strip()))
        else:
            self._add(line, piece, "expression", "unchecked", "not a claim: no relation")

    def _defines_vector(self, reading) -> bool:
        """``\\vec{F} = m \\frac{d\\vec{V}}{dt_i}``: a vector of the text's alone on the left, new in
        the section, equal to others: recorded as that (its later uses are read with it)."""
        first = reading.members[0]
        mine, other = vc.generics(first[0].value), vc.generics(first[1].value)
        if reading.model != "frame" or reading.free or len(first) < 2 or len(mine) != 1 or mine & other:
            return False
        name = next(iter(mine))
        value = first[0].value
        if name in self.ctx.vectors or not isinstance(value, sp.MatrixBase) or \
                not all(isinstance(c, sp.Symbol) for c in value) or not isinstance(first[1].value, sp.MatrixBase):
            return False
        self.ctx.vectors[name] = (tuple(value), tuple(first[1].value))
        return True

    def _position_rate(self, line, piece, text) -> bool:
        """``\\frac{d \\vec{r_i}}{dt} = R_{b \\rightarrow i} \\vec{V_b}``: the rate of a position's
        inertial components is its velocity's body components turned into inertial ones, ṙᵢ = R 𝐕_b
        (𝐕_b = Rᵀṙᵢ by what body components are, R body → inertial). Holds when the written matrix
        is R (the text's own, resolved), fails for another; False when the statement is not one."""
        m = _POSITION_RATE.match(text.strip())
        if m is None or m.group(1) not in "rpxs" or m.group(3) not in "Vv" or "velocity" not in (self.notes.body or ""):
            return False
        try:
            matrix = self._resolve(lx.parse(m.group(2), self.vocab).members[0].value)
        except (lx.NotRead, TypeError, ValueError, AttributeError):
            return False
        if not isinstance(matrix, sp.MatrixBase) or matrix.shape != (3, 3) or not free(matrix) <= set(ANGLES):
            return False
        R = self.d.conv.matrix()
        diff = (matrix - R).applyfunc(lambda e: self.d.rot.trig_reduce(sp.expand(e)))
        what = "the position's inertial rate is its velocity's body components turned by R (body → inertial)"
        if diff == sp.zeros(3, 3):
            self._add(line, piece, "kinematics", "holds", f"{what}: ṙᵢ = R 𝐕_b, 𝐕_b = Rᵀṙᵢ: trig_reduce")
        else:
            turned = (matrix - R.T).applyfunc(lambda e: self.d.rot.trig_reduce(sp.expand(e))) == sp.zeros(3, 3)
            self._add(line, piece, "kinematics", "fails", f"{what}; the matrix written is "
                      + ("Rᵀ, which turns inertial components into body ones" if turned else "not R"))
        return True

    def _weight(self, line, piece, sym, value) -> bool:
        """``F_g = R_{i \\rightarrow b} [0, 0, mg]^T``: the weight named F_g, in body components, is m g
        Rᵀ𝐝 with 𝐝 the inertial frame's downward unit vector the prose gives (north-east-down, "z
        down": +ẑ; "z up": −ẑ). Holds or fails against that; False (not this rule's) when the symbol
        is not a weight or its value not a column in the angles, a mass and g."""
        atom = self.vocab.generic.get(sym)
        claim = self._resolve(value)
        if atom is None or atom.base not in ("F", "W") or not _WEIGHT.fullmatch(atom.sub) or atom.dots or atom.hat \
                or not isinstance(claim, sp.MatrixBase) or claim.shape != (3, 1):
            return False
        g = next((s for s in free(claim) if s.name == "g"), None)
        rest = free(claim) - set(ANGLES) - {g}
        if g is None or len(rest) != 1 or next(iter(rest)).name.split("_")[0] not in ("m", "M", "Mass"):
            return False
        prose = self.notes.body or ""
        down = 1 if _DOWN.search(prose) else (-1 if _UP.search(prose) else 0)
        if not down:
            self._add(line, piece, "weight", "unchecked", f"{self.tex(sym)} as the weight needs the direction "
                      "of gravity in the inertial frame, which the text does not say (z up or down)")
            return True
        weight = next(iter(rest)) * g * self.d.conv.matrix().T * sp.Matrix([0, 0, down])
        diff = (claim - weight).applyfunc(lambda e: self.d.rot.trig_reduce(sp.expand(e)))
        where = f"{self.tex(sym)} as the weight m g Rᵀ𝐝, 𝐝 = {'+' if down > 0 else '−'}ẑ downward (as the text's frame is)"
        if diff == sp.zeros(3, 1):
            self._add(line, piece, "weight", "holds", f"{where}, in body components: trig_reduce")
        else:
            k = next(n for n in range(3) if diff[n] != 0)
            self._add(line, piece, "weight", "fails", f"{where}: component {k + 1} differs")
        return True

    def _vector_fix(self, reading, k, piece):
        """One edit of member k's LaTeX that makes it equal member 0: (corrected LaTeX, what)."""
        rel = {"=": "=", "≡": r"\equiv"}[reading.relations[k - 1]]
        left = reading.source[reading.members[0][0].start:reading.members[0][0].end].strip()
        reread = lambda text: vc.read(text, self.vocab, self.d, self.ctx.vec_model)  # noqa: E731
        for n, edited, what, _, again in vc.edited_readings(reading, k, reread, 80):
            if not vc.surely_differs(again, k) and vc.holds(again, k, f"{piece}/edit{n}")[0]:
                return vc.restore(f"{left} {rel} {edited.strip()}"), what
        return None

    def _torque_free(self, line, piece, parsed):
        """d𝐋/dt = 0 = Σ cᵢ êᵢ with τ = 0 stated: component i of the written d𝐋/dt, set to 0, must be
        Euler's equation i (a non-zero multiple of Iᵢ ω̃̇ᵢ − ((Iω̃)×ω̃)ᵢ); without a written
        d𝐋/dt it restates the torque-free case."""
        stated = any(re.search(r"\\tau(?![a-z])", a) for a in self.ctx.assumptions)
        written = [mm.value for mm in parsed.members[1:] if mm.value != 0]
        if not stated:
            self._add(line, piece, "equation of motion", "unchecked", "d𝐋/dt = 0 needs τ = 0, which the text does not state")
            return
        if not written:
            self._add(line, piece, "equation of motion", "unchecked",
                      "d𝐋/dt = 0: the torque-free case (τ = 0, stated in the text), an assumption")
            return
        try:
            col = column(self._resolve(written[-1]))
        except Mismatch as err:
            self._add(line, piece, "equation of motion", "fails", f"d𝐋/dt = 0 with d𝐋/dt = {err}")
            return
        euler = self.d.euler(self.ctx.subs)
        dyn = set(lx.W) | set(lx.WD)
        for i in range(3):
            r = sp.expand(col[i].xreplace(self.ctx.subs)) if len(col) == 3 else None
            q = sp.cancel(sp.together(r / euler[i])) if r is not None and euler[i] != 0 else None
            if q is None or q == 0 or free(q) & dyn:
                self._add(line, piece, "equation of motion", "fails",
                          f"d𝐋/dt = 0 (τ = 0 stated): component {i + 1} is not Euler's equation {i + 1}")
                return
        self._add(line, piece, "equation of motion", "holds",
                  "d𝐋/dt = 0 with τ = 0 (stated in the text): each component of the written d𝐋/dt, set to 0, "
                  "is Euler's equation for that component (Iᵢ ω̃̇ᵢ = ((Iω̃)×ω̃)ᵢ)")


_LABELLED = VECTOR_MARK + r"\s*\{\s*([A-Za-z])\s*_\s*\{?\s*%s\s*\}?\s*\}"
_POSITION_RATE = re.compile(r"\\frac\s*\{\s*" + vm.DIFFERENTIAL + r"\s*" + _LABELLED % r"(?:i|I|N|e)" + r"\s*\}\s*\{\s*"
                            + vm.DIFFERENTIAL + r"\s*t\s*\}\s*=\s*"
                            r"(R\s*_\s*\{[^{}]*\}(?:\^\s*\{?\s*(?:T|-1)\s*\}?)?)" + SPACE + _LABELLED % r"(?:b|B)" + r"\s*$")
_WEIGHT = re.compile(r"(?:g|grav(?:ity)?)?")  # the subscripts a text gives its weight: F, F_g, W_grav
_DOWN = re.compile(r"north[- ]east[- ]down|\bNED\b|\$?\+?z\$?\s*\(?(?:axis\s+)?(?:points?\s+)?\(?down", re.I)
_UP = re.compile(r"east[- ]north[- ]up|\bENU\b|\$?z\$?\s*\(?(?:axis\s+)?(?:points?\s+)?\(?up(?:ward)?\b", re.I)


def _top_level_plus(src: str) -> list:
    """The positions of the signs + outside brackets and braces."""
    out, depth = [], 0
    for k, ch in enumerate(src):
        depth += 1 if ch in "({[" else (-1 if ch in ")}]" else 0)
        if ch == "+" and depth == 0:
            out.append(k)
    return out


def _evaluated_at(latex: str) -> str:
    """``\\frac{d v}{dt}\\right|_i`` with the ``\\left.`` the reading dropped put back, so a correction pastes."""
    return re.sub(r"(\\frac\s*\{(?:[^{}]|\{[^{}]*\})*\}\s*\{[^{}]*\})\s*\\right\s*\|", r"\\left.\1\\right|", latex)


def _carried_by_the_body(reading, k, ref, seed) -> str:
    """The text's own vectors (``vector_models.GENERIC``: components of their own) whose body rates
    the frame model leaves free, when member k holds against member ``ref`` once those rates are
    zero (d𝐀/dt = 𝛚 × 𝐀 for the text's 𝐀: it says 𝐀 turns with the body); "" otherwise."""
    if reading.model != "frame":
        return ""
    rates = {x for members in reading.members for m in (members[k], members[ref])
             for x in getattr(m.value, "free_symbols", ()) if f"{vm.GENERIC}d" in x.name}
    if not rates:
        return ""
    fixed = [[replace(m, value=m.value.xreplace(dict.fromkeys(rates, 0)) if hasattr(m.value, "xreplace") else m.value)
              for m in members] for members in reading.members]
    ok, _ = vc.holds(replace(reading, members=fixed), k, f"{seed}/fixed{k}", ref)
    return ", ".join(sorted({x.name.split(vm.GENERIC)[0] for x in rates})) if ok else ""
