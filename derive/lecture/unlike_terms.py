"""Sums of unlike quantities: a term in an angular momentum added to a term in its square.

A physical formula adds only quantities of one dimension, so ``h - 2E\\mathbb{I}_3`` with h = ‖Π‖
(an angular momentum) and E an energy is a slip wherever it stands, whatever the formula goes on
to claim: the text meant h² (or E alone). This rule reads each member of a display on its own and
flags a sum two of whose terms have known dimensions that differ, neither of them a pure number.

Dimensions are known only where every name is tied: the model's principal moments I₁, I₂, I₃,
the body rates ω̃ᵢ and their rates, the Euler angles' rates and accelerations, the time t, the
angular momentum's magnitude and its components (a text's Πᵢ read as Iᵢω̃ᵢ), the angles
(dimensionless). The text's own letters (E, h, G, KE, a constant β₂₁) take a dimension only from
an equation the text writes that sets the letter (or a number times a power of it, 2E, h²) equal
to members whose dimensions are known and agree (``… = ½ Σ Πᵢ²/𝕀ᵢ = E``, ``‖Π‖² = Σ Πᵢ² = h²``);
or, alone in one term of a sum whose other terms have one known dimension, the dimension that makes
its term alike (``J^2 = I_1^2 A^2 + I_3^2\\omega_3^2`` makes A a rate);
a letter two such equations give different dimensions is unknown from then on, and a name the text
has set to a number (a worked example, in units it may have scaled) is unknown. A term with any
unknown name is never compared, and a pure number is never compared (a text may write 1 + E in
scaled units); a function's argument is read for sums of its own, its value taken as a pure number.
The components of one of the text's vectors (a₁, a₂, a₃ or a_x, a_y, a_z) share a dimension whatever
it is: a sum of three or more of them, each alone to a power times a number, with every power alike
but one (a₁² + a₂² + a₃³) adds unlike quantities too. So do two terms alike but for two axis components
of one letter of unknown dimension (``\\frac{1}{2} I_z (\\dot\\phi + \\dot\\psi\\cos\\theta) + \\frac{1}{2}
I_x \\dot\\psi^2``: I_z and I_x share a dimension, so the terms differ by a rate): a component along
x, y or z (never 1, 2, 3, which may number a solution's constants C₁ + C₂t) is given its letter's
dimension as an unknown, and two terms are compared only when their unknowns are the same. The components
a sum that writes its range 1 to 3 adds (r₁, r₂, r₃ of Σ_{a=1}^3 r_a², `derive.lecture.axis_sums`) share
one such unknown too, and Kronecker's δ_{ak} is a pure number.

May import: SymPy, :mod:`derive.lecture.latex`, :mod:`derive.lecture.statements`, :mod:`derive.lecture.axis_sums`,
:mod:`derive.symbolic`.
"""
from __future__ import annotations

import copy
import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.axis_sums import shares_dimension
from derive.lecture.statements import top_level
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3, p_alpha, p_gamma
from derive.symbolic.rotations import ANGLES, RATES

_MOMENT, _RATE, _TIME = (1, 2, 0), (0, 0, -1), (0, 0, 1)
"""Exponents of mass, length and time."""
_NONE = (0, 0, 0)


def _times(d, n):
    return tuple(sp.Rational(n) * x for x in d)


def _plus(a, b):
    return tuple(x + y for x, y in zip(a, b))


_TIED = {**{s: _MOMENT for s in (I1, I2, I3)}, **{s: _RATE for s in (*lx.W, *RATES)},
         **{s: _times(_RATE, 2) for s in (*lx.WD, *ACCELS)}, **{s: _NONE for s in ANGLES}, lx.t: _TIME,
         **{s: _plus(_MOMENT, _RATE) for s in (p_alpha, p_gamma, lx.LMAG)}}
"""The model's names and their dimensions."""

