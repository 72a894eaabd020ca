r"""Displays in Kane's frame notation, judged with the text's own orientation algebra.

Takes: the statements of one display and `derive.lecture.frame_algebra.Frames`, the orientations
the text has stated so far. Gives the mixin `FrameDisplays` of `derive.lecture.notes_check.Checker`,
whose `_frame_display` reads a display every statement of which the frame algebra reads:

* a frame stated by its unit vectors in another's (the three rows ``\hat{a}_i = …``, or the matrix
  form ``[\hat{a}] = [c_{ij}] [\hat{n}]``): a simple orientation (one shared axis, one angle) holds in
  the right-hand sense, is left unchecked in the other (the text may measure its angle that way) and
  fails when its rows are no orthonormal set; unless it fails it then orients the frame. Entries the text names (``c_{xy}``) are no claim and leave the frame as it
  was; ``\cos\alpha_{xy}`` for every entry, one name indexed by the row's and the column's axis
  labels, are the direction cosines, which hold (the frame left as it was). Written again in the angles of the orientation already stated, it is checked against it;
* any other relation is checked entry by entry (vectors by their components, matrices entry by
  entry); a row of a block of unit-vector rows that fails, and holds with its left index made the
  one the block leaves out, is a typo for that index. A relation that fails is flagged only when it
  writes a DCM (whose algebra holds for any orientation), the unit vectors of one frame, or frames
  the text has stated and those they are stated in, and only in angles a stated orientation
  carries; else it may be about an orientation the text gives in words, and is left unchecked;
* a display in the notation of motion (`derive.lecture.frame_motion`) is read on `Motion`: a
  statement ``\bar{u} = …`` sets the text's vector (as one its prose sets does, `_frame_setting`),
  any other relation is checked at the motion's exact points.

A 3×3 matrix written alone, with no relation, in a text that has stated a simple orientation in the
right-hand sense: a simple orientation about the axis it leaves fixed holds in that sense and fails
when its rows are no orthonormal set; in the other sense it is left alone (a rotation matrix, not a
DCM, may be meant).

May import: :mod:`derive.lecture.frame_algebra`, :mod:`derive.lecture.frame_motion`,
:mod:`derive.lecture.vocabulary`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture.frame_algebra import (AXES, Frames, Vec, Vecs, equal, matrix_of, one_kind, reduced, simple_turn,
                                          tokens, uses_frames)
from derive.lecture.frame_motion import MOVING, Motion, equal_in_motion
from derive.lecture.vocabulary import NotRead

_ROW = re.compile(r"\s*(\\hat\s*\{\s*[a-z]\s*\}\s*_\s*\{?\s*)([xyz123])(\s*\}?\s*=)")


def _stated(toks):
    """(F, axes, G) when a statement writes unit vectors of F (one, or a column of all three) as
    numbers and scalars times unit vectors of another frame G, with no DCM: else None."""
    if ("op", "=") not in [t[:2] for t in toks]:
        return None
    at = [t[:2] for t in toks].index(("op", "="))
    left, right = toks[:at], toks[at + 1:]
    if len(left) != 1:
        return None
    if left[0][0] == "unit":
        units = [left[0][2]]
    elif left[0][0] == "env" and all(len(r) == 1 for r in left[0][2]):
        try:
            units = [tokens(r[0]) for r in left[0][2]]
        except NotRead:
            return None
        if any(len(u) != 1 or u[0][0] != "unit" for u in units):
            return None
        units = [u[0][2] for u in units]
    else:
        return None
    frame = {u[0] for u in units}
    if len(frame) != 1 or ("op", "=") in [t[:2] for t in right] or any(t[0] == "dcm" for t in right):
        return None
    others = set()
    for t in right:
        if t[0] == "unit":
            others.add(t[2][0])
        elif t[0] == "env":
            others |= set(re.findall(r"\\hat\s*\{\s*([a-z])", " ".join(c for r in t[2] for c in r)))
    if len(others) != 1 or others == frame:
        return None
    return frame.pop().upper(), [AXES[u[1]] for u in units], others.pop().upper()


class FrameDisplays:
    """Mixin of the checker. Uses ``self._add`` and ``self.tex``."""

    def _frames_kept(self) -> Frames:
        if getattr(self, "_frame_algebra", None) is None:
            self._frame_algebra = Frames()
        return self._frame_algebra

    def _frame_display(self, line, pieces) -> bool:
        """The display read as the module says; False (read as before) when a statement is outside
        the frame notation."""
        if not any(uses_frames(p) for p in pieces):
            return self._elementary_alone(line, pieces)
        frames = self._frames_kept()
        try:
            toks = [tokens(p) for p in pieces]
            if any(tok[0] in MOVING for ts in toks for tok in ts):
                return self._motion_display(line, pieces, toks)
            stated = [_stated(t) for t in toks]
            members = [frames.read(p) for p in pieces]
        except (NotRead, ArithmeticError, TypeError, ValueError):
            return False
        if any(len(m) < 2 for m in members) or any(not uses_frames(p) for p in pieces) or \
                any(not one_kind(m) for m in members):
            return False             # a hatted letter that is no frame's unit vector (a component n̂₁ = …): read as before
        rows = [s for s in stated if s is not None and len(s[1]) == 1]
        whole = [s for s in stated if s is not None and len(s[1]) == 3]
        one = {(s[0], s[2]) for s in stated if s is not None}
        c = None
        if len(stated) == len(rows) == 3 and len(one) == 1 and sorted(s[1][0] for s in rows) == [0, 1, 2]:
            order = [s[1][0] for s in rows]
            f, g, c = rows[0][0], rows[0][2], sp.Matrix.vstack(*[members[order.index(k)][1].row for k in range(3)])
        elif len(pieces) == 1 and whole and whole[0][1] == [0, 1, 2] and isinstance(members[0][1], Vecs):
            f, g, c = whole[0][0], whole[0][2], members[0][1].rows
        elif len(pieces) == 1 and [t[0] for t in toks[0]] == ["dcm", "op", "env"] and not uses_frames(pieces[0].split("=", 1)[1]):
            f, g = toks[0][0][2]
            c = members[0][1] * frames.frame(g)
        if c is not None:
            c = (sp.Matrix(c) * frames.frame(g).T).applyfunc(reduced)     # the coefficients the text wrote: ^F C^G
            if f not in frames.stated or not c.free_symbols <= frames.angles():
                self._frame_stated(line, " \\\\ ".join(pieces), f, g, c)
                return True
        missing = _left_out(pieces)
        for piece, values in zip(pieces, members):
            self._frame_relation(line, piece, values, ["="] * (len(values) - 1), missing)
        return True

    def _frames_moving(self) -> Motion:
        if getattr(self, "_frame_motion", None) is None:
            self._frame_motion = Motion()
        return self._frame_motion

    def _frame_setting(self, latex):
        """A vector of the text's set in its prose (``For $\\bar{v} = v\\hat{b}_x$ …``): recorded as a
        display's ``\\bar{u} = …`` is, with no claim made."""
        if not uses_frames(latex):
            return
        try:
            toks = tokens(latex)
            if len(toks) > 2 and toks[0][0] == "vecname" and toks[1][:2] == ("op", "=") and \
                    toks[0][1] not in self._frames_moving().vectors:
                rhs = latex.split("=", 1)[1]
                value = self._frames_moving().read(rhs)
                if len(value) == 1 and isinstance(value[0], Vec):
                    self._frames_moving().vectors[toks[0][1]] = rhs
        except (NotRead, ArithmeticError, TypeError, ValueError):
            return

    def _motion_display(self, line, pieces, toks) -> bool:
        """A display in the notation of motion, read on `frame_motion.Motion`; a statement setting
        one of the text's vectors (``\\bar{u} = …``) records it."""
        motion = self._frames_moving()
        read = []
        motion.rates |= {tok[1] for ts in toks for tok in ts if tok[0] == "dot"}
        for piece, ts in zip(pieces, toks):
            if len(ts) > 2 and ts[0][0] == "vecname" and ts[1][:2] == ("op", "=") and ts[0][1] not in motion.vectors:
                value = motion.read(piece.split("=", 1)[1])
                if len(value) != 1 or not isinstance(value[0], Vec):
                    return False
                read.append((piece, ts[0][1], piece.split("=", 1)[1]))
                continue
            members = motion.read(piece)
            if len(members) < 2 or not one_kind(members):
                return False
            read.append((piece, members, list(motion.relations)))
        for piece, members, relations in read:
            if isinstance(members, str):
                motion.vectors[members] = relations
                self._add(line, piece, "frame", "unchecked", f"not a claim: sets the text's vector {members}")
            else:
                self._frame_relation(line, piece, members, relations, None, motion)
        return True

    def _frame_stated(self, line, piece, f, g, c):
        """F's unit vectors written in G's by the coefficients ``c`` (^F C^G), a statement of F."""
        frames = self._frames_kept()
        turn = simple_turn(c)
        name = f"{{}}^{f}\\mathbf{{C}}^{g}"
        if turn is None and c.free_symbols:
            if _direction_cosines(c, piece):
                self._add(line, piece, "frame", "holds", f"the direction cosines: each entry the cosine of the angle "
                          f"between the unit vector of {f} on its row and that of {g} on its column, named by their "
                          f"two indices in that order (a unit vector's components are those cosines)")
                return
            self._add(line, piece, "frame", "unchecked", f"not a claim: writes the unit vectors of {f} in those "
                      f"of {g} by entries the text names (a general orientation, {name})")
            return
        if turn is None:
            ok = equal(c * c.T, sp.eye(3)) and equal(sp.Matrix([[c.det()]]), sp.Matrix([[1]]))
            verdict, why = ("holds", f"the unit vectors of {f} in those of {g}: an orthonormal right-handed set") \
                if ok else ("fails", f"the unit vectors of {f} written in those of {g} are no orthonormal right-handed set")
        else:
            axis, q, sense = turn
            about = f"{f} turned from {g} about the shared {axis} axis through {self.tex(q)}"
            verdict, why = {True: ("holds", f"a simple orientation, {about} in the right-hand sense: {name}"),
                            False: ("unchecked", f"not checked: {about} in the left-hand sense (a turn through "
                                                 f"{self.tex(-q)}); the text may measure its angle that way"),
                            None: ("fails", f"{about}: its rows are no orthonormal set")}[sense]
            frames.simple += sense is True
        self._add(line, piece, "frame", verdict, why)
        if verdict != "fails":                  # the text's own statement of the frame, in whichever sense
            frames.of[f] = c * frames.frame(g)
            frames.stated.add(f)
            frames.stated_in[f] = g

    def _frame_relation(self, line, piece, values, relations, missing, motion=None):
        """One relation between frame quantities, checked member by member."""
        for a, b, rel in zip(values, values[1:], relations):
            try:
                same = equal(a, b) if motion is None else equal_in_motion(a, b)
            except (ArithmeticError, TypeError, ValueError):
                same = None            # a pole at a point of the motion, or a form the zero test does not take
            if same is None:
                self._add(line, piece, "frame", "unchecked",
                          "cannot check it: two members not compared (of different kinds, or undecided)")
                return
            if rel == "\\neq":
                same = not same
            if not same and motion is not None and not motion.names_in(piece) <= motion.rates:
                self._add(line, piece, "frame", "unchecked", "not checked: it holds for some motions only, and it "
                          "is written in names whose rates the text does not write (constants it may state in words)")
                return
            if not same and motion is None and not self._frames_stated_for(piece):
                self._add(line, piece, "frame", "unchecked", "not checked: it relates unit vectors of frames whose "
                          "orientation the text has not stated to the reader (perhaps in words)")
                return
            if not same and motion is None and not _symbols(values) <= self._frames_kept().angles():
                self._add(line, piece, "frame", "unchecked", "not checked: it is written in angles none of the "
                          "orientations the text has stated carries (an orientation it states in words)")
                return
            if not same:
                fixed = self._relabelled(piece, missing)
                if fixed is not None:
                    self._add(line, piece, "frame", "typo", "the row's left side repeats an earlier row's unit vector: "
                              "with the one the block leaves out it holds", fixed)
                else:
                    self._add(line, piece, "frame", "fails", "the members differ in the text's frames (entry by entry)")
                return
        if motion is not None:
            self._add(line, piece, "frame", "holds", "for frames turning in general (Kane's angular velocity, "
                      "derivatives seen from each frame), entry by entry")
            return
        self._add(line, piece, "frame", "holds", "in the text's frames, entry by entry (unit vectors as rows "
                  "of their frames' orientations, {}^F\\mathbf{C}^G = C_F C_G^T)")

    def _frames_stated_for(self, piece) -> bool:
        """Whether a failing static relation is a slip whatever the frames' orientations: it writes a
        DCM (whose algebra holds for any), the unit vectors of one frame only, or only frames the text
        has stated and those they are stated in."""
        frames = self._frames_kept()
        toks = tokens(piece)
        letters = {t[2][0].upper() for t in toks if t[0] == "unit"}
        known = frames.stated | {g for g in frames.stated_in.values()}
        return any(t[0] == "dcm" for t in toks) or len(letters) <= 1 or letters <= known

    def _relabelled(self, piece, missing):
        m = _ROW.match(piece)
        if not m or missing is None:
            return None
        fixed = piece[:m.start(2)] + missing + piece[m.end(2):]
        try:
            values = self._frames_kept().read(fixed)
        except NotRead:
            return None
        return fixed.strip() if all(equal(a, b) for a, b in zip(values, values[1:])) else None

    def _elementary_alone(self, line, pieces) -> bool:
        frames = getattr(self, "_frame_algebra", None)
        if frames is None or not frames.simple or len(pieces) != 1 or \
                not re.fullmatch(r"\s*\\begin\s*\{\s*[bp]matrix\s*\}.*\\end\s*\{\s*[bp]matrix\s*\}\s*", pieces[0], re.S):
            return False
        try:
            values = frames.read(pieces[0])
        except (NotRead, ArithmeticError, TypeError, ValueError):
            return False
        if len(values) != 1 or not isinstance(values[0], sp.MatrixBase) or values[0].shape != (3, 3):
            return False
        turn = simple_turn(values[0])
        if turn is None or turn[2] is False:
            return False
        axis, q, sense = turn
        if sense:
            self._add(line, pieces[0], "frame", "holds", f"a direction cosine matrix alone: the simple orientation "
                      f"about the shared {axis} axis through {self.tex(q)}, in the right-hand sense of the text's own")
        else:
            self._add(line, pieces[0], "frame", "fails", f"a matrix alone that fixes the {axis} axis, in sines and "
                      f"cosines of {self.tex(q)}: its rows are no orthonormal set, so it is no orientation")
        return True


