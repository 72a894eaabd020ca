"""The notes reader on unit vectors set with the dotless letters: ``\\hat{\\imath}`` and
``\\hat{\\jmath}`` are î and ĵ, read as ``\\hat{i}`` and ``\\hat{j}`` are (TeX drops the dot under a hat)."""
import kept_readings as kept
from derive.lecture import texmacros

verdicts, line_of = kept.verdicts_by_line, kept.line_of
PROSE = ("# Notes\n\nThe moving frame turns with the angular velocity $\\boldsymbol{\\Omega}$, and its unit "
         "vectors turn with it:\n\n")


def test_the_dotless_letters_are_the_letters_i_and_j():
    assert texmacros.synonyms("\\hat{\\imath} + \\hat\\jmath") == "\\hat{i} + \\hat j"
    assert texmacros.synonyms("\\imathx") == "\\imathx"       # another command's name is left alone


def test_a_rate_of_a_dotless_unit_vector_is_read_as_that_of_the_dotted_letter():
    for letter in ("\\imath", "\\jmath"):
        text = PROSE + f"$$\\frac{{d\\boldsymbol{{\\hat{{{letter}}}}}}}{{dt}} = \\boldsymbol{{\\Omega}}\\times\\boldsymbol{{\\hat{{{letter}}}}}$$\n"
        assert verdicts(text)[line_of(text, "$$")] == {"holds"}


def test_a_wrong_rate_of_a_dotless_unit_vector_is_not_taken_to_hold():
    text = PROSE + "$$\\frac{d\\boldsymbol{\\hat{\\imath}}}{dt} = \\boldsymbol{\\hat{\\imath}}\\times\\boldsymbol{\\Omega}$$\n"
    assert "holds" not in verdicts(text)[line_of(text, "$$")]
