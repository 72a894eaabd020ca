"""Vectors a text writes in a basis of its own, bold 𝐞_x, 𝐞_y, 𝐞_z (𝐞₁, 𝐞₂, 𝐞₃, or 𝐢, 𝐣, 𝐤): the points of a
body and their velocities in the body's basis, as texts on rolling bodies write them
(𝐫_P = a 𝐞_x + R 𝐞_z, 𝐯_P = 𝛚 × 𝐫_P = …).

The basis is read as right-handed and orthonormal (what a basis named so means), each vector the
text sets to a combination of it (in a display or in its prose: "With $\\mathbf{r}_Q = …$") is
recorded as its three components, and the text's scalar relations (``\\dot\\psi = \\frac{R}{a}
\\dot\\phi``, a single symbol set to an expression) are kept in order; a rate of one symbol written as a fraction,
``\\frac{\\mathrm{d}\\phi}{\\mathrm{d}t}``, is its dot. A statement that writes a
cross product of such vectors (𝐯 = 𝛚 × 𝐫 = …), or a chain of such combinations whose link does
not hold, is judged link by link: the members' components are compared after the text's relations
are put in, the latest first (a symbol a later relation brings in is not replaced by an older
one: a letter the text reuses keeps its latest meaning). A link that does not reduce to zero is
flagged only when both members are then in the same symbols; otherwise it is `unchecked`, naming
the symbols one side has and the other has not (a relation the text may have stated in words).
A vector set again is recorded anew, never compared with its earlier value; a vector set by a
chain whose members disagree keeps every member, and a later link fails only when it fails for
each of them.

Gives the mixin `BasisVectors` of `derive.lecture.notes_check.Checker`.

May import: :mod:`derive.lecture.differentials`, :mod:`derive.lecture.latex`, :mod:`derive.lecture.vector_parser`,
:mod:`derive.lecture.zero_test`, SymPy.
"""
from __future__ import annotations

import itertools
import re

import sympy as sp

from derive.lecture import differentials
from derive.lecture import latex as lx
from derive.lecture import vector_parser as vp
from derive.lecture import zero_test as zt

BASIS = re.compile(r"(?<!hat\{)\\(?:boldsymbol|mathbf|bm|pmb|vec)\s*(?:\{?\s*e\s*\}?\s*_\s*\{?\s*[xyz123]\b|"
                   r"\{\s*[ijk]\s*\}(?!\s*_))")
"""A bold e with an axis index, or a bold i, j, k, not under a hat (ê_i, the lecture's body axes, and
î, ĵ, k̂ are read elsewhere)."""
_IJK = {"i": 0, "j": 1, "k": 2}
_NOT_ALGEBRA = re.compile(r"\\(?:int|sum|partial|frac\s*\{\s*(?:\\mathrm\s*\{\s*)?d)|\\mathrm\s*\{\s*d\s*\}")
"""Rates, sums and integrals: not the algebra of this reader."""
_RELATION = re.compile(r"\s*\\?[A-Za-z]+(?:\{[^{}]*\}|\s*\\[A-Za-z]+|\s+[A-Za-z](?![A-Za-z]))?\s*(?:_\s*\{?\s*\w+\s*\}?)?\s*=")
"""A statement opening with one symbol and =: a relation of the text's, perhaps (an accent's argument
braced or not, ``\\dot{\\psi}``, ``\\dot\\psi``, ``\\dot x``)."""
_COMBINATIONS = 8
WHY_SET = "sets the text's vector {name} in its basis {basis} (recorded, then used)"
WHY = ("in the text's basis {basis} (right-handed, orthonormal), with the vectors and the relations it set before "
       "(the latest first)")


