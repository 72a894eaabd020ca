"""The moment of inertia of a shape the prose names (``A solid sphere (ball) of radius R and mass
M, about an axis through its centre: I = \\frac{2}{5}MR^2``).

Takes: a display ``I = …`` (the name I or J, any subscript) whose right side is a sum of products of
a mass M (or m) and squares of lengths, and the paragraph of prose just before it
(`derive.lecture.notes.Notes.body`). Gives the mixin `ShapeMoments` of
`derive.lecture.notes_check.Checker`. The paragraph names one uniform body — a solid sphere or
ball, a thin spherical shell, a hoop or ring, a disk, a solid cylinder, a thin rod, a cube, a solid
cone (its axis named by the letter the prose gives its axis of symmetry) — and
the axis: through its centre, its symmetry axis, a diameter or an axis in its plane, or a rod's end
(a paragraph that names a contact point, a tangent, an edge, a parallel axis or a distance names
an axis away from these, and is not read).
The display `holds` when it is that body's moment about one of the axes the paragraph allows, the
lengths in any of their roles; it `fails` only where the body has one length (a sphere, a shell,
a rod, a cube), the paragraph says the axis, and the coefficient of M times that length squared is
another number. A paragraph naming no body, or two, or a display in other names is left to the
other rules, unchanged; the rule judges only a display they left unchecked. A distance ``R = \\frac{3h}{4}``
that the paragraph sets as the centre of mass's from a point of the one body its section names (a
cone's apex or base) holds when it is that body's, and is otherwise left as it is.

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
    # a solid cone of base radius a and height h: about its axis, and across it through its centre of mass,
    # its apex or its base's centre; the cones a rate vector sweeps (body, space, nutation cones) are not bodies
    ("cone", r"(?<!body )(?<!space )(?<!nutation )(?<!sweeps a )\bcone\b",
     {"symmetry": (R_(3, 10), 0), "centre": (R_(3, 20), R_(3, 80)), "apex": (R_(3, 20), R_(3, 5)),
      "base": (R_(3, 20), R_(1, 10))}),
)
_AXES = (("end", r"\bend\b"), ("plane", r"in (?:its|the) plane|diameter|perpendicular to (?:its|the) (?:symmetry )?axis"),
         ("symmetry", r"symmetry axis|axis of symmetry|perpendicular to (?:its|the) plane"),
         ("centre", r"(?:through|about) (?:its|the) cent(?:re|er)"))
# an axis away from the centre (a contact point, a tangent, a parallel axis at a distance): not this table's
_ELSEWHERE = re.compile(r"contact|tangent|\bedge|\brim\b|surface|parallel|distance|\bpoint|offset|from (?:its|the) cent")
_HEADING = re.compile(r"\s*(?:#|\\(?:sub)*section\b|\\chapter\b)")
# where the centre of mass of a uniform body lies on its axis: {point the prose measures from: the
# fraction of the body's one length}; a solid cone's at a quarter of its height above its base
_CENTRES = {"cone": {"apex": R_(3, 4), "base": R_(1, 4)}}
# the volume of a uniform solid in its lengths (a radius first, then a height)
_VOLUMES = {"sphere": (1, lambda x: R_(4, 3) * sp.pi * x ** 3), "cube": (1, lambda x: x ** 3),
            "cylinder": (2, lambda x, y: sp.pi * x ** 2 * y), "cone": (2, lambda x, y: sp.pi * x ** 2 * y / 3)}
_DISTANCE = re.compile(r"\s*([A-Za-z]|\\[A-Za-z]+)(?:_\s*(?:\{[^{}=]*\}|[A-Za-z0-9]))?\s*=[^=]+$")
_NAME = re.compile(r"\s*(?:[IJ](?:_\s*(?:\{[^{}=]*\}|[A-Za-z0-9]))?\s*=\s*)+[^=]+$")
_SUBSCRIPT = re.compile(r"[IJ]_\s*\{?\s*([A-Za-z0-9])\s*\}?\s*=")
# the letter of a cone's axis of symmetry, as the prose sets it ("$z$ its axis of symmetry", "the symmetry axis $z$")
_SYMMETRY_LETTER = re.compile(r"\$([a-z0-9])\$,?\s+(?:is\s+)?(?:its|the)\s+(?:axis of symmetry|symmetry axis)"
                              r"|(?:axis of symmetry|symmetry axis),?\s+\$([a-z0-9])\$")
_CONE_POINTS = (("centre", r"cent(?:re|er) of mass|\bcentroid"), ("apex", r"\bapex|\bvertex|\btip\b"),
                ("base", r"\bbase'?s? cent(?:re|er)|cent(?:re|er) of (?:its|the) base"))
# a cone's axis away from its own points (a contact line, an edge): not this table's
_CONE_ELSEWHERE = re.compile(r"contact|tangent|\bedge|\brim\b|surface|offset|parallel ax")


def _used(coefficients: tuple) -> tuple:
    """The coefficients up to the last length the moment uses (a cylinder's or a cone's axial moment needs no height)."""
    return coefficients[:max(k + 1 for k, c in enumerate(coefficients) if c)]


def paragraph(body: str, line: int, lower: bool = True) -> str:
    """The prose just before the display on ``line``: the lines back to a blank one, or an earlier display."""
    lines, out = body.split("\n"), []
    k = line - 2
    while k >= 0 and not lines[k].strip():
        k -= 1
    while k >= 0 and lines[k].strip() and not re.search(r"\\\]|\$\$|\\end\{", lines[k]) and len(out) < 4:
        out.insert(0, lines[k])
        k -= 1
    text = " ".join(out)
    return text.lower() if lower else text


def section(body: str, line: int) -> str:
    """The text from the heading before the display on ``line`` (a Markdown ``#`` line or a LaTeX
    sectioning command) up to the display, lower case."""
    lines = body.split("\n")[:max(line - 1, 0)]
    k = len(lines) - 1
    while k >= 0 and not _HEADING.match(lines[k]):
        k -= 1
    return " ".join(lines[max(k, 0):]).lower()


def _body(prose: str):
    """(name, axes) of the one body the prose names, or None."""
    found = [(name, axes) for name, pattern, axes in _BODIES if re.search(pattern, prose)]
    if found and found[0][0] == "shell":
        found = found[:1]                     # "a thin spherical shell (sphere)": the shell
    return found[0] if len(found) == 1 else None


def _cone_axes(prose: str, piece: str) -> list:
    """The axes of a cone a display ``I_x = I_y = …`` may be about: its axis of symmetry where every
    name's subscript is the letter the prose gives that axis, the transverse axes (through the points
    the prose names, or all three) where none is; all four where the prose gives no letter."""
    if _CONE_ELSEWHERE.search(prose):
        return []
    m = _SYMMETRY_LETTER.search(prose)
    letter = (m.group(1) or m.group(2)) if m else None
    points = [a for a, pattern in _CONE_POINTS if re.search(pattern, prose)] or ["centre", "apex", "base"]
    subs = {s.lower() for s in _SUBSCRIPT.findall(piece)}
    if letter is None:
        return ["symmetry", *points]
    if subs == {letter}:
        return ["symmetry"]
    return points if subs and letter not in subs else []


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
        if not added or any(c.verdict != "unchecked" for c in added):
            return
        if not _NAME.match(piece):
            self._shape_centre(line, piece, added)
            self._shape_volume(line, piece, added)
            return
        prose = paragraph(getattr(self.notes, "body", "") or "", line)
        body = _body(prose) if prose else None
        if body is None:
            return
        name, axes = body
        allowed = _cone_axes(prose, piece) if name == "cone" else _said_axes(prose, axes)
        try:
            parsed = lx.parse(piece, self.vocab)
        except (lx.NotRead, lx.Words, ValueError, TypeError):
            return
        value = parsed.members[-1].value if len(parsed.members) >= 2 else None
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
        wanted = [sum(c * m * x ** 2 for c, x in zip(_used(axes[a]), roles)) for a in allowed
                  for roles in itertools.permutations(lengths, len(_used(axes[a])))]
        if any(sp.expand(value - w) == 0 for w in wanted):
            verdict = "holds", f"the moment of a uniform {name} about the axis the prose names (expand)"
        elif len(lengths) == 1 and all(len(c) == 1 for c in axes.values()) and len({sp.expand(w) for w in wanted}) == 1 \
                and sp.expand(value / (m * lengths[0] ** 2)).is_number:
            verdict = "fails", (f"a uniform {name}'s moment about the axis the prose names is "
                                f"{sp.latex(wanted[0])}, not {sp.latex(value)}")
        else:
            return
        for c in added:
            c.kind, (c.verdict, c.why) = "moment of a named shape", verdict

    def _shape_centre(self, line, piece, added):
        """Judge ``R = \\frac{3h}{4}`` after prose setting R as the distance of the centre of mass from a
        point of the one body its section names (a cone's apex or base): `holds` when it is that
        body's, else left as it is (the text may mean a hollow body or another length)."""
        body = getattr(self.notes, "body", "") or ""
        said = paragraph(body, line, lower=False)
        prose, found = said.lower(), _body(section(body, line))
        if found is None or found[0] not in _CENTRES or not re.search(r"cent(?:re|er) of mass", prose):
            return
        points = [a for a, pattern in _CONE_POINTS if a in _CENTRES[found[0]] and re.search(pattern, prose)]
        lhs = piece.split("=")[0].strip()
        if len(points) != 1 or not _DISTANCE.match(piece) or f"${lhs}$" not in said or "distance" not in prose:
            return
        value = self._set_value(piece)
        if not isinstance(value, sp.Expr) or isinstance(value, sp.MatrixBase) or len(value.free_symbols) != 1:
            return
        length = next(iter(value.free_symbols))
        if sp.simplify(value / length - _CENTRES[found[0]][points[0]]) != 0:
            return
        for c in added:
            c.kind, c.verdict = "centre of a named shape", "holds"
            c.why = f"the centre of mass of a uniform {found[0]}, its distance from the {points[0]} (exact)"

    def _set_value(self, piece):
        """The value a two-member statement sets its head to, or None when it does not read as one."""
        try:
            parsed = lx.parse(piece, self.vocab)
        except (lx.NotRead, lx.Words, ValueError, TypeError):
            return None
        return parsed.members[-1].value if len(parsed.members) == 2 else None

    def _shape_volume(self, line, piece, added):
        """Judge ``V = \\pi R^2 h`` (the section speaking of a volume) or ``\\rho = \\frac{3M}{\\pi d^2 h}``
        (of a density) against the one uniform solid the section names: `holds` when it is that body's
        volume, or its mass over it (the lengths in any roles); else left as it is."""
        lhs = piece.split("=")[0].strip()
        if lhs not in ("V", "\\rho", "\\varrho") or any(c.verdict != "unchecked" for c in added):
            return
        text = section(getattr(self.notes, "body", "") or "", line)
        found = _body(text)
        if found is None or found[0] not in _VOLUMES or ("volume" if lhs == "V" else "density") not in text:
            return
        value = self._set_value(piece)
        if not isinstance(value, sp.Expr) or isinstance(value, sp.MatrixBase):
            return
        value = value.xreplace({x: sp.Symbol(x.name.strip("|"), positive=True) for x in value.free_symbols})
        masses = [x for x in value.free_symbols if x.name in ("M", "m")]
        lengths = sorted(value.free_symbols - set(masses), key=str)
        count, volume = _VOLUMES[found[0]]
        if len(masses) != (lhs != "V") or len(lengths) != count:
            return
        scale = masses[0] if masses else 1
        if not any(sp.simplify(value - scale / volume(*roles) if masses else value - volume(*roles)) == 0
                   for roles in itertools.permutations(lengths)):
            return
        for c in added:
            c.kind, c.verdict = "volume of a named shape", "holds"
            c.why = f"the {'volume' if lhs == 'V' else 'density'} of a uniform solid {found[0]} (exact)"
