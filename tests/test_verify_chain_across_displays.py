"""The notes reader on a chain of equalities set over several displays, one equation to a display
(as Sphinx sets the paragraphs of a ``math`` directive): a display ending with ``=`` goes on in the
next display that begins with ``=``, whose members are read against the chain's head."""
from kept_readings import verdicts_by_line as verdicts

CHAIN = ("# Chains\n\nThe square:\n\n$$\nT = (a+b)^2 =\n$$\n\n$$\n  = a^2 + 2ab + b^2 =\n$$\n\n"
         "$$\n  = (b+a)^2\n$$\n")


def test_a_display_that_begins_with_equals_goes_on_with_the_chain_the_display_before_it_left_open():
    got = verdicts(CHAIN)
    assert "holds" in got[9] and "holds" in got[13]


def test_a_display_left_open_before_one_that_states_its_own_relation_is_not_joined():
    got = verdicts(CHAIN.replace("  = (b+a)^2", "S = (b+a)^2"))
    assert got[9] == {"unchecked"}
