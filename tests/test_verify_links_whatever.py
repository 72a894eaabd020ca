"""A chain of three or more members in names the text has not tied, not the same throughout: its links
that are identities whatever the names stand for hold, each said so by its members' places; its other
links are left unchecked, never flagged (a law or the text's words may relate them)."""
import kept_readings as kept

HEAD = "# A force on a lever\n\nA force $F$ acts at the distance $r$ from the pivot.\n\n"


def _claims(*displays):
    body = "".join(f"$$\n{d}\n$$\n\nThen\n\n" for d in displays)
    return kept.check_text(HEAD + body)


def _mine(claims, start):
    return [c for c in claims if c.latex.strip().startswith(start)]


def test_a_chain_whose_head_is_a_law_has_its_identical_links_held_and_the_head_left():
    mine = _mine(_claims("M = r m r \\alpha = m r^2 \\alpha"), "M = r m r")
    assert [c.verdict for c in mine] == ["holds", "unchecked"]
    assert "links 2 = 3" in mine[0].why and "links 1 = 2" in mine[1].why


def test_a_chain_with_no_identical_link_is_left_unchecked_never_flagged():
    mine = _mine(_claims("M = r m a = m r^2 \\alpha"), "M = r m a")
    assert [c.verdict for c in mine] == ["unchecked"]


def test_a_chain_of_two_members_is_not_read_link_by_link():
    mine = _mine(_claims("M = r m r \\alpha"), "M = r m r")
    assert all(c.verdict == "unchecked" for c in mine)
