"""A superscript sign closing a name, 𝐯⁺ and 𝐯_rel⁻ (after and before an event, such as a collision):
part of the name, so the display around it is read (derive/lecture/vocabulary.py)."""
import kept_readings as kept
from derive.lecture import vocabulary


def verdicts(body: str) -> list:
    return [c.verdict for c in kept.check_text("# Collision\n\nTwo bodies collide.\n\n" + body)]


def test_a_cross_product_of_vectors_marked_after_and_before_is_read_and_holds():
    holds = ("$$(\\mathbf{v}_a^+ + \\mathbf{v}_{rel}^{-}) \\times \\mathbf{r}_a = \\mathbf{v}_a^+ \\times \\mathbf{r}_a"
             " + \\mathbf{v}_{rel}^{-} \\times \\mathbf{r}_a$$\n")
    assert verdicts(holds) == ["holds"]


def test_a_cross_product_reversed_between_vectors_marked_after_and_before_is_flagged():
    slip = "$$\\mathbf{v}_a^+ \\times \\mathbf{v}_a^- = \\mathbf{v}_a^- \\times \\mathbf{v}_a^+$$\n"
    assert verdicts(slip) == ["typo"]


def test_the_vectors_after_and_before_are_two_names_not_one():
    assert verdicts("$$\\mathbf{v}^+ \\times \\mathbf{r} = \\mathbf{v}^- \\times \\mathbf{r}$$\n") != ["holds"]
    after, before = (vocabulary.scan(f"\\mathbf{{v}}^{s}")[0].value for s in "+-")
    assert after != before


def test_a_sign_before_a_digit_or_a_letter_stays_the_sign_of_an_exponent():
    assert [t.kind for t in vocabulary.scan("x^-1")] == ["atom", "op", "op", "num"]
    assert [t.kind for t in vocabulary.scan("e^-t")] == ["atom", "op", "op", "atom"]
