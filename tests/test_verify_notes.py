"""`derive verify NOTES.md`: the reader, the LaTeX layer and the verdicts.

The lecture's own notes (read through the repository's parent, skipped when absent) are checked
against the curated table of `derive.lecture.claims`, which stays the reference: every typo and
failure it finds must be found by reading the file, and the verdicts must agree on the claims
both check. Our own notes (tests/notes/) hold as written; one planted error at a time is caught.
"""
import json
import os
import re
from pathlib import Path

import pytest

import kept_readings
from derive.lecture import latex as lx
from derive.lecture import notes as nt
from derive.lecture import notes_check as nc
from derive.lecture.latex_spellings import PRIME_SUPERSCRIPT

HERE = Path(__file__).parent
LECTURE = Path(os.environ.get("DERIVE_NOTES")
               or Path(__file__).resolve().parents[2] / "shared" / "notes" / "lecture26-rigid-body.md")
OWN = HERE / "notes" / "rigid-body-zyz.md"
GOLDSTEIN = HERE / "notes" / "rigid-body-zxz.md"
needs_lecture = pytest.mark.skipif(not LECTURE.exists(), reason="the lecture's notes file is not next to the repository")


# ---- the reader -------------------------------------------------------------------------------
def test_reader_lines_displays_and_assumptions():
    text = ("---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Top\n\nIf $I_1 = I_2$ then\n\n"
            "$$T = \\frac{1}{2} I_3 \\dot\\psi^2$$\n\n\\[\n E = 1\n\\]\n## Next\ntext $a = b$ here\n")
    notes = nt.parse_notes(text)
    assert notes.convention == "z-x-z" and notes.angles == ("phi", "theta", "psi")
    kinds = [(i.kind, i.line) for i in notes.items]
    assert kinds == [("heading", 5), ("assumption", 7), ("display", 9), ("display", 11), ("heading", 14), ("inline", 15)]


@pytest.mark.parametrize("text, key", [
    ("---\nconvention: x-x-z\n---\n", "convention"),
    ("---\nangles: [a, b]\n---\n", "angles"),
    ("---\nconvetion: z-x-z\n---\n", "convetion"),
    ("---\nangle: [a, b, c]\n---\n", "angle"),
    ("---\nconvention: z-y-z\n", "front matter"),
])
def test_a_bad_or_misspelt_front_matter_key_of_derives_is_refused_naming_it(text, key):
    with pytest.raises(nt.SceneError, match=f": {key}: "):
        nt.parse_notes(text, "n.md")


def test_front_matter_keys_of_the_tools_that_publish_a_text_are_skipped_unread():
    text = ("---\njupytext:\n  text_representation:\n    extension: .md\n    format_name: myst\nkernelspec:\n"
            "  display_name: Python 3\n  name: python3\ntags:\n- rigid body\n- tops\nimport: os\nlayout: post\n"
            "convention: z-x-z\n---\n# Top\n\n$$T = \\frac{1}{2} I_3 \\dot\\psi^2$$\n")
    notes = nt.parse_notes(text, "n.md")
    assert notes.convention == "z-x-z"
    assert [(i.kind, i.line) for i in notes.items] == [("heading", 16), ("display", 18)]


def test_unreadable_file_is_exit_2_one_line(tmp_path, capsys):
    from derive.cli import main

    bad = tmp_path / "bad.md"
    bad.write_bytes(b"\xff\xfe$$x$$")
    for path in (bad, tmp_path / "missing.md", tmp_path):
        assert main(["verify", str(path)]) == 2
        out, err = capsys.readouterr()
        assert out == "" and err.count("\n") == 1 and err.startswith(f"error: {path}: file: "), err


# ---- the LaTeX layer ----------------------------------------------------------------------------
def test_latex_physics_notation():
    p = lx.parse(r"\widetilde{\omega}_1 = \dot{\alpha}(-\sin\beta\cos\gamma) + \dot{\beta}\sin\gamma")
    from derive.symbolic.rotations import alpha_d, beta, beta_d, gamma
    import sympy as sp
    assert p.members[0].value == lx.W[0]
    assert sp.expand(p.members[1].value - (-alpha_d * sp.sin(beta) * sp.cos(gamma) + beta_d * sp.sin(gamma))) == 0
    m = lx.parse(r"\hat{\mathbf{e}}_{2}' = \begin{pmatrix} \cos \gamma & \sin \gamma & 0 \\ -\sin \gamma & \cos \gamma & 0 \\ 0 & 0 & 1 \end{pmatrix} \begin{pmatrix} 0 \\ 1 \\ 0 \end{pmatrix}")
    assert m.members[0].value == lx.PRIMED[1] and list(m.members[1].value) == [sp.sin(gamma), sp.cos(gamma), 0]
    s = lx.parse(r"T = \frac{1}{2} \sum_i I_i \tilde{\omega}_i^2")
    assert s.members[1].value.free_symbols >= set(lx.W)


