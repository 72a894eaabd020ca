"""The angle convention a text states without front matter: read from its own displays and prose.

Takes: the rendered text of the notes (prose and math, `derive.lecture.source.rendered`). Gives:
`stated(body)`, the conventions the text states, one per section that states one (`Stated`: the
line the section starts on, the sequence, the angles' names when the text gives them).

What states a convention, in a section (cut at Markdown headings and LaTeX ``\\section``-like
commands):

* a product of three single-axis turns named by their axis and applied to one angle each,
  ``R = R_3(\\theta_1) R_1(\\theta_2) R_3(\\theta_3)`` (axes ``1 2 3`` or ``x y z``, any matrix
  letter, bold or roman): the sequence of the axes in the written order (3-1-3 → z-x-z) and the
  angles' names in that order; an axis may be a capital (``R_Z(\\phi)``). When the text writes the
  product's letter out only as passive single-axis turns with their axis and angle
  (``C_X(\\phi) = \\begin{pmatrix} 1 & 0 & 0 \\\\ 0 & \\cos\\phi & \\sin\\phi \\\\ …``, a change of
  coordinates), its rightmost turn is the first and the order is reversed. A product whose
  consecutive axes repeat, or whose arguments are not three different plain symbols, states nothing;
* prose naming the sequence, "3-1-3 Euler angles", "a z-x-z sequence", "the 3-2-1 convention":
  the sequence; the names come from a product in the same section, else from the prose right
  after it, "a turn $\\theta$ about the third axis, then $\\alpha$ about the first, then $\\phi$
  about the second" (three names whose axes are the sequence's), else none (the sequence's usual
  names).

* a product of three matrices the section has written out each as one elementary turn,
  ``U_1 = \\begin{pmatrix} \\cos\\phi & -\\sin\\phi & 0 \\\\ … \\end{pmatrix}, …`` then
  ``U = U_1 U_2 U_3``: a turn about the axis its row and column of ``1`` and ``0`` name, by the angle
  in its cosines and sines; written as the active turn (``-\\sin`` above the diagonal of the
  turning block) the product's order is the sequence's, written as its transpose (a passive turn,
  ``A = BCD``) the order is reversed. Only entries that are a plain ``0``, ``1``, ``\\cos q`` or
  ``\\sin q`` of one plain angle ``q`` make such a matrix (`elementary`).

A product about axes named by letters (``R_i(\\theta_1) R_j(\\theta_2) R_k(\\theta_3)``) is the general
form of every sequence: it states none, and the reader takes it for no claim (`general_form`).
Only the twelve sequences of `derive.lecture.notes.CONVENTIONS` are stated; the front matter, when
it declares a convention, wins over everything read here (`derive.lecture.notes.parse_notes`).

May import: the standard library (`re`, `dataclasses`), :mod:`derive.lecture.latex_spaces`, :mod:`derive.lecture.latex_spellings` and :mod:`derive.lecture.source`
(where math stands in a text).
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from derive.lecture import source
from derive.lecture.latex_spaces import ONE_SPACE, SPACING
from derive.lecture.latex_spellings import SIZED_CLOSE, SIZED_OPEN

_AXIS = {"1": "x", "2": "y", "3": "z", "x": "x", "y": "y", "z": "z", "X": "x", "Y": "y", "Z": "z"}
_ORDINAL = {"first": "x", "second": "y", "third": "z", "1st": "x", "2nd": "y", "3rd": "z"}
_SYMBOL = r"\\?[A-Za-z]+(?:\s*_\s*(?:\{\s*\\?[A-Za-z0-9]+\s*\}|\\?[A-Za-z0-9]))?"
_MATRIX = r"(?:\\(?:mathbf|mathrm|boldsymbol|bm|mathsf)\s*\{\s*[A-Z]\s*\}|[A-Z])"
# a turn's argument in plain or sized brackets, R_3\left(\theta_1\right) as R_3(\theta_1)
_OPEN, _CLOSE = SIZED_OPEN + r"\(", SIZED_CLOSE + r"\)"
_TURN = (_MATRIX + r"\s*_\s*\{?\s*([123xyzXYZ])\s*\}?\s*" + _OPEN + r"\s*(" + _SYMBOL + r")\s*" + _CLOSE)
# a display read whole, before it is cut into statements: three turns set side by side with quads keep their order
_PRODUCT = re.compile(_TURN + SPACING + _TURN + SPACING + _TURN)
_SEQUENCE = re.compile(r"(?<![\w$\\-])([123xyzXYZ])\s*[-–]\s*([123xyzXYZ])\s*[-–]\s*([123xyzXYZ])(?![\w-])"
                       r"(?=[^.$]{0,40}?\b(?:Euler|Tait|Bryan|angles?|sequence|convention|rotations?)\b)")
_ABOUT = re.compile(r"\$\s*(" + _SYMBOL + r")\s*\$[^$.]{0,40}?\babout\s+(?:the\s+)?(?:(?:new|body|fixed|"
                    r"inertial|intermediate)\s+)?(first|second|third|1st|2nd|3rd|[xyzXYZ][- ]?)(?:\s*[- ]?axis)?",
                    re.I)
# "the order here is 3-2-1", "in the order 3-2-1": the word that makes it a sequence stands before it
_SEQUENCE_NAMED = re.compile(r"\b(?:order|sequence|convention)\b[^.$]{0,30}?(?<![\w$\\-])([123xyzXYZ])\s*[-–]\s*"
                             r"([123xyzXYZ])\s*[-–]\s*([123xyzXYZ])(?![\w-])", re.I)
# "about the $z_b$ axis through the heading angle $\psi$": the axis first, then the angle
_THROUGH = re.compile(r"\babout\s+(?:the\s+)?\$\s*([xyzXYZ])(?:\s*_\s*(?:\{[^{}$]*\}|\w))?\s*\$(?:\s*[- ]?axis)?"
                      r"[^$.]{0,30}?\bthrough\s+(?:the\s+|an?\s+)?(?:[A-Za-z]+\s+){0,2}\$\s*(" + _SYMBOL + r")\s*\$")
_SECTION = re.compile(r"^(?:#{1,6}\s|\s*\\(?:sub){0,2}section\*?\s*\{|\s*\\chapter\*?\s*\{)", re.M)


_GENERIC_TURN = (_MATRIX + r"\s*_\s*\{?\s*([a-wA-W])\s*\}?\s*" + _OPEN + r"\s*(" + _SYMBOL + r")\s*" + _CLOSE)
_GENERIC = re.compile(_GENERIC_TURN + SPACING + _GENERIC_TURN + SPACING + _GENERIC_TURN)


def general_form(latex: str) -> bool:
    """Is ``latex`` a product of three turns about axes named by letters, ``R_i(\\theta_1) R_j(\\theta_2)
    R_k(\\theta_3)``: the form every sequence takes, which states none and defines nothing?"""
    return _GENERIC.search(latex) is not None


@dataclass(frozen=True)
class Stated:
    """A convention a section of the text states: from ``line`` (the section's first line) on."""

    line: int
    convention: str
    angles: tuple | None
    """The angles' names in the order of the turns (``("theta_1", "theta_2", "theta_3")``, the
    spelling of the front matter's ``angles``), or None when the text names them nowhere near."""


def _name(tex: str) -> str:
    """A LaTeX angle (``\\theta_{1}``) as the front matter's ``angles`` spell it (``theta_1``)."""
    base, _, sub = re.sub(r"\s", "", tex).partition("_")
    sub = re.sub(r"[\\{}]", "", sub)
    return base.lstrip("\\") + ("_" + sub if sub else "")


def _sequence(axes) -> str | None:
    """Three axes as a sequence (``z-x-z``), when consecutive turns are about different axes."""
    if axes[0] == axes[1] or axes[1] == axes[2]:
        return None
    return "-".join(axes)


def _from_product(text: str, passive: frozenset = frozenset()):
    """(sequence, names) of the first product of three single-axis turns in ``text``, or None. A
    product of turns whose letter the text writes out as passive turns (``passive``, `_passive_letters`)
    turns first by its rightmost factor: its order is reversed."""
    for m in _PRODUCT.finditer(text):
        turns = [(_AXIS[m.group(k)], _name(m.group(k + 1))) for k in (1, 3, 5)]
        if _key(re.match(_MATRIX, m.group(0)).group(0)) in passive:
            turns = turns[::-1]
        seq = _sequence([a for a, _ in turns])
        names = tuple(n for _, n in turns)
        if seq and len(set(names)) == 3:
            return seq, names
    return None


_NAMED_TURN_DEF = re.compile(r"(" + _MATRIX + r")\s*_\s*\{?\s*[123xyzXYZ]\s*\}?\s*\(\s*" + _SYMBOL
                             + r"\s*\)\s*&?\s*=\s*\\begin\{[pb]matrix\}(.*?)\\end\{[pb]matrix\}", re.S)


def _passive_letters(maths) -> frozenset:
    """The letters of single-axis turns the text writes out with their axis and angle, ``C_X(\\phi) =
    \\begin{pmatrix}…``, every one of them as the passive turn (the transpose of the active one)."""
    kinds: dict[str, set] = {}
    for math in maths:
        for m in _NAMED_TURN_DEF.finditer(math):
            turn = elementary(m.group(2))
            if turn:
                kinds.setdefault(_key(m.group(1)), set()).add(turn[2])
    return frozenset(k for k, v in kinds.items() if v == {False})


_PMATRIX_DEF = re.compile(r"(" + _MATRIX + r"(?:\s*_\s*(?:\{[^{}]*\}|[0-9A-Za-z]))?)\s*=\s*\\begin\{[pb]matrix\}(.*?)"
                          r"\\end\{[pb]matrix\}", re.S)
_TRIG = re.compile(r"^(-?)\\(cos|sin)\s*\(?\s*(" + _SYMBOL + r")\s*\)?$")


def _key(tex: str) -> str:
    """A matrix's name without fonts and spaces: ``\\mbf{U}_1`` and ``U_{1}`` are one name."""
    t = re.sub(r"\\(?:mathbf|mathrm|boldsymbol|bm|mathsf|mbf)\s*", "", tex)
    return re.sub(r"[\s{}]", "", t)


def elementary(body: str):
    """(axis, angle, active) of a 3×3 matrix body (its ``&``/``\\\\`` entries) that is one turn about
    a coordinate axis, or None (see the module docstring)."""
    rows = [r for r in (re.split(r"\\\\", body)) if r.strip()]
    # a small space in a cell only sets it apart (``\\cos\\phi \\, \\end{pmatrix}``)
    cells = [[re.sub(ONE_SPACE + "+", " ", c).strip() for c in r.split("&")] for r in rows]
    if len(cells) != 3 or any(len(r) != 3 for r in cells):
        return None
    for k, axis in enumerate("xyz"):
        if cells[k][k] != "1" or any(cells[k][j] != "0" or cells[j][k] != "0" for j in range(3) if j != k):
            continue
        i, j = [m for m in range(3) if m != k]
        trig = [[_TRIG.match(cells[a][b]) for b in (i, j)] for a in (i, j)]
        if not all(all(row) for row in trig):
            return None
        angles = {_name(m.group(3)) for row in trig for m in row}
        kinds = [[(m.group(1), m.group(2)) for m in row] for row in trig]
        if len(angles) != 1 or kinds[0][0] != ("", "cos") or kinds[1][1] != ("", "cos"):
            return None
        # the cyclic order (y, z after x; z, x after y; x, y after z) decides which sign is the active turn's
        sign_up = kinds[0][1] if (i, j) != (0, 2) else kinds[1][0]
        if {kinds[0][1], kinds[1][0]} != {("-", "sin"), ("", "sin")}:
            return None
        return axis, angles.pop(), sign_up == ("-", "sin")
    return None


def _from_written_turns(with_cells, every) -> tuple | None:
    """(sequence, names) of a product of three matrices the section writes out as elementary turns:
    ``with_cells`` its normalised formulas that write cells (a turn written out is among them),
    ``every()`` all its formulas normalised, read for the product once three turns are found."""
    turns = {}
    for math in with_cells:
        for m in _PMATRIX_DEF.finditer(math):
            turn = elementary(m.group(2))
            if turn:
                turns[_key(m.group(1))] = turn
    if len(turns) < 3:
        return None
    name = r"(" + _MATRIX + r"(?:\s*_\s*(?:\{[^{}]*\}|[0-9A-Za-z]))?)"
    product = re.compile(_MATRIX + r"\s*&?\s*=" + SPACING + name + SPACING + name + SPACING + name + r"(?=\s*(?:\\nonumber|=|$|\\\\|&))")
    for math in every():
        for m in product.finditer(math):
            factors = [turns.get(_key(m.group(k))) for k in (1, 2, 3)]
            if not all(factors) or len({f[2] for f in factors}) != 1:
                continue
            if not factors[0][2]:                # passive turns: the first turn is the rightmost
                factors = factors[::-1]
            seq = _sequence([f[0] for f in factors])
            names = tuple(f[1] for f in factors)
            if seq and len(set(names)) == 3:
                return seq, names
    return None


def _from_prose(prose: str, math_free: str):
    """(sequence, names or None, where) of the first sequence the prose names, or None."""
    found = sorted([*_SEQUENCE.finditer(math_free), *_SEQUENCE_NAMED.finditer(math_free)], key=lambda m: m.end())
    for m in found:
        seq = _sequence([_AXIS[g.lower()] for g in m.groups()])
        if seq is None:
            continue
        # "a turn $\theta$ about the third axis, then $\alpha$ about the first, …": the names
        after = prose[m.end():m.end() + 400]
        after = after[:after.find("\n\n")] if "\n\n" in after else after
        turns = [(_name(t.group(1)), _ORDINAL.get(t.group(2).lower(), t.group(2)[:1].lower()))
                 for t in _ABOUT.finditer(after)][:3]
        through = [(t.start(), _name(t.group(2)), t.group(1).lower()) for t in _THROUGH.finditer(after)][:3]
        if len(turns) < 3 and len(through) == 3:
            turns = [(n, a) for _, n, a in through]
        names = None
        if len(turns) == 3 and "-".join(a for _, a in turns) == seq and len({n for n, _ in turns}) == 3:
            names = tuple(n for n, _ in turns)
        return seq, names, m.start()
    return None


def _writes_cells(latex: str, user: dict) -> bool:
    """Whether `source.normalize` of the formula can hold an ``&`` (the cells of a matrix or an
    alignment): only where the formula or one of the file's macros (``user``) writes one, for the
    walk prints back the characters it is given and the steps around it write none (an HTML entity,
    which `source.characters` decodes, starts with ``&`` itself)."""
    return "&" in latex or any("&" in m.body or "&" in (m.default or "") for m in user.values())


def stated(body: str) -> list[Stated]:
    """The conventions the text states, in order: one per section that states one (see the
    module docstring). ``body`` is the rendered text; lines are 1-based."""
    cuts = [0] + [m.start() for m in _SECTION.finditer(body)] + [len(body)]
    user = source.macros(body)
    # a turn written out is a matrix, its entries in cells (&): only formulas that write cells are
    # normalised to look for one (the walk of each formula is most of the cost of this reading)
    cells = lambda maths: [source.normalize(m, user) for m in maths if _writes_cells(m, user)]  # noqa: E731
    passive = _passive_letters(cells(m.group(0) for m in source.MATH.finditer(body)))
    out: list[Stated] = []
    for a, b in zip(cuts, cuts[1:]):
        section = body[a:b]
        if not section.strip():
            continue
        maths = [m.group(0) for m in source.MATH.finditer(section)]
        product = (next((p for p in (_from_product(m, passive) for m in maths) if p), None)
                   or _from_written_turns(cells(maths), lambda: [source.normalize(m, user) for m in maths]))
        math_free = source.MATH.sub(lambda m: " " * len(m.group(0)), section)
        prose = _from_prose(section, math_free)
        if product and (prose is None or prose[0] == product[0]):
            seq, names = product
        elif prose:
            seq, names = prose[0], prose[1]
        else:
            continue
        out.append(Stated(body.count("\n", 0, a) + 1, seq, names))
    return out
