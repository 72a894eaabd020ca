"""The notes reader on a display that ends in a conclusion after ⇒ solving the equation before it
for one of its names: the conclusion holds when it is a root of the premise, fails when the premise
solved for that name gives another value in the same names, and is left to the other rules when
the premise's roots are in other names or the premise does not hold the name."""
import kept_readings as kept

HEAD = "# Rolling\n\nA ball is struck through its centre and slides until it rolls.\n\n"


def _conclusion(text, start):
    return [c for c in kept.check_text(text) if c.latex.startswith(start)]


def test_a_conclusion_that_solves_the_premise_holds():
    text = HEAD + "$$v - V = -\\frac{2}{5} v \\implies v = \\frac{5}{7} V$$\n"
    got = _conclusion(text, "v = \\frac{5}{7}")
    assert [c.verdict for c in got] == ["holds"] and got[0].kind == "implication"


def test_a_premise_with_its_sign_lost_makes_the_conclusion_fail():
    text = HEAD + "$$v - V = \\frac{2}{5} v \\implies v = \\frac{5}{7} V$$\n"
    got = _conclusion(text, "v = \\frac{5}{7}")
    assert [c.verdict for c in got] == ["fails"]
    assert "\\frac{5 V}{3}" in got[0].why


def test_one_link_of_a_chain_premise_giving_the_root_is_enough():
    text = HEAD + ("$$b M R \\alpha = J \\alpha = \\frac{2}{5} M R^2 \\alpha \\Rightarrow b = \\frac{2}{5} R$$\n")
    assert [c.verdict for c in _conclusion(text, "b = \\frac{2}{5}")] == ["holds"]


def test_a_root_in_other_names_is_not_judged():
    # the premise's root keeps a factor the conclusion drops (a small angle, a case): not this rule's
    text = HEAD + "$$m g l \\sin\\theta = J w \\Omega \\implies \\Omega = \\frac{m g l}{J w}$$\n"
    assert not {c.verdict for c in _conclusion(text, "\\Omega =")} & {"fails", "typo"}


def test_a_premise_in_names_the_text_has_set_is_not_flagged():
    text = HEAD + "Here $$V = 3 u$$\n\nso that\n\n$$v - V = \\frac{2}{5} v \\implies v = \\frac{5}{7} V$$\n"
    assert not {c.verdict for c in _conclusion(text, "v = \\frac{5}{7}")} & {"fails", "typo"}
