"""The corpus texts that declare their convention in their front matter, read with that line
removed (a comment in its place, the lines kept): as an outside reader meets a text that states
none. No display the truth table says holds may be flagged; the displays checked may not fall
below `FLOOR` (478 read in z-y-z blindly, 487 with the front matter)."""
import re

import pytest

import kept_readings as kept
from test_verify_corpus import measure

_KEY = re.compile(r"^convention:.*$", re.M)
DECLARING = tuple(s for s in measure.texts()
                  if measure.source(s).suffix == ".md" and _KEY.search(measure.source(s).read_text()))
FLOOR = 485
"""Displays of the whole corpus checked, the front matter's convention removed where it is declared."""


def _blanked(slug: str) -> str:
    text = measure.source(slug).read_text()
    return _KEY.sub("# (convention not given)", text, count=1)


def _figures(slug: str):
    claims = kept.check_text(_blanked(slug), None, str(measure.source(slug)))
    return measure.measure(slug, claims)


def test_the_corpus_has_texts_that_declare_their_convention():
    assert len(DECLARING) >= 10
    assert all(_blanked(s).count("\n") == measure.source(s).read_text().count("\n") for s in DECLARING)


@pytest.mark.slow
@pytest.mark.parametrize("slug", DECLARING)
def test_a_text_read_without_its_declared_convention_raises_no_false_alarm(slug):
    assert _figures(slug).false_alarms == []


@pytest.mark.slow
def test_the_corpus_read_without_declared_conventions_checks_as_many_displays(notes_reading):
    checked = sum(_figures(s).checked if s in DECLARING else measure.measure(s, notes_reading(measure.source(s))).checked
                  for s in measure.texts())
    assert checked >= FLOOR
