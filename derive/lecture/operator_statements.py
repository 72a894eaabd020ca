"""The checker's reading of statements in operator notation (`derive.lecture.operator_notation`).

Takes: the notes (their prose, convention and angles) and one statement. Gives: the mixin
`OperatorStatements` of `derive.lecture.notes_check.Checker`: a statement the operator reading
follows entirely gets its verdict here, any other goes on to the general reader.
May import: the standard library, mpmath, :mod:`derive.lecture.operator_notation`,
:mod:`derive.lecture.operator_prose`, :mod:`derive.lecture.motion_jets`.

A chain a = b = c is evaluated on three instants of motions with a torque (random angle
accelerations; the torque is the one they imply) and, where the section says the body is free,
on three instants of torque-free motions. Each consecutive pair must agree to 10⁻⁹ of its size.
Verdicts: ``holds`` on every motion, or ``holds`` on the free motions under the section's "free
body"; ``fails`` otherwise, naming the pair; ``unchecked`` when a symbol the text leaves
arbitrary (a vector **u**, a rotation R) is in it and it does not hold for every value of it, or
when its left side is a symbol met for the first time (a definition, not a claim).
"""
from __future__ import annotations

import functools
import random
import re

import mpmath

from derive.lecture import motion_jets as mj
from derive.lecture import operator_notation as on
from derive.lecture import operator_prose

_POINTS = 3
_NEAR = 12
"""Lines of prose before a statement that may call its capital letter a rotation."""
_FREE = re.compile(r"free (?:rigid )?body|torque[- ]free|no (?:external )?torques?", re.I)
_ROTATION = re.compile(r"\brotat", re.I)
_LETTERS = {"omega": "angular velocity", "L": "angular momentum", "T": "torque", "tau": "torque", "N": "torque"}
_DISPLAYS = re.compile(r"\$\$.+?\$\$|\\\[.+?\\\]|\\begin\{(equation|align|gather)\*?\}.+?\\end\{\1\*?\}", re.S)


class OperatorStatements:
    """Mixin of the checker (see the module docstring)."""

    @functools.cached_property
    def _op(self) -> operator_prose.Declarations:
        return operator_prose.declarations(getattr(self.notes, "body", ""))

    @functools.cached_property
    def _op_names(self) -> dict:
        names = dict(_LETTERS)
        for (letter, _kind), meaning in self.notes.names.letters.items():
            if meaning in ("angular velocity", "angular momentum", "torque"):
                names[letter] = meaning
        return names

    @functools.cached_property
    def _op_lines(self) -> list:
        return getattr(self.notes, "body", "").split("\n")

    def _op_section_prose(self, line) -> str:
        """The prose from the section's heading to this line (displays left out)."""
        start = max([it.line for it in self.notes.items if it.kind == "heading" and it.line < line], default=0)
        return _DISPLAYS.sub(" ", "\n".join(self._op_lines[start:line - 1]))

    def _operator(self, line, piece, text) -> bool:
        """Check the statement in operator notation; False when that reading does not follow it.
        A statement read again (a second reading of the checker) gets the verdicts of the first."""
        if not self._op.on:
            return False
        done = self.__dict__.setdefault("_op_done", {})
        if (line, piece, text) not in done:
            start = len(self.claims)
            handled = self._op_read(line, piece, text)
            done[(line, piece, text)] = [(c.line, c.latex, c.kind, c.verdict, c.why, c.correction)
                                         for c in self.claims[start:]] if handled else []
            return handled
        for claim in done[(line, piece, text)]:
            self._add(*claim)
        return bool(done[(line, piece, text)])

    def _op_read(self, line, piece, text) -> bool:
        decl = self._op
        seen = self.__dict__.setdefault("_op_seen", set())
        try:
            toks = on.tokens(on.prepared(text))
        except on.NotHandled:
            return False
        keys = [(t.value, t.bold, t.primes, t.sub, t.sup) for t in toks if t.kind == "atom"]
        if not any(_notation(t, decl) for t in toks):
            return False            # nothing of the operator notation in it (θ = 0): the general reader's
        first = [t for t in toks[:next((k for k, t in enumerate(toks) if t.kind == "rel"), 0)]]
        prose = self._op_section_prose(line)
        free_said = bool(_FREE.search(prose))
        near = "\n".join(prose.split("\n")[-_NEAR:])
        try:
            forced = [self._op_values(text, k, False, near) for k in range(_POINTS)]
            free = [self._op_values(text, k, True, near) for k in range(_POINTS)] if free_said else None
        except (on.NotHandled, ZeroDivisionError, ValueError, IndexError):
            seen.update(keys)
            return False
        seen_before = set(seen)
        seen.update(keys)
        if len(forced[0][0]) < 2:
            return False
        self.ctx.head = _left_side(text)
        atoms = [t for t in first if t.kind == "atom"]
        if len(atoms) == 1 and len(first) == 1 and (atoms[0].value, atoms[0].bold, atoms[0].primes, atoms[0].sub,
                                                     atoms[0].sup) not in seen_before:
            self._add(line, piece, "definition", "unchecked",
                      f"defines {atoms[0].value} (met here first): a definition, not a claim")
            return True
        bad = _disagreeing(forced)
        if bad is None:
            self._add(line, piece, "operator identity", "holds", "holds on any motion (" + self._op_reading(forced) + ")")
            return True
        if free is not None and _disagreeing(free) is None:
            self._add(line, piece, "operator identity", "holds",
                      "holds for a free body, as the section says (" + self._op_reading(forced) + ")")
            return True
        if any(v[1] for v in forced):
            names = ", ".join(sorted(set().union(*(v[1] for v in forced))))
            self._add(line, piece, "operator identity", "unchecked",
                      f"does not hold whatever {names} stand for, and the text leaves {names} arbitrary")
            return True
        which = _disagreeing(free) if free is not None else bad
        motion = "on a torque-free motion" if free is not None else "on a motion with a torque"
        why = f"as written: member {which + 1} ≠ member {which + 2} {motion} ({self._op_reading(forced)})"
        fix = _sign_fix(text, piece, forced, free)
        if fix is not None:
            self._add(line, piece, "operator identity", "typo", f"{why}; one edit (the sign of member {fix[1] + 1}) "
                      "makes it hold", fix[0])
        else:
            self._add(line, piece, "operator identity", "fails", why)
        return True

    def _op_values(self, text, k, free, prose):
        """(members' values, arbitrary symbols used) on the k-th instant."""
        rng = random.Random(f"{text}/{k}")
        moments = [rng.uniform(1, 3) for _ in range(3)]
        instant = mj.Instant(self.d.conv.axes, moments, f"{text}/{k}/{free}", free)
        values = on.Values(self._op, instant, tuple(self.notes.angles), self._op_names, f"{text}/{k}/arbitrary",
                           rotations=bool(_ROTATION.search(prose)))
        members = [on.flat(m) for m in on.evaluate(text, values)]
        if len({len(m) for m in members}) != 1:
            raise on.NotHandled("members of different shapes")
        if any(mpmath.isnan(x) for m in members for x in m):
            raise on.NotHandled("a derivative beyond what the motion's jets keep")
        return members, values.free

    def _op_reading(self, forced) -> str:
        decl = self._op
        parts = []
        if decl.derivative:
            parts.append(f"{decl.derivative} the time derivative")
        if decl.orientation:
            parts.append(f"{decl.orientation} the orientation matrix of the {self.notes.convention} angles")
        if decl.cross:
            parts.append(f"{decl.cross}(v) the cross-product matrix of v")
        return ", ".join(parts)


