"""A text's own macros, read and expanded as TeX expands them."""
import pytest

import kept_readings as kept
from derive.lecture import source, texmacros

DEFS = (r"\newcommand{\vect}[1]{\vec{\boldsymbol{#1}}}"
        r"\providecommand{\d}{\mathrm{d}}"
        r"\newcommand{\pdiff}[3][]{\frac{\partial^{#1}#2}{\partial{#3}^{#1}}}"
        r"\newcommand{\diff}[3][]{\frac{\d^{#1} #2}{\d{#3}^{#1}}}")


def expanded(latex, defs=DEFS):
    return source.normalize(latex, source.macros(defs))


def test_an_optional_first_argument_takes_its_default_when_not_given():
    assert expanded(r"\diff{x}{t}") == r"\frac{\mathrm{d} x}{\mathrm{d} t}"


def test_an_optional_first_argument_is_read_from_brackets():
    assert expanded(r"\diff[2]{x}{t}") == r"\frac{\mathrm{d}^{2} x}{\mathrm{d} t^{2}}"


def test_an_empty_mandatory_argument_is_an_argument():
    # \diff{}{t}: the operator d/dt, then the next macro's own arguments
    assert expanded(r"\diff{}{t}\pdiff{L}{\dot{\theta}}") == \
        r"\frac{\mathrm{d} }{\mathrm{d} t}\frac{\partial L}{\partial{\dot{\theta}}}"


def test_arguments_are_one_token_when_not_braced():
    assert expanded(r"\vect\omega + \vect L") == r"\vec{\boldsymbol{\omega}} + \vec{\boldsymbol{L}}"


def test_a_macro_in_an_argument_of_the_same_macro_is_expanded():
    assert expanded(r"\vect{\vect{a}}") == r"\vec{\boldsymbol{\vec{\boldsymbol{a}}}}"


def test_macros_inside_other_macros_bodies_are_expanded():
    defs = DEFS + r"\newcommand{\ddt}[1]{\diff{#1}{t}}"
    assert expanded(r"\ddt{\theta}", defs) == r"\frac{\mathrm{d} \theta}{\mathrm{d} t}"


@pytest.mark.parametrize("defs", [
    r"\def\half{\frac12} \def\w#1#2{\omega_{#1#2}}",
    r"\newcommand\half{\frac12} \newcommand*{\w}[2]{\omega_{#1#2}}",
])
def test_def_and_newcommand_with_and_without_arguments(defs):
    assert expanded(r"\half \w{1}{2}", defs) == r"\frac{1}{2} \omega_{12}"


def test_renewcommand_replaces_and_providecommand_does_not():
    defs = r"\newcommand{\k}{a} \renewcommand{\k}{b} \providecommand{\k}{c}"
    assert source.macros(defs)["k"].body == "b"


def test_declare_math_operator_is_an_operator_name():
    assert expanded(r"\Tr\,A", r"\DeclareMathOperator{\Tr}{Tr}") == r"\mathrm{Tr}\,A"


def test_a_macro_name_is_not_a_prefix_of_a_longer_command():
    assert expanded(r"\dot{x} + \d x") == r"\dot{x} + \mathrm{d} x"


def test_a_control_word_in_a_body_does_not_merge_with_the_letter_after_it():
    assert expanded(r"\w x", r"\newcommand{\w}{\omega}") == r"\omega x"
    assert expanded(r"\w{x}", r"\newcommand{\w}[1]{\alpha#1}") == r"\alpha x"


def test_a_definition_inside_a_display_is_not_read_as_mathematics():
    assert expanded(DEFS + r"\diff{x}{t} = 0") == r"\frac{\mathrm{d} x}{\mathrm{d} t} = 0"
    assert expanded(DEFS) == ""


@pytest.mark.parametrize("defs, name", [
    (r"\newcommand{\loopy}{\loopy + 1}", "loopy"),
    (r"\def\ping{\pong} \def\pong{2\ping}", "ping"),
])
def test_a_macro_that_expands_into_itself_raises_naming_it(defs, name):
    with pytest.raises(texmacros.MacroLoop, match=name):
        texmacros.expand("\\" + name, source.macros(defs))


def test_a_self_referencing_macro_leaves_its_display_unchecked_naming_it():
    text = ("# Energy\n\n$$\\newcommand{\\loopy}{\\loopy}$$\n\n"
            "$$T = \\frac{1}{2} I_1 \\omega_1^2 + \\loopy$$\n")
    [check] = kept.check_text(text)
    assert check.verdict == "unchecked"
    assert "\\loopy" in check.why


def test_a_display_written_with_the_files_macros_is_checked():
    text = ("# Energy\n\n$$\\newcommand{\\half}{\\frac{1}{2}}\\newcommand{\\w}[2][1]{\\omega_{#1}^{#2}}$$\n\n"
            "$$T = \\half I_1 \\w{2} + \\half I_2 \\w[2]{2} + \\half I_3 \\w[3]{2}$$\n")
    assert [c.verdict for c in kept.check_text(text)] == ["holds"]


def test_a_differential_with_a_braced_variable_is_the_derivative():
    # \d{#3} in a macro body gives \mathrm{d}{t}: the braces only group, d{t} is dt
    text = "# Rates\n\n$$\\frac{\\mathrm{d} \\gamma}{\\mathrm{d}{t}} = \\dot{\\gamma}$$\n"
    assert [c.verdict for c in kept.check_text(text)] == ["holds"]
