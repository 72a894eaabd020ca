"""Index notation written out: a chain whose members are the same at every value of its free indices,
each index written twice in a term summed over 1, 2, 3 (``\\delta_{ij}`` Kronecker's delta,
``\\varepsilon_{ijk}`` the Levi-Civita symbol, a component the text defines over generic indices put
in), holds; a chain that is not the same has its links that are held and the others left unchecked, never flagged."""
import kept_readings as kept

HEAD = ("---\nconvention: z-y-z\n---\n# Rotations in index notation\n\n"
        "A rotation through $\\vartheta$ about the unit vector $n$ takes $x$ to $y$.\n\n")


def _claims(*displays):
    body = "".join(f"$$\n{d}\n$$\n\nThen\n\n" for d in displays)
    return kept.check_text(HEAD + body)


def _verdicts(claims, start):
    return [c.verdict for c in claims if c.latex.strip().startswith(start)]


def test_a_contraction_with_kroneckers_delta_holds():
    claims = _claims("\\delta_{ij} a_{j} = a_i", "\\delta_{ij}b_{ij} = b_{ii}")
    assert _verdicts(claims, "\\delta_{ij} a_{j}") == ["holds"]
    assert _verdicts(claims, "\\delta_{ij}b_{ij}") == ["holds"]


def test_a_levi_civita_sum_with_a_definition_over_generic_indices_put_in_holds():
    claims = _claims("R_{ij} = \\delta_{ij} \\cos\\vartheta + (1 - \\cos\\vartheta)n_in_j"
                     " - \\varepsilon_{ijk}n_k\\sin\\vartheta",
                     "n_k\\sin\\vartheta = -\\frac{1}{2}\\varepsilon_{ijk}R_{ij}")
    assert _verdicts(claims, "n_k\\sin") == ["holds"]
    assert "index notation" in [c for c in claims if c.latex.startswith("n_k")][0].why


def test_a_swapped_levi_civita_index_is_left_unchecked_never_flagged():
    claims = _claims("\\varepsilon_{ijk} a_j b_k = \\varepsilon_{ikj} a_j b_k")
    assert _verdicts(claims, "\\varepsilon_{ijk} a_j") == ["unchecked"]


def test_a_chain_with_unlike_free_indices_or_a_thrice_written_index_is_not_read_as_index_notation():
    claims = _claims("c_i = a_j b_j", "d = a_i b_i c_i")
    assert all(c.verdict != "holds" or "index notation" not in c.why for c in claims)


def test_an_instance_of_a_definition_over_generic_indices_takes_its_indices():
    claims = _claims("K_{jh} \\equiv I_j - I_h", "K_{31} + K_{12} = I_3 - I_2")
    assert _verdicts(claims, "K_{31} + K_{12}") == ["holds"]


def test_a_chain_whose_members_differ_has_its_links_that_are_identities_held_and_the_others_left():
    claims = _claims("y_i = x_i\\cos\\vartheta + (1 - \\cos\\vartheta) n_jx_jn_i"
                     " + \\varepsilon_{ikj}n_kx_j\\sin\\vartheta",
                     "R_{ij} = \\delta_{ij} \\cos\\vartheta + (1 - \\cos\\vartheta)n_in_j"
                     " - \\varepsilon_{ijk}n_k\\sin\\vartheta",
                     "y_i = R_{ij}x_j = \\delta_{ij}x_j - \\varepsilon_{ijk}n_kx_j\\delta\\vartheta"
                     " = x_i + \\varepsilon_{ikj}n_kx_j\\delta\\vartheta")
    mine = [c for c in claims if c.latex.startswith("y_i = R_{ij}")]
    assert [c.verdict for c in mine] == ["holds", "unchecked"]
    assert "links 1 = 2 and 3 = 4" in mine[0].why and "links 2 = 3" in mine[1].why


def test_a_chain_with_a_wrong_link_is_never_flagged_and_its_identities_still_held():
    claims = _claims("\\delta_{ij}b_{ij} = b_{ii} = b_{11} + b_{22}")
    assert _verdicts(claims, "\\delta_{ij}b_{ij}") == ["holds", "unchecked"]
