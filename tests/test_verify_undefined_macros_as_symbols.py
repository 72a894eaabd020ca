"""A macro a LaTeX file uses without defining it (its project's shared macro package left out)
is read as a symbol of its own name where the file's own use shows one: never given an argument,
and once at least written with an index, a power or a prime, or alone as a term. A display that
ties such a symbol to the derivation is then judged; a macro used between terms (a relation of
the package) or given an argument stays unread, naming itself."""
from __future__ import annotations

import kept_readings as kept
from derive.lecture import source
from derive.lecture.undefined_macros import as_symbols

TOP = r"""\documentclass{article}
\usepackage{projectmacros}
\begin{document}
\section*{The free symmetric top}
If $I_1 = I_2$ and $\tau = 0$, the third equation gives a constant $\tilde{\omega}_3$ and with
\[
\gW \equiv \tilde{\omega}_3 \frac{I_3 - I_1}{I_1}
\]
the other two read
\[
\dot{\tilde{\omega}}_1 = -\gW \tilde{\omega}_2
\]
\[
\dot{\tilde{\omega}}_2 = SIGN\gW \tilde{\omega}_1
\]
and the package's own relation names the product $\gP \DefineAs \gW \tilde{\omega}_1$, its
bracket $\pa{\gW t}$ taking an argument.
\end{document}
"""


def _verdicts(sign: str) -> dict[int, str]:
    return {c.line: c.verdict for c in kept.check_text(TOP.replace("SIGN", sign), path="top.tex")}


def test_a_rate_written_with_an_undefined_macro_is_checked():
    got = _verdicts("")
    assert got[10] == "holds" and got[13] == "holds"


def test_a_sign_slip_beside_an_undefined_macro_is_flagged():
    assert _verdicts("-")[13] == "typo"


def test_only_a_macro_used_as_a_symbol_is_read_as_one():
    text = TOP.replace("SIGN", "")
    read = as_symbols(text, source.macros(text))
    assert set(read) == {"gW"}                    # not \DefineAs (between terms), \pa (an argument), \gP
    assert read["gW"].nargs == 0 and read["gW"].body == r"\mathrm{gW}"


def test_a_command_of_latex_is_never_a_files_own_macro():
    text = r"$$ \int_0^1 x \, dx = \frac{1}{2}, \quad \imath^2 = -1, \quad f^\prime = g $$"
    assert as_symbols(text, source.macros(text)) == {}


def test_a_macro_the_file_defines_is_expanded_not_guessed():
    text = r"\newcommand{\gW}{\Omega}" + TOP.replace("SIGN", "")
    assert as_symbols(text, source.macros(text)) == {}
