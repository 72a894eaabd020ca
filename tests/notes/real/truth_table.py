"""The check every truth script ends with: its own derivation's verdicts against its table.

A truth script fills ``CHECKS`` (display line → the claim holds) from its own SymPy derivation and
lists ``LINES``, the lines of its displays; run as a program, it compares them with
``<slug>.truth.toml`` beside it and exits 1 on any disagreement. Shared by the scripts so that each
holds only its derivation; it reads no part of the reader (nothing from ``derive``).
"""
from __future__ import annotations

import json
import pathlib
import tomllib

import mpmath
import sympy as sp
from sympy.core.function import AppliedUndef


def compare(script: str, checks: dict, lines: list) -> int:
    """Print one line per display (computed verdict, the table's, OK or MISMATCH); the exit status:
    0 when every row agrees (a computed slip agrees with ``typo`` and ``fails``), else 1."""
    path = pathlib.Path(script)
    table = tomllib.loads(path.with_name(path.name.removesuffix("_truth.py") + ".truth.toml")
                          .read_text())["display"]
    assert [r["line"] for r in table] == lines
    bad = 0
    for row in table:
        key = row["line"]
        comp = "not a claim" if key not in checks else ("holds" if checks[key] else "slip")
        want = row["verdict"]
        agree = comp == want or (comp == "slip" and want in ("typo", "fails"))
        print(f"line {key:4d} computed={comp:11s} toml={want:11s} {'OK' if agree else 'MISMATCH'}")
        bad += not agree
    return 1 if bad else 0


def write_table(script: str, rows: dict, checks: dict, lines: list) -> None:
    """Write ``<slug>.truth.toml`` from ``rows`` (display line → (verdict, why[, correction], hand
    check 1, hand check 2)), once each row agrees with the script's own derivation (``checks``)."""
    path = pathlib.Path(script)
    text = _text_lines(path.with_name(path.name.removesuffix("_truth.py")))
    out = []
    for ln in lines:
        row = rows[ln]
        got = "not a claim" if ln not in checks else ("holds" if checks[ln] else "slip")
        assert got == row[0] or (got == "slip" and row[0] in ("typo", "fails")), (ln, got, row[0])
        start = "".join(text[ln - 1:ln + 1]).strip()[:22]
        s = f"[[display]]\nline = {ln}\nstart = {json.dumps(start)}\nverdict = {json.dumps(row[0])}\nwhy = {json.dumps(row[1])}\n"
        if row[0] in ("typo", "fails"):
            if row[0] == "typo":
                s += f"correction = {json.dumps(row[2])}\n"
            s += f"hand_check_1 = {json.dumps(row[3])}\nhand_check_2 = {json.dumps(row[4])}\n"
        out.append(s)
    path.with_name(path.name.removesuffix("_truth.py") + ".truth.toml").write_text("\n".join(out))


def _text_lines(stem: pathlib.Path) -> list:
    """The text's lines, each with its line break; a notebook's line holding a piece of a cell's
    source gives that piece, decoded, so that a display's opening reads as the notebook writes it
    (its other lines, the JSON around the pieces, give nothing)."""
    path = next(stem.with_name(stem.name + ext) for ext in (".tex", ".md", ".ipynb")
                if stem.with_name(stem.name + ext).exists())
    lines = [ln + "\n" for ln in path.read_text().split("\n")]
    if path.suffix != ".ipynb":
        return lines
    out = []
    for ln in lines:
        piece = ln.strip().removesuffix(",")
        try:
            piece = json.loads(piece) if piece.startswith('"') else ""
        except json.JSONDecodeError:
            piece = ""
        out.append(piece if isinstance(piece, str) else "")
    return out


def Rx(a):
    """The active turn by ``a`` about the x axis (right-handed): the elementary rotation the scripts build from."""
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])


def Ry(a):
    """The active turn by ``a`` about the y axis (right-handed)."""
    return sp.Matrix([[sp.cos(a), 0, sp.sin(a)], [0, 1, 0], [-sp.sin(a), 0, sp.cos(a)]])


def Rz(a):
    """The active turn by ``a`` about the z axis (right-handed)."""
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])


def zero(expr) -> bool:
    """``expr`` (a scalar or a matrix) simplifies to zero."""
    m = expr if hasattr(expr, "shape") else sp.Matrix([expr])
    return sp.simplify(m) == sp.zeros(*m.shape)


def numeric_zero(expr, t) -> bool:
    """``expr`` (a scalar or a matrix) vanishes at three sample points once every unknown function of
    ``t`` is given a concrete smooth form and every other symbol a rational value (an identity holds
    for all of them, so a slip shows), evaluated with 30 digits: for identities whose simplification
    is too slow."""
    m = expr if hasattr(expr, "shape") else sp.Matrix([expr])
    funcs = sorted(m.atoms(AppliedUndef), key=str)
    m = m.subs({g: sp.sin((k + 2) * t / 3) + sp.Rational(k + 1, 5) * t ** 2 + k for k, g in enumerate(funcs)}).doit()
    syms = sorted(m.free_symbols - {t}, key=str)
    f = sp.lambdify([t, *syms], list(m), "mpmath")
    with mpmath.workdps(30):
        for shift, t0 in enumerate(("0.31", "0.77", "1.4")):
            vals = [mpmath.mpf(3 + 2 * i + shift) / (7 + i) for i in range(len(syms))]
            if max(abs(x) for x in f(mpmath.mpf(t0), *vals)) > mpmath.mpf(10) ** -20:
                return False
    return True


def notebook_display_lines(path) -> list:
    """The notebook file's line of each display's first row: a piece of a cell's source opening
    ``$$``, ``align`` or ``gather`` (its cells in order)."""
    text = pathlib.Path(path).read_text()
    lines, offset, inside = [], 0, None
    for cell in json.loads(text)['cells']:
        for piece in cell['source']:
            at = text.find(json.dumps(piece, ensure_ascii=False), offset)
            offset = at + 1
            st = piece.strip()
            if inside is None and (st.startswith('$$') or st.startswith('\\begin{align') or st.startswith('\\begin{gather')):
                lines.append(text.count('\n', 0, at) + 1)
                closed = st.startswith('$$') and st.count('$$') >= 2
                inside = None if closed else ('$$' if st.startswith('$$') else '\\end{')
            elif inside is not None and inside in st:
                inside = None
    return lines
