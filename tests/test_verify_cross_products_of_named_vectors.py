"""Cross products of a text's named vectors (derive/lecture/named_vectors.py): each named vector a
general 3-vector, a position between named points 𝐩_A − 𝐩_B, a text's definitions put in their place."""
import kept_readings as kept
from derive.lecture import named_vectors as nv

RESULTANT = "$$\\vec{\\bf{F}} = \\sum\\limits_{i=1}^n \\vec{\\bf{F_i}}$$\n\n"
MOMENT = "$$\\vec{\\bf{M_O}} = \\sum\\limits_{i}\\vec{\\bf{r_{i/O}}} \\times \\vec{\\bf{F_i}} + \\sum\\limits_{i}\\vec{\\bf{M_{F_i}}}$$\n\n"


def verdicts(body: str) -> dict:
    out = {}
    for c in kept.check_text("# Forces\n\nThe forces on a body.\n\n" + body):
        out.setdefault(c.line, []).append(c.verdict)
    return out


def last(body: str) -> list:
    found = verdicts(body)
    return found[max(found)]


def test_a_moment_moved_to_another_point_holds_with_the_position_between_the_points():
    moved = "$$\\vec{\\bf{M_{O'}}} = \\vec{\\bf{M_O}} + \\vec{\\bf{r_{O/O'}}} \\times \\vec{\\bf{F}}$$\n"
    assert last(RESULTANT + MOMENT + moved) == ["holds"]


def test_a_moment_moved_with_the_position_reversed_is_flagged():
    moved = "$$\\vec{\\bf{M_{O'}}} = \\vec{\\bf{M_O}} + \\vec{\\bf{r_{O'/O}}} \\times \\vec{\\bf{F}}$$\n"
    assert last(RESULTANT + MOMENT + moved) == ["typo"]


def test_a_definition_of_a_named_vector_is_recorded_not_judged():
    assert verdicts(RESULTANT + MOMENT) == {5: ["unchecked"], 7: ["unchecked"]}


def test_lagranges_identity_with_magnitudes_beside_the_bold_letters():
    holds = "$$(\\mathbf{A} \\times \\mathbf{B}) \\cdot (\\mathbf{A} \\times \\mathbf{B}) = A^2B^2 - (\\mathbf{A} \\cdot \\mathbf{B})^2$$\n"
    slip = holds.replace("- (", "+ (")
    assert last(holds) == ["holds"]
    assert last(slip) == ["typo"]


def test_a_chain_of_the_product_rule_judges_each_link_and_leaves_the_laws():
    chain = ("$$\\mathbf{N}_A = \\frac{d}{dt}(\\mathbf{s}_A \\times \\mathbf{Q}) = \\frac{d\\mathbf{s}_A}{dt} \\times "
             "\\mathbf{Q} + \\mathbf{s}_A \\times \\frac{d\\mathbf{Q}}{dt} = \\mathbf{u} \\times (m\\mathbf{u}) + "
             "\\mathbf{s}_A \\times \\mathbf{G} = 0 + \\mathbf{s}_A \\times \\mathbf{G}$$\n")
    # the definition, the product rule (holds), the text's own facts ṡ_A = 𝐮 and Q̇ = 𝐆 (unjudged), 𝐮 × m𝐮 = 0
    assert last(chain) == ["unchecked", "holds", "unchecked", "holds"]


def test_positions_between_named_points_reverse_and_add():
    reading = nv.read("\\mathbf{r}_{A/C} = \\mathbf{r}_{A/B} + \\mathbf{r}_{B/C} = -\\mathbf{r}_{C/A}")
    values = [m.value for m in reading.members[0]]
    assert values[0] == values[1] == values[2]


def test_a_vector_set_again_to_what_cannot_be_compared_takes_the_later_value():
    law = "$$\\mathbf{N}_A = \\frac{d\\mathbf{Q}}{dt}$$\n\n"
    again = "$$\\mathbf{N}_A = \\mathbf{s}_A \\times \\mathbf{G}$$\n\n"
    size = "$$|\\mathbf{N}_A| = |\\mathbf{s}_A \\times \\mathbf{G}| = |\\mathbf{G} \\times \\mathbf{s}_A|$$\n"
    assert last(law + again + size) == ["holds", "holds"]


def test_a_statement_the_vector_algebra_reader_leaves_unjudged_is_judged_as_general_vectors():
    # 𝐑 and 𝐏 are vectors the vector-algebra reader cannot tie to the body
    first = "$$\\mathbf{L} = \\mathbf{J} + \\mathbf{R} \\times \\mathbf{P}$$\n\n"
    assert last(first + "$$\\mathbf{L} = \\mathbf{J} - \\mathbf{P} \\times \\mathbf{R}$$\n") == ["holds"]
    assert last(first + "$$\\mathbf{L} = \\mathbf{J} + \\mathbf{P} \\times \\mathbf{R}$$\n") == ["typo"]


def test_norms_in_double_bars_side_by_side_are_a_product():
    reading = nv.read("||\\mathbf{s} \\times \\mathbf{G}|| = ||\\mathbf{s}||\\:||\\mathbf{G}||\\sin(\\theta)")
    assert len(reading.members[0]) == 2
    assert last("$$\\mathbf{N} = \\mathbf{s} \\times \\mathbf{G}$$\n\n"
                "$$||\\mathbf{N}|| = ||\\mathbf{G} \\times \\mathbf{s}|| = ||\\mathbf{s}||\\:||\\mathbf{G}||\\sin(\\theta)$$\n") \
        == ["holds", "unchecked"]
