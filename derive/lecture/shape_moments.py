"""The moment of inertia of a shape the prose names (``A solid sphere (ball) of radius R and mass
M, about an axis through its centre: I = \\frac{2}{5}MR^2``).

Takes: a display ``I = …`` (the name I or J, any subscript) whose right side is a sum of products of
a mass M (or m) and squares of lengths, and the paragraph of prose just before it
(`derive.lecture.notes.Notes.body`). Gives the mixin `ShapeMoments` of
`derive.lecture.notes_check.Checker`. The paragraph names one uniform body — a solid sphere or
ball, a thin spherical shell, a hoop or ring, a disk, a solid cylinder, a thin rod, a cube — and
the axis: through its centre, its symmetry axis, a diameter or an axis in its plane, or a rod's end
(a paragraph that names a contact point, a tangent, an edge, a parallel axis or a distance names
an axis away from these, and is not read).
The display `holds` when it is that body's moment about one of the axes the paragraph allows, the
lengths in any of their roles; it `fails` only where the body has one length (a sphere, a shell,
a rod, a cube), the paragraph says the axis, and the coefficient of M times that length squared is
another number. A paragraph naming no body, or two, or a display in other names is left to the
other rules, unchanged; the rule judges only a display they left unchecked.

May import: sympy, :mod:`derive.lecture.latex`.
"""
from __future__ import annotations

import itertools
import re

import sympy as sp

from derive.lecture import latex as lx

R_ = sp.Rational
# each body: (pattern of the prose, {axis: coefficients of M x², M y² for lengths (x, y)})
_BODIES = (
    ("shell", r"spherical shell|hollow (?:sphere|ball)|thin shell", {"centre": (R_(2, 3),), "plane": (R_(2, 3),)}),
    ("sphere", r"solid sphere|\bsphere\b|\bball\b", {"centre": (R_(2, 5),), "plane": (R_(2, 5),)}),
    ("hoop", r"\bhoop\b|\bring\b", {"symmetry": (1,), "plane": (R_(1, 2),)}),
    ("disk", r"\bdis[ck]\b", {"symmetry": (R_(1, 2),), "plane": (R_(1, 4),)}),
    ("cylinder", r"\bcylinder\b", {"symmetry": (R_(1, 2), 0), "plane": (R_(1, 4), R_(1, 12))}),
    ("rod", r"\brod\b|\bstick\b", {"centre": (R_(1, 12),), "end": (R_(1, 3),)}),
    ("cube", r"\bcube\b", {"centre": (R_(1, 6),)}),
)
_AXES = (("end", r"\bend\b"), ("plane", r"in (?:its|the) plane|diameter|perpendicular to (?:its|the) (?:symmetry )?axis"),
         ("symmetry", r"symmetry axis|axis of symmetry|perpendicular to (?:its|the) plane"),
         ("centre", r"(?:through|about) (?:its|the) cent(?:re|er)"))
# an axis away from the centre (a contact point, a tangent, a parallel axis at a distance): not this table's
_ELSEWHERE = re.compile(r"contact|tangent|\bedge|\brim\b|surface|parallel|distance|\bpoint|offset|from (?:its|the) cent")
_NAME = re.compile(r"\s*[IJ](?:_\s*(?:\{[^{}=]*\}|[A-Za-z0-9]))?\s*=[^=]+$")


def paragraph(body: str, line: int) -> str:
    """The prose just before the display on ``line``: the lines back to a blank one, or an earlier display."""
    lines, out = body.split("\n"), []
    k = line - 2
    while k >= 0 and not lines[k].strip():
        k -= 1
    while k >= 0 and lines[k].strip() and not re.search(r"\\\]|\$\$|\\end\{", lines[k]) and len(out) < 4:
        out.insert(0, lines[k])
        k -= 1
    return " ".join(out).lower()


def _body(prose: str):
    """(name, axes) of the one body the prose names, or None."""
    found = [(name, axes) for name, pattern, axes in _BODIES if re.search(pattern, prose)]
    if found and found[0][0] == "shell":
        found = found[:1]                     # "a thin spherical shell (sphere)": the shell
    return found[0] if len(found) == 1 else None


def _said_axes(prose: str, axes: dict) -> list:
    """The axes of ``axes`` the prose allows: the ones it names, a named centre standing for the body's
    axes through it (all but a rod's end)."""
    named = [a for a, pattern in _AXES if re.search(pattern, prose)]
    if not named or _ELSEWHERE.search(prose):
        return []
    specific = [a for a in named if a != "centre" and a in axes]
    if specific:
        return specific
    return [a for a in axes if a != "end"] if "centre" in named else []


class ShapeMoments:
    """Mixin of the checker. Uses ``self.notes``, ``self.vocab``, ``self.claims``."""

    def _shape_moment(self, line, piece, start):
        """Judge ``I = c M a²`` against the moment of the body the prose before it names, where the
        statement's claims from ``start`` are all unchecked."""
        added = self.claims[start:]
        if not added or any(c.verdict != "unchecked" for c in added) or not _NAME.match(piece):
            return
        prose = paragraph(getattr(self.notes, "body", "") or "", line)
        body = _body(prose) if prose else None
        if body is None:
            return
        name, axes = body
        allowed = _said_axes(prose, axes)
        try:
            parsed = lx.parse(piece, self.vocab)
        except (lx.NotRead, lx.Words, ValueError, TypeError):
            return
        value = parsed.members[-1].value if len(parsed.members) == 2 else None
        if not isinstance(value, sp.Expr) or isinstance(value, sp.MatrixBase) or not allowed:
            return
        # the letters as written: L is a rod's length here, whatever the reader takes it for elsewhere
        value = value.xreplace({x: sp.Symbol(x.name.strip("|"), positive=True) for x in value.free_symbols})
        names = value.free_symbols
        masses = [s for s in names if s.name in ("M", "m")]
        lengths = sorted(names - set(masses), key=str)
        if len(masses) != 1 or not 1 <= len(lengths) <= 2 or any(len(s.name) != 1 for s in lengths):
            return
        m = masses[0]
        wanted = [sum(c * m * x ** 2 for c, x in zip(axes[a], roles)) for a in allowed
                  for roles in itertools.permutations(lengths, len(axes[a])) if len(roles) == len(axes[a])]
        if any(sp.expand(value - w) == 0 for w in wanted):
            verdict = "holds", f"the moment of a uniform {name} about the axis the prose names (expand)"
        elif len(lengths) == 1 and len({sp.expand(w) for w in wanted}) == 1 \
                and sp.expand(value / (m * lengths[0] ** 2)).is_number:
            verdict = "fails", (f"a uniform {name}'s moment about the axis the prose names is "
                                f"{sp.latex(wanted[0])}, not {sp.latex(value)}")
        else:
            return
        for c in added:
            c.kind, (c.verdict, c.why) = "moment of a named shape", verdict
