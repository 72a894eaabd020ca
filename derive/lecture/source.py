"""LaTeX as real texts write it, brought to the plain form the formula reader takes.

Takes: the text of a notes file, or one formula of it. Gives: the text with what is not rendered
blanked out (`rendered`), the file's own macros (`macros`), and each formula normalised
(`normalize`): the same mathematics, in the small dialect `derive.lecture.latex` scans.
May import: the standard library, ``pylatexenc``, `derive.lecture.texmacros`, `derive.lecture.latex_spaces`,
`derive.lecture.angle_columns`, `derive.lecture.bar_determinants`, `derive.lecture.bracket_cross`, `derive.lecture.latex_spellings`, `derive.lecture.left_indices`, `derive.lecture.fences`, `derive.lecture.tex_structure` and `derive.lecture.statements` (its top-level comma split).

Why pylatexenc: a formula from a real text carries comments (``%``), optional arguments
(``\\sqrt[3]{x}``, ``\\\\[2pt]``), nested groups, environments and the file's own macros. Its
walker turns the formula into nodes (macro with its parsed arguments, group, characters,
environment), so each rule below is one entry of a table acting on a node, and nothing is
matched with a regular expression across braces. Text is never evaluated: the nodes are
printed back as LaTeX.

What is normalised:

* **Characters**: Unicode math (− × · ⋅ ≤ ≥ ≈ ≡ ≠ ′ ″ ² ³ ½ ∂ ∑ √ ∞ →, Greek letters, the
  non-breaking space) becomes its command; HTML entities (``&#8211;``, ``&minus;``, ``&lt;``)
  are decoded.
* **Not mathematics**: ``\\tag``, ``\\notag``, ``\\nonumber``, ``\\label``, ``\\displaystyle``,
  ``\\hspace``, ``\\phantom``, ``\\noalign``, a kern by a length (``\\mkern-1.5mu``), comments,
  a font size switch (``\\footnotesize{…}``, ``\\small``), ``\\left.`` and ``\\right.`` are dropped.
* **Wrappers**: ``\\boxed{X}``, ``\\ensuremath``, ``\\mathcal``/``\\mathscr`` (their letter),
  ``\\pmb``/``\\vb``/``\\bm`` (bold), ``\\vu`` (a bold hat), ``\\operatorname{sin}`` (the
  function), ``\\dfrac``/``\\tfrac`` (``\\frac``), ``\\qty``, ``\\abs``, ``\\norm``,
  ``\\dv``/``\\pdv`` (the physics package's derivatives), ``\\vdot``/``\\cross``.
* **Degrees**: ``30^{\\circ}`` is 30·π/180.
* **Order of scripts**: ``\\omega^2_1`` is ``\\omega_1^2``; an empty group ``{}`` is nothing; a prime
  set as a superscript, ``V^{\\prime}``, is ``V'``; ``R\\left(t\\right)`` (one token sized) is ``R(t)``.
* **The file's macros**: ``\\newcommand``, ``\\renewcommand``, ``\\providecommand``, ``\\def``
  and ``\\DeclareMathOperator``, with their arguments (#1 … #9) and an optional first argument's
  default, expanded as TeX expands them before the walk (`derive.lecture.texmacros`).
"""
from __future__ import annotations

import functools
import html
import re
import unicodedata

from pylatexenc.latexwalker import (LatexCharsNode, LatexCommentNode, LatexEnvironmentNode,
                                    LatexGroupNode, LatexMacroNode, LatexMathNode,
                                    LatexSpecialsNode, LatexWalker,
                                    get_default_latex_context_db)
from pylatexenc.macrospec import MacroSpec

from derive.lecture import angle_columns, bar_determinants, bracket_cross, differentials, fences, imaginary_unit, left_indices, tex_structure, texmacros, units
from derive.lecture.latex_spaces import KERN, ONE_SPACE, SPACE, SPACE_SYMBOL, SPACING, TIE
from derive.lecture.latex_spellings import DEFINITION_NAMES, EQUATION_LABEL, FONT_SIZES, PRIME_SUPERSCRIPT, REWRITTEN_BOLD_NAMES, SIZED_ONE_TOKEN
from derive.lecture.statements import split_top

# --- characters --------------------------------------------------------------------------------
_UNICODE = {
    "\u2212": "-", "\u2013": "-", "\u2014": "-", "\u00d7": r"\times ", "\u00b7": r"\cdot ",
    "\u22c5": r"\cdot ", "\u2219": r"\cdot ", "\u2264": r"\le ", "\u2265": r"\ge ",
    "\u2a7d": r"\le ", "\u2a7e": r"\ge ", "\u2248": r"\approx ", "\u2261": r"\equiv ",
    "\u2260": r"\neq ", "\u2032": "'", "\u2033": "''",
    "\u00bd": r"\frac{1}{2}", "\u2202": r"\partial ", "\u2211": r"\sum ",
    "\u221a": r"\sqrt ", "\u221e": r"\infty ", "\u2192": r"\to ", "\u21d2": r"\Rightarrow ",
    "\u00a0": " ", "\u2009": " ", "\u202f": " ", "\u2061": "", "\u2062": " ", "\u200b": "", "\u00b1": r"\pm ",
    "\u2207": r"\nabla ", "\u03d5": r"\phi ", "\u03c6": r"\varphi ", "\u03b5": r"\varepsilon ",
    "\u03d1": r"\vartheta ", "\u2218": r"\circ ", "\u00b0": r"^{\circ}", "\u2225": r"\parallel ",
    "\u22a5": r"\perp ", "\u27c2": r"\perp ", "\u2026": r"\ldots ", "\u22ef": r"\cdots ",
}