class _Model:
    """The grammar's model (see `derive.lecture.vector_parser`): the basis vectors, the text's
    recorded vectors (one candidate each, chosen by ``pick``), every other symbol a scalar of its own."""

    vocabulary = False
    free = ""
    matrix_products = False
    rates = False
    frames: dict = {}

    def __init__(self, vectors: dict, pick: dict):
        self.vectors, self.pick = vectors, pick
        self.unknown: list = []                 # bold names not recorded, in order
        self.used: set = set()                  # recorded names the statement uses

    def atom(self, p, a, env, tok):
        if a.base in ("d", "partial") and not a.sub or a.hat or a.tilde or a.primes:
            raise lx.Unknown(f"not this reader's symbol {a.text}", tok.pos + 1)
        bold = a.bold or a.text.startswith("\\vec")
        if bold and a.base == "e" and a.sub in vp.AXES and not a.dots and not a.sup:
            return sp.ImmutableMatrix(sp.eye(3)[:, vp.AXES[a.sub]])
        if bold and a.base in _IJK and not (a.sub or a.sup or a.dots):
            return sp.ImmutableMatrix(sp.eye(3)[:, _IJK[a.base]])
        if bold:
            key = name(a)
            if a.dots or a.sup:
                raise lx.Unknown(f"not this reader's vector {a.text}", tok.pos + 1)
            if key in self.vectors:
                self.used.add(key)
                return self.vectors[key][self.pick.get(key, 0)]
            self.unknown.append(key)
            return sp.ImmutableMatrix([sp.Symbol(f"{key}[{i}]") for i in range(3)])
        if a.base == "pi" and not a.sub and not a.dots:
            return sp.pi
        return sp.Symbol(name(a))

    def summed(self, p, names, upper, env, tok):
        p.fail("a sum", tok)

    def points(self):
        raise lx.NotRead("an integral")


def name(a) -> str:
    """A symbol's name, the same however its braces are written."""
    return a.base + (f"_{a.sub}" if a.sub else "") + (f"^{a.sup}" if a.sup else "") + "'" * a.primes + \
        "dot" * a.dots + ("bold" if a.bold or a.text.startswith("\\vec") else "")


def _read(text: str, vectors: dict, pick: dict):
    model = _Model(vectors, pick)
    reading = vp.read(lx.scan_cells(text), text, lx.Vocabulary(), model, "basis")
    return reading.members[0], reading.relations, model


def _readings(text: str, vectors: dict):
    """The statement read once per choice of its vectors' candidates (`lx.NotRead` when it cannot)."""
    first, rels, model = _read(text, vectors, {})
    many = sorted(k for k in model.used if len(vectors[k]) > 1)
    out = [(first, model)]
    for choice in itertools.islice(itertools.product(*(range(len(vectors[k])) for k in many)), 1, _COMBINATIONS):
        members, _, m = _read(text, vectors, dict(zip(many, choice)))
        out.append((members, m))
    return out, rels


def _vector(v) -> bool:
    return isinstance(v, sp.MatrixBase) and v.shape == (3, 1)


def _put_in(value, relations):
    """The text's relations put into a value, the latest first; a symbol a later relation brought
    in, or already replaced, is not replaced by an older relation."""
    replaced, kept = set(), set()
    for symbol, expr in reversed(relations):
        if symbol in replaced or symbol in kept or expr.free_symbols & replaced:
            continue
        value = value.xreplace({symbol: expr})
        replaced.add(symbol)
        kept |= expr.free_symbols
    return value


def compare(a, b, relations) -> tuple[str, str]:
    """(verdict, why) of two vectors' equality under the text's relations."""
    a, b = _put_in(a, relations), _put_in(b, relations)
    differs = False
    for x, y in zip(a, b):
        d = sp.expand(x - y)
        if d == 0 or zt.symbolic_zero(d) is not None or zt.numeric_zero(sp.Matrix([x]), sp.Matrix([y]), "basis").ok:
            continue
        differs = True
    if not differs:
        return "holds", ""
    sa, sb = sp.Matrix(a).free_symbols, sp.Matrix(b).free_symbols
    if sa != sb:
        odd = sorted(s.name for s in sa ^ sb)
        return "unchecked", (f"the two sides differ in {', '.join(odd)}, which the text has not related to the "
                             "other side's symbols (it may do so in words)")
    return "fails", "the components differ"


