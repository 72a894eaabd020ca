"""The notes reader on products of turns written by their axis and angle (R(\\hat z, \\alpha), R_z(\\alpha)),
never written out as matrices: a statement whose members are such products holds when they are equal
for every angle; one that is not such an identity is left unchecked, never flagged."""
import kept_readings as kept

HEAD = "# Rotations\n\nA general rotation is a product of turns about the coordinate axes.\n\n"

verdicts = kept.verdicts_by_line


def test_turns_about_named_axes_rewritten_by_commuting_turns_about_one_axis_hold():
    text = HEAD + ("$$\nR(\\hat z,\\alpha) R(\\hat y,\\beta) R(\\hat z,-\\alpha) R(\\hat z, \\gamma) R(\\hat z,\\alpha)"
                   " = R(\\hat z,\\alpha) R(\\hat y,\\beta) R(\\hat z,\\gamma)\n$$\n")
    assert verdicts(text)[5] == {"holds"}


def test_a_chain_link_of_turns_is_read_with_the_member_before_it():
    text = HEAD + ("$$\n\\begin{align}\nR(\\alpha,\\beta,\\gamma) & = R({\\hat y}',\\beta) R({\\hat z}, \\gamma) "
                   "R({\\hat z},\\alpha)\\\\\n& = R({\\hat z},\\alpha) R({\\hat y},\\beta) R({\\hat z},\\gamma) "
                   "R({\\hat z}, -\\alpha) R({\\hat z},\\alpha)\\\\\n& = R({\\hat z},\\alpha) R({\\hat y},\\beta) "
                   "R({\\hat z},\\gamma)\n\\end{align}\n$$\n")
    claims = kept.by_line(text)[5]
    assert [c.verdict for c in claims if c.latex.strip().startswith("=")][-1] == "holds"


def test_turns_by_subscripted_axis_and_angle_hold_as_an_identity_of_every_angle():
    text = HEAD + "$$\nR_x(\\theta) R_x(-\\theta) R_y(\\phi) = R_y(\\phi)\n$$\n"
    assert verdicts(text)[5] == {"holds"}


def test_turns_that_are_not_equal_for_every_angle_are_not_flagged():
    text = HEAD + "$$\nR_z(\\alpha) R_y(\\beta) = R_y(\\alpha) R_z(\\beta)\n$$\n"
    assert verdicts(text)[5] == {"unchecked"}


def test_a_turn_about_a_moved_axis_is_not_read():
    text = HEAD + "$$\nR(\\hat Z,\\gamma) R(\\hat Z,-\\gamma) = R(\\hat z,\\alpha) R(\\hat z,-\\alpha)\n$$\n"
    assert verdicts(text)[5] == {"unchecked"}


def test_turns_in_sized_brackets_hold_as_in_plain_ones():
    text = HEAD + "$$\nR_x\\left(\\theta\\right) R_x\\left(-\\theta\\right) R\\left(\\hat y,\\phi\\right) = R_y(\\phi)\n$$\n"
    assert verdicts(text)[5] == {"holds"}