def _greek(ch: str) -> str | None:
    """ω → \\omega, Ω → \\Omega (by the character's Unicode name)."""
    try:
        name = unicodedata.name(ch)
    except ValueError:
        return None
    m = re.fullmatch(r"(?:MATHEMATICAL ITALIC )?GREEK (SMALL|CAPITAL) LETTER ([A-Z]+)", name)
    if not m:
        return None
    letter = m.group(2).lower()
    if letter == "lamda":
        letter = "lambda"
    return "\\" + (letter if m.group(1) == "SMALL" else letter.capitalize()) + " "


_SUBSCRIPTS = {chr(0x2080 + k): str(k) for k in range(10)}
_SUPERSCRIPTS = {"\u2070": "0", "\u00b9": "1", "\u00b2": "2", "\u00b3": "3",
                 **{chr(0x2070 + k): str(k) for k in range(4, 10)}}
_COMBINING = {"\u0307": r"\dot", "\u0308": r"\ddot", "\u0303": r"\tilde", "\u0302": r"\hat",
              "\u20d7": r"\vec", "\u0304": r"\bar"}


def characters(latex: str) -> str:
    """Unicode math and HTML entities as LaTeX commands (everything else unchanged): ω → \\omega,
    ω₃ → \\omega_{3}, θ̇ (a combining dot) → \\dot{\\theta}, r² → r^{2}."""
    if "&" in latex and re.search(r"&(#\d+|#x[0-9a-fA-F]+|[A-Za-z]+);", latex):
        latex = re.sub(r"&(#\d+|#x[0-9a-fA-F]+|[A-Za-z]+);", lambda m: html.unescape(m.group(0)), latex)
    if latex.isascii():
        return latex
    out = []
    for ch in latex:
        if out and out[-1][:1] == "\\" and out[-1][-1:] == " " and not (ch.isascii() and ch.isalpha()):
            out[-1] = out[-1][:-1]          # the space only parts a command from a letter after it: θ) is \theta)
        if ch.isascii():
            out.append(ch)
        elif ch in _COMBINING and out:
            out[-1] = _COMBINING[ch] + "{" + out[-1].strip() + "}"
        elif ch in _SUBSCRIPTS:
            out.append("_{" + _SUBSCRIPTS[ch] + "}")
        elif ch in _SUPERSCRIPTS:
            out.append("^{" + _SUPERSCRIPTS[ch] + "}")
        else:
            out.append(_UNICODE.get(ch) or _greek(ch) or ch)
    return "".join(out)


# --- what is not rendered ----------------------------------------------------------------------
def _blank(m: re.Match) -> str:
    """The matched text as spaces, its newlines kept (so line numbers do not move)."""
    return re.sub(r"[^\n]", " ", m.group(0))


_COMMENT = re.compile(r"<!--.*?-->", re.S)
_DISPLAY_ENVS = r"equation|align|alignat|eqnarray|gather|multline|flalign|displaymath|math|numcases|subnumcases"
MATH = re.compile(r"\$\$(?P<d>.+?)\$\$|\\\[(?P<b>.+?)\\\]"
                   r"|(?P<e>\\begin\{(?P<env>" + _DISPLAY_ENVS + r")\*?\}(?P<eb>.*?)\\end\{(?P=env)\*?\})"
                   r"|(?<![\\$])\$(?P<i>(?:[^$\n]|\n(?![ \t]*\n))+?)(?<!\\)\$", re.S)
"""Math in a rendered text: a display ``$$…$$`` (group d), ``\\[…\\]`` (b), a display environment (e,
its name env and its body eb) or inline ``$…$`` (i), the one pattern every reader of the text uses."""

_MATH_SPAN = re.compile(r"\$\$.+?\$\$|(?<![\\$])\$[^$\n]+?(?<!\\)\$|\\\[.+?\\\]|\\begin\{(" + _DISPLAY_ENVS + r")\*?\}.+?\\end\{\1\*?\}",
                        re.S)
_CODE = re.compile(r"(?<!`)`[^`\n]+`(?!`)")
_TEX_COMMENT = re.compile(r"((?:^|[^\\])(?:\\\\)*)(%[^\n]*)", re.M)  # an even run of \ before %
_TEX_SOURCE = re.compile(r"\\documentclass|\\begin\{document\}")


