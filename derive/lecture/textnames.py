"""A text's own names and settings, as a reader keeps them while reading: the part of the notes
checker that learns from the text instead of knowing in advance.

Takes: statements parsed by `derive.lecture.latex` with an *open* vocabulary (an atom outside the
derivation's vocabulary is a `latex.Generic` symbol of the text's). Gives: the mixin `TextNames`
of `derive.lecture.notes_check.Checker`, which

1. **records a new name's definition**: ``X = …`` or ``X \\equiv …`` with X a symbol the text has
   not defined (``u = \\cos\\theta``, ``T_{rot} = …``, ``\\dot p_\\phi = …``, ``k_1 = I_z - I_y``)
   is not a claim: X stands for its right side from here on, and a chain ``X = a = b`` checks
   a = b;
2. **takes settings for what they are**: ``\\theta = 0``, ``I_3 = 0``, ``\\omega_1 = 0``,
   ``I_1 = I_2 \\neq I_3``, ``\\phi = 30^\\circ`` set a variable or a parameter to a value (a case,
   a special body, a numeric example): they hold for the rest of their display, or, when the
   display says nothing else, for the rest of the section; never a claim;
3. **declines to judge names it cannot tie**: a relation between symbols of the text's that no definition ties to
   the derivation is checked only when it is an identity whatever they stand for (then ``holds``), or read as
   the definition of its one new symbol after a definition sign (`right_named`); else ``unchecked``, naming them;
4. **differentiates**: ``\\frac{d}{dt}`` (`latex.DT`) by the chain rule through the angles, their
   rates, ω̃ᵢ (→ ω̃̇ᵢ) and the text's symbols (X → Ẋ, and Ẋ of a defined X, or X'(q) of a defined X(q), is the
   derivative of its definition); ``\\frac{\\partial A}{\\partial v}`` with A written in ω̃ᵢ and v an angle or a rate
   through ω̃(q, q̇).

May import: :mod:`derive.lecture.component_names`, :mod:`derive.lecture.latex`, :mod:`derive.lecture.primed_functions`, :mod:`derive.lecture.right_named`, :mod:`derive.lecture.sparse_forms`, :mod:`derive.lecture.untied_partials`, :mod:`derive.lecture.zero_test`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import itertools
import re

import sympy as sp

from derive.lecture import euler_moments
from derive.lecture import component_names
from derive.lecture import latex as lx, primed_functions, right_named, untied_partials
from derive.lecture.vocabulary import Atom
from derive.lecture.moments_small import written_name
from derive.lecture.stated_settings import under_settings
from derive.lecture.text_matrices import matrix_power
from derive.lecture.unread_members import UnreadMembers
from derive.lecture.sparse_forms import free_symbols
from derive.lecture.zero_test import entry_zero
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3, Mass, g, l
from derive.symbolic.rotations import ANGLES, RATES, time_derivative

PARAMETERS = (I1, I2, I3, Mass, g, l)
VARIABLES = ANGLES + RATES + ACCELS + tuple(lx.W) + tuple(lx.WD)


_FRAME = r"\s*\^\s*(\{[^{}]*\}|\\[A-Za-z]+|\w)"
_COORDINATE = re.compile(r"^\s*&?\s*([xyz])" + _FRAME + r"\s*&?=\s*(.+?)\s*[.,]?\s*$", re.S)
_COORDINATE_USE = re.compile(r"(?<![A-Za-z\\])([xyz])" + _FRAME)
"""A coordinate labelled by its frame (x^{\\psi}), the rows of a change of frame."""


def _a_torque(residual, name) -> bool:
    """``name`` enters the equation as a torque would: a term of its own, not a coefficient of ω̃ᵢ
    (Ω of ω̃̇₁ + Ωω̃₂ = 0 is a frequency the text has not yet said, not a torque)."""
    try:
        slope = sp.diff(residual, name)
    except (TypeError, ValueError):
        return False
    return sp.diff(slope, name) == 0 and not _free(slope) & set(lx.W)


_FUNCTION_OF = re.compile(r"\s*[^=()]+?\(\s*[^()]+,[^()]+\)\s*$")
"""A side that is one name with the variables it depends on listed: ``f_{1}(\\omega_1, \\omega_2, \\omega_3)``."""


def _right_side(text) -> str:
    return text.split("=", 1)[1] if "=" in text else ""


def _moment_multiple(m) -> bool:
    """A parameter, or a positive number times a principal moment (the 2I₃ of I₁ = I₂ = 2I₃)."""
    k, rest = sp.sympify(m).as_coeff_Mul()
    return m in PARAMETERS or (k.is_Rational and k > 0 and rest in (I1, I2, I3))


def _free(obj) -> set:
    return set(free_symbols(obj)) if hasattr(obj, "free_symbols") else set()


def _is_value(v, defined) -> bool:
    """What a setting sets a variable to: a number, a parameter, or an expression in the
    parameters and the text's own symbols not yet defined (an example's ω sin α)."""
    return not isinstance(v, sp.MatrixBase) and all(
        s in PARAMETERS or s == lx.t or (isinstance(s, lx.Generic) and s not in defined) for s in _free(v))


class TextNames(UnreadMembers):
    """Mixin of the checker: see the module docstring. Uses ``self.ctx`` (defs, subs),
    ``self.vocab``, ``self.d`` (the derivation) and ``self._add``."""

    # -- 1 to 3: before the kinds -----------------------------------------------------------------
    def _constant_dropped(self, line, piece, parsed):
        """``… = \\text{const}``: the text says a quantity is conserved. A chain is checked without
        that member; ``X = const`` alone is an assumption (None: nothing left to check)."""
        members = [m.value for m in parsed.members]
        const = [k for k, m in enumerate(members) if isinstance(m, lx.Generic) and m.name == "const"]
        if not const:
            return parsed
        rest = [k for k in range(len(members)) if k not in const]
        named = len(rest) == 2 and (self._new_name(members[rest[1]]) or isinstance(members[rest[1]], lx.Quantity))
        if len(rest) == 1 or named:
            if self._conserved(line, piece, members[rest[0]]) or \
                    len(rest) == 1 and self._conserved_free(line, piece, members[rest[0]]):   # an integral
                if named and self._new_name(members[rest[1]]):
                    self.ctx.defs[members[rest[1]]] = members[rest[0]]
                return None
        if len(members) == 2:
            self._add(line, piece, "assumption", "unchecked",
                      "states that a quantity is constant (an assumption or a conservation law)")
            return None
        return self._members_kept(parsed, [k for k in range(len(members)) if k not in const])

    def _members_kept(self, parsed, keep):
        """The statement with only the members ``keep`` (and the relations between them)."""
        return type(parsed)([parsed.members[k] for k in keep], [parsed.relations[k - 1] for k in keep[1:]])

    def _text_statement(self, line, piece, parsed) -> bool:
        """Handle a statement about the text's own names or a setting; True when it is done."""
        members = [m.value for m in parsed.members]
        rels = parsed.relations
        if any(isinstance(m, sp.MatrixBase) for m in members):
            if (why := component_names.named(self, members)) is not None:
                return self._add(line, piece, "new symbol", "unchecked", why) or True
            members[0] = self._free_letter_named(members[0], members[1])
            if self._new_name(members[0]) and isinstance(members[1], sp.MatrixBase):
                if self.vocab.generic[members[0]].bold and self._vectors(line, piece, getattr(self, "_text", piece)):
                    return True          # a tensor the vector reader knows (Ï, 𝐈 as a matrix)
                mat = self._matrix_name(members[0], members[1])
                self.settings_only = False
                self._turn_meant = None
                if not (self._rotation(line, piece, sp.Matrix(members[1]), self._turn_label(getattr(self, "_text", piece)))
                        or self._angular_velocity_column(line, piece, sp.Matrix(members[1]))):
                    self._add(line, piece, "new symbol", "unchecked",
                              f"defines the text's matrix {self.tex(members[0])} (recorded, then used)")
                if self._turn_meant is not None:      # the turn its name says: what the products after it use
                    self.ctx.defs[mat] = sp.ImmutableMatrix(self._turn_meant)
                for k in range(2, len(members)):      # a chain X = a = b …: a = b is checked, as for a symbol
                    self._one(line, piece, "identity", members[1], members[k], parsed, k)
                return True
            if len(members) == 2 and isinstance(members[1], sp.MatrixBase):
                return self._matrix_again(line, piece, members[0], members[1])
            return False
        if len(members) == 2 and rels == ["="] and self._new_name(members[1]) and not self._new_name(members[0]) \
                and not _free(members[0]) & {members[1]} and _FUNCTION_OF.match(_right_side(getattr(self, "_text", piece))):
            # ω̃̇₁ = f₁(ω̃₁, ω̃₂, ω̃₃): the text names the left side as a function of what it lists
            self.ctx.defs[members[1]] = members[0]
            self._mark_defined(members[1])
            self.settings_only = False
            self._add(line, piece, "new symbol", "unchecked",
                      f"defines the text's function {self.tex(members[1])} as the left side (recorded, then used)")
            return True
        if "≠" in rels and "=" in rels or (len(members) > 2 and all(_moment_multiple(m) for m in members)):
            return self._settings_before_neq(line, piece, members, rels)      # I₁ = I₂ ≠ I₃, I₁ = I₂ = I₃
        m0 = members[0]
        base = m0.base if isinstance(m0, sp.Pow) and m0.exp == 2 else None
        if self._new_name(base) and (base not in getattr(self, "generics_before", ()) or base not in self._constants()) \
                and rels[0] in ("=", "≡") and not (_free(members[1]) & {base}):
            # "names it k₄² = …" (or "where k² = …" after using k): k is the positive root
            self.ctx.defs[base] = sp.sqrt(members[1])
            self._add(line, piece, "new symbol", "unchecked",
                      f"defines the text's symbol {self.tex(base)} by its square (recorded, then used)")
            self.settings_only = False
            return True
        if set(rels) - {"=", "≡", "≈"}:
            if self._new_name(m0) and rels[0] in ("=", "≡") and not (_free(members[1]) & {m0}):
                self.ctx.defs[m0] = members[1]       # k₁ ≡ I_z − I_y > 0: the name, and a condition
                self._add(line, piece, "new symbol", "unchecked",
                          f"defines the text's symbol {self.tex(m0)} (recorded, then used) and states a condition")
                self.settings_only = False
                return True
            return self._undefined(line, piece, members, rels)
        if self._new_names_set_alike(line, piece, members, rels):
            return True
        if self._new_name(m0) and not (_free(members[1]) & {m0}):
            if len(members) == 2 and self._nutation_rate(line, piece, m0, members[1]):
                return True       # a nutation rate the prose names: judged, and recorded only where it holds
            self.ctx.defs[m0] = members[1]
            if getattr(self, "_inline", False):
                self.ctx.running[m0] = line
            self._mark_defined(m0)
            self.settings_only = False
            if len(members) == 2:
                value = self._resolve(members[1])
                if isinstance(value, sp.MatrixBase) and value.shape == (3, 3) and \
                        self._rotation(line, piece, sp.Matrix(value)):
                    self._matrix_name(m0, value)     # a product of the text's matrices: a rotation
                    return True
                euler = euler_moments.row(value, self.d.euler(self.ctx.subs), self.ctx.subs)
                if euler is not None:            # the moment's body component i set to Euler's left side
                    self._add(line, piece, "equation of motion", "holds" if euler[1] == 0 else "fails",
                              f"Euler's equation {euler[0] + 1} about the centre of mass, the text's "
                              f"{self.tex(m0)} the moment's component" + ("" if euler[1] == 0 else
                                                                        f": off by {sp.sstr(euler[1])}"))
                elif not self._space_component(line, piece, m0, members[1]) and not self._weight(line, piece, m0, members[1]):
                    self._add(line, piece, "new symbol", "unchecked",
                              f"defines the text's symbol {self.tex(m0)} (recorded, then used)")
                return True
            self._flush()
            self._named_chain(line, piece, members, parsed, rels)     # a chain X = a = b …: a = b is checked
            return True
        if len(members) > 2 and set(rels) == {"="} and _is_value(members[-1], self.ctx.defs) and len(set(members[:-1])) \
                == len(members) - 1 and all(self._settable(m) and not isinstance(m, lx.Quantity) for m in members[:-1]):
            for k in range(len(members) - 1):     # ω̃₁ = ω̃₂ = 0: each set to the value, as ω̃₁ = 0, ω̃₂ = 0 are
                self._text_statement(line, piece, type(parsed)([parsed.members[k], parsed.members[-1]], ["="]))
            return True
        if len(members) == 2 and rels[0] == "=" and self._settable(m0) \
                and _is_value(members[1], self.ctx.defs) and not isinstance(m0, lx.Quantity):
            # ω̃̇ᵢ = 0 that Euler's equations give under the settings before it (I₁ = I₂ = I₃): a claim
            follows = self._eom_check(m0 - members[1]) if m0 in lx.WD else (False, "", None)
            implied = None if follows[0] else under_settings(self, m0, members[1])
            if implied:                               # ω̃₃ = ω_p cos θ₀ + ω_s after θ = θ₀, …: a consequence
                self._add(line, piece, "identity", "holds", implied)
                return True
            if sp.sympify(m0).xreplace(self.ctx.subs) != sp.sympify(members[1]).xreplace(self.ctx.subs):
                self.ctx.subs[m0] = members[1]        # (not again what the text already said)
                self.ctx.stated[m0] = f"line {line}"
                self.ctx.given[written_name(piece)] = (members[1], f"line {line}")
                self.display_settings.append(m0)
            self.display_relations.append((m0, "=", members[1]))
            if m0 in self.d.rot.ANGLES:
                self.last_angle_set = (m0, members[1])     # the turn a numeric matrix then shows
            self._spin_set(m0, members[1])
            if follows[0]:
                self._add(line, piece, "equation of motion", "holds", f"{follows[1]}, under the settings stated before it")
                return True
            self._add(line, piece, "setting", "unchecked",
                      f"sets {self.tex(m0)} = {self.tex(members[1])}: a case or an assumption of the text, not a claim")
            return True
        return self._undefined(line, piece, members, rels)

    def _spin_set(self, w, value):
        """ω̃ᵢ set to a constant: ω̃̇ᵢ = 0 too; and a spin the text has moved to this axis (ω̃₂ = Ω after
        ω̃₁ = Ω: the body turning about another axis) is no longer about the old one."""
        if w not in lx.W:
            return
        for k, other in enumerate(lx.W):
            if other != w and other in self.ctx.subs and self.ctx.subs[other] == value and _free(value):
                del self.ctx.subs[other]
                self.ctx.subs.pop(lx.WD[k], None)
        if not _free(value) & {lx.t}:
            self.ctx.subs[lx.WD[lx.W.index(w)]] = sp.S.Zero     # a constant component

    def _settings_before_neq(self, line, piece, members, rels) -> bool:
        """``I_1 = I_2 \\neq I_3``: the equalities are what the text assumes (the ≠ says the rest)."""
        if (set(rels) <= {"<", "≤"} or set(rels) <= {">", "≥"}) and all(m in (I1, I2, I3) for m in members):
            self.ctx.orderings.append(list(members)[::1 if rels[0] in "<≤" else -1])   # I₁ < I₂ < I₃, I₃ > I₂ > I₁
        for k, rel in enumerate(rels):
            a, b = members[k], members[k + 1]
            self.display_relations.append((a, rel, b))
            if rel == "=" and _moment_multiple(b) and not isinstance(b, sp.Symbol):
                k, b = b.as_coeff_Mul()             # I₂ = 2I₃: I₃ is I₂/2 from here on
                a = a / k
            if rel == "=" and isinstance(b, sp.Symbol) and self._settable(b) and \
                    sp.sympify(a).xreplace(self.ctx.subs) != b.xreplace(self.ctx.subs):
                self.ctx.subs[b] = a
                self.ctx.stated[b] = f"line {line}"
                self.display_settings.append(b)
        self._add(line, piece, "setting", "unchecked", "an assumption of the text (its equalities hold from here on)")
        return True

    def _undefined(self, line, piece, members, rels) -> bool:
        """A relation with symbols of the text's that nothing ties: decided only if it is an identity whatever they are."""
        self._flush()                   # a claim: the solutions before it are a complete group
        implied = under_settings(self, members[0], members[1]) if rels == ["="] else None
        if implied:
            self._add(line, piece, "identity", "holds", implied)
            return True
        if set(rels) <= {"<", ">", "≤", "≥"} and self._ordered(line, piece, members, rels):
            return True
        loose = set()
        for m in members:
            loose |= {s for s in _free(self._resolve(m)) if isinstance(s, lx.Generic)}
        loose -= self._constants()
        if not loose:
            return False
        if len(loose) == 1 and any(_free(self._resolve(m)) & set(lx.WD) for m in members) and \
                _a_torque(self._resolve(members[0] - members[-1]), next(iter(loose))):
            return False          # an equation of motion with a torque of the text's own (N₃)
        if len(loose) == 1 and rels == ["="] and self._euler_in_angles(line, piece, members):
            return True           # Euler's equation in the angles, with a torque of the text's own (T₁ᵉ)
        self.settings_only = False
        if self._vectors(line, piece, getattr(self, "_text", piece)):
            return True
        if self._restated(line, piece, members, rels):
            return True
        if set(rels) <= {"=", "≡"} and self._identity_then_named(line, piece, members, loose) or \
                right_named.defines(self, line, piece, members, rels, loose):
            return True
        names = ", ".join(sorted(self.tex(s) for s in loose))
        if set(rels) <= {"=", "≡"} and self._identity_whatever(members):
            self._add(line, piece, "identity", "holds", f"an identity whatever {names} stand for (expand)")
            return True
        if self._index_identity(line, piece, members, rels) or self._links_whatever(line, piece, members, rels):
            return True
        self._add(line, piece, "unknown", "unchecked",
                  f"relates {names}, which the text has not tied to the derivation")
        if not getattr(self, "_rereading_later", False):
            self.deferred.append((self.claims[-1], line, piece, self._snapshot()))
        self.settings_only = False
        return True

    def _read_later_definitions(self):
        """A statement in names the text defines only further on (a product of matrices given one
        by one below it) is read again at the end with those definitions, judging only (a flagged
        reading is thrown away); kept when it then holds: a reading not yet given is no ground for a flag."""
        final = self.ctx.defs
        self._rereading_later = True
        try:
            for claim, line, piece, saved in self.deferred:
                later = {k: v for k, v in final.items() if k not in saved.defs}
                if not later or claim not in self.claims:
                    continue
                ctx = self._snapshot()
                ctx.__dict__.update(saved.__dict__)
                ctx.defs = {**saved.defs, **later}
                second, _ = self._sandbox(ctx, line, piece, False, (), judging_only=True)
                if second and all(c.verdict == "holds" for c in second):
                    for c in second:
                        c.why += " (with names the text defines further on)"
                    at = self.claims.index(claim)
                    self.claims[at:at + 1] = second
        finally:
            self._rereading_later = False

    def _constants(self) -> set:
        """The text's symbols that its settings and solutions give meaning to: the value of a
        setting (Ω of ω̃₁ = Ω) and the integration constants of a solution it wrote (ω₀, ε of
        ω̃₁ = ω₀ cos(nt + ε)). A relation in them is checked with the settings and solutions put in."""
        out = set()
        for v in list(self.ctx.subs.values()) + list(self.ctx.solutions.values()):
            out |= {s for s in _free(v) if isinstance(s, lx.Generic)}
        return out

    def _new_name(self, sym) -> bool:
        """A symbol of the text's that it has not defined, nor the rate of one it has (u̇ of u)."""
        if not isinstance(sym, lx.Generic) or sym in self.ctx.defs:
            return False
        base = self.vocab.undotted(sym)
        return (base is None or base[0] not in self.ctx.defs) and sym not in self._dotted_definitions(sym, [sym])

    def _settable(self, sym) -> bool:
        return isinstance(sym, sp.Symbol) and (sym in VARIABLES or sym in PARAMETERS or sym == lx.t or
                                               sym in (lx.p_alpha_sym(), lx.p_gamma_sym()))

    def _mark_defined(self, sym):
        """A defined symbol of the text's is no longer 'loose'."""

    def _space_component(self, line, piece, sym, value) -> bool:
        """``\\omega_x = …`` where the text's ω₁, ω₂, ω₃ are the body components: the reading that
        fits is the space (inertial) component (R ω̃)ₓ = ω⁰ₓ of the text's sequence. Holds when that
        reading makes it hold; otherwise nothing is said (the text may mean something else)."""
        atom = self.vocab.generic.get(sym)
        if atom is None or atom.base != "omega" or atom.sub not in ("x", "y", "z") or \
                atom.dots or atom.bold or atom.hat or atom.tilde or atom.primes:
            return False
        claim = self._resolve(value)
        if not _free(claim) <= set(ANGLES) | set(RATES):
            return False
        target = self.d.conv.omega_space()["xyz".index(atom.sub)]
        if self.d.rot.trig_reduce(sp.expand(claim - target)) != 0:
            return False
        self._add(line, piece, "definition", "holds",
                  f"reading {self.tex(sym)} as the space (inertial) component of the angular velocity, "
                  f"(R ω̃)_{atom.sub} = {self.tex(target)}: trig_reduce")
        return True

    def _rotation(self, line, piece, m, label=None) -> bool:
        """A 3×3 matrix of the angles the text names as a matrix of its own: a rotation, checked as
        one. Of one angle: the active or the passive (coordinate) turn about x, y or z by it; of
        all three: the convention's R (body → space) or its transpose, the passive matrix that
        takes space components to body ones. A name that says its turn (``label``: the axis and
        angle of ``R_{x'}(\\theta)``) is held to it. False (nothing said) for any other matrix."""
        rot = self.d.rot
        angles = set(rot.ANGLES)
        if m.shape != (3, 3) or not _free(m) <= angles:
            return False
        if label is not None and len(_free(m)) == 1 and _free(m) != {label[1]}:
            return self._turn_by_another_angle(line, piece, m, *label)
        if not _free(m):       # numbers: the turn at the angle the text has just set (φ = 30°)
            # (an angle set in running text holds for its sentence only, so the value is kept here)
            last, value = getattr(self, "last_angle_set", (None, None))
            if last is None or not sp.sympify(value).is_number:
                return False
            used, at = [last], {last: value}
        else:
            used, at = sorted(_free(m) & angles, key=rot.ANGLES.index), {}
        if len(used) == 1:
            a = used[0]
            named = {f"the {kind} turn about {axis} by {self.tex(a)}": f(axis, a)
                     for axis in "xyz" for kind, f in (("passive", rot.passive), ("active", rot.active))}
        elif len(used) == 3:
            R = self.d.conv.matrix()
            named = {"the rotation R (body → space)": R, "the passive matrix Rᵀ (space → body)": R.T}
        else:
            return self._rate_matrix(line, piece, m)
        named = {what: target.xreplace(at) for what, target in named.items()}
        offs = {what: [k for k in range(9) if not entry_zero(m[k] - target[k])] for what, target in named.items()}
        for what, off in offs.items():
            if not off:
                self._add(line, piece, "rotation", "holds", f"{what}")
                return True
        for what, off in offs.items():         # one entry off: a typo of that matrix
            if len(off) == 1 and entry_zero(m[off[0]] + named[what][off[0]]):
                row, col = divmod(off[0], 3)
                self._add(line, piece, "rotation", "typo",
                          f"{what} but for the sign of the entry in row {row + 1}, column {col + 1}",
                          self.tex(named[what]))
                return True
        for what, off in offs.items():         # a name that says its turn: any one entry off is a typo
            if label is not None and f"about {label[0]} " in what and len(off) == 1:
                row, col = divmod(off[0], 3)
                self._add(line, piece, "rotation", "typo",
                          f"named {what}, which it is but for the entry in row {row + 1}, column {col + 1}",
                          self.tex(named[what]))
                return True
        return len(used) == 3 and (self._angles_exchanged(line, piece, m, named) or
                                   self._one_entry_off(line, piece, m, named))

    def _rate_matrix(self, line, piece, m) -> bool:
        """A 3×3 matrix of two angles: the matrix of the rates, ω̃ = B q̇ (body) or ω⁰ = B⁰ q̇ (space),
        or its inverse, with the rates in any order (a text lists its Euler vector as it likes:
        (φ̇, θ̇, ψ̇) for a 3-2-1 sequence whose first turn is ψ). Only a match is reported."""
        conv, rot = self.d.conv, self.d.rot
        names = [self.tex(q) for q in RATES]
        for what, B, cols in (("ω̃ = B q̇, the body components", conv.rate_matrix(), True),
                              ("ω⁰ = B⁰ q̇, the space components", conv.space_rate_matrix(), True),
                              ("q̇ = B⁻¹ ω̃, the rates from the body components", None, False)):
            if B is None:
                B = sp.Matrix(conv.rates_from_omega(sp.Matrix(lx.W))).jacobian(sp.Matrix(lx.W))
            for order in itertools.permutations(range(3)):
                P = B[:, list(order)] if cols else B[list(order), :]
                if all(rot.trig_reduce(sp.together(x - y)) == 0 for x, y in zip(m, P)):
                    listed = ", ".join(names[k] for k in order)
                    self._add(line, piece, "rotation", "holds", f"the matrix of the rates: {what}, "
                              f"with the rates in the order ({listed})")
                    return True
        return False

    def _coordinate_turn(self, line, pieces) -> bool:
        """Three rows ``x^{B} = … x^{A} + … y^{A}``, ``y^{B} = …``, ``z^{B} = …``: coordinates in frame B
        from those in frame A, a linear map whose matrix is checked as a rotation (`_rotation`).
        False (the rows read one by one) when they are not such a block or the matrix is no turn."""
        rows = [_COORDINATE.match(p) for p in pieces]
        if len(pieces) != 3 or not all(rows) or [r.group(1) for r in rows] != ["x", "y", "z"] \
                or len({r.group(2) for r in rows}) != 1:
            return False
        frames = {m.group(2) for r in rows for m in _COORDINATE_USE.finditer(r.group(3))}
        if len(frames) != 1 or frames == {rows[0].group(2)}:
            return False
        xyz = [self.vocab._generic(Atom(c)) for c in "xyz"]
        try:
            sides = [lx.parse(_COORDINATE_USE.sub(lambda m: " " + m.group(1) + " ", r.group(3)), self.vocab)
                     for r in rows]
        except lx.NotRead:
            return False
        values = [sp.expand(p.members[0].value) for p in sides if len(p.members) == 1]
        if len(values) != 3:
            return False
        m = sp.Matrix([[sp.diff(v, c) for c in xyz] for v in values])
        if any(sp.expand(v - sum(m[i, j] * xyz[j] for j in range(3))) != 0 for i, v in enumerate(values)) \
                or _free(m) & set(xyz):
            return False
        self.settings_only = False
        return self._rotation(line, " \\\\ ".join(pieces), m)

    def _matrix_name(self, sym, value):
        """X = (a matrix): X is from here on a non-commuting symbol (a product keeps its order)."""
        atom = self.vocab.generic.pop(sym)
        mat = lx.Generic(sym.name, commutative=False)
        self.vocab.generic[mat] = atom
        self._free_letter_moved(sym, mat, atom)
        self.ctx.defs[mat] = sp.ImmutableMatrix(value)
        self.ctx.columns.add(mat)
        return mat

    # -- display scope of settings ----------------------------------------------------------------
    def _open_display(self, inline=False, line=None):
        self.display_settings = []
        self.display_relations = []    # what its settings state, (a, relation, b)
        self.settings_only = not inline
        self._inline = inline      # the body's parameters set in running text stay (I₁ = I₂)
        self._subs_before = dict(self.ctx.subs)
        self._display_line = line
        if not inline:
            self._running_settings = None      # a display ends the sentences that listed cases

    def _close_display(self, concluded=()):
        """Settings made inside a display with claims, or in running text ("the case $\\theta = 0$"),
        hold there only; a display of settings alone sets them for the section, and so does a
        display's conclusion after ⇒ (``I_3 \\dot{\\omega}_3 = 0 \\Rightarrow \\omega_3 = \\Omega``): ``concluded``."""
        if getattr(self, "pending", None):
            self.pending_subs = dict(self.ctx.subs)      # the settings the pending solutions were written under
        if self.display_settings and not self.settings_only:
            keep = {k: v for k, v in self.ctx.subs.items() if k in PARAMETERS and k in self.display_settings}
            rates = [lx.WD[lx.W.index(k)] for k in concluded if k in lx.W]   # a constant spin's rate, 0
            kept = {k: self.ctx.subs[k] for k in [*concluded, *rates] if k in self.ctx.subs}
            self.ctx.subs = {**self._subs_before, **(keep if self._inline else {}), **kept}
        if self._inline and self.display_relations:
            self._cases_listed()

    def _cases_listed(self):
        """Settings in running text that contradict one another in one sentence ("the cases $I_1=I_2>I_3$,
        $I_1=I_2=I_3$ and $I_1=I_2<I_3$") are cases the text lists, not assumptions: none of them holds
        after it. Adjacent lines with no display between them count as one sentence."""
        line, prev = self._display_line, getattr(self, "_running_settings", None)
        if prev is None or line is None or prev["line"] is None or line - prev["line"] > 1:
            prev = {"before": dict(self._subs_before), "relations": [], "cases": False, "lines": set()}
        prev["line"] = line
        prev["lines"].add(line)
        prev["relations"] += self.display_relations
        ops = {"=": sp.Eq, ">": sp.Gt, "<": sp.Lt, "≥": sp.Ge, "≤": sp.Le}
        subs = self.ctx.subs

        def put(v):          # the settings in one another too (I₃ → I₂ → I₁)
            for _ in range(4):
                v = sp.sympify(v).xreplace(subs)
            return v

        def false(a, rel, b):
            if rel not in ops:
                return False
            try:
                return ops[rel](put(a), put(b)) is sp.false
            except (TypeError, ValueError):
                return False

        if prev["cases"] or any(false(*r) for r in prev["relations"]):
            prev["cases"] = True
            self.ctx.subs = dict(prev["before"])
            for c in self.claims:
                if c.kind == "setting" and c.line in prev["lines"]:
                    c.why = "one of the cases the text lists in this sentence (not assumed after it)"
        self._running_settings = prev

    # -- 4: calculus ------------------------------------------------------------------------------
    def _calculus(self, v):
        """``DT(e)`` and ``Derivative(e, x)`` evaluated (the module docstring, item 4)."""
        if not hasattr(v, "has") or not v.has(lx.Transposed, sp.MatPow, lx.DT, sp.Derivative):
            return v            # (one walk of v for the four kinds, most values holding none)
        if v.has(lx.Transposed):
            v = v.replace(lambda e: isinstance(e, lx.Transposed) and isinstance(e.args[0], sp.MatrixBase),
                          lambda e: e.args[0].T)
        if v.has(sp.MatPow):
            v = v.replace(lambda e: isinstance(e, sp.MatPow) and isinstance(e.args[0], sp.MatrixBase)
                          and e.args[1].is_integer, matrix_power)
        if not (v.has(lx.DT) or v.has(sp.Derivative)):
            return v
        v = v.replace(lambda e: isinstance(e, sp.Derivative), lambda e: self._partial(e))
        return v.replace(lambda e: isinstance(e, lx.DT), lambda e: self._dt(e.args[0]))

    def _partial(self, e):
        expr, pairs = self._resolve(e.expr), e.variable_count
        for var, n in pairs:
            # ω̃ in the angles only where expr holds it: deriving ω̃ for a sequence costs more than the rest
            if (var in ANGLES or var in RATES) and (not hasattr(expr, "has") or expr.has(*lx.W)):
                expr = expr.xreplace({w: self.d.omega[i] for i, w in enumerate(lx.W)})
            expr = untied_partials.partial(expr, var, n, self)     # a name it has not tied is no constant
        return expr

    def _dt(self, e):
        e = self._resolve(e)
        if isinstance(e, sp.MatrixBase):
            return e.applyfunc(self._dt)         # a matrix of the text's: entry by entry
        out = time_derivative(e, accels=ACCELS)
        out += sum((sp.diff(e, w) * wd for w, wd in zip(lx.W, lx.WD)), sp.S.Zero)
        out += sum((sp.diff(e, wd) * self._second_rate_symbol(i) for i, wd in enumerate(lx.WD) if e.has(wd)), sp.S.Zero)
        for s in _free(e):
            if isinstance(s, lx.Generic):
                atom = self.vocab.generic[s]
                out += sp.diff(e, s) * self.vocab._generic(atom.with_(dots=atom.dots + 1))
        return out + sp.diff(e, lx.t)

    def _second_rate_symbol(self, i):
        """ω̃̈ᵢ, the rate of ω̃̇ᵢ: the text's own symbol for it if it has written one, else
        ``\\ddot{\\tilde\\omega}_i`` (a symbol of the text's, as the reader takes one written)."""
        for s in list(self.vocab.generic):
            if self._second_rate(s) == i:
                return s
        return self.vocab._generic(Atom(base="omega", dots=2, tilde=True, sub=str(i + 1)))

    def _dotted_definitions(self, v, syms=None) -> dict:
        """Ẋ → d/dt of X's definition, for the text's dotted symbols whose X it has defined (``syms``: v's free symbols)."""
        rep = {}
        for s in _free(v) if syms is None else syms:
            if isinstance(s, lx.Generic) and s not in self.ctx.defs:
                base = self.vocab.undotted(s)
                if base is not None and base[0] in self.ctx.defs:
                    value = self.ctx.defs[base[0]]
                    for _ in range(base[1]):
                        value = self._dt(value)
                    rep[s] = value
        return rep | primed_functions.definitions(self.vocab, self.ctx.defs, _free(v) if syms is None else syms, self.tex)
