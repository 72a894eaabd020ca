"""A display on which a step of the reader raises outside a statement's own guard (here: a matrix
divided by its norm, which SymPy's matrix expressions refuse) is `unchecked` naming the step, and
the reader goes on with the next display: a user's text never stops the run."""
import kept_readings as kept

TEXT = ("# A unit vector\n\n$$\\hat\\Omega = R^T\\dot R$$\n\nIts direction:\n\n"
        "$$n=\\Omega/||\\Omega||$$\n\n"
        "A free symmetric body:\n\n$$I_1 \\dot{\\omega}_1 = (I_2 - I_3)\\omega_2\\omega_3$$\n")


def test_a_display_the_reader_cannot_follow_is_unchecked_and_the_next_is_read():
    claims = kept.check_text(TEXT)
    first = [c for c in claims if c.line == 7]
    assert first and all(c.verdict == "unchecked" for c in first)
    assert any("a step of the reader failed on it" in c.why for c in first)
    assert [c.verdict for c in claims if c.line == 11] == ["holds"]