def latex_source(text: str, path: str = "") -> bool:
    """Whether a notes file is a LaTeX source (``.tex``, or a document with ``\\documentclass``)
    rather than Markdown: there ``%`` starts a comment."""
    return str(path).endswith(".tex") or _TEX_SOURCE.search(text) is not None


def rendered(text: str, latex_source: bool = False) -> str:
    """The text with what a reader never sees blanked out: HTML comments, fenced code blocks and
    inline code spans (the line structure is kept); a fenced ``math`` block is a display and a MyST
    directive's body is text (`derive.lecture.fences`).
    In a LaTeX source (``latex_source``), a ``%`` not escaped as ``\\%`` comments out the rest
    of its line, as TeX reads it, and its inline ``\\( … \\)`` and sectioning commands are read
    as Markdown's (`derive.lecture.tex_structure`)."""
    if latex_source:
        text = _TEX_COMMENT.sub(lambda m: m.group(1) + " " * len(m.group(2)), text)
        text = tex_structure.as_notes(text)
    text = _COMMENT.sub(_blank, text)
    text = fences.rendered_fences(text)
    text = _MATH_SPAN.sub(lambda m: characters(m.group(0)), _CODE.sub(_blank, text))   # θ is \theta in all its math
    return left_indices.dropped(_SMALL_SPACED_EQUALS.sub(" ", text))   # a \;=\; b; {}_I 𝐞 in one frame only


# --- the file's macros (read and expanded in `derive.lecture.texmacros`) ------------------------
macros = texmacros.definitions
definitions_removed = texmacros.definitions_removed


# --- the walk ----------------------------------------------------------------------------------
_DROP = {"tag": "*{", "label": "{", "notag": "", "nonumber": "", "displaystyle": "", "textstyle": "",
         "scriptstyle": "", "hspace": "*{", "vspace": "*{", "phantom": "{", "hphantom": "{",
         "vphantom": "{", "mathstrut": "", "strut": "", "eqref": "{", "ref": "{", "allowbreak": "",
         "medskip": "", "smallskip": "", "bigskip": "", "noindent": "", "hfill": "", "break": "", "noalign": "{",
         **dict.fromkeys(FONT_SIZES, "")}
_WRAP = {"boxed": "", "ensuremath": "", "mathcal": "", "mathscr": "", "mathfrak": "", "mathsf": "",
         "mathnormal": "", "mathtt": "", "underline": "", "overline": "", "color": None, "textcolor": None,
         "cancel": "", "bcancel": "", "xcancel": "", "cancelto": None, "bbox": None}
_RENAME = {"dfrac": "frac", "tfrac": "frac", "cfrac": "frac", "vdot": "cdot", "cross": "times",
           "cp": "times", "lvert": "vert", "rvert": "vert", "lVert": "vert", "rVert": "vert",
           "Vert": "vert", "cdotp": "cdot", "leqslant": "le", "geqslant": "ge", "dotsb": "cdots",
           "dotsm": "cdots", "dotsc": "cdots", "land": "quad", "And": "quad", "implies": "Rightarrow",
           "iff": "Leftrightarrow", "Longrightarrow": "Rightarrow", "longrightarrow": "to",
           "mathbb": "mathrm", "rm": "mathrm", "degree": "circ", "lbrace": "{", "rbrace": "}",
           "thinspace": ",", "medspace": ":", "thickspace": ";", "enspace": "quad",
           "textup": "text", "textnormal": "text",     # upright words, as \\text sets them
           # a definition written with its own sign (mathtools' :=, "equal by definition")
           **{name: "equiv" for name in DEFINITION_NAMES},
           **{"var" + g: g for g in ("Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi",
                                     "Psi", "Omega")}}
_SIZED = {f"{size}{side}": ("left" if side == "l" else "right")
          for size in ("big", "Big", "bigg", "Bigg") for side in "lr"}
"""A bracket sized by hand, opening (``\\bigl(``) or closing (``\\bigr)``): the pair ``\\left( … \\right)`` sets."""
_FUNCTION_NAMES = {"sin", "cos", "tan", "cot", "sec", "csc", "exp", "ln", "log", "sinh", "cosh", "tanh",
                   "arcsin", "arccos", "arctan"}


def _context():
    db = get_default_latex_context_db()
    specs = [MacroSpec(name, args) for name, args in _DROP.items()]
    specs += [MacroSpec(name, "{") for name, a in _WRAP.items() if a is not None]
    specs += [MacroSpec("color", "{"), MacroSpec("textcolor", "{{"), MacroSpec("bbox", "[{"), MacroSpec("cancelto", "{{")]
    specs += [MacroSpec(name, "{") for name in REWRITTEN_BOLD_NAMES | {"vu", "abs", "norm", "operatorname", "qty",
                                                                       "mathrm", "text", "mathit", "hat", "dot",
                                                                       "ddot", "tilde", "widetilde", "widehat", "bar"}]
    specs += [MacroSpec("overbrace", "{"), MacroSpec("underbrace", "{"), MacroSpec("overset", "{{"),
              MacroSpec("underset", "{{"), MacroSpec("stackrel", "{{")]
    specs += [MacroSpec("dv", "[{{"), MacroSpec("pdv", "[{{"), MacroSpec("frac", "{{"),
              MacroSpec("dfrac", "{{"), MacroSpec("tfrac", "{{"), MacroSpec("cfrac", "{{")]
    db.add_context_category("derive-notes", macros=specs, prepend=True)
    return db


