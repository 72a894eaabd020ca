"""The angular velocity of each turn, 𝛚_φ, 𝛚_θ, 𝛚_ψ, and its components in the frames between the turns.

Takes: a statement of the notes checker (`derive.lecture.notes_check.Checker`) whose members are
the angular velocities of single turns — a bold ω with one of the text's angles as its subscript
(``\\vec{\\omega}_{\\phi}``), the angular velocity of the turn by that angle — their sum, the body's
𝛚, or such a vector's components in a frame (``(\\vec{\\omega}_{\\phi})_{\\{x',y',z'\\}}``,
``(\\vec{\\omega}_\\psi)_\\mathrm{body}``), or a written column. Gives: the mixin `TurnRates`,
whose ``_turn_rates`` judges such a statement, link by link.

The turn by the k-th angle q_k is about the axis a_k of the frame the first k − 1 turns reached,
so 𝛚_{q_k} = q̇_k F_{k−1} e_{a_k} in space components, F_0 = 𝟙, F_1 = R_{a₁}(q₁),
F_2 = R_{a₁}(q₁) R_{a₂}(q₂), F_3 = R (active turns). A frame named by its axes with n primes,
{x⁽ⁿ⁾, y⁽ⁿ⁾, z⁽ⁿ⁾}, is F_n, the frame after n turns ({x, y, z} space, {x‴, y‴, z‴} the body's), as
texts that name the frames so write them; ``space``, ``fixed``, ``inertial`` name F_0 and
``body`` F_3. A vector's components in F_n are F_nᵀ v. A member in a frame of another name
(``intermediate``) is the chain's own name for the next member and is left out. A statement that
does not hold is `fails` only when every frame it names is space or body; with a frame named by
primes it stays `unchecked`, saying how the primes were read (a text may count its primes
otherwise). A member may also be the angles' rates times unit vectors of axes named by letter
(``\\dot\\phi \\bm e_Z + \\dot\\theta \\bm e_N + \\dot\\psi \\bm e_z``, ``\\hat{Z}``, ``\\hat{K}``, ``\\mathbf{k}``): a
capital X, Y, Z (I, J, K) the fixed frame's axis, a small x, y, z (i, j, k) the body's, N the line of nodes (the second turn's axis, for a
sequence whose first and third axes agree), read only where the member writes both capitals and small
letters; a frame bar after a vector (``\\bm\\Omega\\big|_{(Z,N,z)}``) names the axes it is written along
and is dropped. Which frame the capitals name is the text's to say (some letter the body's axes X, Y,
Z): its prose decides where it puts the word fixed, inertial or space, or body or moving, nearest to
the capital axes in a sentence ("a *fixed* frame has the basis $(\\bm e_X,\\bm e_Y,\\bm e_Z)$"). A
statement holds when it holds in the frame the prose names (the fixed one where it names none); it
`fails` when it does not hold there, the prose having named it, or under either reading.
May import: :mod:`derive.lecture.latex_spellings`, :mod:`derive.lecture.latex`, :mod:`derive.lecture.latex_spaces`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.latex_spaces import SPACE
from derive.lecture.latex_spellings import BOLD_MARK, VECTOR_MARK
from derive.symbolic import rotations as rot

_BOLD = rf"(?:{VECTOR_MARK}|\\vect)\s*"
_OMEGA = rf"{_BOLD}\{{?\s*(?:{_BOLD}\{{\s*)?\\omega\s*\}}?\s*\}}?"
_TURN = re.compile(rf"\s*{_OMEGA}\s*(?:_\s*\{{?\s*(\\[A-Za-z]+)\s*\}}?)?\s*")
_OPEN = r"(?:\\(?:left|bigl|Bigl|biggl|Biggl|big|Big|bigg|Bigg)\s*)?"
_CLOSE = r"(?:\\(?:right|bigr|Bigr|biggr|Biggr|big|Big|bigg|Bigg)\s*)?"
"""A bracket's sizing, none, ``\\left``/``\\right`` or ``\\bigl``/``\\bigr``: the same bracket however tall it is set."""
_FRAMED = re.compile(rf"\s*{_OPEN}\(\s*({_OMEGA}\s*(?:_\s*\{{?\s*\\[A-Za-z]+\s*\}}?)?)\s*{_CLOSE}\)\s*_\s*"
                     r"(\{\s*\\\{[^{}]*\\\}\s*\}|\\\{[^{}]*\\\}|\{\s*\\?(?:mathrm|text)?\s*\{?\s*[a-z]+\s*\}?\s*\}|\\(?:mathrm|text)\s*\{\s*[a-z]+\s*\})\s*")
