"""The notes reader on products of names written with arguments (R(ẑ, α), R_z(α)): such names are
turns and operators as often as numbers, so a statement that only holds if their products commute
is no identity "whatever the names stand for"; one that holds for numbers and matrices alike still is."""
import kept_readings as kept

HEAD = "# Rotations\n\n"


def _verdicts(display):
    text = HEAD + "$$\n" + display + "\n$$\n"
    return kept.verdicts_by_line(text)[kept.line_of(text, "$$")]


def test_turns_written_with_arguments_in_swapped_order_are_not_passed():
    assert "holds" not in _verdicts("R(\\hat z,\\alpha) R(\\hat y,\\beta) = R(\\hat y,\\beta) R(\\hat z,\\alpha)")
    assert "holds" not in _verdicts("R_z(\\alpha) R_y(\\beta) R_z(\\gamma) = R_z(\\gamma) R_y(\\beta) R_z(\\alpha)")


def test_a_relation_of_untied_names_without_arguments_still_holds_whatever_they_stand_for():
    assert _verdicts("a (b + c) = a b + a c") == {"holds"}