def _direction_cosines(c, piece) -> bool:
    """Whether every entry (i, j) is cos α_{ij} of one name α, its indices the row's and the column's
    axis labels as the statement writes them (x, y, z or 1, 2, 3)."""
    family = "xyz" if re.search(r"\\hat\s*\{\s*[a-z]\s*\}\s*_\s*\{?\s*[xyz]", piece) else "123"
    first = c[0, 0]
    if not (isinstance(first, sp.cos) and isinstance(first.args[0], sp.Symbol)):
        return False
    base, _, index = first.args[0].name.rpartition("_")
    if index != family[0] * 2:
        return False
    return all(c[i, j] == sp.cos(sp.Symbol(f"{base}_{family[i]}{family[j]}", real=True)) for i in range(3) for j in range(3))


def _symbols(values) -> set:
    return set().union(*(matrix_of(v).free_symbols for v in values))


def _left_out(pieces):
    """The axis letter a block of unit-vector rows leaves out when one row repeats another's, else None."""
    found = [_ROW.match(p) for p in pieces]
    if len(pieces) != 3 or not all(found):
        return None
    axes = [m.group(2) for m in found]
    family = "xyz" if set(axes) <= set("xyz") else "123"
    left = [a for a in family if a not in axes]
    return left[0] if len(left) == 1 else None