@functools.lru_cache(maxsize=1)
def _ctx():
    db = _context()
    db.test_for_specials = _specials_test(db)
    return db


def _specials_test(db):
    """``db.test_for_specials`` with the specials looked up by their first character: what
    pylatexenc's own gives (the longest match across the categories, the first found of that
    length), without trying every specials of every category at each character of a formula."""
    by_first: dict = {}
    for cat in db.category_list:
        for chars, spec in db.d[cat]["specials"].items():
            if chars:
                by_first.setdefault(chars[0], []).append((chars, spec))

    def test_for_specials(s, pos, parsing_state=None):
        best, length = None, 0
        for chars, spec in by_first.get(s[pos:pos + 1], ()):
            if len(chars) > length and s.startswith(chars, pos):
                best, length = spec, len(chars)
        return best
    return test_for_specials


def _arg(node, k: int, user: dict) -> str | None:
    args = node.nodeargd.argnlist if node.nodeargd is not None else []
    if k >= len(args) or args[k] is None:
        return None
    a = args[k]
    return _print(a.nodelist, user) if isinstance(a, LatexGroupNode) else _print([a], user)


def _last_arg(node, user: dict) -> str | None:
    args = node.nodeargd.argnlist if node.nodeargd is not None else []
    for a in reversed(args):
        if a is not None:
            return _print(a.nodelist, user) if isinstance(a, LatexGroupNode) else _print([a], user)
    return None


def _macro(node, nodes, k, user) -> tuple[str, int]:
    """One macro node printed normalised; returns the text and how many following nodes it used."""
    name = node.macroname
    post = node.macro_post_space or ""
    if name in ("\\", "cr"):
        return "\\\\ ", 0                  # a row break (plain TeX's \\cr too); its spacing argument ([10pt]) is no mathematics
    if name in _DROP:
        return " ", 0
    if name in _WRAP:
        inner = (_arg(node, 0, user) if name == "cancelto" else _last_arg(node, user)) or ""  # \cancelto{0}{X}: X is 0 here
        if name in ("mathcal", "mathscr", "mathfrak", "mathsf", "mathtt"):
            return r"\mathrm{" + inner + "}", 0
        if name in ("boxed", "ensuremath", "color", "textcolor", "bbox"):   # a frame or a colour around a statement
            return (" " if name == "color" else " " + inner + " "), 0     # (\\color{red}{+}: the argument names a colour)
        return "{" + inner + "}", 0
    if name in REWRITTEN_BOLD_NAMES:          # \pmb, \vb, …: written as a bold every reader knows
        inner = _last_arg(node, user)
        if inner is None:
            return "\\" + name + post, 0
        return r"\boldsymbol{" + inner + "}" if name not in ("vec", "overrightarrow") else \
            "\\" + name + "{" + inner + "}", 0
    if name in ("overbrace", "underbrace", "overset", "underset", "stackrel") and node.nodeargd is not None:
        return _braced_label(name, node, nodes, k, user)
    if name == "vu":
        return r"\hat{\boldsymbol{" + (_last_arg(node, user) or "") + "}}", 0
    if name in ("abs", "norm"):
        return r"\left|" + (_last_arg(node, user) or "") + r"\right|", 0
    if name == "qty":
        return r"\left(" + (_last_arg(node, user) or "") + r"\right)", 0
    if name == "operatorname":
        # \operatorname{d\!}: a book's differential, its kerning inside the name
        inner = re.sub(ONE_SPACE, "", _last_arg(node, user) or "").lstrip("\\")
        return ("\\" + inner + " ") if inner in _FUNCTION_NAMES else r"\mathrm{" + inner + "}", 0
    if name in ("dv", "pdv"):
        order, f, x = _arg(node, 0, user), _arg(node, 1, user) or "", _arg(node, 2, user) or ""
        d = "d" if name == "dv" else r"\partial "
        n = f"^{{{order}}}" if order else ""
        return rf"\frac{{{d}{n} {f}}}{{{d} {x}{n}}}", 0
    if name in ("left", "right") or name in _SIZED:
        # \left. and \right. are invisible delimiters
        if k + 1 < len(nodes) and isinstance(nodes[k + 1], LatexCharsNode) and nodes[k + 1].chars.startswith("."):
            nodes[k + 1] = LatexCharsNode(parsing_state=nodes[k + 1].parsing_state,
                                          chars=nodes[k + 1].chars[1:], pos=nodes[k + 1].pos, len=nodes[k + 1].len)
            return " ", 0
        return "\\" + _SIZED.get(name, name) + post, 0
    if name in _RENAME:
        new = _RENAME[name]
        args = node.nodeargd.argnlist if node.nodeargd is not None else []
        printed = [_token_argument(name, a.latex_verbatim()) if not isinstance(a, LatexGroupNode)
                   else "{" + _print(a.nodelist, user) + "}" for a in args if a is not None]
        if new in ("{", "}"):
            return "\\" + new, 0
        return _spaced("\\" + new, printed) if printed else "\\" + new + " ", 0
    # any other macro: its own name, with its arguments normalised
    args = node.nodeargd.argnlist if node.nodeargd is not None else []
    printed = []
    for a in args:
        if a is None:
            continue
        if isinstance(a, LatexGroupNode):
            left, right = getattr(a, "delimiters", ("{", "}")) or ("{", "}")
            printed.append(left + _print(a.nodelist, user) + right)
        else:
            printed.append(_token_argument(name, a.latex_verbatim()))
    return _spaced("\\" + name, printed) if printed else "\\" + name + post, 0


