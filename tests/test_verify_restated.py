"""The notes reader on a relation of the text's own names written again: once the text has defined
a name it puts into a later form of the same relation, the later form holds when it expands to
the earlier one; one that differs is not judged, and the first statement is never judged by it."""
import sympy as sp

import kept_readings as kept
from derive.lecture import restated
from derive.lecture.notes_claims import Claim

HEAD = "# Notes\n\n"
PARALLEL = "With $J_C$ the moment about the centre of mass,\n\n$$ J_{z^\\prime} = J_C + m d^2$$\n\n"
KOENIG = "$$T = \\frac{1}{2} m v_c^2 + \\frac{1}{2} J_C \\omega^2$$\n\n"


verdicts, line_of = kept.verdicts_by_line, kept.line_of


def test_a_relation_written_again_with_a_defined_name_put_in_holds():
    again = "and so\n\n$$T = \\frac{1}{2} m v_c^2 + \\frac{1}{2} (J_{z^\\prime} - m d^2) \\omega^2$$\n"
    text = HEAD + PARALLEL + KOENIG + again
    got = verdicts(text)
    assert got[line_of(text, "(J_{z^\\prime} - m d^2)")] == {"holds"}
    first = kept.by_line(text)[line_of(text, "J_C \\omega^2$$")]
    assert {c.kind for c in first} == {"König"}      # the first statement is judged as the theorem, not by the restatement


def test_a_relation_written_again_differently_is_not_judged():
    again = "and so\n\n$$T = \\frac{1}{2} m v_c^2 + \\frac{1}{2} (J_{z^\\prime} + m d^2) \\omega^2$$\n"
    text = HEAD + PARALLEL + KOENIG + again
    assert not verdicts(text)[line_of(text, "(J_{z^\\prime} + m d^2)")] & {"holds", "fails", "typo"}


def test_a_relation_with_another_left_side_is_not_a_restatement():
    again = "and so\n\n$$U = \\frac{1}{2} m v_c^2 + \\frac{1}{2} (J_{z^\\prime} - m d^2) \\omega^2$$\n"
    text = HEAD + PARALLEL + KOENIG + again
    assert "holds" not in verdicts(text)[line_of(text, "$$U =")]


RATIO = "$$\n\\frac{\\omega_1}{\\omega_2} = \\frac{a}{b}\n$$\n\nthat is\n\n"


def _solved(text, start):
    return [c for c in kept.check_text(text) if c.latex.startswith(start)]


def test_an_earlier_relation_solved_for_one_of_its_names_holds():
    text = HEAD + RATIO + "$$\n\\omega_2 = \\frac{b}{a} \\omega_1\n$$\n"
    got = _solved(text, "\\omega_2 =")
    assert [c.verdict for c in got] == ["holds"] and "solved for" in got[0].why


def test_a_relation_that_holds_by_the_texts_own_equation_is_marked_as_confirming_no_names():
    """A restatement holds whatever the text's names mean, so it is marked (`Claim.self_consistent`)
    and a statement beside it never takes it as confirming the prose's reading of a name."""
    text = HEAD + RATIO + "$$\n\\omega_2 = \\frac{b}{a} \\omega_1\n$$\n"
    assert [c.self_consistent for c in _solved(text, "\\omega_2 =")] == [True]
    u, v = sp.symbols("u v")
    checker = _Stub()
    assert not checker._restated(3, "u = v", [u, v], ["="])
    assert checker._restated(7, "u = v + 0", [u, v + 0 * u], ["="])
    assert [c.self_consistent for c in checker.claims] == [True]


def test_an_earlier_relation_solved_wrongly_is_not_judged():
    text = HEAD + RATIO + "$$\n\\omega_2 = \\frac{a}{b} \\omega_1\n$$\n"
    assert not {c.verdict for c in _solved(text, "\\omega_2 =")} & {"holds", "fails", "typo"}


class _Stub(restated.Restated):
    """The checker's three hooks the mixin uses, with the text's definitions already put in."""

    def __init__(self):
        self.claims = []

    def _resolve(self, x):
        return x

    def _add(self, *claim):
        self.claims.append(Claim(*claim))

    def tex(self, x):
        return str(x)


def test_a_matrix_relation_after_a_scalar_one_is_kept_not_a_failure():
    """A text's scalar equation of its own names, then a matrix equated to another name: no
    restatement is sought across the two kinds, and nothing raises (a reader step that raises leaves
    the display 'unchecked' with a failure, where the relation's own reason belongs)."""
    p, q, a, b, x = sp.symbols("p q a b x")
    checker = _Stub()
    assert not checker._restated(3, "p/q = a/b", [p / q, a / b], ["="])
    rotation = sp.ImmutableMatrix([[1, 0], [0, x]])
    assert not checker._restated(9, "R = ...", [sp.Symbol("R"), rotation], ["="])
    assert not checker._restated(12, "p = R", [p, rotation], ["="])
    assert not checker._restated(15, "S = R", [sp.Symbol("S"), sp.ImmutableMatrix([[1, 0], [0, 1]])], ["="])
    assert checker.claims == []
