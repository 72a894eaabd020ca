"""Names a text gives its symbols in its formulas rather than in words.

Takes: the rendered text (`derive.lecture.source.rendered`) and the `Names` the prose gave
(`derive.lecture.names.learn`). Gives: `learn`, which adds, for the whole text and only where
neither the prose nor the front matter named the symbol:

* the mass from a weight: a plain ``m`` or ``M`` written right before the gravitational
  acceleration ``g`` (``mgd``, ``M g l``, ``m\\,g``) in any formula is the body's mass, as every
  heavy-top text writes its potential m g z and its torque m g d sin θ;
* the axial moment from the symmetric pair: a text that states its moments about the body's x and
  y axes equal, ``I_x=I_y``, and writes the third, ``I_z``, has told which axis is the symmetry
  axis — ``I_z`` is the axial moment, the same about the centre of mass and about a pivot on that
  axis. The equal pair is not bound (the transverse moment depends on the point it is taken about,
  ``I_O = I_x + md^2``), nor is a moment the text gives a formula or a value for (``I_z = \frac{1}{2}
  m R^2``: its own quantity, checked as it defines it). Numbered moments need no rule: I₃ is the
  axial one already;
* the principal moments from a diagonal inertia matrix: a display that sets a symbol equal to a
  three-by-three matrix whose off-diagonal entries are all 0 and whose diagonal holds one letter
  numbered 1, 2, 3 (``\\boldsymbol{J} = [J_1, 0, 0; 0, J_2, 0; 0, 0, J_3]``), after prose that calls
  it the moment of inertia, the inertia tensor or its principal axes, names those three the
  principal moments I₁, I₂, I₃ — unless the text gives one of them a formula of its own.

May import: :mod:`derive.lecture.names`, :mod:`derive.lecture.latex_spaces`, :mod:`derive.lecture.latex_spellings`.
"""
from __future__ import annotations

import re

from derive.lecture import names as nm
from derive.lecture.latex_spaces import SPACE
from derive.lecture.latex_spellings import SIZED_OPEN

_MATH = re.compile(r"\$\$(.+?)\$\$|(?<![\\$])\$([^$]+?)(?<!\\)\$|\\\[(.+?)\\\]|"
                   r"\\begin\{(equation|align|eqnarray|gather|multline)\*?\}(.+?)\\end\{\4\*?\}", re.S)
_WEIGHT = re.compile(r"(?<![\\A-Za-z_^])(?<!_\{)(?<!\^\{)([mM])" + SPACE + r"(?:\\cdot" + SPACE + r")?g(?![a-z]{2})")
_PAIR = re.compile(r"(?<![\\A-Za-z])([IJ])_\{?([xy])\}?\s*=\s*\1_\{?([xy])\}?(?![\w{^])")


_SYMBOL = r"[A-Za-z]_\{?[A-Za-z0-9]+\}?"
_SHIFT = re.compile(r"(?:^|\\\\|[,;&])\s*(" + _SYMBOL + r")\s*&?\s*=\s*(" + _SYMBOL + r")\s*\+\s*([mM])\s*([a-z])\s*\^\s*\{?2\}?"
                    r"\s*(?=$|[,;.]|\\\\)")
# the matrix in brackets sized by \\left or by hand (\\bigl[), or plain, or none
_MATRIX = re.compile(r"=\s*" + SIZED_OPEN + r"[\[(]?\s*\\begin\{(array|[bpvBV]?matrix)\}(?:\{[lcr|]*\})?(.+?)\\end\{\1\}",
                     re.S)
_INERTIA = re.compile(r"moments? of inertia|inertia (?:tensor|matrix)|tensor of inertia|principal ax[ie]s",
                      re.I)
_PRINCIPAL = ("transverse moment", "second moment", "axial moment")
_NUMBER = re.compile(r"=\s*-?\d+(?:\.\d+)?\s*(?:$|[,;]|\\\\)")


def _formulas(body: str):
    """(line, LaTeX) of every formula of the text, inline or displayed."""
    for m in _MATH.finditer(body):
        tex = next(g for g in (m.group(1), m.group(2), m.group(3), m.group(5)) if g is not None)
        yield body.count("\n", 0, m.start()) + 1, tex


def _unnamed(names: nm.Names, key) -> bool:
    return key not in names.symbols and (key[0], "plain" if not key[1] else "vector") not in names.letters