_COLUMN = re.compile(rf"\s*(?:{_OPEN}[\[(]\s*)?\\begin\{{(array|bmatrix|pmatrix)\}}(?:\{{[a-z]*\}})?"
                     rf"(.*?)\\end\{{\1\}}(?:\s*{_CLOSE}[\])])?\s*", re.S)
"""A written column, bare or in brackets, plain, ``\\left``/``\\right`` or sized (``\\bigl[ … \\bigr]``)."""
_AXES = re.compile(r"\\\{\s*x\s*('*)\s*,\s*y\s*('*)\s*,\s*z\s*('*)\s*\\\}")
_NAMED = {"space": 0, "fixed": 0, "inertial": 0, "body": 3}
_UNIT = (r"(?:" + VECTOR_MARK + r"\s*\{?\s*e\s*\}?\s*_\s*\{?\s*([XYZNxyz])\s*\}?"
         r"|\\(?:wide)?hat\s*\{?\s*(?:" + BOLD_MARK + r"\s*)?\{?\s*([XYZNxyzIJKijk])\s*\}?\s*\}?"
         r"|" + BOLD_MARK + r"\s*\{?\s*([IJKNijk])\s*\}?)(?![A-Za-z_'])")
_LETTER_AXIS = {"i": "x", "j": "y", "k": "z", "x": "x", "y": "y", "z": "z"}
_AXIS_TERM = re.compile(r"(.*?)" + SPACE + _UNIT + SPACE + "$", re.S)
"""A term that ends in a unit vector named by its axis letter: the coefficient, then the letter."""
_BAR = re.compile(SPACE + r"(?:\\(?:big|Big|bigg|Bigg|right)\s*)?\|\s*_\s*\{[^{}]*\}")
"""A frame bar, ``\\big|_{(xyz)}``: the axes a vector is written along."""
_FRAME_WORDS = re.compile(r"\b(?:(fixed|inertial|space|laboratory|fixe)|(body|moving|rotating|mobile))\b", re.I)
_INLINE = re.compile(r"\$([^$]+)\$")
_CLAUSE = re.compile(r",|\b(?:and|to|while|whereas|but)\b")


def capitals_frame(body: str) -> int | None:
    """The frame the text's capital axes X, Y, Z name, by its prose (see the module docstring): 0 the
    fixed frame, 3 the body's, None where the prose names neither or both."""
    said = set()
    for sentence in re.split(r"(?<=[.;])\s|\n\s*\n", body):
        # a clause of the sentence: its math kept whole, cut at commas, "and", "to", "while" outside it
        parts = re.split(r"(\$[^$]+\$)", sentence)
        clauses, current = [], ""
        for k, part in enumerate(parts):
            pieces = [part] if k % 2 else re.split(_CLAUSE, part)
            current += pieces[0]
            for piece in pieces[1:]:
                clauses.append(current)
                current = piece
        clauses.append(current)
        for clause in clauses:
            words = {bool(w.group(1)) for w in _FRAME_WORDS.finditer(clause)}
            if len(words) != 1:
                continue
            for m in _INLINE.finditer(clause):
                letters = set(re.findall(r"[A-Za-z]", re.sub(r"\\[A-Za-z]+", " ", m.group(1))))
                if (set("XYZ") <= letters or set("IJK") <= letters) and not letters & set("xyzijk"):
                    said.add(0 if words.pop() else 3)
                    break
    return said.pop() if len(said) == 1 else None


def _frame(label: str):
    """(n, named): the frame after n turns a subscript names and whether by a name (space, body);
    None for a name the reader does not know."""
    m = _AXES.search(label)
    if m:
        primes = {len(g) for g in m.groups()}
        return (primes.pop(), False) if len(primes) == 1 and max(primes | {0}) <= 3 else None
    word = re.sub(r"\\(?:mathrm|text)|[{}\s\\]", "", label)
    return (_NAMED[word], True) if word in _NAMED else None


