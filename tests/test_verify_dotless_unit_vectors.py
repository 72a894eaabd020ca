"""The dotless ı and ȷ under a hat are the unit vectors' letters i and j (`derive.lecture.source`), and
unit vectors of two frames, î′ beside î, are not one basis (`derive.lecture.vector_algebra_model`)."""
from derive.lecture import notes_check as nc
from derive.lecture.source import normalize
from derive.lecture.vocabulary import scan


def test_a_hat_over_a_dotless_i_is_the_unit_vector_i():
    atoms = [t.value for t in scan(normalize(r"\hat\imath'")) if t.kind == "atom"]
    assert len(atoms) == 1 and (atoms[0].base, atoms[0].hat, atoms[0].primes) == ("i", True, 1)
    atoms = [t.value for t in scan(normalize(r"\mathbf{\hat{\jmath}}")) if t.kind == "atom"]
    assert len(atoms) == 1 and atoms[0].base == "j"


def test_one_frames_unit_vectors_are_read_as_a_basis_and_two_frames_are_not():
    one = "# Unit vectors\n\n$$\\hat{i}' \\times \\hat{j}' = \\hat{k}'$$\n"
    assert [c.verdict for c in nc.check_text(one) if c.line == 3] == ["holds"]
    two = "# Unit vectors\n\n$$\\hat{i}' \\times \\hat{j} = \\hat{k}$$\n"
    assert not {"holds", "typo", "fails"} & {c.verdict for c in nc.check_text(two) if c.line == 3}