def _token_argument(name: str, arg: str) -> str:
    """A fraction's argument given as one token, ``\\frac12``, in braces (``\\frac{1}{2}``, as TeX
    reads it), so the reader meets one spelling of a fraction."""
    return "{" + arg.strip() + "}" if name in ("frac", "dfrac", "tfrac", "cfrac") else arg


def _spaced(head: str, args) -> str:
    """A command and its arguments given without braces (``\\dot x``, ``\\vec N``), joined with the
    space that ended the command's name wherever two letters would meet (``\\dotx`` would be
    another command)."""
    out = head
    for a in args:
        out += " " + a if out[-1:].isalpha() and a[:1].isalpha() else a
    return out


def _braced_label(name, node, nodes, k, user) -> tuple[str, int]:
    """``\\underbrace{X}_{label}`` and ``\\overbrace{X}^{label}`` are X (the label is a comment on it),
    but ``\\overbrace{X}^{\\cdot}``, a dot over a long product, is its time derivative;
    ``\\overset{a}{=}`` and ``\\stackrel{a}{=}`` are the relation."""
    inner = _last_arg(node, user) or ""
    if name == "underset" and re.fullmatch(r"\s*(?:\\mathrm\{lim\}|\\lim|\\operatorname\{lim\})\s*", inner):
        # a limit set under its operator keeps the variable it takes to the value
        return r" \lim_{" + (_arg(node, 0, user) or "") + "} ", 0
    if name in ("overset", "underset", "stackrel"):
        return " " + inner + " ", 0
    used, label = 0, ""
    j = k + 1
    if j < len(nodes) and isinstance(nodes[j], LatexCharsNode) and nodes[j].chars.lstrip()[:1] in "^_" \
            and nodes[j].chars.strip():
        rest = nodes[j].chars.lstrip()[1:]
        if rest.strip():
            label = rest.strip()[0]
            tail = rest.strip()[1:]
            nodes[j] = LatexCharsNode(parsing_state=nodes[j].parsing_state, chars=tail, pos=nodes[j].pos, len=nodes[j].len)
        elif j + 1 < len(nodes):
            nxt = nodes[j + 1]
            label = _print(nxt.nodelist, user) if isinstance(nxt, LatexGroupNode) else _print([nxt], user)
            used = 2
        else:
            used = 1
    if name == "overbrace" and label.strip() in ("\\cdot", "\\cdot ", "."):
        return r" \frac{d}{dt}\left(" + inner + r"\right) ", used
    return " " + inner + " ", used


def _takes_arguments(node) -> bool:
    """Whether a macro node carries arguments (``\\text{eff}``), so that as an unbraced script it is
    the whole command with them, as TeX reads ``_\\text{eff}``."""
    return node.nodeargd is not None and any(a is not None for a in (node.nodeargd.argnlist or []))


def _print(nodes, user: dict) -> str:
    nodes = list(nodes or [])
    out, k = [], 0
    while k < len(nodes):
        node = nodes[k]
        if isinstance(node, LatexCommentNode):
            out.append(" ")
        elif isinstance(node, LatexMacroNode):
            text, used = _macro(node, nodes, k, user)
            if _takes_arguments(node) and next((o.rstrip()[-1] for o in reversed(out) if o.strip()), " ") in "_^":
                text = "{" + text.strip() + "}"   # `V_\text{eff}`: the script is the command with its argument
            out.append(text)
            k += used
        elif isinstance(node, LatexGroupNode):
            out.append("{" + _over(node.nodelist, user) + "}")
        elif isinstance(node, LatexEnvironmentNode):
            name = node.environmentname
            args = "".join(a.latex_verbatim() for a in (node.nodeargd.argnlist if node.nodeargd else []) if a)
            out.append(rf"\begin{{{name}}}{args}" + _print(node.nodelist, user) + rf"\end{{{name}}}")
        elif isinstance(node, LatexMathNode):
            out.append(_print(node.nodelist, user))
        elif isinstance(node, LatexSpecialsNode):
            out.append(node.specials_chars)
        elif isinstance(node, LatexCharsNode):
            out.append(_BARE_TRIG.sub(r"\\\1 ", node.chars))
        else:
            out.append(node.latex_verbatim())
        k += 1
    return "".join(out)