def _notation(tok, decl) -> bool:
    """Is the token part of the operator notation (D, 𝒜, ∂, a bold quantity, a labelled component)?"""
    if tok.kind == "cmd":
        return tok.value in ("partial", "times")
    if tok.kind != "atom":
        return tok.kind == "env"
    return tok.bold or tok.value in (decl.derivative, decl.orientation) or (tok.roman and tok.value == decl.cross) \
        or bool(tok.sup) or (tok.sub in decl.labels and not tok.sub.isdigit())


def _sign_fix(text, piece, forced, free):
    """(the statement with one member's sign turned, that member) when that makes it hold, else
    None; only a member of one term is turned (its leading '-' added or dropped)."""
    members = _split_members(text)
    if len(members) != len(forced[0][0]):
        return None
    head = len(_split_members(piece)) < len(members)         # a continuation row: its head is member 0
    order = sorted(range(1 if head else 0, len(members)), key=lambda k: not members[k].strip().startswith("-"))
    for k in order:                                         # dropping a '-' first, then adding one
        body = members[k].strip()
        bare = body[1:].strip() if body.startswith("-") else body
        if _split_members(bare, "+-") != [bare]:
            continue
        turned = [([-x for x in m] if j == k else m for j, m in enumerate(v[0])) for v in forced]
        ok = _disagreeing([(list(t), ()) for t in turned]) is None
        if not ok and free is not None:
            turned = [([-x for x in m] if j == k else m for j, m in enumerate(v[0])) for v in free]
            ok = _disagreeing([(list(t), ()) for t in turned]) is None
        if ok:
            out = list(members)
            out[k] = (" " if k else "") + (bare if body.startswith("-") else "-" + body) + " "
            latex = "=".join(out).strip()
            return (latex[len(_left_side(text)):].strip() if head else latex), k
    return None


def _split_members(text, seps="=") -> list:
    """The text cut at top-level separators (outside braces and brackets); a leading one is no cut."""
    out, depth, last = [], 0, 0
    for i, ch in enumerate(text):
        if ch in "{([":
            depth += 1
        elif ch in "})]":
            depth -= 1
        elif ch in seps and depth == 0 and i > 0 and text[i - 1] != "\\" and text[:i].strip():
            out.append(text[last:i])
            last = i + 1
    out.append(text[last:])
    return out


def _disagreeing(points) -> int | None:
    """The first pair of consecutive members that differ on some instant, or None."""
    for members, _ in points:
        for j in range(len(members) - 1):
            a, b = members[j], members[j + 1]
            size = 1 + max(abs(x) for x in a + b)
            if any(abs(x - y) > 1e-9 * size for x, y in zip(a, b)):
                return j
    return None


def _left_side(text: str) -> str:
    depth = 0
    for i, ch in enumerate(text):
        if ch in "{(":
            depth += 1
        elif ch in "})":
            depth -= 1
        elif ch == "=" and depth == 0:
            return text[:i].strip()
    return text
