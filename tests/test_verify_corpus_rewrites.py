"""The corpus of public texts read again under rewrites that keep every display's meaning.

A text nobody here wrote spells its formulas its own way. Each rewrite below changes every display
of every corpus text kept as Markdown or LaTeX (tests/notes/real) in one way authors write the same
formula (``\\left( … \\right)`` around each round bracket, an upright ``\\mathrm{d}`` in a
derivative's fraction, ``\\dfrac``, braces around an accent's argument, a spaced relation
``\\;=\\;``, Greek letters in Unicode) and keeps the text's lines where they are. Against the text
read as written, per display of its truth table:

* no display that holds is newly flagged (a false alarm);
* no slip flagged as written goes unflagged;
* no display checked as written goes unchecked.

Each rewrite reads the whole corpus again (about as long as `tests/test_verify_corpus.py`), so the
module runs in ``make test-slow``.
"""
import re
import sys
from pathlib import Path

import pytest

import kept_readings as kept

REAL = Path(__file__).resolve().parent / "notes" / "real"
sys.path.insert(0, str(REAL))
import measure  # noqa: E402  (the corpus's own measuring code, beside its texts)

pytestmark = pytest.mark.slow

# A display: $$ … $$, \[ … \] or a display environment (its starred form too).
_DISPLAY = re.compile(r"\$\$.*?\$\$|\\\[.*?\\\]|\\begin\{(equation|align|eqnarray|gather|multline)\*?\}.*?\\end\{\1\*?\}",
                      re.S)
_GREEK = {"omega": "ω", "theta": "θ", "psi": "ψ", "Omega": "Ω", "varphi": "φ", "alpha": "α", "lambda": "λ"}


def _left_right(latex: str) -> str:
    """Every round bracket sized with ``\\left``/``\\right`` (a display whose brackets do not pair,
    or that sizes some already, is left as written)."""
    if latex.count("(") != latex.count(")") or re.search(r"\\(left|right|[Bb]igg?[lr]?)\b", latex):
        return latex
    return latex.replace("(", "\\left(").replace(")", "\\right)")


REWRITES = {
    "left-right brackets": _left_right,
    "upright d": lambda latex: re.sub(r"\\frac\{d([^{}]*)\}\{d(?=[ \\A-Za-z])", r"\\frac{\\mathrm{d}\1}{\\mathrm{d}", latex),
    "dfrac": lambda latex: re.sub(r"\\frac(?![A-Za-z])", r"\\dfrac", latex),
    "accent argument braced": lambda latex: re.sub(r"\\(dot|ddot)\s*(\\[A-Za-z]+|[A-Za-z])(?![A-Za-z])", r"\\\1{\2}", latex),
    "spaced relation": lambda latex: re.sub(r"(?<![<>\\!:&])=(?!=)", r"\\;=\\;", latex),
    "unicode greek": lambda latex: re.sub(r"(?<![A-Za-z])\\(omega|theta|psi|Omega|varphi|alpha|lambda)(?![A-Za-z])[ \t]?",
                                          lambda m: _GREEK[m.group(1)], latex),
}
TEXTS = [slug for slug in measure.texts() if measure.source(slug).suffix in (".md", ".tex")]


def _by_line(claims) -> dict[int, set]:
    out: dict[int, set] = {}
    for c in claims:
        out.setdefault(c.line, set()).add(c.verdict)
    return out


def _worse(slug: str, before: dict, after: dict) -> list[str]:
    """The displays of ``slug`` the rewrite made worse, each with its verdicts before and after."""
    out = []
    for row in measure.truth(slug):
        truth, line = row["verdict"], row["line"]
        was, now = before.get(line, set()), after.get(line, set())
        if truth == "not a claim" or was == now:
            continue
        flagged_was, flagged_now = bool(was & measure.SLIPS), bool(now & measure.SLIPS)
        if (truth == "holds" and flagged_now and not flagged_was) or (truth in measure.SLIPS and flagged_was and not flagged_now) \
                or (was & measure.CHECKED and not now & measure.CHECKED):
            out.append(f"{slug}:{line} {sorted(was)} -> {sorted(now)}")
    return out


@pytest.mark.parametrize("rewrite", list(REWRITES), ids=lambda name: name.replace(" ", "-"))
def test_a_rewrite_that_keeps_the_meaning_keeps_every_verdict_or_reads_more(rewrite, tmp_path):
    change, worse, rewritten = REWRITES[rewrite], [], 0
    for slug in TEXTS:
        path = measure.source(slug)
        text = path.read_text(encoding="utf-8")
        new = _DISPLAY.sub(lambda m: change(m.group(0)), text)
        if new == text:
            continue
        assert new.count("\n") == text.count("\n"), slug
        rewritten += 1
        (tmp_path / path.name).write_text(new, encoding="utf-8")
        worse += _worse(slug, _by_line(kept.check_notes(path)), _by_line(kept.check_notes(tmp_path / path.name)))
    assert rewritten, f"the rewrite {rewrite!r} changed no text"
    assert worse == [], worse
