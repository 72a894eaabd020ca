"""A chain of three or more members in names the text has not tied, not the same throughout: its links
from some link on that are identities whatever the names stand for hold, said so by its members' places;
the links before them are left unchecked, never flagged (a law or the text's words may relate them)."""
import kept_readings as kept

HEAD = "# A force on a lever\n\nA force $F$ acts at the distance $r$ from the pivot.\n\n"


def _claims(*displays):
    body = "".join(f"$$\n{d}\n$$\n\nThen\n\n" for d in displays)
    return kept.check_text(HEAD + body)


def _mine(claims, start):
    return [c for c in claims if c.latex.strip().startswith(start)]


def test_a_chain_whose_head_is_a_law_has_its_identical_links_held_and_the_head_left():
    mine = _mine(_claims("Q = r F", "Q = r m r \\alpha = m r^2 \\alpha"), "Q = r m r")
    assert [c.verdict for c in mine] == ["holds", "unchecked"]
    assert "links 2 = 3" in mine[0].why and "links 1 = 2" in mine[1].why


def test_a_chain_with_no_identical_link_is_left_unchecked_never_flagged():
    mine = _mine(_claims("Q = r F", "Q = r m a = m r^2 \\alpha"), "Q = r m a")
    assert [c.verdict for c in mine] == ["unchecked"]


def test_a_chain_of_two_members_is_not_read_link_by_link():
    mine = _mine(_claims("Q = r F", "Q = r m r \\alpha"), "Q = r m r")
    assert all(c.verdict == "unchecked" for c in mine)


def test_an_identity_before_a_link_it_does_not_pass_is_not_held():
    mine = _mine(_claims("Q = r F", "Q = F r \\alpha = r F \\alpha = 3 F r"), "Q = F r")
    assert "holds" not in [c.verdict for c in mine]