def learn(names: nm.Names, body: str) -> None:
    """Add to ``names`` the names the text's formulas give (see the module docstring)."""
    formulas = list(_formulas(body))
    for line, tex in formulas:
        for m in _WEIGHT.finditer(tex):
            key = (m.group(1), "")
            if _unnamed(names, key):
                nm._put(names.symbols, key, "mass", False)
                names.where[key] = f"line {line}"
    _axial_moment(names, formulas)
    _pivot_moments(names, formulas)
    _diagonal_moments(names, body)


def _diagonal(cells) -> list:
    """The three diagonal atoms of a 3×3 matrix whose other entries are 0, one letter numbered 1, 2, 3; else []."""
    if len(cells) != 3 or any(len(row) != 3 for row in cells):
        return []
    if any(cells[i][j].strip() != "0" for i in range(3) for j in range(3) if i != j):
        return []
    atoms = [nm._atoms(cells[i][i].strip()) for i in range(3)]
    if any(len(a) != 1 for a in atoms):
        return []
    atoms = [a[0] for a in atoms]
    if len({a.base for a in atoms}) != 1 or [a.sub for a in atoms] != ["1", "2", "3"] or any(a.bold for a in atoms):
        return []
    return atoms


def _diagonal_moments(names: nm.Names, body: str) -> None:
    """A diagonal inertia matrix of J_1, J_2, J_3: the principal moments (see the module docstring)."""
    formulas = list(_MATH.finditer(body))
    for k, m in enumerate(formulas):
        tex = next(g for g in (m.group(1), m.group(3), m.group(5)) if g is not None) if m.group(2) is None else None
        found = _MATRIX.search(tex) if tex else None
        if found is None:
            continue
        # the prose right before the display says what the matrix is (a rotation matrix can be diagonal too)
        before = body[formulas[k - 1].end() if k else 0:m.start()]
        rows = [r for r in re.split(r"\\\\", found.group(2)) if r.strip()]
        atoms = _diagonal([r.split("&") for r in rows])
        if not atoms or not _INERTIA.search(before):
            continue
        keys = [(a.base, a.sub) for a in atoms]
        heads = [rf"(?:^|\\\\|[,;&}}\n])\s*{re.escape(a.base)}_\{{?{a.sub}\}}?\s*&?\s*=" for a in atoms]
        if any(re.search(h, f.group(0).strip("$")) for h in heads for f in formulas):
            continue            # a moment the text gives a formula of its own is its own quantity
        if all(_unnamed(names, key) for key in keys):
            for key, meaning in zip(keys, _PRINCIPAL):
                nm._put(names.symbols, key, meaning, False)
                names.where[key] = f"line {body.count(chr(10), 0, m.start()) + 1}"


def _axial_moment(names: nm.Names, formulas) -> None:
    """``I_x=I_y`` beside ``I_z``: the axial moment (see the module docstring)."""
    pairs = {(m.group(1), frozenset((m.group(2), m.group(3))), line)
             for line, tex in formulas for m in _PAIR.finditer(tex) if m.group(2) != m.group(3)}
    if len({(letter, pair) for letter, pair, _ in pairs}) != 1:
        return                      # no pair, or pairs that disagree: no axis is told
    letter, _, line = next(iter(pairs))
    third = rf"(?<![\\A-Za-z]){letter}_\{{?z\}}?(?![\w{{])"
    written = any(re.search(third, tex) for _, tex in formulas)
    # a moment the text gives a formula or a value for is its own quantity (I_z = ½ m R² = 0.0405)
    own = any(re.search(r"(?:^|\\\\|[,;&])\s*" + third + r"\s*&?\s*=", tex) for _, tex in formulas)
    key = (letter, "z")
    if written and not own and _unnamed(names, key):
        nm._put(names.symbols, key, "axial moment", False)
        names.where[key] = f"line {line}"


def _pivot_moments(names: nm.Names, formulas) -> None:
    """``I_O = I_x + md^2``: the moment about the pivot (see the module docstring)."""
    for line, tex in formulas:
        for m in _SHIFT.finditer(tex):
            moment, mass, arm = nm._atoms(m.group(1)), m.group(3), m.group(4)
            if len(moment) != 1 or names.symbols.get((mass, "")) != "mass" or \
                    names.symbols.get((arm, "")) != "centre-of-mass distance":
                continue
            key = (moment[0].base, moment[0].sub)
            head = rf"(?:^|\\\\|[,;&])\s*{re.escape(m.group(1))}\s*&?\s*="
            valued = any(re.search(head, t) and _NUMBER.search(t) for _, t in formulas)
            if not valued and _unnamed(names, key):
                nm._put(names.symbols, key, "transverse moment", False)
                names.where[key] = f"line {line}"