def _over(nodes, user: dict) -> str:
    """A group's contents; ``{a \\over b}`` is plain TeX's fraction of the whole group, ``\\frac{a}{b}``."""
    nodes = list(nodes or [])
    at = [k for k, n in enumerate(nodes) if isinstance(n, LatexMacroNode) and n.macroname == "over"]
    if len(at) != 1:
        return _print(nodes, user)
    k = at[0]
    numerator, denominator = (_OVER_SPACED.sub("", _print(part, user)) for part in (nodes[:k], nodes[k + 1:]))
    return r"\frac{" + numerator + "}{" + denominator + "}"


_OVER_SPACED = re.compile(rf"^{SPACE}|{SPACE}$")
"""Spaces set around plain TeX's ``\\over``, ``{d(m v) \\, \\over \\, dt}``: at an end of the numerator or the
denominator they set nothing apart."""


# `cos \theta` (or `\ cos`) typed without its backslash renders as the word cos: a reader reads cosine
_BARE_TRIG = re.compile(r"(?<![A-Za-z])(sin|cos|tan|cot|sec|csc|sinh|cosh|tanh)(?![A-Za-z])")
_WORD_TRIG = re.compile(r"\\(text|mathrm|mathit|operatorname)\{\s*\\(sin|cos|tan|cot|sec|csc|sinh|cosh|tanh) \}")


# ":=" typed as two characters (never the label colon before a row, "\\theta:", nor "=:")
_COLON_EQUALS = re.compile(r"(?<![=:\\])\s*:\s*=(?!:)")
_ELLIPTIC = re.compile(r"\\(?:mathrm|operatorname)\{\s*(sn|cn|dn)\s*\}" + SPACE)


_TRANSPOSE = re.compile(r"\s*\^\s*(?:\{\s*(?:T|\\top|\\intercal|\\mathsf\{T\}|\\mathrm\{T\})\s*\}|T(?![A-Za-z])|\\top\b|\\intercal\b)")
_PAIRS = {"]": "[", ")": "("}


def _transposed_rows(text: str) -> str:
    """``[x, y, z]^T`` (also ``(x, y, z)^T``, ``\\left[ … \\right]^{\\top}``): a row of entries
    transposed, the column vector the text means, written as a ``bmatrix`` column."""
    at = 0
    while True:
        m = next((m for m in _TRANSPOSE.finditer(text, at) if text[:m.start()].rstrip()[-1:] in _PAIRS), None)
        if m is None:
            return text
        close = text[:m.start()].rstrip()
        right = close.endswith("\\right" + close[-1])
        end, depth, k, commas = len(close) - 1, 0, len(close) - 1, []
        while k >= 0:
            ch = text[k]
            if ch in ")]}":
                depth += 1
            elif ch in "([{":
                depth -= 1
                if depth == 0:
                    break
            elif ch == "," and depth == 1 and text[k - 1] != "\\":      # a thin space \, is no comma
                commas.append(k)
            k -= 1
        called = text[k] == "(" and k > 0 and (text[k - 1].isalnum() or text[k - 1] in "}_'")   # f(x, y)
        if k < 0 or text[k] != _PAIRS[close[-1]] or not commas or called:
            at = m.end()
            continue
        left = k - 5 if text[max(k - 5, 0):k] == "\\left" else k
        inner = text[k + 1:end - (6 if right else 0)]
        entries = [e.strip() for e in split_top(inner)]
        column = r"\begin{bmatrix} " + r" \\ ".join(entries) + r" \end{bmatrix}"
        text = text[:left] + column + text[m.end():]
        at = left + len(column)


_MATHOP = re.compile(r"\\mathop\s*\{((?:[^{}]|\{[^{}]*\})*)\}(\s*\\!)?")
"""``\\mathop{…}``, an operator set for its spacing, with the negative thin space ``\\!`` a text may set
after it: ``\\mathop{}\\!\\mathrm{d}`` is how a text's macro writes an upright differential d."""


def _operator_body(m: re.Match) -> str:
    """What ``\\mathop{…}`` sets: its body, read as the text's own symbols (none for ``\\mathop{}``)."""
    return f" {m.group(1).strip()} " if m.group(1).strip() else " "


# a full stop or a comma, spaced or not (``… = T \\, .``), never a command's (``\\,``, a row break's ``\\\\``) nor an invisible delimiter's
_STOP = r"(?<!\\)" + SPACING + r"(?<!\\)(?<!\\right)(?<!\\left)(?<!\\[bB]igr)(?<!\\[bB]iggr)[.,]"
_ROW_STOP = re.compile(r"(?<=[\w}])" + _STOP + r"(?=\s*(?:\\\\|\\end\{|\\right))")
_FORMULA_STOP = re.compile(_STOP + r"\s*$")
_DEGREES = re.compile(r"\^\s*(?:\{\s*\\circ\s*\}|\\circ\b)")


