"""The kinetic energy of a rigid body written about a point of it that moves: ``T = \\frac{1}{2}m
\\mathbf{v}_B^2 + m\\mathbf{v}_B\\cdot(\\boldsymbol\\omega\\times\\mathbf{r}_{G/B}) + \\frac{1}{2}
\\boldsymbol\\omega\\cdot\\mathbf{H}_B``.

Takes: a statement's text. Gives: `energy_about_a_point`, the verdict on a statement that sets T
to a sum of terms of three kinds, each with the coefficient ½ or 1: a mass times two velocities of
labelled points (``m\\mathbf{v}_B^2``, ``m\\mathbf{v}_B\\cdot\\mathbf{v}_G``, ``m\\mathbf{v}_B\\cdot
\\mathbf{v}_{G/B}``, ``m\\mathbf{v}_B\\cdot(\\boldsymbol\\omega\\times\\mathbf{r}_{G/B})``) and ½ 𝛚·𝐇_P
(``\\boldsymbol\\omega\\cdot\\mathbf{H}_B`` or one bold group ``\\mathbf{\\omega H_B}``). The points are
the centre of mass (a subscript C, G, cm, …) and one other point B of the body; a velocity of G
relative to B is 𝛚 × 𝐫_{G/B}. The sum is compared, at random states (𝛚, 𝐯_B, 𝐫_{G/B}, m and the
inertia about G), with T = ½ m v_G² + ½ 𝛚·𝐈_G𝛚, 𝐇_B read both ways texts define it: from the
velocities relative to B (𝐈_B𝛚) and from the absolute ones (𝐈_B𝛚 + m 𝐫_{G/B} × 𝐯_B). It holds
under either, naming it, and fails under both. Any other term, point or coefficient is not read
(None). May import: the standard library, :mod:`derive.lecture.latex_spaces`.
"""
from __future__ import annotations

import random
import re

from derive.lecture.latex_spaces import SPACE_SYMBOL, TIE

_BOLD = r"\\(?:mathbf|boldsymbol|bm|pmb|vec)"
_LABEL = r"_\s*(\{[^{}]*\}|[A-Za-z])"
_V = rf"(?:{_BOLD}\s*\{{?\s*v\s*\}}?|v)\s*{_LABEL}"
_R = rf"(?:{_BOLD}\s*\{{?\s*(?:r|\\rho)\s*\}}?|r|\\rho)\s*{_LABEL}"
_W = rf"(?:{_BOLD}\s*\{{?\s*\\omega\s*\}}?|\\omega)"
_HALF = r"(?:\\[dt]?frac\s*\{\s*1\s*\}\s*\{\s*2\s*\}|\\[dt]?frac\s*12)"
_MASS = r"[mM]\s*(?:\\cdot\s*)?"
_TERMS = (
    ("vv", re.compile(rf"{_MASS}{_V}\s*\^\s*\{{?\s*2\s*\}}?")),
    ("vv", re.compile(rf"{_MASS}{_V}\s*\\cdot\s*{_V}")),
    ("vw", re.compile(rf"{_MASS}{_V}\s*\\cdot\s*\(\s*{_W}\s*\\times\s*{_R}\s*\)")),
    ("wH", re.compile(rf"{_BOLD}\s*\{{\s*\\omega\s*H\s*{_LABEL}\s*\}}")),
    ("wH", re.compile(rf"{_W}\s*\\cdot\s*(?:{_BOLD}\s*\{{?\s*H\s*\}}?|H)\s*{_LABEL}")),
)
_CENTRE = {"C", "c", "G", "cm", "CM", "com"}
_SPACING = re.compile(rf"(?<!\\)(?:{SPACE_SYMBOL}|{TIE})|\\left|\\right")


def _label(raw: str) -> str:
    return re.sub(r"\\(?:mathrm|text)\s*", "", raw).replace("{", "").replace("}", "").replace(" ", "")


def _terms(rhs: str):
    """The signed terms of a sum, as (sign, text), split at the + and − outside brackets."""
    out, depth, start, sign = [], 0, 0, 1
    body = rhs.strip()
    if body.startswith(("+", "-")):
        sign, body = (-1 if body[0] == "-" else 1), body[1:]
    for k, ch in enumerate(body):
        depth += (ch in "({[") - (ch in ")}]")
        if depth == 0 and ch in "+-" and k > start:
            out.append((sign, body[start:k]))
            sign, start = (-1 if ch == "-" else 1), k + 1
    out.append((sign, body[start:]))
    return out


