"""Macros a file uses without defining them, read as symbols where the file's own use shows one.

Takes: the text of a notes file and the macros it defines (`derive.lecture.texmacros.definitions`).
Gives: `as_symbols`, a macro for each control word the file uses, does not define and the reader
cannot read (a project's shared macro package left out of the file: ``\\gD_2``, ``\\gs'``), whose
every use shows it to be one symbol: it never takes an argument (no ``{`` or ``[`` after any use)
and at least one use carries an index, a power or a prime (``\\gD_j``, ``\\gl^2``, ``\\gs'``) or
stands alone as a term between signs, commas, brackets or a relation (``{\\vm}``, ``t - \\gn,``,
``\\[ \\gW \\equiv``). Such a macro is read as an upright symbol of its own name (``\\mathrm{gD}``):
nothing is assumed of what it stands for, so a display that relates it only to other such names
stays `unchecked` naming them, as letters the text has not tied would; one that ties it to the
derivation (``\\dot\\omega_1 = -\\gW \\omega_2`` after ``\\gW \\equiv …``) is judged; a macro
used between two terms (a relation or an operator of the package) or with an argument stays
unread, unless the package the file loads is one whose commands the reader knows
(`derive.lecture.package_macros`: semtex's ``\\DefineAs``, ``\\pa{…}``, ``\\TimeDerivative{…}``).
May import: the standard library, ``pylatexenc``, `derive.lecture.source`, `derive.lecture.texmacros`,
`derive.lecture.vocabulary`.
"""
from __future__ import annotations

import functools
import re

from pylatexenc import latex2text, latexwalker

from derive.lecture import source, texmacros
from derive.lecture import vocabulary as vc

# a control word, after any number of escaped backslashes (\\ is a line break, not a macro)
_USE = re.compile(r"\\\\|\\([A-Za-z]+)")
_OPENS = "{["                  # an argument after a use
_MARKS = "_^'"                 # an index, a power or a prime on a use
_BEFORE, _AFTER = "+-=(,{[$&", "+-=),}"     # a use alone between signs, commas or brackets: a term
# a relation after a use that opens a term (\[ \gW \equiv …): the use is that side's term
_RELATION = re.compile(r"[=<>]|\\(?:equiv|approx|simeq|le|ge|leq|geq|neq|ne|coloneqq)(?![A-Za-z])")


# TeX's and amsmath's commands that pylatexenc's tables leave out (symbols, spacing, sizes, styles)
_ALSO_LATEX = frozenset("""Re Im imath jmath bot top dagger ddagger Box triangle degree checkmark mkern mskip kern
    hskip vskip hfill hfil vfill relax strut mathstrut mathring implies impliedby iff coloneqq eqqcolon
    colon bigl bigr Bigl Bigr biggl biggr Biggl Biggr middle limits nolimits displaystyle textstyle
    scriptstyle scriptscriptstyle phantom vphantom hphantom smash boxed cancel bcancel xcancel tag notag
    nonumber enspace thinspace negthinspace medspace thickspace negmedspace negthickspace dotsb dotsc
    dotsi dotsm dotso hdots vdots ddots iddots""".split())


@functools.lru_cache(maxsize=1)
def _latex_names() -> frozenset:
    """The commands of LaTeX and its common packages (``\\int``, ``\\prime``, ``\\hbar``): never a
    file's own macro, whether or not the reader reads them."""
    names = set()
    for db in (latex2text.get_default_latex_context_db(), latexwalker.get_default_latex_context_db()):
        for category in db.categories():
            names.update(spec.macroname for spec in db.iter_macro_specs([category]))
    return frozenset(names) | _ALSO_LATEX


def _unreadable(name: str) -> bool:
    """Whether the reader refuses the control word on its own (it knows every other one)."""
    try:
        vc.scan(source.normalize("\\" + name + " "))
    except vc.NotRead as e:
        return str(e).startswith(f"cannot read '\\{name}'")
    except Exception:        # noqa: BLE001  (any other refusal: not a macro this rule reads)
        return False
    return False


def as_symbols(text: str, defined: dict) -> dict[str, texmacros.Macro]:
    """The file's undefined macros that its use shows to be symbols, each as an upright symbol
    of its name.

    Parameters
    ----------
    text : str
        The notes file (prose and math).
    defined : dict
        The macros the file defines (they are expanded as written, never read here).

    Returns
    -------
    dict
        name → `texmacros.Macro` with no argument and the body ``\\mathrm{name}``; empty when the
        file uses no control word the reader cannot read.
    """
    uses: dict[str, list[tuple[str, str]]] = {}
    for m in _USE.finditer(text):
        name = m.group(1)
        if name is None or name in defined or name in vc.GREEK or name in vc.DECORATIONS or name in vc.FUNCTIONS:
            continue            # the reader's own words first: the cheap test
        before = text[:m.start()].rstrip()[-1:]
        rest = text[m.end():].lstrip(" \t")
        after = "=" if _RELATION.match(rest) else rest[:1]
        uses.setdefault(name, []).append((before, after))
    out: dict[str, texmacros.Macro] = {}
    for name, seen in uses.items():
        if any(a in _OPENS for _, a in seen if a):
            continue
        if not any(a in _MARKS or (b in _BEFORE and a in _AFTER) for b, a in seen if a and b):
            continue
        if name not in _latex_names() and _unreadable(name):
            out[name] = texmacros.Macro(0, r"\mathrm{" + name + "}")
    return out
