"""A perturbation the text names: ``\\omega_1 = \\eta_1``, ``\\omega_2 = 1 + \\eta_2``, ``\\omega_3 =
\\eta_3`` (a body component of the angular velocity set to a constant plus a symbol the text has not
used before), and the equations it then writes in those symbols, ``I_1\\dot\\eta_1 = (I_2 -
I_3)\\eta_3 + O(\\eta^2)``, ``\\ddot\\eta_1 = \\frac{(I_2 - I_3)(I_1 - I_2)}{I_3I_1}\\eta_1``.

Takes: the checker's items and statements (`derive.lecture.notes_check.Checker`). Gives: the mixin
`Perturbations`. ``_perturbation_named`` records, for the rest of the section, each ηᵢ with its
component i and its constant cᵢ (ω̃ᵢ = cᵢ + ηᵢ; a number or the text's constants, never the time,
an angle or a rate). ``_perturbed`` judges a statement in the ηᵢ
that writes a rate η̇ᵢ or η̈ᵢ and no name the perturbation does not tie (the moments and cᵢ
aside): with ηᵢ = ε eᵢ, η̇ᵢ the body's rate ω̃̇ᵢ = fᵢ(c + ε e) from Euler's equations, η̈ᵢ its
derivative along them, the difference of the two sides must vanish to the order the statement
keeps, a written remainder ``O(\\eta^n)`` keeping order n − 1. A statement with no remainder
is held to first order once the section has written one (the text works to first order from
there); otherwise exactly. It `holds` when every kept order vanishes, and `fails` when one does
not (its why naming the order). Everything else is left to the rest of the reader.
May import: sympy, :mod:`derive.lecture.latex`, :mod:`derive.lecture.comparing`, :mod:`derive.symbolic.lagrangian`,
:mod:`derive.symbolic.rotations`, :mod:`derive.lecture.statements`.

The perturbation may be written as variations (`derive.lecture.variations`): ``\\omega_1 = \\Omega +
\\delta\\omega_1``, or the column ``\\vec\\omega = (\\delta\\omega_1, \\Omega_0 + \\delta\\omega_2,
\\delta\\omega_3)``; δωᵢ is then ηᵢ, kept apart from ωᵢ by its mark. A statement written with ≈ and no
remainder keeps first order, as one with ``O(\\eta^2)`` does. A perturbed component may stand beside
the ηᵢ: ω̃ᵢ is cᵢ + ηᵢ there and ω̃̇ᵢ the body's rate (``\\dot\\omega_1 = \\delta\\dot\\omega_1``). A steady
column ``\\vec\\omega = (0, 0, \\Omega)`` followed in its section by the column of its variations
``\\delta\\vec\\omega = (\\delta\\omega_1, \\delta\\omega_2, 0)`` names the perturbation ω̃ᵢ = cᵢ + δωᵢ for all three
components, the steady column's letters its constants; ``O(\\delta\\omega^2)`` is then its remainder.
"""
from __future__ import annotations

import functools
import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.comparing import free
from derive.lecture.statements import split_top, statements
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3
from derive.symbolic.rotations import ANGLES, RATES

# a remainder O(η^n) (or O(|η|^n)): its letter and n
_REMAINDER = re.compile(r"O\s*(?:\\(?:left|[Bb]igg?l?)\s*)?\(\s*\|?\s*((?:\\delta\s*)?\\?[A-Za-z]+)\s*\|?\s*\^\s*\{?\s*(\d)\s*\}?\s*"
                        r"(?:\\(?:right|[Bb]igg?r?)\s*)?\)")     # O(eta^2), O\left(\eta^2\right)
_TERM = re.compile(r"\s*[+-]\s*" + _REMAINDER.pattern)


def _without_remainders(text):
    """(text without its O(·) terms, a member that is one alone read as 0; their letters and least n)."""
    # O(δω²) is the variations' remainder: its letter is the varied one
    found = [(re.sub(r"^\\delta\s*", "", m.group(1)).lstrip("\\"), int(m.group(2))) for m in _REMAINDER.finditer(text)]
    out = _TERM.sub("", text)
    out = _REMAINDER.sub("0", out)
    return out, found


def _key(atom):
    """A perturbation's symbol as the section records it: its letter, index, bold face and mark (δ)."""
    return atom.base, atom.sub, atom.bold, atom.mark


def _written(key) -> str:
    """The letter of a recorded perturbation as LaTeX: ``\\eta``, ``\\delta\\omega``."""
    letter = "\\" + key[0] if len(key[0]) > 1 else key[0]
    return "\\delta " + letter if key[3] == "delta" else letter