def _term(text: str):
    """(coefficient, kind, labels) of one term, or None where it is not one of the three kinds."""
    text = text.strip()
    m = re.match(_HALF, text)
    coeff = 0.5 if m else 1.0
    text = text[m.end():].strip() if m else text
    for kind, form in _TERMS:
        hit = form.fullmatch(text)
        if hit:
            return coeff, kind, tuple(_label(g) for g in hit.groups())
    return None


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def _values(terms, point, rng):
    """T as written and as derived, at one random state, under each reading of 𝐇 (relative, absolute)."""
    w, vb, r = ([rng.uniform(-1, 1) for _ in range(3)] for _ in range(3))
    mass = rng.uniform(0.5, 2)
    a = [[rng.uniform(-1, 1) for _ in range(3)] for _ in range(3)]
    ig = [[_dot(a[i], a[j]) + (i == j) for j in range(3)] for i in range(3)]       # an inertia about G
    shift = [[mass * ((i == j) * _dot(r, r) - r[i] * r[j]) for j in range(3)] for i in range(3)]
    ib = [[ig[i][j] + shift[i][j] for j in range(3)] for i in range(3)]
    vg = tuple(x + y for x, y in zip(vb, _cross(w, r)))
    velocity = {point: vb, "G": vg, f"G/{point}": _cross(w, r)}
    times = lambda m, v: tuple(_dot(row, v) for row in m)      # noqa: E731
    derived = 0.5 * mass * _dot(vg, vg) + 0.5 * _dot(w, times(ig, w))
    out = []
    for absolute in (False, True):
        h = {"G": times(ig, w), point: times(ib, w)}
        if absolute:
            h[point] = tuple(x + mass * y for x, y in zip(h[point], _cross(r, vb)))
        total = 0.0
        for sign, coeff, kind, labels in terms:
            if kind == "wH":
                value = _dot(w, h[labels[0]])
            elif kind == "vw":
                value = mass * _dot(velocity[labels[0]], _cross(w, r))
            else:
                value = mass * _dot(velocity[labels[0]], velocity[labels[-1]])
            total += sign * coeff * value
        out.append(abs(total - derived) <= 1e-9 * (1 + abs(derived)))
    return out


def energy_about_a_point(piece: str):
    """``("holds" | "fails", why)`` for T written about a moving point of the body, or None.

    Parameters
    ----------
    piece : str
        One statement, ``T = …``.

    Returns
    -------
    tuple of (str, str), or None
        None where the statement is not T set to a sum of the three kinds of term about the
        centre of mass and one other point (see the module docstring).
    """
    piece = _SPACING.sub(" ", piece).strip().rstrip(".,;").strip()
    m = re.fullmatch(r"T\s*=(.*)", piece, re.S)
    if m is None or "=" in m.group(1):
        return None
    terms = []
    for sign, text in _terms(m.group(1)):
        read = _term(text)
        if read is None:
            return None
        terms.append((sign, *read))
    points = set()
    for _, _, kind, labels in terms:
        for lab in labels:
            points |= set(lab.split("/")) if kind != "vw" else {lab.split("/")[0]} if "/" in lab else {lab}
    centre = {p for p in points if p in _CENTRE}
    others = points - centre
    if len(centre) > 1 or len(others) != 1 or not any(k == "wH" for _, _, k, _ in terms):
        return None
    point = next(iter(others))
    if not any(k == "vv" and point in labels for _, _, k, labels in terms):
        return None                      # T = ½ 𝛚·𝐇_B alone: a fixed point's form, not a moving one's
    rename = {c: "G" for c in centre}
    fixed = []
    for sign, coeff, kind, labels in terms:
        labels = tuple("/".join(rename.get(p, p) for p in lab.split("/")) for lab in labels)
        if kind == "vw" and labels[1] != f"G/{point}" or kind == "vv" and f"{point}/G" in labels \
                or any("/" in lab and lab != f"G/{point}" for lab in labels):
            return None
        fixed.append((sign, coeff, kind, labels))
    rng = random.Random(1)
    relative, absolute = (all(x) for x in zip(*(_values(fixed, point, rng) for _ in range(3))))
    if relative or absolute:
        how = "from the velocities relative to" if relative else "from the absolute velocities about"
        return "holds", (f"the kinetic energy about a moving point {point} of the body, ½ m v_G² + ½ 𝛚·𝐈_G𝛚 "
                         f"written with 𝐯_{point} and 𝐇_{point} ({how} {point})")
    return "fails", (f"not the kinetic energy about a moving point {point} of the body under either reading of 𝐇_{point}: "
                     f"½ m v_{point}² + m 𝐯_{point}·(𝛚 × 𝐫_G/{point}) + ½ 𝛚·𝐈_{point}𝛚 (𝐇_{point} from the velocities "
                     f"relative to {point}) or ½ m v_{point}² + ½ m 𝐯_{point}·(𝛚 × 𝐫_G/{point}) + ½ 𝛚·𝐇_{point} "
                     f"(from the absolute velocities), checked at random states")
