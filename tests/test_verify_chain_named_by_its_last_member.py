"""A chain in names the text has not tied, whose last member brings in a name of its own that names
the chain (R = (R − S) + S = d + S, d then defined in words): the links before it are checked as an
identity whatever the names stand for; a chain that is no identity is never passed."""
import kept_readings as kept

HEAD = "Let $\\mathbf{R}$ be the centre of mass and $\\mathbf{S}$ another point.\n\n"


def claims(display: str) -> list:
    return kept.check_text(HEAD + "$$" + display + "$$\n\nwhere d is the vector from S to R.\n")


def test_an_identity_named_by_a_new_vector_in_its_last_member_holds():
    found = claims("\\mathbf{R} = (\\mathbf{R}-\\mathbf{S}) + \\mathbf{S} = \\mathbf{d} + \\mathbf{S}")
    assert [c.verdict for c in found] == ["holds"]
    assert "names the chain with d" in found[0].why


def test_a_chain_that_is_no_identity_is_not_passed():
    found = claims("\\mathbf{R} = (\\mathbf{R}-\\mathbf{S}) - \\mathbf{S} = \\mathbf{d} + \\mathbf{S}")
    assert "holds" not in [c.verdict for c in found]


def test_a_last_member_whose_names_are_all_written_before_it_is_not_a_naming():
    found = claims("\\mathbf{R} = (\\mathbf{R}-\\mathbf{S}) + \\mathbf{S} = \\mathbf{R} + 2\\mathbf{S}")
    assert "holds" not in [c.verdict for c in found]
