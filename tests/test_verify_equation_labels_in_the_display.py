"""An equation's label written inside the display by a book's toolchain, ``{{numeq}}{eq:name}``
(mdBook's numeq preprocessor) or ``(\\#eq:name)`` (bookdown): dropped like ``\\label``, so the rows
before it are judged (derive/lecture/latex_spellings.py, derive/lecture/source.py)."""
import kept_readings as kept
from derive.lecture import source

LAGRANGE = "(\\mathbf{A} \\times \\mathbf{B}) \\cdot (\\mathbf{A} \\times \\mathbf{B}) = A^2B^2 - (\\mathbf{A} \\cdot \\mathbf{B})^2"


def verdicts(body: str) -> list:
    return [c.verdict for c in kept.check_text("# Vectors\n\nTwo vectors.\n\n" + body)]


def test_an_identity_labelled_by_mdbook_numeq_is_judged():
    display = "$$\n\\begin{aligned}\n" + LAGRANGE + "\n\\end{aligned}\n{{numeq}}{eq:lec25:lagrange}\n$$\n"
    assert verdicts(display) == ["holds"]
    assert verdicts(display.replace("- (", "+ (")) == ["typo"]


def test_an_identity_labelled_by_bookdown_is_judged():
    display = "$$\n" + LAGRANGE + " (\\#eq:lagrange)\n$$\n"
    assert verdicts(display) == ["holds"]
    assert verdicts(display.replace("- (", "+ (")) == ["typo"]


def test_a_bracket_that_is_not_a_label_stays():
    assert "(x)" in source.normalize("f = g (x)")