_RELATIONS = re.compile(r"(?<![<>!\\])=|:=|\\(?:equiv|approx|triangleq|simeq|leq?|geq?|leqslant|geqslant)(?![A-Za-z])|<|>")
_EQUAL = re.compile(r"\s*(?:=|:=|\\equiv|\\triangleq)\s*$")
_SIGN = re.compile(r"[+-]")
_LONE = re.compile(r"\s*\d*\s*(?:\\[A-Za-z]+\s*\{\s*\w+\s*\}|\\[A-Za-z]+|[A-Za-z])\s*(?:_\s*(?:\{[^{}]*\}|\w))?"
                   r"\s*(?:\^\s*(?:\{\s*\d\s*\}|\d))?\s*[.,]?\s*$")
"""A member that may be a number times a power of one letter: ``2E``, ``h^2``, ``\\mathrm{KE}``, ``G_0``."""
_CONFLICT = "conflict"
_COMPONENTS = {"1", "2", "3", "x", "y", "z"}
_NAMES = ("M", "L", "T")


_AXIS_COMPONENTS = {"x", "y", "z"}


def _shown(d) -> str:
    """A dimension as exponents of M, L, T: ``M L^2 T^-1``; a letter's unknown dimension by its name, ``[I] T^-1``."""
    d = [sp.sympify(e) for e in d]
    letters = sorted({s for s in d[0].free_symbols if s.name.endswith("_M")}, key=str)
    parts = [s.name[:-2] if d[0].coeff(s) == 1 else f"{s.name[:-2]}^{d[0].coeff(s)}" for s in letters]
    d = [e.subs({s: 0 for s in e.free_symbols}) for e in d]
    parts += [n if e == 1 else f"{n}^{e}" for n, e in zip(_NAMES, d) if e != 0]
    return " ".join(parts) or "1"


def _numeric(d) -> bool:
    """A dimension known outright (no letter's unknown dimension in it)."""
    return d is not None and d != _CONFLICT and all(sp.sympify(e).is_number for e in d)


def _comparable(a, b) -> bool:
    """Two dimensions whose letters' unknowns are the same, so that they differ only by known exponents."""
    return all(sp.sympify(x - y).is_number for x, y in zip(a, b))


