"""The notes reader on a term crossed out: ``\\cancelto{0}{X}`` is read as the value the arrow gives
(the author's word that X is 0 there), ``\\cancel{X}``, ``\\bcancel{X}`` and ``\\xcancel{X}`` as X,
the stroke only marking it; and on a comma typed for a thin space between factors (``+,\\Omega``,
``\\Omega ,\\sin``), read as that space."""
import kept_readings as kept
from derive.lecture import source, texmacros

verdicts, line_of = kept.verdicts_by_line, kept.line_of


def test_a_term_cancelled_to_zero_is_read_as_zero():
    text = "# Notes\n\n$$(a + b)^2 = a^2 + 2 a b + b^2 + \\cancelto{0}{c\\,d}$$\n"
    assert verdicts(text)[line_of(text, "$$(a + b)^2")] == {"holds"}


def test_a_term_cancelled_to_zero_does_not_make_a_wrong_identity_hold():
    text = "# Notes\n\n$$(a + b)^2 = a^2 + a b + b^2 + \\cancelto{0}{c\\,d}$$\n"
    assert "holds" not in verdicts(text)[line_of(text, "$$(a + b)^2")]


def test_a_term_struck_through_without_a_value_is_read_as_written():
    assert source.normalize(r"a + \bcancel{b} = \xcancel{c} + \cancel{d}") == "a + {b} = {c} + {d}"
    assert source.normalize(r"x = \cancelto{0}{\frac{\partial}{\partial t} y} + z") == "x = {0} + z"


def test_a_comma_typed_for_a_thin_space_between_factors_is_read_as_a_space():
    text = "# Notes\n\n$$(a + b)^2 = a^2 + 4 a ,\\frac{b}{2} +,b^2$$\n"
    assert verdicts(text)[line_of(text, "$$(a + b)^2")] == {"holds"}


def test_a_comma_after_a_sign_in_a_script_or_between_arguments_is_kept():
    assert texmacros.synonyms(r"\omega_{+,-} = x^{+,-}") == r"\omega_{+,-} = x^{+,-}"
    assert texmacros.synonyms(r"f(x ,\sin y)") == r"f(x ,\sin y)"
    assert texmacros.synonyms(r"\mathbf I=\mathbf R\quad ,\mathbf{\dot{I}}") == r"\mathbf I=\mathbf R\quad ,\mathbf{\dot{I}}"


def test_a_comma_read_as_a_thin_space_does_not_make_a_wrong_identity_hold():
    text = "# Notes\n\n$$(a + b)^2 = a^2 + 2 a ,\\frac{b}{2} +,b^2$$\n"
    assert "holds" not in verdicts(text)[line_of(text, "$$(a + b)^2")]
