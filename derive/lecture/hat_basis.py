"""Vectors written on hatted unit vectors, x î + y ĵ + z k̂ (or Î Ĵ K̂, x̂ ŷ ẑ, î′ ĵ′ k̂′), and their rates.

Takes: a statement of the notes checker that the other readers left unchecked, writing hatted unit vectors of one
family only (``\\hat{i}``, ``\\mathbf{\\hat{j}}``, ``\\boldsymbol{\\hat{\\imath}}``, ``\\hat{\\mathbf{k}}``;
the capitals I, J, K, the letters x, y, z or X, Y, Z, each family with or without one prime). Gives:
the mixin `HatBasis`, which reads it on that family taken as a right-handed orthonormal basis, each
coefficient a scalar of its own, through the grammar of `derive.lecture.vector_parser` (cross and dot
products, a determinant along its row of unit vectors):

* **a vector set** (a bold letter = a sum on the basis, in a display or in any statement, read by
  another reader or not) is recorded, with its basis family and its line; the same letter set again
  later in the same family is compared with that earlier value: equal, the restatement `holds`;
  otherwise it is recorded anew, never flagged (a text reuses a letter for another vector);
* **a chain** is judged link by link, as `derive.lecture.basis_vectors` judges one in bold 𝐞ᵢ:
  `fails` only where both members are then in the same symbols;
* **rates** (``\\frac{d}{dt}``, ``\\frac{d X}{dt}``, ``(\\frac{d X}{dt})_{rel}``): each coefficient
  depends on time (ẋ its rate), and the basis is read twice, fixed and turning with an angular
  velocity of generic components w (dê/dt = w × ê; a rate relative to the turning basis leaves the
  w term out). A link holds when it holds in either reading and fails only when it fails in both;
* **a lost backslash**: a hat over the letters of a symbol's command (``\\hat{imath}`` for
  ``\\hat{\\imath}``, ``\\hat{omega}``; names of four letters or more) sets those letters as a product: a `typo`, corrected by the backslash;
* **a rate without its d**: a fraction over dt whose numerator is one symbol with no differential
  (``\\frac{B_Y}{dt}``) beside the rate of a sibling component (``\\frac{dB_X}{dt}``) is a `typo`,
  corrected by the missing d.

Sums, integrals, partial derivatives, a second basis family and any bold letter the text has not
set (past the statement's head) leave the statement to the readers before. May import:
:mod:`derive.lecture.latex`, :mod:`derive.lecture.vector_parser`, :mod:`derive.lecture.basis_vectors`,
:mod:`derive.lecture.latex_spellings`, :mod:`derive.lecture.vector_models`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import vector_parser as vp
from derive.lecture.basis_vectors import compare, name
from derive.lecture.latex_spellings import VECTOR_MARK
from derive.lecture.vector_models import DIFFERENTIAL

_FAMILIES = ("ijk", "IJK", "xyz", "XYZ")
_HATTED = re.compile(r"\\hat\b|\\widehat\b")
_NOT_HERE = re.compile(r"\\(?:int|oint|sum|prod|partial|lim)\b")
"""Sums, integrals, partial derivatives and limits: not this reader's algebra."""
_DOTLESS = re.compile(r"\\[dt]?frac\s*\{\s*([A-Za-z])(_\s*(?:\{[^{}]*\}|\w))?\s*\}\s*\{\s*" + DIFFERENTIAL + r"\s*t\s*\}")
"""A fraction over dt of one letter (with its index) and no differential: a rate that lost its d."""
_LOST_BACKSLASH = re.compile(r"\\(?:hat|widehat)\s*\{\s*(imath|jmath|alpha|beta|gamma|delta|epsilon|zeta|theta|iota|kappa|"
                             r"lambda|sigma|upsilon|omega|Omega|Theta|Lambda|Sigma|Gamma|Delta)\s*\}")
"""A hat over the letters of a symbol's command (``\\hat{imath}``): the command's backslash lost (names of
four letters or more: two or three letters under a hat may be a text's own product)."""
_RATE_OF = r"\\[dt]?frac\s*\{{\s*d\s*{letter}(?![A-Za-z])"
_ARGUMENT = re.compile(r"(" + VECTOR_MARK + r"\s*\{[^{}]*\})\s*\(\s*t\s*\)")
"""A bold letter written as a function of time, 𝐯(t): the letter."""
_FRAMES = {"inertial": "inertial", "fixed": "inertial", "space": "inertial", "abs": "inertial",
           "rel": "relative", "r": "relative", "relative": "relative", "rot": "relative", "body": "relative",
           "b": "relative", "B": "relative"}
_W = sp.ImmutableMatrix(sp.symbols("w_1 w_2 w_3"))
"""The turning basis's angular velocity, generic, in its own components."""
WHY_SET = "sets the text's vector {name} on the unit vectors {basis} (recorded, then used)"
WHY = "on the unit vectors {basis} (right-handed, orthonormal; coefficients its own scalars{rates})"
RATES = ", each depending on time; the basis read fixed and turning, holding in either"


