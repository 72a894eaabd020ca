"""The notes reader on the signs texts write a definition with, mathtools' cases, aligned rows of
column pairs, and a file's macro used as a command's unbraced argument."""
import pytest

import kept_readings as kept
from derive.lecture import source
from derive.lecture.statements import statements


def verdicts(text):
    return [(c.line, c.verdict) for c in kept.check_text(text)]


_DEFINED = "\n\n$$Q = I_1 \\omega_1$$\n\n$$Q = 2 I_1 \\omega_1$$\n"


@pytest.mark.parametrize("sign", [r"\equiv", ":=", r"\coloneqq", r"\triangleq"])
def test_a_definition_written_with_its_own_sign_defines_a_name_like_equiv(sign):
    text = f"# Notes\n\n$$Q {sign} I_1 \\omega_1$${_DEFINED}"
    assert verdicts(text) == [(3, "unchecked"), (5, "holds"), (7, "typo")]


def test_a_label_colon_before_a_statement_is_not_a_definition():
    assert r"\equiv" not in source.normalize(r"\theta: \quad \dot\theta = 0")
    assert r"\equiv" not in source.normalize(r"a =: b")


_ROWS = ("I_1 \\dot{\\omega}_1 = (I_2 - I_3)\\omega_2\\omega_3 \\\\\n"
         "I_2 \\dot{\\omega}_2 = (I_1 - I_3)\\omega_3\\omega_1\n")


@pytest.mark.parametrize("env", ["dcases", "dcases*", "rcases", "drcases"])
def test_mathtools_cases_are_cut_into_rows_like_cases(env):
    text = f"# Euler\n\n\\[\n\\begin{{{env}}}\n{_ROWS}\\end{{{env}}}\n\\]\n"
    assert verdicts(text) == [(3, "holds"), (3, "typo")]


_T = r"T &= \frac{1}{2} I_1 \omega_1^2 + \frac{1}{2} I_2 \omega_2^2 + \frac{1}{2} I_3 \omega_3^2"


def test_column_pairs_side_by_side_in_an_aligned_row_are_separate_statements():
    text = f"# Notes\n\n\\begin{{align*}}\n{_T} & Q &\\equiv I_1 \\omega_1\n\\end{{align*}}{_DEFINED}"
    assert verdicts(text) == [(3, "holds"), (3, "unchecked"), (7, "holds"), (9, "typo")]


def test_words_in_an_aligned_rows_other_column_stay_with_its_statement():
    text = f"# Notes\n\n\\begin{{align*}}\n{_T} && \\text{{the kinetic energy}}\n\\end{{align*}}\n"
    assert verdicts(text) == [(3, "holds")]


def test_a_column_that_goes_on_with_the_statement_before_it_is_not_a_new_statement():
    rows = [r"F_x &= m a_x &\rightarrow F_x &= m a_x", r"\Omega_1 &= a, \quad \Omega_2 &&= -a"]
    assert [len(statements(r"\begin{alignat}{2}" + row + r"\end{alignat}")) for row in rows] == [1, 2]


def test_a_files_macro_as_the_unbraced_argument_of_a_command_is_its_whole_expansion():
    macros = source.macros(r"\newcommand{\vw}{\boldsymbol{\omega}} \newcommand{\vm}{\mathbf{m}}")
    assert source.normalize(r"\dot\vw = 0", macros) == r"\dot{\boldsymbol{\omega}} = 0"
    assert source.normalize(r"\norm\vm = G", macros) == r"\left|\mathbf{m}\right| = G"
    assert source.normalize(r"\vw_1", macros) == r"\boldsymbol{\omega}_1"
