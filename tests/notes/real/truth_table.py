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

import sympy as sp


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
    stem = path.name.removesuffix("_truth.py")
    # the text is kept in one of the corpus formats (measure.FORMATS)
    found = [path.with_name(stem + ext) for ext in (".tex", ".md", ".ipynb") if path.with_name(stem + ext).exists()]
    text = found[0].read_text().split("\n")
    out = []
    for ln in lines:
        row = rows[ln]
        got = "not a claim" if ln not in checks else ("holds" if checks[ln] else "slip")
        assert got == row[0] or (got == "slip" and row[0] in ("typo", "fails")), (ln, got, row[0])
        start = "\n".join(text[ln - 1:ln + 1]).strip()[:22]
        s = f"[[display]]\nline = {ln}\nstart = {json.dumps(start)}\nverdict = {json.dumps(row[0])}\nwhy = {json.dumps(row[1])}\n"
        if row[0] in ("typo", "fails"):
            if row[0] == "typo":
                s += f"correction = {json.dumps(row[2])}\n"
            s += f"hand_check_1 = {json.dumps(row[3])}\nhand_check_2 = {json.dumps(row[4])}\n"
        out.append(s)
    path.with_name(path.name.removesuffix("_truth.py") + ".truth.toml").write_text("\n".join(out))


def zero(expr) -> bool:
    """``expr`` (a scalar or a matrix) simplifies to zero."""
    m = expr if hasattr(expr, "shape") else sp.Matrix([expr])
    return sp.simplify(m) == sp.zeros(*m.shape)


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
