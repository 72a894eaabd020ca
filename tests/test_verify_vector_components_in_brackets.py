"""The notes reader on a vector written as its three components in round brackets,
``\\boldsymbol\\Omega = (\\omega \\sin\\alpha, 0, \\omega \\cos\\alpha)``: the triple is the column a
``pmatrix`` would write, so the vector set again in other symbols is compared with it component by
component; a pair or a longer list (an interval, a point of a plane, a state) is not a 3-vector."""
from kept_readings import line_of, verdicts_by_line as verdicts

NOTE = ("# A cone rolling on a plane\n\nThe rate about the line of contact:\n\n"
        "$$\\omega = \\dot\\psi \\cot \\alpha$$\n\nThe angular velocity in the cone's axes:\n\n"
        "$$\\boldsymbol \\Omega = (\\omega \\sin \\alpha, 0, \\omega \\cos \\alpha)$$\n\nor\n\n"
        "$$\\boldsymbol \\Omega = \\left(\\dot\\psi \\cos \\alpha, 0, "
        "\\dot\\psi \\frac{\\cos^2 \\alpha}{\\sin \\alpha}\\right)$$\n\n")


def test_a_vector_set_again_as_a_triple_holds_when_its_components_agree():
    got = verdicts(NOTE)
    assert got[line_of(NOTE, "\\left(")] == {"holds"}


def test_a_triple_with_a_component_slipped_is_flagged():
    slipped = NOTE.replace("\\cos^2 \\alpha", "\\cos \\alpha")
    got = verdicts(slipped)
    assert got[line_of(slipped, "\\left(")] & {"typo", "fails"}


def test_a_pair_is_not_read_as_a_vector():
    pair = NOTE.replace(", 0, \\omega \\cos \\alpha)", ", \\omega \\cos \\alpha)")
    got = verdicts(pair)
    assert all(not got.get(line_of(pair, mark), set()) & {"holds", "typo", "fails"}
               for mark in ("\\omega \\sin", "\\left("))


def test_a_vector_named_in_words_then_written_as_a_triple_is_named_anew():
    named = NOTE.replace("The angular velocity in the cone's axes:",
                         "The angular velocity $\\boldsymbol \\Omega = \\omega \\boldsymbol n$, with $\\boldsymbol n$ "
                         "along the line of contact, in the cone's axes:")
    got = verdicts(named)
    assert got[line_of(named, "\\omega \\sin")] == {"unchecked"} and got[line_of(named, "\\left(")] == {"holds"}
    slipped = named.replace("\\cos^2 \\alpha", "\\cos \\alpha")
    assert verdicts(slipped)[line_of(slipped, "\\left(")] & {"typo", "fails"}


def test_three_numbers_are_a_direction_not_the_components_of_a_name():
    axes = ("# Axes\n\nThe fixed axis $Z$:\n\n$$\\boldsymbol{a} = (0, 0, 1)$$\n\nbecomes, in the moving basis,\n\n"
            "$$\\boldsymbol{a} = \\begin{pmatrix} \\sin\\theta \\sin\\psi \\\\ \\sin\\theta \\cos\\psi \\\\ "
            "\\cos\\theta \\end{pmatrix}$$\n\nthat is\n\n"
            "$$\\boldsymbol{a} = (\\sin\\theta \\sin\\psi, \\sin\\theta \\cos\\psi, \\cos\\theta)$$\n")
    got = verdicts(axes)
    assert not got.get(line_of(axes, "\\sin\\theta"), set()) & {"typo", "fails"}
    assert got[line_of(axes, "(\\sin")] == {"holds"}
