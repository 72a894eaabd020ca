"""The reader's shortcuts give what the long way gives: the scanner's tokens kept per formula, the
text's symbol of an atom found through an index, pylatexenc's specials looked up by their first
character, and the screen that spares a vector statement's candidate corrections the zero test."""
from types import SimpleNamespace

import pytest
import sympy as sp

from derive.lecture import source
from derive.lecture import vectors as vc
from derive.lecture import zero_test as zt
from derive.lecture.latex import Generic
from derive.lecture.vocabulary import Atom, Vocabulary, scan

x, y = sp.symbols("x y", real=True)


def test_a_formula_scanned_again_gives_the_same_tokens_in_a_list_of_its_own():
    formula = r"\dot{\omega}_1 = \frac{I_2 - I_3}{I_1} \omega_2 \omega_3"
    first = scan(formula)
    first.pop()
    again = scan(formula)
    assert again[:-1] == first and len(again) == len(first) + 1
    assert again is not scan(formula)


def test_an_atom_keeps_its_symbol_and_follows_it_when_the_name_becomes_a_matrix():
    vocab = Vocabulary(open=True)
    a, b = Atom("Q"), Atom("Q", dots=1)
    q = vocab._generic(a)
    assert vocab._generic(Atom("Q", text="Q")) is q and vocab._generic(b) != q
    # the checker's one edit of the table: a name set equal to a matrix becomes a non-commuting symbol
    atom = vocab.generic.pop(q)
    matrix = Generic(q.name, commutative=False)
    vocab.generic[matrix] = atom
    assert vocab._generic(a) is matrix
    assert vocab.undotted(vocab._generic(b)) == (matrix, 1)


@pytest.mark.parametrize("text", [r"a~b -- c --- d `` e '' f & g \\ h", "x^{2}_{i} & \\alpha~\\beta", ""])
def test_the_specials_found_at_every_position_are_pylatexencs(text):
    fast, plain = source._ctx(), source._context()
    for pos in range(len(text) + 1):
        a, b = fast.test_for_specials(text, pos), plain.test_for_specials(text, pos)
        assert (a and a.specials_chars) == (b and b.specials_chars)


def _reading(*pairs):
    member = lambda v: SimpleNamespace(value=v)  # noqa: E731
    return SimpleNamespace(members=[[member(a), member(b)] for a, b in pairs], free="i" if len(pairs) > 1 else "")


@pytest.mark.parametrize("pairs, equal", [
    ([(sp.Matrix([x * (x + y), sp.sin(x) ** 2, 0]), sp.Matrix([x**2 + x * y, 1 - sp.cos(x) ** 2, 0]))], True),
    ([(sp.Matrix([x * (x + y), sp.sin(x) ** 2, 0]), sp.Matrix([x**2 + x * y, 1 + sp.cos(x) ** 2, 0]))], False),
    ([((x + 1) ** 2, x**2 + 2 * x + 1), (x * y, y * x)], True),
    ([((x + 1) ** 2, x**2 + 2 * x + 1), (x * y, -y * x)], False),
])
def test_a_candidate_the_screen_proves_unequal_is_one_the_zero_test_finds_unequal(pairs, equal):
    reading = _reading(*pairs)
    ok, _ = vc.holds(reading, 1, "screen", ref=0)
    assert ok is equal
    assert vc.surely_differs(reading, 1) is (not equal)


def test_a_difference_with_a_root_or_an_absolute_value_is_left_to_the_zero_test():
    # non-zero at the screen's point, but such a difference may vanish where the zero test samples
    assert zt.surely_nonzero(sp.sqrt(x**2 + 1) - x)
    for a, b in [(sp.Abs(x) + 1, x), (sp.sqrt(x**2 + 1), x), (sp.Function("f")(x), x)]:
        assert not vc.surely_differs(_reading((a, b)), 1)
