"""A superscript that is a word is a label on its symbol, never a power (`derive.lecture.vocabulary`,
`derive.lecture.latex_spellings.LABEL_WORD`): ``F^{ext}``, ``g^{\\text{horizontal}}_{eff}``."""
import pytest

from derive.lecture import notes_check as nc
from derive.lecture.vocabulary import scan


def _atoms(formula):
    return [t.value for t in scan(formula) if t.kind == "atom"]


@pytest.mark.parametrize("formula, sup", [("F^{ext}", "ext"), ("g^{horizontal}_{eff}", "horizontal"),
                                          (r"\mathbf{F}^{\text{ext}}", r"\text{ext}"), (r"T^{\mathrm{rot}}", r"\mathrm{rot}")])
def test_a_word_as_superscript_is_one_symbol_with_its_label(formula, sup):
    atoms = _atoms(formula)
    assert len(atoms) == 1 and atoms[0].sup.replace(" ", "") in (sup, sup.split("{")[-1].rstrip("}"))


@pytest.mark.parametrize("formula", ["x^{ab}", "e^{abc}", r"x^{\alpha}", "x^{2}"])
def test_a_short_or_greek_or_numeric_superscript_and_a_power_of_e_stay_powers(formula):
    toks = scan(formula)
    assert any(t.kind == "op" and t.value == "^" for t in toks)


def test_a_labelled_force_is_the_texts_own_name_not_a_power_of_three_letters():
    text = "# Forces\n\n$$F^{ext} = m a$$\n"
    why = " ".join(c.why for c in nc.check_text(text))
    assert "F^{ext}" in why and "x, " not in why