@functools.lru_cache(maxsize=64)
def _perturbed_model(d, moments, perturbation):
    """`Perturbations._perturbed_model` for the section's settings: every statement of a section
    in its perturbation asks for the same model, so it is solved once."""
    eps = sp.Dummy("epsilon")
    e = [sp.Dummy(f"e{k + 1}") for k in range(3)]
    residuals = d.euler(dict(moments))
    rate = [sp.solve(residuals[i], lx.WD[i])[0] for i in range(3)]
    second = [sum(sp.diff(rate[i], lx.W[j]) * rate[j] for j in range(3)) for i in range(3)]
    at = {lx.W[i]: base + eps * e[i] for i, base in perturbation}
    return eps, e, [sp.expand(x.xreplace(at)) for x in rate], [sp.expand(x.xreplace(at)) for x in second]


class Perturbations:
    """The mixin's recording of a named perturbation and its judging of the equations in it."""

    def _perturbation_named(self, item, before):
        """``\\omega_i = c + \\eta`` in the prose or a display, η new (not among ``before``, the text's
        symbols met before the item was read), or the column ``\\vec\\omega = (\\delta\\omega_1, \\Omega_0 +
        \\delta\\omega_2, \\delta\\omega_3)`` of them: recorded for the section."""
        latex = getattr(item, "latex", None)
        if item.kind not in ("assumption", "inline", "display") or not latex or "\\omega" not in latex:
            return
        try:
            read = [lx.parse(latex, self.vocab)]
        except lx.NotRead:          # a list of settings, or a setting and a condition: each statement
            read = [r for whole in statements(latex) for p in split_top(whole) if (r := self._read(p)) is not None]
        for parsed in read:
            if parsed.relations != ["="]:
                continue
            left, right = parsed.members[0].value, parsed.members[1].value
            if left in lx.W:
                self._component_perturbed(lx.W.index(left), sp.sympify(right), before)
            elif left is lx.OMEGA_VEC and isinstance(right, sp.MatrixBase) and right.shape == (3, 1):
                for i in range(3):      # the column of the body components, each one perturbed
                    self._component_perturbed(i, sp.sympify(right[i]), before)
                self.ctx.steady = self._steady_column(right)
            elif isinstance(right, sp.MatrixBase) and right.shape == (3, 1) and self.ctx.steady is not None:
                self._variation_column(left, right)

    def _steady_column(self, column):
        """The column of constants a statement sets 𝛚 to (a steady spin), or None when an entry moves."""
        moving = set(lx.W) | set(lx.WD) | set(ANGLES) | set(RATES) | set(ACCELS) | {lx.t}
        entries = [sp.sympify(x) for x in column]
        if any(free(x) & moving or any(isinstance(s, lx.Quantity) for s in free(x)) for x in entries):
            return None
        return tuple(entries)

    def _variation_column(self, left, right):
        """``\\delta\\vec\\omega = (\\delta\\omega_1, \\delta\\omega_2, 0)`` after the steady column c of 𝛚:
        each δωᵢ is ω̃ᵢ − cᵢ, a 0 entry saying only that the kick leaves that component alone."""
        atom = self.vocab.generic.get(left) if isinstance(left, lx.Generic) else None
        if atom is None or atom.base != "omega" or not atom.bold or not atom.mark.startswith("delta") or atom.sub:
            return
        keys = []
        for i, entry in enumerate(sp.sympify(x) for x in right):
            a = self.vocab.generic.get(entry) if isinstance(entry, lx.Generic) else None
            if entry == 0:
                continue
            if a is None or a.base != "omega" or a.sub != str(i + 1) or a.mark != atom.mark or a.bold or a.dots:
                return
            keys.append(_key(a))
        if not keys:
            return
        # the steady column's own letters (Ω) are its constants, no perturbation of it
        constants = {_key(self.vocab.generic[x]) for c in self.ctx.steady for x in free(c) if x in self.vocab.generic}
        self.ctx.perturbation = {k: v for k, v in self.ctx.perturbation.items() if k not in constants}
        for i in range(3):
            key = (keys[0][0], str(i + 1), False, keys[0][3])
            self.ctx.perturbation[key] = (i, self.ctx.steady[i])

    def _read(self, piece):
        """A statement read, or None."""
        try:
            return lx.parse(piece, self.vocab)
        except lx.NotRead:
            return None

    def _component_perturbed(self, i, right, before):
        """Record ω̃ᵢ = right when right is a steady cᵢ plus one new symbol of the text's."""
        new = [s for s in free(right) if isinstance(s, lx.Generic) and s not in before and sp.diff(right, s) == 1]
        if len(new) > 1:        # ω₂ = Ω + η₂, both new: the perturbation is the one indexed as the component
            new = [s for s in new if self.vocab.generic[s].sub == str(i + 1)]
        if len(new) != 1:
            return
        base = sp.expand(right - new[0])
        moving = set(lx.W) | set(lx.WD) | set(ANGLES) | set(RATES) | set(ACCELS) | {lx.t} | set(new)
        if free(base) & moving or any(isinstance(s, lx.Quantity) for s in free(base)):
            return                  # a base that moves (ω̃₁ = A cos Ωt + ε) is no steady motion to perturb
        self.ctx.perturbation[_key(self.vocab.generic[new[0]])] = (i, base)

    def _perturbed(self, line, piece, text) -> bool:
        """Judge a statement in the section's perturbation (True: judged here)."""
        named = self.ctx.perturbation
        if not named or ("=" not in text and "\\approx" not in text):
            return False
        plain, remainders = _without_remainders(text)
        letters = {key[0] for key in named}
        if any(letter not in letters for letter, _ in remainders):
            return False
        try:
            parsed = lx.parse(plain, self.vocab)
        except lx.NotRead:
            return False
        if not set(parsed.relations) <= {"=", "≈"} or not parsed.relations:
            return False
        eps, e, model, rates = self._perturbed_model()
        put, has_rate = {}, False
        constants = {I1, I2, I3}.union(*(free(base) for _, base in named.values()))
        # the perturbed components themselves, ω̃ᵢ = cᵢ + ηᵢ and ω̃̇ᵢ = η̇ᵢ (ω̇₁ = δω̇₁ about a steady spin)
        whole = {w: v for i, base in named.values() for w, v in ((lx.W[i], base + eps * e[i]), (lx.WD[i], model[i]))}
        for s in set().union(*(free(sp.sympify(m.value)) for m in parsed.members)):
            if s in whole:
                put[s] = whole[s]
                has_rate |= s in lx.WD
                continue
            atom = self.vocab.generic.get(s) if isinstance(s, lx.Generic) else None
            if atom is None or _key(atom) not in named:
                if s not in constants:
                    return False            # a name the perturbation does not tie
                continue
            i, _ = named[_key(atom)]
            if atom.dots > 2 or atom.tilde or atom.hat or atom.primes or atom.sup:
                return False
            put[s] = (eps * e[i], model[i], rates[i])[atom.dots]
            has_rate |= atom.dots > 0
        if not has_rate or not put.keys() - whole.keys():
            return False                    # no rate, or none of the ηᵢ themselves: left to the rest of the reader
        # a remainder O(ηⁿ) keeps order n − 1; an ≈ without one, first order (the text linearises from there)
        order = min((n for _, n in remainders), default=2 if "≈" in parsed.relations else None)
        if order is not None:
            self.ctx.perturbation_order = order - 1
        keep = order - 1 if order is not None else self.ctx.perturbation_order
        for k in range(len(parsed.members) - 1):
            r = sp.sympify(parsed.members[k].value - parsed.members[k + 1].value).xreplace(put)
            self._add(line, piece, "equation of motion", *self._perturbed_verdict(r, eps, keep))
        return True

    def _perturbed_model(self):
        """(ε, e, ω̃̇ᵢ, ω̃̈ᵢ): the body's rates from Euler's equations (the section's settings of the
        moments in), at ω̃ = c + ε e."""
        moments = tuple((k, v) for k, v in self.ctx.subs.items() if k not in lx.W and k not in lx.WD)
        return _perturbed_model(self.d, moments, tuple(self.ctx.perturbation.values()))

    def _perturbed_verdict(self, r, eps, keep):
        """(verdict, why) of a difference r(ε) that must vanish to order ``keep`` (None: exactly)."""
        names = ", ".join(sorted({_written(key) for key in self.ctx.perturbation}))
        put = f"the text's perturbation \\omega_i = c_i + {names}_i put in"
        r = sp.expand(r)
        if free(r) & (set(lx.W) | set(lx.WD)):
            return "unchecked", "a component the text's perturbation leaves untied"
        if keep is None:
            if r == 0:
                return "holds", f"Euler's equations with {put}: exact (expand)"
            return "unchecked", ("not exact in the text's perturbation, and no remainder O(·) written in its section "
                                 "says to which order it is meant")
        for n in range(keep + 1):
            coefficient = sp.expand(r.coeff(eps, n))
            if coefficient != 0:
                return "fails", (f"Euler's equations with {put}: the terms of order {n} in {names} "
                                 f"differ by {sp.latex(coefficient)}")
        return "holds", f"Euler's equations with {put}, to order {keep} in {names} (expand)"
