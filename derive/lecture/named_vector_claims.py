"""Statements in a text's named vectors for the notes checker (read by `derive.lecture.named_vectors`):
a definition recorded, each link of a chain judged against the member before it.

Gives the mixin `NamedVectors` of `derive.lecture.notes_check.Checker`: `_named_vectors`, tried
last, on a statement no other reader read, and `_algebra_or_named`, on one the vector-algebra reader
read without a verdict.

A statement ``𝐗 = …`` whose left side is a vector the section has not set, and which its right
side does not involve, defines it: recorded (`named_vectors.Definitions`), not judged; set again to
an expression its recorded one cannot be compared with (a law's 𝐌_O = d𝐇_O/dt, then 𝐌_O = 𝐫_O × 𝐅),
the later one is its value from there on; a bold Ω the prose before it says precesses, set to an
expression in one torque and one angular momentum, is judged instead as the precession vector
(`derive.lecture.precession_vector`) and recorded only where it holds. Each
other link ``a = b`` of a chain is judged with the section's definitions put in: it **holds**
when its two sides are the same vector for every value of the vectors they involve. When the sides
differ, the link is a **typo** only if both involve the very same vectors and one edit of the
later side (a sign, a factor, the order of a cross product, an index) makes it hold; otherwise it
is left unchecked, since a text's chain may use a fact of its own (𝐯 = d𝐫/dt, 𝐅 = d(m𝐯)/dt, a
motion in a plane) that a general vector does not have.

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.named_vectors`, :mod:`derive.lecture.precession_vector`, the single edits of
:mod:`derive.lecture.vectors`, :mod:`derive.lecture.mp_values`, :mod:`derive.lecture.zero_test`
(`expanded`), SymPy, mpmath.
"""
from __future__ import annotations

import random

import mpmath
import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import mp_values
from derive.lecture import named_vectors as nv
from derive.lecture import precession_vector
from derive.lecture import vectors as vc
from derive.lecture.zero_test import expanded

WHY = "as vectors in general (each named vector a 3-vector of its own, 𝐫_{A/B} = 𝐩_A − 𝐩_B, sums for two generic terms)"
DEFINES = "defines the text's {name} (recorded, then used in its section)"
APART = ("involves {loose} on one side only: a fact of the text's (a law, a rate, a motion it sets) "
         "ties them, which a general vector does not have")
UNMENDED = "its sides differ as vectors in general, and no single edit mends it: the text may use a fact of its own"
IN_PLANE = "its sides differ as vectors in general; in the plane the text set, a fact of that motion may tie them"


class NamedVectors:
    """Mixin of the checker. Uses ``self._add``, ``self.claims``, ``self.ctx``, ``self._algebra``, ``self._section_of``,
    ``self._plane_at``, ``self.notes`` (the prose before a display) and ``self.judging_only``."""

    def _algebra_or_named(self, line, piece, text) -> bool:
        """The vector-algebra reader (`derive.lecture.algebra_claims`); where it leaves every claim of a
        statement unchecked (vectors it cannot tie to the body), this reader's verdicts instead when it
        gives one."""
        start = len(self.claims)
        if not self._algebra(line, piece, text):
            return False
        theirs = self.claims[start:]
        if any(c.verdict != "unchecked" for c in theirs):
            return True
        del self.claims[start:]
        if not (self._named_vectors(line, piece, text) and any(c.verdict != "unchecked" for c in self.claims[start:])):
            self.claims[start:] = theirs
        return True

    def _named_vectors(self, line, piece, text) -> bool:
        """Read and judge a statement in named vectors (False when it is not one)."""
        table = self.__dict__.setdefault("_named_definitions", {})
        definitions = table.setdefault(self._section_of(line), nv.Definitions())
        try:
            reading = nv.read(text, definitions)
        except lx.NotRead:
            return False
        first = reading.members[0]
        if reading.free or set(reading.relations) - {"=", "≡"} or len(first) < 2:
            return False
        start = 1
        head = first[0].atom
        key = _key(head) if head is not None else None
        if key is not None and not definitions.known(*key) and not _involves(first[1].value, head):
            if not self._precession_defined(line, piece, reading, definitions):
                definitions.add(*key, reading.source[first[1].start:first[1].end].strip())
                self._add(line, piece, "definition", "unchecked", DEFINES.format(name=head.text))
            start = 2
        self.ctx.head = reading.source[:first[0].end].strip()      # a row that opens with = continues it
        for k in range(start, len(first)):
            verdict, why, fix = self._named_link(line, reading, k, definitions)
            self._add(line, piece, "identity", verdict, why, fix)
            if k == 1 and key is not None and verdict == "unchecked":
                # set again to what the earlier value cannot be compared with: the text's value from here on
                definitions.add(*key, reading.source[first[1].start:first[1].end].strip())
        return True

    def _precession_defined(self, line, piece, reading, definitions) -> bool:
        """Judge 𝛀 = … as the precession vector where the prose ties its head to the precession
        (`derive.lecture.precession_vector`); recorded only where it holds. False when it is not one."""
        first = reading.members[0]
        lead = next((i.lead for i in self.notes.items if i.line == line and i.kind in ("display", "inline")), "")
        judged = precession_vector.judged(first[1].value) if precession_vector.ties(first[0].atom, lead) else None
        if judged is None:
            return False
        verdict, why = judged
        fix = None
        if verdict == "typo" and not self.judging_only:
            reread = lambda src: nv.read(src, definitions)  # noqa: E731
            fix = next((again_src.strip() for _, _, _, again_src, again in vc.edited_readings(reading, 1, reread, 60)
                        if (precession_vector.judged(again.members[0][1].value) or ("",))[0] == "holds"), None)
        if verdict == "typo" and fix is None:
            verdict = "fails"       # its negative, but no single edit of the side writes the solution
        if verdict == "holds":
            definitions.add(*_key(first[0].atom), reading.source[first[1].start:first[1].end].strip())
        self._add(line, piece, "precession vector", verdict, why, fix)
        return True

    def _named_link(self, line, reading, k, definitions):
        """Member k against member k − 1: (verdict, why, correction)."""
        first = reading.members[0]
        a, b = first[k - 1].value, first[k].value
        if _same(a, b):
            return "holds", WHY, None
        if _same(a, b) is None:
            return "unchecked", "its sides are not of one kind (a vector against a scalar)", None
        if self._plane_at(line) is not None:
            return "unchecked", IN_PLANE, None
        if not self.judging_only:
            reread = lambda src: nv.read(src, definitions)  # noqa: E731
            for _, _, what, again_src, again in vc.edited_readings(reading, k, reread, 60):
                members = again.members[0]
                if _same(members[k - 1].value, members[k].value):
                    return "typo", f"{WHY}: its sides differ; one edit ({what}) makes it hold", again_src.strip()
        names = (s.name.split(".")[0].rstrip("^.") for s in _symbols(a) ^ _symbols(b))
        loose = sorted({n for n in names if "#" not in n and not n.startswith("p_")})
        return "unchecked", APART.format(loose=", ".join(loose)) if loose else UNMENDED, None


