"""The corpus texts written another way: the reader's verdict follows what a formula says, not how
it is typeset.

Each variant kind of `test_verify_latex_variants` (``\\dfrac``, ``\\mathrm{d}``, ``\\bigl(``, a thin
space between factors, ``\\bm``, a tag, a trailing full stop, ``\\operatorname{sin}``, …) rewrites
every display of a public text of the corpus (tests/notes/real: a ``$$`` block, ``\\[…\\]``, a
display environment, a fenced ``math`` block, a formula set on its own line), keeping its lines
where they are; the rewritten text is read again and compared line by line with the text as
written:

* a display the reader did not flag (and that the truth table does not call a slip) is not flagged
  now: a false alarm is always a bug;
* a display that held still holds (a kind the reader cannot follow everywhere yet is a strict
  expected failure naming what it misses, in `MISSES`);
* a slip that was flagged is still flagged.

A rewrite is applied to a display's LaTeX between its delimiters; a display whose line count the
rewrite would change is left as written. Each kind reads half the corpus (`texts`).
"""
from __future__ import annotations

import functools
import re
from collections import Counter

import pytest

import kept_readings as kept
from test_verify_corpus import _DISPLAY, _rendered_lines, measure
from test_verify_latex_variants import VARIANTS

FLAGGED = ("typo", "fails")

#: The corpus, in order. Reading every text under every kind is a few CPU-minutes, so a kind reads
#: every other text (the kind's position in `VARIANTS` says which half): each text is read under
#: half the kinds, each kind over half the corpus, the same halves in every run.
CORPUS = tuple(measure.texts())


def texts(kind: str) -> tuple:
    """The texts ``kind`` reads: the half of `CORPUS` at the parity of the kind's position."""
    k = list(VARIANTS).index(kind)
    return CORPUS[k % 2::2]


# A display's delimiters and its LaTeX between them (the closing one with the punctuation after it).
_INNER = re.compile(r"^(```math\n|\$\$|\\\[|\\begin\{[a-z]+\*?\}(?:\{[^{}]*\})?|[^$]*\$)(.*?)"
                    r"(```|\$\$|\\\]|\\end\{[a-z]+\*?\}|\$[ \t]*[.,;:]?[ \t]*)$", re.S)

_CHANGES_MEANING = ("the rewrite changes what some displays say: a factor between the text's operators, matrices or "
                    "vectors and what they act on (D \\cdot (M L'), \\frac{d}{dt} \\quad m_i), or a \\quad before a factor "
                    "of a statement that goes on with a relation (L = I_z \\quad \\omega_s = …), which a reader too takes "
                    "for two statements")
MISSES: dict[str, str] = {
    "quad between factors": _CHANGES_MEANING, "cdot between scalar factors": _CHANGES_MEANING,
}
"""Kinds that still leave some displays of the corpus unchecked (or, for the two that change what a
display says, flag some): what the reader misses."""
FALSE_ALARMS_OF_A_CHANGED_MEANING = ("quad between factors",)


# A command the text defines with arguments takes what follows it as its first (``\\vv L`` is ``\\bm{L}``):
# a space set after it would be that argument, so the space after it is kept as written.
_OWN_WITH_ARGUMENTS = re.compile(r"\\(?:re)?newcommand\*?\s*\{?\s*\\([A-Za-z]+)\s*\}?\s*\[\s*[1-9]")


def _arguments_kept(text: str, change):
    """``change``, leaving the space after each of ``text``'s own commands with arguments as it is."""
    own = sorted({m[1] for m in _OWN_WITH_ARGUMENTS.finditer(text)})
    if not own:
        return change
    held = re.compile(r"(\\(?:" + "|".join(own) + r"))(?![A-Za-z]) ")
    return lambda latex: change(held.sub("\\1\x00", latex)).replace("\x00", " ")


def rewrite(text: str, change) -> str:
    """``text`` with every display's LaTeX passed through ``change``, lines kept in place."""
    out, last = [], 0
    change = _arguments_kept(text, change)
    for m in _DISPLAY.finditer(text):
        parts = _INNER.match(m.group(0))
        if not parts:
            continue
        core = parts[2].rstrip()        # what ends the display stays where it is (a fence on its own line)
        inner = change(core) + parts[2][len(core):]
        if inner.count("\n") != parts[2].count("\n"):
            continue
        out += [text[last:m.start()], parts[1] + inner + parts[3]]
        last = m.end()
    return "".join(out + [text[last:]])


def _verdicts(text: str, path: str) -> dict[int, Counter]:
    out: dict[int, Counter] = {}
    for claim in kept.check_text(text, None, path):
        out.setdefault(claim.line, Counter())[claim.verdict] += 1
    return out


