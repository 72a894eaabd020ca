"""A trial reading (a statement read again in a sandbox: a second meaning of a name, an edit sought
as a correction) leaves the checker as it found it: no solution waiting for its group, no statement
to read again later, no verdict waiting to be placed comes from it."""
from derive.lecture import notes as nt
from derive.lecture import notes_check as nc

TEXT = ("---\ntitle: free body\n---\n# The free symmetric top\n\nFor a symmetric body, $I_1 = I_2$, with no "
        "torque.\n\n$$\n\\Omega \\equiv \\tilde\\omega_3 \\frac{I_3 - I_1}{I_1}\n$$\n")


def test_a_trial_reading_leaves_no_solution_pending_and_nothing_deferred():
    checker = nc.Checker(nt.parse_notes(TEXT, "<notes>", None))
    checker.run()
    state = (list(checker.pending), list(checker.deferred), list(checker.flushed))
    solution, untied = r"\tilde\omega_1 = A\cos(\Omega t)", r"\tilde\omega_2 \zeta = \kappa \tilde\omega_1"
    for piece in (solution, untied, solution):
        checker._sandbox(checker._snapshot(), 20, piece, False, ())
        assert (checker.pending, checker.deferred, checker.flushed) == state, piece


def test_a_trial_reading_kept_keeps_what_it_left_to_read_later():
    checker = nc.Checker(nt.parse_notes(TEXT, "<notes>", None))
    checker.run()
    before = len(checker.claims)
    claims, ctx = checker._sandbox(checker._snapshot(), 20, r"\tilde\omega_2 \zeta = \kappa \tilde\omega_1", False, ())
    assert not checker.deferred
    checker._keep(before, claims, ctx)
    assert [piece for _, _, piece, _ in checker.deferred] == [r"\tilde\omega_2 \zeta = \kappa \tilde\omega_1"]