class UnlikeTerms:
    """The mixin of `derive.lecture.notes_check.Checker` that flags sums of unlike quantities."""

    def _unlike_terms(self, line, piece):
        """Learn the dimensions the piece's equations give the text's letters; (piece, why) when a
        member of it adds quantities of unlike dimensions, else None."""
        if not hasattr(self, "_dimensions"):
            self._dimensions, self._unknowns = {}, {}
        cuts = top_level(piece, _RELATIONS)
        if not cuts and not _SIGN.search(piece):
            return None
        bounds = [0, *(p for m in cuts for p in (m.start(), m.end())), len(piece)]
        members = [piece[bounds[k]:bounds[k + 1]] for k in range(0, len(bounds), 2)]
        relations = [m.group(0) for m in cuts]
        # only what can be a sum or a lone letter to learn is read again (the cheap test first)
        learn = bool(relations) and all(_EQUAL.match(r) for r in relations) and any(_LONE.match(m) for m in members)
        values = [self._member_value(m) if learn or _SIGN.search(m) else None for m in members]
        for text, value in zip(members, values):
            if value is None or not _SIGN.search(text):
                continue
            found = []
            try:
                self._dimension(value, found)
            except (TypeError, AttributeError, ValueError):
                continue            # a node the walk does not know: the member is not compared
            if found:
                a, b = (-x if x.could_extract_minus_sign() else x for x in found[0])
                return piece, (f"adds quantities of unlike dimensions: {self.tex(a)} ({_shown(self._dimension(a, []))}) "
                               f"and {self.tex(b)} ({_shown(self._dimension(b, []))})")
            odd = self._unlike_components(value)
            if odd is not None:
                return piece, ("adds unlike powers of the components of one vector, which share a dimension: "
                               f"{self.tex(odd[0])} and {self.tex(odd[1])}")
        if learn:
            try:
                self._learn(values)
            except (TypeError, AttributeError, ValueError):
                pass                # nothing is learned from a member the walk does not know
        return None

    def _unlike_components(self, value):
        """(a term, the odd term) of a sum in ``value`` that adds powers of three or more components of
        one of the text's vectors (a_1, a_2, a_3 or a_x, a_y, a_z, each alone times a number) with every
        power alike but one (a_1^2 + a_2^2 + a_3^3), else None."""
        for add in value.atoms(sp.Add):
            powers = {}
            for t in add.args:
                one = _lone_letter(t)
                atom = self.vocab.generic.get(one[0]) if one is not None else None
                if atom is None or atom.sub not in _COMPONENTS:
                    continue
                powers.setdefault(atom.with_(sub="", text=""), []).append((atom.sub, one[1], t))
            for found in powers.values():
                exps = [e for _, e, _ in found]
                if len(found) < 3 or len({sub for sub, _, _ in found}) != len(found) or len(set(exps)) != 2:
                    continue
                odd = [t for _, e, t in found if exps.count(e) == 1]
                if len(odd) == 1:
                    return next(t for _, e, t in found if exps.count(e) > 1), odd[0]
        return None

    def _unlike_flagged(self, line, unlike, start):
        """Flag the display's pieces that add unlike quantities, once the display is read: a piece
        its reading flagged already (a claim from ``start`` on, written as the piece) is not flagged
        twice."""
        for piece, why in unlike:
            if not any(c.latex == piece and c.verdict in ("typo", "fails") for c in self.claims[start:]):
                self._add(line, piece, "dimensions", "fails", why)

    def _member_value(self, text):
        """The member read alone (None where it does not read as one expression), leaving the
        vocabulary's record of the text's names as it was."""
        if not text.strip():
            return None
        vocab = copy.copy(self.vocab)
        vocab.generic, vocab._atoms_met, vocab.defined = dict(vocab.generic), dict(vocab._atoms_met), dict(vocab.defined)
        try:
            parsed = lx.parse(text, vocab)
        except (lx.NotRead, ArithmeticError, TypeError, ValueError, AttributeError, IndexError, KeyError,
                NotImplementedError, RecursionError):
            return None
        if len(parsed.members) != 1 or parsed.relations:
            return None
        value = parsed.members[0].value
        return value if isinstance(value, sp.Expr) and not isinstance(value, sp.MatrixBase) else None

    def _learn(self, values):
        """Letters set equal to members of known dimensions that agree take that dimension."""
        letters = [_lone_letter(v) for v in values]
        known = {d for d in (self._dimension(v, []) for v, one in zip(values, letters)
                             if v is not None and v.free_symbols and (one is None or one[0] in _TIED)) if _numeric(d)}
        for v in values:
            self._learn_from_sum(v, known)
        if len(known) != 1:
            return          # two members that disagree, or none known: nothing is learned from it
        (whole,) = known
        for one in letters:
            if one is None or one[0] in _TIED:
                continue
            letter, power = one
            d = _times(whole, sp.Rational(1) / power)
            had = self._dimensions.get(letter)
            if had is None:
                self._dimensions[letter] = d
            elif had != d:
                self._dimensions[letter] = _CONFLICT

    def _learn_from_sum(self, value, known):
        """A letter of the text's in one term of a sum whose other terms have one known dimension,
        agreeing with the equation's other members where they are known, takes the dimension that
        makes its term alike (``J^2 = I_1^2 A^2 + I_3^2 \\omega_3^2`` gives A a rate's)."""
        if not isinstance(value, sp.Add):
            return
        dims = [(t, self._dimension(t, [])) for t in value.args]
        if any(d is not None and not _numeric(d) for _, d in dims):
            return          # a term in a letter's unknown dimension: nothing is learned from it
        alike = {d for _, d in dims if d is not None}
        odd = [t for t, d in dims if d is None]
        # pure numbers among the terms (scaled units) or two members that disagree: nothing is learned
        if len(odd) != 1 or len(alike) != 1 or _NONE in alike or known and known != alike:
            return
        (whole,) = alike
        letters = [s for s in odd[0].free_symbols if self._symbol_dimension(s) is None]
        if len(letters) != 1:
            return          # two unknown letters in the term: neither is read off
        letter = letters[0]
        rest, part = odd[0].as_independent(letter, as_Add=False)
        base, power = part.as_base_exp()
        if base != letter or not power.is_Rational or power == 0:
            return          # the letter inside a function or a sum of its own: its dimension is not read off
        d = self._dimension(rest, [])
        if not _numeric(d):
            return
        d = _times(_plus(whole, _times(d, -1)), sp.Rational(1) / power)
        had = self._dimensions.get(letter)
        self._dimensions[letter] = d if had is None or had == d else _CONFLICT

    def _symbol_dimension(self, s):
        for table in (self.ctx.subs, self.ctx.defs):
            v = table.get(s)
            if isinstance(v, sp.Expr) and v.is_number:
                return None           # set to a number: the text's units may be scaled
        d = _TIED.get(s, self._dimensions.get(s))
        if d is None:
            return self._component_dimension(s)
        return None if d == _CONFLICT else d

    def _component_dimension(self, s):
        """An axis component of one of the text's letters (I_x, I_z), plain, of unknown dimension: its
        letter's dimension as unknowns, which every component along x, y, z shares; else None."""
        atom = self.vocab.generic.get(s)
        if atom is not None and atom.base == "delta" and re.fullmatch(r"[a-z]{2}", atom.sub) and not atom.mark:
            return _NONE        # Kronecker's δ_ak: a pure number
        summed = shares_dimension(self.vocab, atom)       # r_a summed over a = 1 … 3: r₁, r₂, r₃ alike
        if atom is None or not summed and (atom.sub not in _AXIS_COMPONENTS or atom.sup) or atom.dots or atom.primes or \
                atom.tilde or atom.hat or atom.mark:
            return None
        key = atom.with_(sub="", sup="", text="")
        if key not in self._unknowns:
            name = f"[{key.base}]"
            self._unknowns[key] = tuple(sp.Symbol(f"{name}_{n}") for n in _NAMES)
        return self._unknowns[key]

    def _dimension(self, e, found):
        """The dimension of ``e`` (None where a name in it has none known); the unlike pairs of terms
        of its sums are appended to ``found``."""
        if e.is_Number or e in (sp.pi, sp.E, sp.I):
            return _NONE
        if isinstance(e, sp.Symbol):
            return self._symbol_dimension(e)
        if isinstance(e, sp.Add):
            dims = [(t, self._dimension(t, found)) for t in e.args]
            real = [(t, d) for t, d in dims if d is not None and d != _NONE]
            for k, (t, d) in enumerate(real):
                for u, e in real[:k]:
                    if d != e and _comparable(d, e) and not found:
                        found.append((u, t))
            known = {d for _, d in dims}
            return known.pop() if len(known) == 1 else None
        if isinstance(e, sp.Mul):
            out = _NONE
            for f in e.args:
                d = self._dimension(f, found)
                out = None if d is None or out is None else _plus(out, d)
            return out
        if isinstance(e, sp.Pow):
            d = self._dimension(e.base, found)
            self._dimension(e.exp, found)
            if d is None:
                return None
            if e.exp.is_Rational:
                return _times(d, e.exp)
            return _NONE if d == _NONE else None
        if isinstance(e, sp.Abs):
            return self._dimension(e.args[0], found)
        if isinstance(e, sp.Function) and isinstance(e.func, sp.FunctionClass) and e.args \
                and not isinstance(e, sp.core.function.AppliedUndef) and not isinstance(e, (lx.DT, lx.MatProduct, lx.Transposed)):
            for a in e.args:
                self._dimension(a, found)
            return _NONE           # sin, cos, exp, sn, cn, dn of their argument: a pure number
        return None


def _lone_letter(v):
    """(letter, power) of a member that is a number times a power of one letter (2E, h², KE)."""
    if v is None:
        return None
    _, rest = v.as_coeff_Mul()
    base, power = rest.as_base_exp()
    if isinstance(base, sp.Symbol) and power.is_Rational and power != 0:
        return base, power
    return None