@functools.cache
def _original(slug: str):
    text = "\n".join(_rendered_lines(slug))
    path = str(measure.source(slug))
    truth = {r["line"]: r["verdict"] for r in measure.truth(slug)}
    return text, path, truth, _verdicts(text, path)


@functools.cache
def _compare(kind: str):
    """(false alarms, displays that no longer hold, slips no longer flagged, displays changed)."""
    change = VARIANTS[kind][1]
    alarms, lost, unflagged, changed = [], [], [], 0
    for slug in texts(kind):
        text, path, truth, before = _original(slug)
        variant = rewrite(text, change)
        if variant == text:
            continue
        changed += sum(a != b for a, b in zip(text.split("\n"), variant.split("\n")))
        after = _verdicts(variant, path)
        for line in set(before) | set(after):
            was, now = before.get(line, Counter()), after.get(line, Counter())
            was_flagged, now_flagged = any(was[v] for v in FLAGGED), any(now[v] for v in FLAGGED)
            if now_flagged and not was_flagged and truth.get(line) not in FLAGGED:
                alarms.append(f"{slug}:{line} {dict(now)}")
            elif was_flagged and not now_flagged:
                unflagged.append(f"{slug}:{line} {dict(now)}")
            elif not was_flagged and now["holds"] < was["holds"]:
                lost.append(f"{slug}:{line} {dict(now)}")
    return alarms, lost, unflagged, changed


def _kind_cases(xfails: bool):
    for kind in VARIANTS:
        marks = [pytest.mark.slow]
        if kind in MISSES and (xfails or kind in FALSE_ALARMS_OF_A_CHANGED_MEANING):
            marks.append(pytest.mark.xfail(strict=True, reason=MISSES[kind]))
        yield pytest.param(kind, marks=marks, id=kind.replace(" ", "-"))


def test_a_rewrite_sets_no_space_between_a_texts_own_command_and_its_argument():
    text = "\\newcommand{\\vv}[1]{\\bm{#1}}\n\n$$\n\\vv L = \\vv r \\times m \\vv v\n$$\n"
    out = rewrite(text, VARIANTS["thin space between factors"][1])
    assert out == text.replace("r \\times m \\vv", "r \\times m \\, \\vv")


def test_an_arrow_rewrite_leaves_a_matrix_between_two_frames_bold():
    # an arrow would make Kane's direction cosine matrix a vector; the vector beside it takes the arrow
    arrows = VARIANTS["vec for bold letters"][1]
    assert arrows("\\left({}^A\\mathbf{C}^N\\right)^{-1} \\mathbf{a}") == "\\left({}^A\\mathbf{C}^N\\right)^{-1} \\vec{a}"
    assert arrows("{}^N\\mathbf{H}^{B/O} = \\mathbf{r}") == "{}^N\\vec{H}^{B/O} = \\vec{r}"   # a point's label: a vector


def test_a_rewrite_keeps_a_texts_lines_and_leaves_what_ends_a_fence_alone():
    text = "# T\n\n```math\na = b\n```\n\n$$\nc = d\n$$\n\n- $e = f$.\n"
    out = rewrite(text, lambda latex: latex + " \\tag{1}")
    assert out == "# T\n\n```math\na = b \\tag{1}\n```\n\n$$\nc = d \\tag{1}\n$$\n\n- $e = f \\tag{1}$.\n"


@pytest.mark.parametrize("kind", list(_kind_cases(xfails=False)))
def test_a_corpus_text_written_another_way_raises_no_false_alarm(kind):
    alarms, _, _, changed = _compare(kind)
    if not changed:
        pytest.skip(f"no display of this half of the corpus is written so that {kind!r} rewrites it")
    assert alarms == [], alarms


@pytest.mark.parametrize("kind", list(_kind_cases(xfails=True)))
def test_a_corpus_text_written_another_way_keeps_every_display_checked(kind):
    _, lost, unflagged, changed = _compare(kind)
    if not changed:
        pytest.skip(f"no display of this half of the corpus is written so that {kind!r} rewrites it")
    assert (lost, unflagged) == ([], []), f"{len(lost)} displays no longer hold: {lost}; slips no longer flagged: {unflagged}"


def test_a_plain_bracket_rewrite_leaves_a_pair_with_an_invisible_delimiter_sized():
    plain = VARIANTS["plain brackets for left-right"][1]
    assert plain(r"\left.\frac{dB}{dt}\right)_{rel} = \left(a\right)") == r"\left.\frac{dB}{dt}\right)_{rel} = (a)"