class BasisVectors:
    """Mixin of the checker: uses ``self.notes``, ``self._add``."""

    def _basis_state(self) -> dict | None:
        if "_basis" not in self.__dict__:
            written = any(BASIS.search(getattr(it, "latex", None) or "") for it in self.notes.items)
            self._basis = {"vectors": {}, "relations": [], "basis": set()} if written else None
        return self._basis

    def _basis_setting(self, latex) -> None:
        """A vector of the text's set in its prose (``With $\\mathbf{r}_P = a\\mathbf{e}_x + …$``):
        recorded, no claim made."""
        state = self._basis_state()
        latex = differentials.dotted(latex)             # d\phi/dt is the rate \dot{\phi} this reader knows
        if state is not None and BASIS.search(latex):
            self._basis_read(latex, state, claim=False)
        elif state is not None and _RELATION.match(latex) and not _NOT_ALGEBRA.search(latex):
            self._basis_relation(latex, state)

    def _basis_statement(self, line, piece, text) -> bool:
        """Judge a statement in the text's basis (False: not one this reader judges; a vector set
        or a scalar relation is recorded all the same)."""
        state = self._basis_state()
        text = differentials.dotted(text)               # d\phi/dt is the rate \dot{\phi} this reader knows
        if state is None or _NOT_ALGEBRA.search(text):
            return False
        if not BASIS.search(text) and not any(v in text for v in state.get("spelled", ())):
            if _RELATION.match(text):
                self._basis_relation(text, state)
            return False
        return self._basis_read(text, state, claim=True, line=line, piece=piece)

    def _basis_relation(self, text, state) -> None:
        try:
            members, rels, model = _read(text, {}, {})
        except (lx.NotRead, ArithmeticError, TypeError, ValueError, AttributeError, IndexError, KeyError):
            return
        head = members[0]
        if model.unknown or len(members) < 2 or set(rels) != {"="} or head.atom is None or \
                not isinstance(head.value, sp.Symbol) or any(isinstance(m.value, sp.MatrixBase) for m in members):
            return
        value = members[-1].value
        if head.value not in value.free_symbols:
            state["relations"].append((head.value, value))

    def _basis_read(self, text, state, claim, line=None, piece=None) -> bool:
        try:
            readings, rels = _readings(text, state["vectors"])
        except (lx.NotRead, ArithmeticError, TypeError, ValueError, AttributeError, IndexError, KeyError):
            return False
        members, model = readings[0]
        head = members[0]
        key = model.unknown[0] if model.unknown else None
        if len(members) < 2 or set(rels) != {"="} or head.atom is None or not _vector(head.value) or \
                not all(_vector(m.value) for m in members[1:]):
            return False
        own = name(head.atom)
        if model.unknown and (model.unknown != [own] or any(m.atom is not None and name(m.atom) == own for m in members[1:])):
            return False                            # a vector the text has not set, past the head
        if key is None and own not in model.used:
            return False
        basis = {m.group(0) for m in BASIS.finditer(text)}
        state["basis"] |= basis
        crossed = "\\times" in text
        verdicts = []
        for k in range(2, len(members)):
            found = [compare(ms[k - 1].value, ms[k].value, state["relations"]) for ms, _ in readings]
            verdict = next((v for v in found if v[0] == "holds"), None) or \
                next((v for v in found if v[0] == "unchecked"), None) or found[0]
            verdicts.append((k, verdict))
        new = [ms[k].value for ms, _ in readings for k in range(1, len(members))]
        values = []
        for v in new:
            if not any(sp.ImmutableMatrix(v) == w for w in values):
                values.append(sp.ImmutableMatrix(v))
        state["vectors"][own] = values[:_COMBINATIONS]
        state.setdefault("spelled", set()).add(text[head.start:head.end].strip())
        if not claim or not verdicts or not (crossed or any(v[0] == "fails" for _, v in verdicts)):
            return False
        spelled = ", ".join(sorted(state["basis"]))
        self._add(line, piece, "definition", "unchecked", WHY_SET.format(name=text[head.start:head.end].strip(),
                                                                          basis=spelled))
        for k, (verdict, why) in verdicts:
            link = f"members {k - 1} and {k}: " if len(members) > 3 else ""
            self._add(line, piece, "identity", verdict, link + WHY.format(basis=spelled) + (f": {why}" if why else ""))
        return True
