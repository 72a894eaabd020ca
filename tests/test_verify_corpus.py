"""The notes reader measured on public texts nobody on the project wrote (tests/notes/real).

Each text comes with a truth table made without the reader (its own SymPy derivation in
``<slug>_truth.py``). The figures per text are the three of docs/verify.md: displays checked of
the checkable ones, slips flagged of the slips, correct displays flagged of those that hold.
The targets are 70 %, 70 % and at most 5 %; where a text is short of one today, its row in
`SHORT` says so and the test is a strict expected failure, so a change that reaches the target
turns it red until the row is removed. `FLOOR` holds the corpus's totals: no change may lower
what the reader checks and finds, or raise its false alarms.
"""
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

REAL = Path(__file__).resolve().parent / "notes" / "real"
sys.path.insert(0, str(REAL))
import measure  # noqa: E402  (the corpus's own measuring code, beside its texts)

TEXTS = measure.texts()
TARGETS = {"checked": 0.70, "found": 0.70}
FALSE_ALARMS = 0.05

SHORT = {
    # (text, target): why the reader is short of it today
}

FLOOR = {"checked": 264, "slips_flagged": 29, "holds_flagged": 0}
"""The corpus's totals when the floor was last raised (``python tests/notes/real/measure.py``)."""


def _figures(notes_reading, slug):
    """The reader's figures on one text, read once per test run (every test process shares it) and
    kept between runs while the text and derive's source stay the same (``notes_reading``)."""
    return measure.measure(slug, notes_reading(REAL / f"{slug}.md"))


def test_the_corpus_has_a_dozen_texts_of_the_kinds_the_reader_must_meet():
    assert len(TEXTS) >= 12
    heads = [(REAL / f"{s}.md").read_text().split("---")[1] for s in TEXTS]
    assert sum("convention: z-x-z" in h for h in heads) >= 4
    assert any(re.search(r"convention: z-y-x", h) for h in heads)


@pytest.mark.parametrize("slug", TEXTS)
def test_a_text_names_its_source_commit_and_licence(slug):
    head = (REAL / f"{slug}.md").read_text().split("---")[1]
    assert re.search(r"^source: .+", head, flags=re.M)
    assert re.search(r"^licence: .+", head, flags=re.M)
    assert "symbols:" not in head          # the reader learns the text's names itself


_DISPLAY = re.compile(r"^```math\n.+?^```|\$\$.+?\$\$|\\\[.+?\\\]|\\begin\{(equation|align|eqnarray|gather|multline|subnumcases|numcases)(\*?)\}.+?"
                      r"\\end\{\1\2\}", re.S | re.M)
_OPENING = re.compile(r"^\s*(```math|\$\$|\\\[|\\begin\{(equation|align|eqnarray|gather|multline|subnumcases|numcases)\*?\})")


@pytest.mark.parametrize("slug", TEXTS)
def test_a_truth_table_has_one_row_per_display_with_its_reasons(slug):
    lines = (REAL / f"{slug}.md").read_text().split("\n")
    rows = measure.truth(slug)
    for row in rows:
        assert _OPENING.match(lines[row["line"] - 1]), (slug, row["line"])
        assert row["verdict"] in ("holds", "typo", "fails", "not a claim")
        assert row["why"].strip()
        if row["verdict"] in ("typo", "fails"):     # every slip checked twice by hand
            assert row.get("hand_check_1", "").strip() and row.get("hand_check_2", "").strip()
        if row["verdict"] == "typo":
            assert row.get("correction", "").strip()
    text = "\n".join(lines)
    displays = {text.count("\n", 0, m.start()) + 1 for m in _DISPLAY.finditer(text)}
    assert {r["line"] for r in rows} == displays


@pytest.mark.parametrize("slug", TEXTS)
def test_a_truth_script_does_not_use_the_reader(slug):
    source = (REAL / f"{slug}_truth.py").read_text()
    assert not re.search(r"^\s*(from|import)\s+derive\b", source, flags=re.M)


@pytest.mark.slow
@pytest.mark.parametrize("slug", TEXTS)
def test_a_truth_script_derives_its_table(slug):
    out = subprocess.run([sys.executable, str(REAL / f"{slug}_truth.py")], capture_output=True, text=True,
                         timeout=300, cwd=REAL)
    assert out.returncode == 0, out.stdout[-2000:] + out.stderr[-2000:]


def _share(f, target):
    return {"checked": f.checked_share, "found": f.found_share, "false": f.false_share}[target]


@pytest.mark.parametrize("target", ["checked", "found", "false"])
@pytest.mark.parametrize("slug", TEXTS)
def test_the_reader_meets_its_targets_on_a_text(notes_reading, slug, target, request):
    if (slug, target) in SHORT:
        request.applymarker(pytest.mark.xfail(reason=SHORT[(slug, target)], strict=True))
    f = _figures(notes_reading, slug)
    if target == "false":
        assert f.false_share <= FALSE_ALARMS, (f.holds_flagged, f.holds, f.false_alarms)
    else:
        assert _share(f, target) >= TARGETS[target], (f.checked, f.checkable, f.slips_flagged, f.slips, f.missed)


def test_the_corpus_totals_do_not_fall(notes_reading):
    figures = {slug: _figures(notes_reading, slug) for slug in TEXTS}
    total = {k: sum(getattr(f, k) for f in figures.values()) for k in FLOOR}
    print("\n" + measure.table(list(figures.values())))
    assert total["checked"] >= FLOOR["checked"]
    assert total["slips_flagged"] >= FLOOR["slips_flagged"]
    assert total["holds_flagged"] <= FLOOR["holds_flagged"]
