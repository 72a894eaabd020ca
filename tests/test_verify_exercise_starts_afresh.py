"""The notes reader on a problem set: a heading that opens a new exercise (``EXERCISE 6.8``,
``Problem 2``) forgets what the text defined in its own names in the exercise before, so the next
exercise's definition of the same symbol is a definition again, never a claim against the old one."""
import kept_readings as kept
from derive.lecture.problem_sections import starts_a_problem

verdicts, line_of = kept.verdicts_by_line, kept.line_of


def test_a_symbol_defined_again_in_the_next_exercise_is_not_judged_against_the_first():
    text = ("# Exercise 1\n\nA thin bar along its axis.\n\n$$\nI_{xx} = 0\n$$\n\n"
            "# Exercise 2\n\nA flywheel spun about its axis.\n\n$$\nI_{xx} = I_1\n$$\n")
    assert verdicts(text)[line_of(text, "$$\nI_{xx} = I_1")] == {"unchecked"}


def test_within_one_exercise_the_texts_definition_still_holds_for_the_next_section():
    text = ("# Exercise 1\n\nA thin bar along its axis.\n\n$$\nI_{xx} = 0\n$$\n\n"
            "## Its moment again\n\n$$\nI_{xx} = I_1\n$$\n")
    assert "fails" in verdicts(text)[line_of(text, "$$\nI_{xx} = I_1")]


def test_the_headings_that_open_an_exercise():
    assert starts_a_problem("EXERCISE 6.8") and starts_a_problem("Problem 1: EXERCISE 5.13")
    assert starts_a_problem("Aufgabe 2: Kardanisch gelagerter Kreisel") and starts_a_problem("Exercice 3")
    assert not starts_a_problem("Problems of rigid bodies") and not starts_a_problem("The exercise bike")
    assert not starts_a_problem("Matlab Code Used")