def _members(text: str) -> list[str] | None:
    """The members of a chain of ``=`` at brace depth 0, or None when it has another relation."""
    out, depth, start = [], 0, 0
    for k, ch in enumerate(text):
        depth += ch in "{[(" and 1 or 0
        depth -= ch in "}])" and 1 or 0
        if ch == "=" and depth == 0:
            out.append(text[start:k])
            start = k + 1
    out.append(text[start:])
    if len(out) < 2 or any(re.search(r"\\(?:approx|equiv|le|ge|neq)\b|[<>]", m) for m in out):
        return None
    return out


def _zero(e) -> bool:
    """Whether an entry vanishes: expanded, then with the angles' sines and cosines reduced."""
    e = sp.expand(e)
    return e == 0 or rot.trig_reduce(e) == 0 or sp.simplify(e) == 0


class TurnRates:
    """Mixin of the checker. Uses ``self.d`` (the derivation), ``self.vocab`` and ``_add``."""

    def _turn_frames(self) -> list:
        a1, a2, _ = self.d.conv.axes
        q = rot.ANGLES
        first = rot.active(a1, q[0])
        return [sp.eye(3), first, first * rot.active(a2, q[1]), self.d.conv.matrix()]

    def _turn_vector(self, angle: str | None):
        """The space components of 𝛚 (angle None) or of the turn by the text's angle, or None."""
        if angle is None:
            return sp.Matrix(self.d.conv.omega_space())
        try:
            value = lx.parse(angle, self.vocab).members[0].value
        except (lx.NotRead, IndexError, AttributeError):
            return None
        if value not in rot.ANGLES:
            return None
        k = rot.ANGLES.index(value)
        return rot.RATES[k] * self._turn_frames()[k] * rot.unit(self.d.conv.axes[k])

    def _axis_sum(self, text: str, capitals: int):
        """The space components of a sum of coefficients times lettered unit vectors, capitals
        naming the frame after ``capitals`` turns (0 or 3) and small letters the other; None when
        the member is no such sum or the text's names do not read."""
        terms, depth, start = [], 0, 0
        for k, ch in enumerate(text):
            depth += (ch in "{[(") - (ch in "}])")
            if ch in "+-" and depth == 0 and k > start and text[start:k].strip():
                terms.append(text[start:k])
                start = k
        terms.append(text[start:])
        frames, (a1, a2, a3) = self._turn_frames(), self.d.conv.axes
        total = sp.zeros(3, 1)
        for term in terms:
            m = _AXIS_TERM.fullmatch(term.strip())
            if m is None:
                return None
            letter = m.group(2) or m.group(3) or m.group(4)
            coefficient = m.group(1).strip().removeprefix("+").strip()
            if letter == "N":
                if a1 != a3:
                    return None      # a line of nodes only in a sequence whose first and third axes agree
                axis = frames[1] * rot.unit(a2)
            else:
                axis = frames[capitals if letter.isupper() else 3 - capitals] * rot.unit(_LETTER_AXIS[letter.lower()])
            if coefficient in ("", "+", "-"):
                value = sp.Integer(-1 if coefficient == "-" else 1)
            else:
                try:
                    value = lx.parse(coefficient, self.vocab).members[0].value
                except (lx.NotRead, IndexError, AttributeError):
                    return None
                if not isinstance(value, sp.Expr) or not value.free_symbols <= set(rot.ANGLES) | set(rot.RATES):
                    return None
            total += value * axis
        return total

    def _names_omega(self, text: str) -> bool:
        """Whether a member is the body's 𝛚 alone, a bold letter the text names the angular velocity."""
        if not re.fullmatch(r"\s*" + VECTOR_MARK + r"\s*\{?\s*\\(?:omega|Omega)\s*\}?\s*", text):
            return False
        try:
            return lx.parse(text, self.vocab).members[0].value is lx.OMEGA_VEC
        except (lx.NotRead, IndexError, AttributeError):
            return False

    def _axes_named(self, line, piece) -> bool:
        """Judge 𝛚 = a sum of the rates about lettered axes (see the module docstring); False when the
        statement is not one."""
        letters = {g for m in re.finditer(_UNIT, piece) for g in m.groups() if g}
        if not (letters & set("XYZIJK") and letters & set("xyzijk")):
            return False
        members = _members(_BAR.sub("", piece))
        if members is None or len(members) != 2:
            return False
        omega = [m for m in members if self._names_omega(m)]
        if len(omega) != 1:
            return False
        rest = next(m for m in members if m is not omega[0])
        said = capitals_frame(self.notes.body)
        readings = (3, 0) if said == 3 else (0, 3)
        target = self._turn_vector(None)
        held = [None if v is None else all(_zero(e) for e in v - target)
                for v in (self._axis_sum(rest, capitals) for capitals in readings)]
        if held[0] is None:
            return False
        where = ("the capitals the " + ("body's" if readings[0] == 3 else "fixed frame's") + " axes"
                 + (" as the prose names them" if said is not None else ""))
        if held[0]:
            self._add(line, piece, "identity", "holds",
                      f"the angles' rates about their turns' axes, {where}, N the line of nodes")
        elif held[1] and said is None:
            self._add(line, piece, "identity", "unchecked",
                      "holds only reading the capitals as the body's axes and the small letters as the fixed "
                      "frame's, which the text does not say")
        else:
            self._add(line, piece, "identity", "fails",
                      f"each angle's rate is about its own turn's axis ({where}; the first angle's about the fixed "
                      "frame's, the second's about the line of nodes, the third's about the body's): the sum differs")
        return True

    def _turn_member(self, text: str):
        """(space components, frame) of one member; frame None for a vector, (n, named) for its
        components in a frame; "skip" for a frame the reader does not know; None when not read."""
        m = _FRAMED.fullmatch(text)
        if m:
            inner = _TURN.fullmatch(m.group(1))
            frame = _frame(m.group(2))
            if inner is None:
                return None
            if frame is None:
                return "skip"
            v = self._turn_vector(inner.group(1))
            return None if v is None else (v, frame)
        m = _COLUMN.fullmatch(text)
        if m:
            rows = [r for r in m.group(2).split("\\\\") if r.strip()]
            if len(rows) != 3 or any("&" in r for r in rows):
                return None
            try:
                entries = [lx.parse(r.strip().rstrip(",."), self.vocab).members[0].value for r in rows]
            except (lx.NotRead, IndexError, AttributeError):
                return None
            if not all(isinstance(e, sp.Expr) for e in entries):
                return None
            return sp.Matrix(entries), "column"
        matches = [_TURN.fullmatch(t) for t in text.split("+")]
        if not all(matches):
            return None
        total = sp.zeros(3, 1)
        for m in matches:            # 𝛚 alone, or a sum of the turns' 𝛚_q
            part = self._turn_vector(m.group(1))
            if part is None:
                return None
            total += part
        return total, None

    def _turn_rates(self, line, piece) -> bool:
        """Judge a statement of turns' angular velocities (see the module docstring); False when
        it is not one."""
        if not re.search(rf"{_OMEGA}\s*_\s*\{{?\s*\\[A-Za-z]+", piece):
            return re.search(_UNIT, piece) is not None and self._axes_named(line, piece)
        members = _members(piece)
        if members is None:
            return False
        read = [self._turn_member(m) for m in members]
        if any(r is None for r in read):
            return False
        kept = [r for r in read if r != "skip"]
        if len(kept) < 2 or all(r[1] == "column" for r in kept):
            return False
        if any(r[1] == "column" for r in kept) and all(r[1] is None for r in kept if r[1] != "column"):
            return False             # a column against a vector with no frame: which frame is not said
        frames = self._turn_frames()
        ref = next(r for r in kept if r[1] != "column")
        components = [r[0] if r[1] == "column" else
                      (r[0] if r[1] is None else frames[r[1][0]].T * r[0]) for r in kept]
        vectors = [r[0] for r in kept if r[1] is None]
        if vectors and len(vectors) != sum(r[1] != "column" for r in kept):
            return False             # a vector beside components: the reader compares like with like
        base = components[kept.index(ref)]
        holds = all(all(_zero(e) for e in c - base) for c in components)
        primed = any(isinstance(r[1], tuple) and not r[1][1] for r in kept)
        if holds:
            why = ("the angular velocity of each turn, about its axis in the frame the turns before it reached"
                   + (", the frame {x⁽ⁿ⁾, y⁽ⁿ⁾, z⁽ⁿ⁾} read as the frame after n turns" if primed else ""))
            self._add(line, piece, "identity", "holds", why)
        elif primed:
            self._add(line, piece, "identity", "unchecked",
                      "does not hold reading a frame {x⁽ⁿ⁾, y⁽ⁿ⁾, z⁽ⁿ⁾} as the frame after n turns of the "
                      "angle sequence: the text may count its primes otherwise")
        else:
            self._add(line, piece, "identity", "fails",
                      "the angular velocity of each turn is its rate about its own axis, in the frame the turns "
                      "before it reached: the members differ")
        return True
