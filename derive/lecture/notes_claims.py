"""The rows ``derive verify NOTES.md`` reports: one `Claim` per formula (the JSON row of the
contract), their summary, the exit status and the text, Markdown and JSON renderings.

May import: the standard library.
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field

VERDICTS = ("holds", "typo", "fails", "unchecked")


@dataclass
class Claim:
    """One checked (or not) formula: the JSON row of the contract."""

    line: int
    latex: str
    kind: str
    verdict: str
    correction: str | None = None
    why: str = ""
    assumes: list = field(default_factory=list)    # what it holds under: stated (with where) or not
    # holds by the text's own earlier equation whatever its names mean, so it confirms no reading of them
    self_consistent: bool = field(default=False, compare=False)
    # judged without the Euler angles' sequence (the text's own coordinate): alike in every sequence
    sequence_free: bool = field(default=False, compare=False)

    def as_dict(self) -> dict:
        return {"line": self.line, "latex": self.latex, "kind": self.kind, "verdict": self.verdict,
                "correction": self.correction, "why": self.why, "assumes": list(self.assumes)}


def summary(claims) -> dict:
    out = {v: sum(c.verdict == v for c in claims) for v in VERDICTS}
    out["claims"] = len(claims)
    out["checked"] = sum(c.verdict != "unchecked" for c in claims)
    return out


def exit_status(claims) -> int:
    """0 when every checked claim holds, 1 when any is a typo or fails."""
    return 1 if any(c.verdict in ("typo", "fails") for c in claims) else 0


def render(claims, fmt: str = "text", path: str = "") -> str:
    """The report: ``text`` (one line per claim, indented why/correction), ``markdown`` (a table)
    or ``json`` (the contract's shape)."""
    if fmt == "json":
        return json.dumps({"claims": [c.as_dict() for c in claims], "summary": summary(claims)}, ensure_ascii=False, indent=1) + "\n"
    s = summary(claims)
    total = f"{s['claims']} claims ({s['checked']} checked): " + ", ".join(f"{s[v]} {v}" for v in VERDICTS)
    if fmt == "markdown":
        lines = ["| line | kind | verdict | formula | why |", "|---|---|---|---|---|"]
        for c in claims:
            verdict = f"typo → ${c.correction}$" if c.verdict == "typo" and c.correction else f"**{c.verdict}**"
            cells = (str(c.line), c.kind, verdict, f"${' '.join(c.latex.split())}$", c.why)
            lines.append("| " + " | ".join(x.replace("|", r"\|").replace("\n", " ") for x in cells) + " |")
        return "\n".join(lines) + f"\n\n{total}\n"
    if fmt != "text":
        raise ValueError(f"unknown format {fmt!r} (text, markdown or json)")
    out = []
    for c in claims:
        out.append(f"{path}:{c.line}: {c.verdict:<9} {c.kind}: {' '.join(c.latex.split())[:100]}")
        if c.correction:
            out.append(f"    corrected: {c.correction}")
        if c.why:
            out.append(f"    why: {c.why}")
    out.append(total)
    return "\n".join(out) + "\n"