def _spaced_equals(gap: str, spaces: str) -> re.Pattern:
    """An ``=`` set apart by ``spaces`` (a control symbol's backslash not a row break's), with ``gap`` between."""
    return re.compile(rf"(?:{gap}(?<!\\)(?:{spaces}))+{gap}(?==)|(?<==)(?:{gap}(?<!\\)(?:{spaces}))+")


_SMALL_SPACED_EQUALS = _spaced_equals(r"[ \t]*", SPACE_SYMBOL)   # in the raw text: no newline, no tie of prose
_SPACED_EQUALS = _spaced_equals(r"\s*", rf"{SPACE_SYMBOL}|{TIE}")
_RELATION_NAMES = ("equiv", "approx", "simeq", "sim", "propto", "neq", "ne", "leq", "le", "geq", "ge", "ll", "gg")
_SMALL_SPACES = rf"(?:\s*(?<!\\)(?:{SPACE_SYMBOL}|{TIE}))+"
_SPACED_RELATION = re.compile(_SMALL_SPACES + r"\s*(?=\\(?:" + "|".join(_RELATION_NAMES) + r")(?![A-Za-z])|[<>])|(?:"
                              + "|".join(rf"(?<=\\{n})" for n in _RELATION_NAMES) + r"|(?<=[<>]))(?![A-Za-z])" + _SMALL_SPACES)
"""Small spaces or a tie setting a relation other than ``=`` apart, ``\\Omega \\, \\equiv \\, \\frac{…}{…}``,
``a \\; \\le \\; b``: they only set the sign apart, as around an ``=``."""
_UNBRACED_ACCENT = re.compile(r"(?<!\\)\\(hat|widehat|bar|check|breve)\s*(\\(?:var)?(?:alpha|beta|gamma|delta|epsilon|"
                              r"zeta|eta|theta|iota|kappa|lambda|mu|nu|xi|pi|rho|sigma|tau|upsilon|phi|chi|psi|omega|"
                              r"Gamma|Delta|Theta|Lambda|Xi|Pi|Sigma|Upsilon|Phi|Psi|Omega)(?![A-Za-z]))")
"""An accent that marks a vector (a unit vector's hat, Kane's bar) over a Greek letter written without braces,
``{}^A\\hat\\omega^B``: TeX sets the letter, the accent's one-token argument, as ``\\hat{\\omega}^B`` does (a rate's
dot, an arrow and a tilde are read unbraced already, and a correction shows them as the text wrote them)."""
_DIFFERENTIAL = re.compile(r"(\\mathrm\{d\})\s*\{((?:[^{}]|\{[^{}]*\})*)\}")
_WORD_SCRIPT = re.compile(r"([\^_])\s*\{\s*\\(?:text|mathrm|textrm|rm|mathit|textnormal|textup)\s*\{\s*([A-Za-z]+)\s*\}\s*\}")
"""A script that is one word set upright, ``_{\\text{body}}``: the word, as ``_{body}`` (an upright label)."""
_SCRIPT_SPACING = re.compile(r"(?<=[\^_])\{[^{}]*" + SPACE_SYMBOL + r"[^{}]*\}")
"""A script holding spacing, ``_{\\beta \\, \\alpha}``: spacing sets no part of a label apart."""
_EMPTY_SCRIPT = re.compile(r"(?<!\\)[\^_]\s*\{\s*\}(?=([A-Za-z])?)")
_EMPTY_GROUP = re.compile(r"(?<![\^_\\])\{\s*\}")
_SCRIPT = r"(?:\{[^{}]*\}|\\[A-Za-z]+|[^\s{}\\])"
_ONE_SYMBOL = r"(?:\\[A-Za-z]+|[A-Za-z])"
_DRESSED = (r"\\(?:dot|ddot|hat|widehat|vec|bar|overline|tilde|check|breve|boldsymbol|mathbf|bm|pmb|mathit)\s*\{\s*"
            r"(?:" + _ONE_SYMBOL + r"|\\[A-Za-z]+\s*\{\s*" + _ONE_SYMBOL + r"\s*\})\s*\}")
_GROUPED_SYMBOL = re.compile(r"(?<![\\\w^_])\{\s*(" + _DRESSED + r"|" + _ONE_SYMBOL + r")\s*\}(?=\s*[_^])")
_AFTER_SCRIPT = re.compile(r"[_^]\s*\{[^{}]*\}$")
"""A brace group holding one symbol, bare or under an accent or a bold face, before its index,
``{\\Omega}_1``, ``{\\dot {\\omega }}_{1}``, ``{\\boldsymbol {I}}_{0}^{-1}`` (how an encyclopaedia
renders its formulas): the braces only group."""
_SIZED_ONE_TOKEN, _PRIME_SCRIPT = re.compile(SIZED_ONE_TOKEN), re.compile(PRIME_SUPERSCRIPT)
_SUP_FIRST = re.compile(r"((?:\\[A-Za-z]+\{(?:[^{}]|\{[^{}]*\})*\}|\\[A-Za-z]+|[A-Za-z])(?:\s*')*)\s*\^\s*("
                        + _SCRIPT + r")\s*_\s*(" + _SCRIPT + r")")