def _key(atom):
    """What a head names in `named_vectors.Definitions` (a bold letter or a plain one), or None."""
    if atom.hat or atom.dots or atom.sup or atom.tilde or atom.mark:
        return None
    bold = atom.bold or atom.text.startswith("\\vec")
    return (atom.base if bold else nv.PLAIN + atom.base, atom.sub, atom.primes)


def _involves(value, atom) -> bool:
    name = nv._name(atom.base, atom.sub, atom.primes, {})
    return any(s.name.split(".")[0] == name for s in _symbols(value))


def _symbols(value) -> set:
    return set(value.free_symbols) if isinstance(value, (sp.Basic, sp.MatrixBase)) else set()


def _same(a, b):
    """Whether two sides are one value (a vector against 0 the zero vector): True, False, or None
    when their shapes differ."""
    va_, vb = (sp.Matrix(x) if isinstance(x, sp.MatrixBase) else x for x in (a, b))
    if isinstance(va_, sp.MatrixBase) and not isinstance(vb, sp.MatrixBase) and vb == 0:
        vb = sp.zeros(*va_.shape)
    if isinstance(vb, sp.MatrixBase) and not isinstance(va_, sp.MatrixBase) and va_ == 0:
        va_ = sp.zeros(*vb.shape)
    if isinstance(va_, sp.MatrixBase) != isinstance(vb, sp.MatrixBase) or \
            (isinstance(va_, sp.MatrixBase) and va_.shape != vb.shape):
        return None
    diffs = list(va_ - vb) if isinstance(va_, sp.MatrixBase) else [sp.sympify(va_ - vb)]
    diffs = [expanded(d) for d in diffs]
    if all(d == 0 for d in diffs):
        return True
    return _numerically_zero(diffs)


def _numerically_zero(diffs) -> bool:
    """Zero at three random points (each symbol of size 1 to 2, a mass positive)."""
    names = sorted({s for d in diffs for s in d.free_symbols}, key=lambda s: s.name)
    rng = random.Random(20)
    walk = mp_values.walker(names, diffs)
    for _ in range(3):
        point = {s: sp.Rational(rng.randint(100, 200), 100) * (1 if s.is_positive else rng.choice((-1, 1)))
                 for s in names}
        if any(abs(v) > 1e-12 for v in _values(walk, diffs, point)):
            return False
    return True


def _values(walk, diffs, point):
    """The differences at the point: walked in mpmath at 50 digits (a substitution of exact
    rationals into an expanded tree costs a tenth of a second), or substituted and evaluated at
    30 digits where the walk has no finite value or reads not every node."""
    if walk is not None:
        try:
            with mpmath.workdps(50):
                values = [mpmath.mpmathify(v) for v in walk(*(mpmath.mpf(x.p) / x.q for x in point.values()))]
            if all(mpmath.isfinite(v) for v in values):
                return [complex(v) for v in values]
        except (ZeroDivisionError, ValueError, TypeError, OverflowError):
            pass
    return (complex(sp.N(d.subs(point), 30)) for d in diffs)
