"""Components in index notation equated across unlike free indices are a slip: ``y_i = R_{ij} = x_j``
sets a vector's component equal to a matrix's entry; ``y_i = R_{ij} x_j`` (j summed), a label such
as ``v_x`` or ``E_k``, and one index on both sides (``m_i = m_j``) are never flagged."""
import kept_readings as kept

HEAD = ("---\nconvention: z-y-z\n---\n# Rotations in index notation\n\n"
        "A rotation through $\\vartheta$ about the unit vector $\\hat n$ takes $x$ to $y$:\n\n")


def _flagged(display):
    return [c for c in kept.check_text(HEAD + f"$$\n{display}\n$$\n") if c.verdict in ("typo", "fails")]


def test_a_component_equated_with_a_matrix_entry_of_other_indices_is_flagged():
    flagged = _flagged("y_i = R_{ij}(\\vartheta, \\hat{n}) = x_j")
    assert [(c.kind, c.verdict) for c in flagged] == [("indices", "fails")]
    assert "free indices i, j" in flagged[0].why


def test_index_notation_with_its_summed_index_or_labels_is_not_flagged():
    assert _flagged("y_i = R_{ij}(\\vartheta, \\hat{n}) x_j") == []
    assert _flagged("I_{ij} = I_{ji}") == []
    assert _flagged("m_i = m_j") == []
    assert _flagged("E_k = T_{xy}") == []


def test_a_matrix_entry_with_its_arguments_in_sized_brackets_is_compared_as_with_plain_ones():
    flagged = _flagged("y_i = R_{ij}\\left(\\vartheta, \\hat{n}\\right) = x_j")
    assert [(c.kind, c.verdict) for c in flagged] == [("indices", "fails")]
    assert _flagged("y_i = R_{ij}\\left(\\vartheta, \\hat{n}\\right) x_j") == []


def test_a_sum_over_a_letter_its_summand_does_not_carry_is_a_typo_for_the_letter_it_carries():
    flagged = _flagged("\\sum_{i,k} I_{ki} \\omega_{km}\\omega_{in} = \\sum_i I_{nn}\\omega_{km}\\omega_{kn}")
    assert [(c.kind, c.verdict) for c in flagged] == [("indices", "typo")]
    assert "\\sum_k I_{nn}" in flagged[0].correction


def test_sums_over_letters_their_summands_carry_are_not_flagged():
    assert _flagged("\\sum_{i,k} I_{ik} \\omega_{km}\\omega_{in} = \\sum_i I_{mm}\\omega_{im}\\omega_{in}") == []
    assert _flagged("\\sum_{i,k} I_{ki} \\omega_{km}\\omega_{in} = \\sum_k I_{nn}\\omega_{km}\\omega_{kn}") == []
    assert _flagged("L_{im} = \\sum^3_k I_{ik} \\omega_{km} = I_{m}\\omega_{im}") == []