def _ungrouped(m: re.Match) -> str:
    """The symbol of a brace group before its index, unless the group is a command's argument: it
    follows a group that itself follows a command or a group (``\\frac{1}{x}^2``)."""
    before = m.string[:m.start()]
    if not before.endswith("}") or _AFTER_SCRIPT.search(before):
        return m.group(1)
    depth, k = 0, len(before) - 1
    while k >= 0:
        depth += {"}": 1, "{": -1}.get(before[k], 0) if before[k - 1:k] != "\\" else 0
        if depth == 0:
            break
        k -= 1
    head = before[:k].rstrip()
    argument = re.search(r"(\\[A-Za-z]+|\})$", head) and not head.endswith("\\begin")
    return m.group(0) if argument else m.group(1)


def normalize(latex: str, user: dict | None = None) -> str:
    """One formula in the reader's dialect (see the module docstring).

    Parameters
    ----------
    latex : str
        The formula as the text writes it (without its ``$$`` delimiters).
    user : dict, optional
        The file's macros (`macros`), expanded where used.

    Returns
    -------
    str
        The same formula, normalised; a formula the walker cannot follow is returned with only
        its characters normalised.
    """
    return _normalized(latex, tuple(sorted((user or {}).items())))


@functools.lru_cache(maxsize=4096)
def _normalized(latex: str, user: tuple) -> str:
    """`normalize`, memoised: the notes, the names the prose gives and the hat maps each normalise
    the text's formulas."""
    latex = bar_determinants.vertical(angle_columns.squared(units.plain_numbers(texmacros.synonyms(texmacros.font_switches(definitions_removed(re.sub(EQUATION_LABEL, " ", characters(latex))))))))
    user = dict(user)
    try:
        latex = texmacros.expand(latex, user)
    except texmacros.MacroLoop as loop:
        # a macro that expands into itself stays as written: the reader names it as unreadable
        latex = texmacros.expand(latex, {k: v for k, v in user.items() if k != loop.name})
    latex = imaginary_unit.read(re.sub(KERN, " ", latex))   # once the macros are expanded: a unit vector î shows
    latex = re.sub(r"\\([ij])math(?![A-Za-z])", r" \1", latex)   # the dotless ı, ȷ of \hat\imath: the letters i, j
    latex = _MATHOP.sub(_operator_body, latex)       # \\mathop{}\\!\\mathrm{d}: the upright differential d
    try:
        nodes, _, _ = LatexWalker(latex, latex_context=_ctx(), tolerant_parsing=True).get_latex_nodes()
        text = _print(nodes, user)
    except Exception:  # noqa: BLE001 - a walker failure leaves the formula for the reader to refuse
        text = latex
    text = _SIZED_ONE_TOKEN.sub(r"(\1)", text)           # R\\left(t\\right) is R(t)
    text = _UNBRACED_ACCENT.sub(r"\\\1{\2}", text)       # \\hat\\omega is \\hat{\\omega}
    text = _transposed_rows(bracket_cross.cross_matrices(text))
    text = _FORMULA_STOP.sub("", _ROW_STOP.sub(" ", text))  # "1." before a row's or the formula's end: punctuation
    text = _WORD_TRIG.sub(r"\\\1{\2}", text)           # a word in \\text{…} stays a word
    text = _ELLIPTIC.sub(r"\\\1 ", text)              # \\mathrm{sn}: Jacobi's elliptic sine
    text = _DEGREES.sub(r" \\cdot \\frac{\\pi}{180}", text)
    text = _DIFFERENTIAL.sub(r"\1 \2", text)          # \\mathrm{d}{t}: braces only group
    text = _WORD_SCRIPT.sub(r"\1{\2}", text)         # _{\\text{body}}: the label body
    text = _SCRIPT_SPACING.sub(lambda m: re.sub(r"\s*" + SPACE_SYMBOL + r"\s*", " ", m.group(0)), text)
    text = _EMPTY_SCRIPT.sub(lambda m: " " if m.group(1) else "", text)  # ^{}: an empty default
    text = _EMPTY_GROUP.sub(" ", text)                # {} is nothing: {}= and \\begin{aligned}{}
    text = _GROUPED_SYMBOL.sub(_ungrouped, text)     # {\\Omega}_1 is \\Omega_1
    text = _COLON_EQUALS.sub(r" \\equiv ", text)       # a := b defines a, as a \\equiv b
    text = _PRIME_SCRIPT.sub(lambda m: "'" * m.group(1).count("prime"), text)  # V^{\\prime} is V'
    text = _SUP_FIRST.sub(r"\1_\3^\2", text)          # \\omega^2_1 is \\omega_1^2
    text = _SPACED_EQUALS.sub(" ", text)              # a \\;=\\; b: the small spaces only set the = apart
    text = _SPACED_RELATION.sub(" ", text)            # a \\, \\equiv \\, b: as around an =
    text = differentials.written(text)                # \\mathrm{d}, dx = v_x, d(m v)/dt: the reader's derivatives
    return re.sub(r"[ \t]{2,}", " ", text).strip()
