"""What the reader writes back (a why, a correction) spells the derivation's symbols as the text
does: its ω_x for the body angular velocity, not the lecture's ω̃₁."""
import kept_readings
from derive.lecture import latex as lx
from derive.lecture.spellings import spellings

SMALL = r'''# Spin about the first axis

A free body turns about its first principal axis; the other two components of the angular
velocity, $\omega_y$ and $\omega_z$, are small. Euler's equations with $\omega_x$, $\omega_y$,
$\omega_z$ the body components:

$$
I_y \dot\omega_y = (I_z - I_x)\,\omega_z\omega_x
$$

$$
I_x \dot\omega_x = 0
$$
'''


def test_a_why_names_the_small_components_as_the_text_writes_them():
    claims = kept_readings.check_text(SMALL)
    (last,) = [c for c in claims if c.latex.strip() == r"I_x \dot\omega_x = 0"]
    assert last.verdict == "holds"
    assert r"\omega_y, \omega_z" in last.why and r"\tilde" not in last.why


def test_the_tilde_spelling_is_the_texts_when_it_writes_one():
    vocab = lx.Vocabulary()
    found = spellings(r"I_1 \dot{\tilde\omega}_1 = (I_2 - I_3)\tilde\omega_2\tilde\omega_3", vocab,
                      {*lx.W, *lx.WD})
    assert found[lx.WD[0]] == r"\dot{\tilde\omega}_1"
    assert found[lx.W[0]] == r"\tilde\omega_1" and found[lx.W[1]] == r"\tilde\omega_2"