def _rate(value):
    """The time derivative of a value whose every symbol depends on time (ṡ named s + 'dot')."""
    if isinstance(value, sp.MatrixBase):
        return sp.ImmutableMatrix(value.applyfunc(_rate))
    return sum((sp.diff(value, s) * sp.Symbol(s.name + "dot") for s in value.free_symbols), sp.Integer(0))


class _Model:
    """The grammar's model: the family's unit vectors, the text's recorded vectors in that family,
    every other symbol a scalar of its own; ``w`` the basis's angular velocity (zero: fixed)."""

    vocabulary = False
    free = ""
    matrix_products = False
    rates = True
    frames = _FRAMES

    def __init__(self, family: str, vectors: dict, w):
        self.family, self.vectors, self.w = family, vectors, w
        self.unknown: list = []
        self.used: set = set()

    def atom(self, p, a, env, tok):
        if a.base in ("d", "partial") and not a.sub or a.tilde:
            raise lx.Unknown(f"not this reader's symbol {a.text}", tok.pos + 1)
        if a.hat:
            if a.base not in self.family[:3] or a.sub or a.sup or a.dots or a.primes != len(self.family) - 3:
                raise lx.Unknown(f"not this reader's unit vector {a.text}", tok.pos + 1)
            return sp.ImmutableMatrix(sp.eye(3)[:, self.family.index(a.base)])
        if a.primes:
            raise lx.Unknown(f"not this reader's symbol {a.text}", tok.pos + 1)
        if a.bold or a.text.startswith("\\vec"):
            if a.dots or a.sup:
                raise lx.Unknown(f"not this reader's vector {a.text}", tok.pos + 1)
            key = name(a)
            if key in self.vectors:
                self.used.add(key)
                return self.vectors[key]
            self.unknown.append(key)
            return sp.ImmutableMatrix([sp.Symbol(f"{key}[{i}]") for i in range(3)])
        if a.base == "pi" and not a.sub and not a.dots:
            return sp.pi
        return sp.Symbol(name(a))

    def rate(self, value, frame):
        if frame not in ("inertial", "relative"):
            return None
        out = _rate(value)
        if isinstance(value, sp.MatrixBase) and frame == "inertial":
            out = sp.ImmutableMatrix(out + self.w.cross(value))
        return out

    def summed(self, p, names, upper, env, tok):
        p.fail("a sum", tok)

    def points(self):
        raise lx.NotRead("an integral")


def family(text: str) -> str | None:
    """The one family of hatted unit vectors a statement writes ('ijk', "ijk'" …), or None (none, or two)."""
    if not _HATTED.search(text):
        return None
    try:
        toks = lx.scan_cells(text)
    except lx.NotRead:
        return None
    found = set()
    for t in toks:
        if t.kind == "atom" and t.value.hat:
            a = t.value
            fam = next((f for f in _FAMILIES if a.base in f), None)
            if fam is None or a.sub or a.sup or a.primes > 1:
                return None
            found.add(fam + "'" * a.primes)
    return found.pop() if len(found) == 1 else None


def _prepared(text: str) -> str:
    text = re.sub(r"\\([ij])math(?![A-Za-z])", r"\1", text)
    return _ARGUMENT.sub(r"\1", text)


def _vector(v) -> bool:
    return isinstance(v, sp.MatrixBase) and v.shape == (3, 1)