@pytest.mark.parametrize("formula, why", [
    (r"x_{7} = 1", "unknown symbol x_{7}"),
    (r"T = \frac{1}{2} I_1 \mathcal{Q}", "cannot read '\\mathcal'"),
    (r"T = (I_1 + ", "cannot parse at column"),
])
def test_latex_refuses_with_a_reason(formula, why):
    with pytest.raises(lx.NotRead) as err:
        lx.parse(formula)
    assert why in err.value.why


def test_latex_never_evaluates_text():
    with pytest.raises(lx.NotRead):
        lx.parse(r"T = \_\_import\_\_('os')")


# ---- the lecture's notes ----------------------------------------------------------------------
def _matching(claims, quote):
    def norm(s):
        s = re.sub(r"\\(begin|end)\{[a-z*]+\}|\$\$|&", "", s)
        s = re.sub(PRIME_SUPERSCRIPT, lambda m: "'" * m.group(1).count("prime"), s)   # a claim shows V^{\\prime} as V'
        return "".join(s.split())

    q = norm(quote)
    return [c for c in claims if q in norm(c.latex)]


@needs_lecture
def test_lecture_every_curated_slip_is_found(lecture_claims):
    from derive.lecture import claims as cur
    for claim in cur.CLAIMS:
        if cur.EXPECTED[claim.id] in ("typo", "fails"):
            mine = _matching(lecture_claims, claim.quote)
            assert any(c.verdict in ("typo", "fails") for c in mine), (claim.id, [c.verdict for c in mine])


@needs_lecture
def test_lecture_many_checked_and_agreeing(lecture_claims):
    from derive.lecture import claims as cur
    checked = [c for c in lecture_claims if c.verdict != "unchecked"]
    assert len(checked) >= 60
    both = agree = 0
    for claim in cur.CLAIMS:
        mine = [c for c in _matching(lecture_claims, claim.quote) if c.verdict != "unchecked"]
        if not mine:
            continue
        both += 1
        expected = cur.EXPECTED[claim.id]
        agree += expected in {c.verdict for c in mine}
    assert both >= 40 and agree / both >= 0.95, (agree, both)


@needs_lecture
def test_lecture_json_contract(capsys, monkeypatch, lecture_claims):
    # the command line in this process, given the run's one checked reading of the lecture (the
    # checks themselves are pinned above): this pins the command's JSON and its exit status
    from derive.cli import main

    asked = []

    def checked(path, convention=None):
        asked.append((Path(path), convention))
        return lecture_claims

    monkeypatch.setattr(nc, "check_notes", checked)
    code = main(["verify", str(LECTURE), "--format", "json"])
    out, err = capsys.readouterr()
    assert asked == [(LECTURE, None)]
    assert code == 1, err                         # the lecture has slips
    data = json.loads(out)
    assert set(data) == {"claims", "summary"}
    lines = LECTURE.read_text(encoding="utf-8").split("\n")
    for c in data["claims"]:
        assert set(c) == {"line", "latex", "kind", "verdict", "correction", "why", "assumes"}
        assert isinstance(c["assumes"], list)
        assert c["verdict"] in ("holds", "typo", "fails", "unchecked")
        assert ("$$" in lines[c["line"] - 1]) or ("$" in lines[c["line"] - 1]) or ("\\[" in lines[c["line"] - 1])
        assert (c["correction"] is not None) == (c["verdict"] == "typo")
    assert data["summary"]["typo"] + data["summary"]["fails"] >= 5


def test_a_kept_reading_is_read_again_when_its_text_or_derives_source_changes(tmp_path, monkeypatch):
    # the suite keeps the reader's claims between runs: they are reused only while nothing they
    # depend on has changed
    monkeypatch.setenv("DERIVE_CACHE", str(tmp_path / "cache"))
    notes = tmp_path / "top.md"
    notes.write_text("# Particles\n\n$$T = \\frac{1}{2} \\sum_{ij} I_{ij} \\omega_i \\omega_j$$\n", encoding="utf-8")
    read = []
    real = nc.check_notes
    monkeypatch.setattr(nc, "check_notes", lambda path, convention=None: read.append(convention) or real(path, convention))
    first = kept_readings.check_notes(notes)
    assert read == [None] and [c.verdict for c in first] == ["holds"]
    assert kept_readings.check_notes(notes) == first and read == [None]
    assert kept_readings.check_notes(notes, "z-x-z") and read == [None, "z-x-z"]
    notes.write_text(notes.read_text(encoding="utf-8").replace("\\frac{1}{2} ", ""), encoding="utf-8")
    assert [c.verdict for c in kept_readings.check_notes(notes)] == ["typo"] and len(read) == 3
    monkeypatch.setattr(kept_readings, "source_key", lambda: "another-source")
    assert [c.verdict for c in kept_readings.check_notes(notes)] == ["typo"] and len(read) == 4
    text = notes.read_text(encoding="utf-8")
    real_text = nc.check_text
    monkeypatch.setattr(nc, "check_text", lambda text, convention=None, path="<notes>": read.append(path) or
                        real_text(text, convention, path))
    assert kept_readings.check_text(text) == kept_readings.check_text(text) and read[4:] == ["<notes>"]
    assert kept_readings.check_text(text, path="top.md") and read[4:] == ["<notes>", "top.md"]
