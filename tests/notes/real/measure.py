"""The reader measured on the corpus of public texts: each text's displays against its truth table.

Every text here is a public text on rigid-body rotation that nobody on the project wrote, kept in
its native format: ``<slug>.md`` (Markdown), ``<slug>.tex`` (a LaTeX source) or ``<slug>.ipynb`` (a
Jupyter notebook, read through its Markdown cells): its displays exactly as the source writes them,
the prose between them in our own words, the source, commit and licence at its top (front matter,
a ``%`` comment block, or the notebook's first cell and metadata). A truth table's line numbers are
the text file's own lines. A display is a ``$$`` block, ``\\[…\\]``, a display environment, a fenced
``math`` block (or a MyST ``{math}`` directive), or a formula in inline math that a text sets as a list item or a paragraph of its own.
``<slug>.truth.toml`` is its truth table, one
verdict per display (``holds``, ``typo``, ``fails``, ``not a claim``) with the reason, derived by
``<slug>_truth.py``: a SymPy derivation in the text's own convention and names that never goes
through the reader. Every ``typo``/``fails`` row carries two hand checks.

A display's figures (three of them):

* **checkable**: its truth is not ``not a claim``;
* **checked**: the reader gave at least one statement of it a verdict (holds, typo, fails);
* **flagged**: the reader called at least one statement of it typo or fails. A slip (truth typo
  or fails) flagged is found; a display that holds flagged is a false alarm.

``python tests/notes/real/measure.py`` prints the table (Markdown) for docs/verify.md.
"""
from __future__ import annotations

import sys
import tomllib
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
FORMATS = (".md", ".tex", ".ipynb")
CHECKED = {"holds", "typo", "fails"}
SLIPS = {"typo", "fails"}


def texts() -> list[str]:
    """The slugs of the corpus, sorted."""
    return sorted(p.name[:-len(".truth.toml")] for p in HERE.glob("*.truth.toml"))


def source(slug: str) -> Path:
    """The text of ``slug``, in whichever of the formats it is kept."""
    found = [HERE / f"{slug}{ext}" for ext in FORMATS if (HERE / f"{slug}{ext}").exists()]
    if len(found) != 1:
        raise FileNotFoundError(f"{slug}: expected one text in {FORMATS}, found {len(found)}")
    return found[0]


def truth(slug: str) -> list[dict]:
    """The truth table's rows, in the order of the text."""
    with open(HERE / f"{slug}.truth.toml", "rb") as fh:
        return tomllib.load(fh)["display"]


@dataclass
class Figures:
    """One text's figures (counts of displays)."""

    slug: str
    displays: int
    checkable: int
    checked: int
    slips: int
    slips_flagged: int
    holds: int
    holds_flagged: int
    missed: list            # lines of slips not flagged
    false_alarms: list      # lines of correct displays flagged

    @property
    def checked_share(self) -> float:
        return self.checked / self.checkable if self.checkable else 1.0

    @property
    def found_share(self) -> float:
        return self.slips_flagged / self.slips if self.slips else 1.0

    @property
    def false_share(self) -> float:
        return self.holds_flagged / self.holds if self.holds else 0.0


def measure(slug: str, claims) -> Figures:
    """The figures of one text from the reader's claims (`derive.lecture.notes_check.Claim`)."""
    by_line: dict[int, list] = {}
    for c in claims:
        by_line.setdefault(c.line, []).append(c.verdict)
    rows = truth(slug)
    checkable = [r for r in rows if r["verdict"] != "not a claim"]
    checked = [r for r in checkable if CHECKED & set(by_line.get(r["line"], ()))]
    slips = [r for r in rows if r["verdict"] in SLIPS]
    holds = [r for r in rows if r["verdict"] == "holds"]
    flagged = lambda r: bool(SLIPS & set(by_line.get(r["line"], ())))  # noqa: E731
    return Figures(slug, len(rows), len(checkable), len(checked), len(slips),
                   sum(map(flagged, slips)), len(holds), sum(map(flagged, holds)),
                   [r["line"] for r in slips if not flagged(r)], [r["line"] for r in holds if flagged(r)])


def table(figures: list[Figures]) -> str:
    """The figures as a Markdown table, with a total row."""
    head = ("| text | displays | checkable | checked | slips | slips flagged | correct flagged |\n"
            "|---|---|---|---|---|---|---|\n")
    rows = []
    for f in figures + [Figures("**all**", *(sum(getattr(f, k) for f in figures) for k in
                                             ("displays", "checkable", "checked", "slips", "slips_flagged",
                                              "holds", "holds_flagged")), [], [])]:
        rows.append(f"| {f.slug} | {f.displays} | {f.checkable} | {f.checked} ({f.checked_share:.0%}) | "
                    f"{f.slips} | {f.slips_flagged} | {f.holds_flagged} of {f.holds} |")
    return head + "\n".join(rows) + "\n"


if __name__ == "__main__":
    sys.path.insert(0, str(HERE.parents[2]))
    from derive.lecture import notes_check

    out = [measure(s, notes_check.check_notes(source(s))) for s in texts()]
    print(table(out))
    for f in out:
        if f.missed or f.false_alarms:
            print(f"{f.slug}: slips missed at lines {f.missed}; correct displays flagged at {f.false_alarms}")