class HatBasis:
    """Mixin of the checker: uses ``self._add``."""

    def _hat_state(self) -> dict:
        return self.__dict__.setdefault("_hats", {})

    def _hat_known(self, fam, line) -> dict:
        """The vectors of family ``fam`` as the text set them before ``line``."""
        out = {}
        for (key, f), history in self._hat_state().items():
            earlier = [v for at, v in history if at < line]
            if f == fam and earlier:
                out[key] = earlier[-1]
        return out

    def _hat_read(self, text, fam, line, w):
        model = _Model(fam, self._hat_known(fam, line), w)
        reading = vp.read(lx.scan_cells(text), text, lx.Vocabulary(), model, "hat basis")
        return reading.members[0], reading.relations, model

    def _hat_note(self, line, text) -> None:
        """Record a vector a statement sets on a hatted basis, whichever reader judges it."""
        self._hat_judge(line, None, text, claim=False)

    def _hat_unread(self, line, piece, before) -> None:
        """Judge a statement that writes a hatted basis where the readers before left it unchecked
        (the claims from ``before`` on): their claims give way to this reader's where it gives a verdict."""
        if any(c.verdict != "unchecked" for c in self.claims[before:]):
            return
        text = piece
        if re.match(r"\s*(=|\\approx|\\equiv)", piece) and self.ctx.head:
            text = self.ctx.head + " " + piece
        end = len(self.claims)
        if not self._hat_judge(line, piece, text, claim=True):
            return
        if all(c.verdict == "unchecked" for c in self.claims[end:]):
            del self.claims[end:]           # a vector only set: the readers before say more of it (a fixed axis)
        else:
            del self.claims[before:end]

    def _hat_judge(self, line, piece, text, claim) -> bool:
        if claim and self._hat_lost_backslash(line, piece, text):
            return True
        fam = family(text)
        if fam is None or _NOT_HERE.search(text):
            return False
        text = _prepared(text)
        basis = ", ".join(f"\\hat{{{c}}}" + "'" * (len(fam) - 3) for c in fam[:3])
        if claim and self._hat_dotless(line, piece, text, basis):
            return True
        try:
            readings = [self._hat_read(text, fam, line, w) for w in (sp.zeros(3, 1), _W)]
        except (lx.NotRead, ArithmeticError, TypeError, ValueError, AttributeError, IndexError, KeyError):
            return False
        (members, rels, model), rated = readings[0], any(m.rated for m in readings[0][0])
        if not rated:
            readings = readings[:1]
        head = members[0]
        vectors = all(_vector(m.value) for m in members)
        if len(members) < 2 or set(rels) != {"="} or not (vectors or not any(_vector(m.value) for m in members)):
            return False
        own = name(head.atom) if head.atom is not None and _vector(head.value) else None
        if any(k != own for k in model.unknown) or \
                own is not None and any(m.atom is not None and name(m.atom) == own for m in members[1:]):
            return False                    # a vector the text has not set, past the head
        first = 1 if own is not None else 0
        links = []
        for k in range(first + 1, len(members)):
            links.append((k, self._hat_link([(r[0][k - 1].value, r[0][k].value) for r in readings])))
        earlier = None
        if own is not None and own not in model.unknown and not rated:
            earlier = compare(head.value, members[1].value, [])
        if own is not None and not rated:
            history = self._hat_state().setdefault((own, fam), [])
            if history and history[-1][0] == line:
                history.pop()
            history.append((line, sp.ImmutableMatrix(members[-1].value)))
        if not claim:
            return False
        why = WHY.format(basis=basis, rates=RATES if rated else "")
        spelled = text[head.start:head.end].strip()
        if earlier is not None and earlier[0] == "holds":
            self._add(line, piece, "identity", "holds", f"restates the text's vector {spelled} as set before, " + why)
        elif own is not None:
            self._add(line, piece, "definition", "unchecked", WHY_SET.format(name=spelled, basis=basis))
        for k, (verdict, reason) in links:
            at = f"members {k - 1} and {k}: " if len(members) > 2 else ""
            self._add(line, piece, "identity", verdict, at + why + (f": {reason}" if reason else ""))
        return True

    @staticmethod
    def _hat_link(pairs) -> tuple[str, str]:
        """One link's verdict over the readings: holds in either, fails only in both."""
        found = [compare(a, b, []) if _vector(a) == _vector(b) else ("unchecked", "a vector against a scalar")
                 for a, b in pairs]
        held = next((v for v in found if v[0] == "holds"), None)
        if held is not None:
            return held
        if all(v[0] == "fails" for v in found):
            return found[0]
        return next(v for v in found if v[0] == "unchecked")

    def _hat_dotless(self, line, piece, text, basis) -> bool:
        """A fraction over dt that lost its numerator's d, beside a sibling's rate: a typo."""
        slips = [m for m in _DOTLESS.finditer(text) if m.group(1) != "d"
                 and re.search(_RATE_OF.format(letter=m.group(1)), text)]
        if not slips:
            return False
        fixed = piece
        for m in slips:
            fixed = fixed.replace(m.group(0), m.group(0).replace("{" + m.group(1), "{d" + m.group(1), 1), 1)
        names = ", ".join(m.group(1) + (m.group(2) or "") for m in slips)
        self._add(line, piece, "rate", "typo",
                  f"writes {names} over dt with no d: a component divided by the differential dt, not its rate, where "
                  f"the same statement writes a sibling component's rate with its d (on the unit vectors {basis})",
                  fixed if fixed != piece else None)
        return True

    def _hat_lost_backslash(self, line, piece, text) -> bool:
        """A hat over a symbol's command written without its backslash: a typo, whatever the rest says."""
        lost = list(dict.fromkeys(m.group(1) for m in _LOST_BACKSLASH.finditer(text)))
        if not lost:
            return False
        fixed = _LOST_BACKSLASH.sub(lambda m: m.group(0).replace(m.group(1), "\\" + m.group(1), 1), piece)
        names = ", ".join(lost)
        self._add(line, piece, "symbol", "typo",
                  f"sets the letters {names} under a hat, where the symbol \\{lost[0]} is meant (its backslash lost): "
                  "a product of letters, not the unit vector or symbol the other terms write", fixed if fixed != piece else None)
        return True
