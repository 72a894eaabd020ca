"""A chain ``a = b = c`` with a member the reader cannot read (a name the text never defines): its
verdict is at most what the links it can read show, and names the member it left out."""
from kept_readings import check_text

HEAD = "---\ntitle: free body\n---\n# Euler's equations of a free body\n\nIn principal axes, with no torque:\n\n"


def _claims(display):
    return check_text(HEAD + f"$$\n{display}\n$$\n")


def test_a_chain_whose_every_link_passes_through_an_unread_member_is_unchecked_naming_it():
    claims = _claims(r"I_1 \dot\omega_1 = \zeta_1 = (I_2 - I_3)\omega_2\omega_3")
    assert [c.verdict for c in claims] == ["unchecked"]
    assert "\\zeta_1 not read" in claims[0].why


def test_a_readable_link_beside_an_unread_member_is_judged_and_the_member_named():
    claims = _claims(r"I_1 \dot\omega_1 = (I_2 - I_3)\omega_2\omega_3 = \zeta_1")
    assert [c.verdict for c in claims] == ["holds"]
    assert "without \\zeta_1" in claims[0].why


def test_members_around_an_unread_one_that_disagree_still_flag_the_chain():
    claims = _claims(r"I_1 \dot\omega_1 = \zeta_1 = (I_3 - I_2)\omega_2\omega_3")
    assert {c.verdict for c in claims} & {"typo", "fails"}
