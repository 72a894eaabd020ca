"""A text's own LaTeX macros: their definitions read, and their uses expanded as TeX expands them.

Takes: the text of a notes file (its definitions) and one formula of it (the uses). Gives: the
macros the file defines (`definitions`), the formula without those definitions
(`definitions_removed`), the formula with every use replaced by the macro's body
(`expand`) and with plain TeX's font switches written as LaTeX's commands (`font_switches`).
May import: the standard library, :mod:`derive.lecture.latex_spaces`, :mod:`derive.lecture.latex_spellings`.

What is read: ``\\newcommand``, ``\\renewcommand``, ``\\providecommand`` (starred or not, the
name braced or not), with ``[n]`` arguments and an optional first argument with its default
(``\\newcommand{\\diff}[3][]{…}``: ``\\diff{x}{t}`` takes #1 from the default, ``\\diff[2]{x}{t}``
from the brackets); ``\\def\\x{…}`` and ``\\def\\x#1#2{…}``; ``\\DeclareMathOperator{\\Tr}{Tr}``
(an ``\\operatorname``). Arguments are read as TeX reads undelimited ones: a braced group (its
braces stripped), else one token (a control sequence or a character). Macros used inside other
macros' bodies are expanded in turn; a macro whose expansion reaches itself raises `MacroLoop`
naming it, where TeX would loop forever.

Why a scanner of its own rather than pylatexenc's walker: the walker parses the arguments of the
macros it is told about but expands nothing (no #n substitution, no default, no rescanning of a
body), and it does not know ``\\def``'s parameter text; the TeX rules for one argument (a group or
one token) are the whole grammar needed here, and they are applied on the text before the walker
(`derive.lecture.source`) normalises the expanded formula.
"""
from __future__ import annotations

import re
from typing import NamedTuple

from derive.lecture.latex_spaces import SPACE
from derive.lecture.latex_spellings import BOLD

_HEAD = re.compile(r"\\(newcommand|renewcommand|providecommand|DeclareMathOperator|def)(?![A-Za-z])")
_WORD = re.compile(r"\\([A-Za-z]+)")


class Macro(NamedTuple):
    """One macro: how many arguments, its body (#1 … #9 in it) and the default of an optional
    first argument (None when the first argument is not optional)."""
    nargs: int
    body: str
    default: str | None = None


class MacroLoop(ValueError):
    """A macro whose expansion reaches itself (TeX would loop forever)."""

    def __init__(self, name: str):
        super().__init__(f"the macro '\\{name}' expands into itself")
        self.name = name


def _skip_space(text: str, i: int) -> int:
    while i < len(text) and text[i] in " \t\n":
        i += 1
    return i


def _group(text: str, i: int, open_: str = "{", close: str = "}") -> tuple[str, int] | None:
    """The content of the group opening at text[i] (brace-balanced) and the index after it."""
    if i >= len(text) or text[i] != open_:
        return None
    depth, j = 0, i + (0 if open_ == "{" else 1)
    while j < len(text):
        ch = text[j]
        if ch == "\\":
            j += 2
            continue
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
            if open_ == "{" and depth == 0:
                return text[i + 1:j], j + 1
            if depth < 0:
                return None
        elif ch == close and depth == 0 and open_ != "{":
            return text[i + 1:j], j + 1
        j += 1
    return None


def _token(text: str, i: int) -> tuple[str, int] | None:
    """One undelimited argument at text[i] (spaces skipped): a braced group's content, a control
    sequence, a parameter (#1) or one character."""
    i = _skip_space(text, i)
    if i >= len(text) or text[i] in "}":
        return None
    if text[i] == "{":
        return _group(text, i)
    if text[i] == "\\":
        m = _WORD.match(text, i)
        return (m.group(0), m.end()) if m else (text[i:i + 2], i + 2)
    if text[i] == "#" and i + 1 < len(text) and text[i + 1].isdigit():
        return text[i:i + 2], i + 2
    return text[i], i + 1


def _name(text: str, i: int) -> tuple[str, int] | None:
    """The macro name being defined at text[i]: ``\\x`` or ``{\\x}``."""
    i = _skip_space(text, i)
    got = _group(text, i)
    inner, j = got if got else (text[i:], None)
    m = _WORD.match(inner.strip())
    if m is None:
        return None
    return (m.group(1), j) if got else (m.group(1), i + m.end())


def _definition(text: str, m: re.Match) -> tuple[str, Macro, int] | None:
    """The definition starting at match m: its name, the macro and the index after its body."""
    kind, i = m.group(1), m.end()
    if kind != "def" and text[i:i + 1] == "*":
        i += 1
    got = _name(text, i)
    if got is None:
        return None
    name, i = got
    if kind == "def":
        params = re.compile(r"\s*((?:#\d)*)\s*\{").match(text, i)
        if params is None:
            return None                  # delimited parameters (#1.) are not read
        body = _group(text, params.end() - 1)
        return (name, Macro(len(params.group(1)) // 2, body[0]), body[1]) if body else None
    if kind == "DeclareMathOperator":
        body = _group(text, _skip_space(text, i))
        return (name, Macro(0, r"\operatorname{" + body[0] + "}"), body[1]) if body else None
    nargs, default = 0, None
    j = _skip_space(text, i)
    count = _group(text, j, "[", "]")
    if count is not None and count[0].strip().isdigit():
        nargs, j = int(count[0]), _skip_space(text, count[1])
        opt = _group(text, j, "[", "]")
        if opt is not None:
            default, j = opt[0], _skip_space(text, opt[1])
    body = _group(text, j)
    return (name, Macro(nargs, body[0], default), body[1]) if body else None


def _definitions_in(text: str):
    for m in _HEAD.finditer(text):
        got = _definition(text, m)
        if got is not None:
            yield m.start(), m.group(1), got


def definitions(text: str) -> dict[str, Macro]:
    """The macros a file defines, name → `Macro`, in the order TeX meets them: a later
    ``\\newcommand``, ``\\renewcommand`` or ``\\def`` replaces an earlier one; ``\\providecommand``
    defines only a name the file has not defined before."""
    found: dict[str, Macro] = {}
    for _, kind, (name, macro, _) in _definitions_in(text):
        if kind == "providecommand" and name in found:
            continue
        found[name] = macro
    return found


def definitions_removed(latex: str) -> str:
    """A formula without the macro definitions written in it (a display that only defines macros
    becomes blank)."""
    out, i = [], 0
    for start, _, (_, _, end) in _definitions_in(latex):
        if start < i:
            continue
        out.append(latex[i:start])
        i = end
    out.append(latex[i:])
    return "".join(out)


def _join(left: str, right: str) -> str:
    """left + right, a space between a control word and a letter that would otherwise merge."""
    if right[:1].isalpha() and re.search(r"\\[A-Za-z]+$", left):
        return left + " " + right
    return left + right


def _substitute(body: str, args: list[str]) -> str:
    """The body with #1 … #9 replaced by the arguments, in one pass (an argument that contains
    ``#2`` is not substituted again)."""
    out, i = "", 0
    for m in re.finditer(r"#(\d)", body):
        n = int(m.group(1))
        out = _join(_join(out, body[i:m.start()]), args[n - 1] if n <= len(args) else m.group(0))
        i = m.end()
    return _join(out, body[i:])


# a command that takes an argument, or a script, just before a use: in TeX its argument is the
# macro's whole expansion
_TAKES_IT = re.compile(r"(?:\\(?:dot|ddot|dddot|hat|widehat|bar|overline|underline|tilde|widetilde|vec|check|breve|"
                       r"mathbf|mathrm|mathit|mathcal|mathbb|boldsymbol|bm|pmb|vb|vu|norm|abs|sqrt|frac|dfrac|tfrac|"
                       r"operatorname|text|textbf)|[_^])\s*$")
_ONE_TOKEN = re.compile(r"\s*(?:\\[A-Za-z]+|\\.|[^\\\s{}])\s*$|\s*\{.*\}\s*$", re.S)


# plain TeX's font switches, each for the rest of its group, and the commands LaTeX writes for them
_SWITCH = re.compile(r"\{\s*\\(bf|rm)(?![A-Za-z])" + SPACE)      # a space after it sets nothing apart
_SWITCHED = {"bf": "mathbf", "rm": "mathrm"}


def font_switches(latex: str) -> str:
    """The formula with each group that opens with a plain-TeX font switch written as LaTeX's
    command for it: ``{\\bf r}`` as ``{\\mathbf{r}}`` (the bold r), ``{\\rm rot}`` as
    ``{\\mathrm{rot}}``, as older texts and reference books set their vectors and labels.

    Parameters
    ----------
    latex : str
        One formula.

    Returns
    -------
    str
        The formula, its switches written as commands; an unclosed group is left as written.
    """
    out, i = "", 0
    for m in _SWITCH.finditer(latex):
        if m.start() < i or (m.start() > 0 and latex[m.start() - 1] == "\\"):
            continue
        group = _group(latex, m.start())
        if group is None:
            continue
        rest = font_switches(latex[m.end():group[1] - 1]).strip()
        out += latex[i:m.start()] + "{\\" + _SWITCHED[m.group(1)] + "{" + rest + "}}"
        i = group[1]
    return out + latex[i:]


_DOTLESS = re.compile(r"\\([ij])math(?![A-Za-z])")
_SCRIPT_L = re.compile(r"\\ell(?![A-Za-z])")
# a comma typed where a thin space was meant: after a sign (``+,\\Omega``, never in a script's ``{+,-}``),
# or spaced before and not after, in front of a function's command (``\\Omega ,\\sin``)
_STRAY_COMMA = re.compile(r"(?<![{_^,\s])(\s*[+-])\s*,(?=\s*[\\A-Za-z0-9({])"
                          r"|(?<=[A-Za-z0-9})])(\s+),(?=\\(?:sin|cos|tan|cot|exp|sqrt|frac)(?![A-Za-z]))")


def _stray_commas(latex: str) -> str:
    """The formula without the commas `_STRAY_COMMA` finds outside brackets (inside them a comma
    may part a function's arguments, ``f(x ,\\sin y)``)."""
    def thin(m):
        depth = sum(latex[:m.start()].count(c) for c in "([") - sum(latex[:m.start()].count(c) for c in ")]")
        return m.group(0) if depth > 0 and m.group(1) is None else (m.group(1) or m.group(2)) + " "
    return _STRAY_COMMA.sub(thin, latex)


_OPENS, _CLOSES = r"\\(?:left|[bB]igg?l)(?![A-Za-z])", r"\\(?:right|[bB]igg?r)(?![A-Za-z])"
_HALF_OPEN = re.compile(_OPENS + r"\s*\.((?:(?!" + _OPENS + "|" + _CLOSES + r").)*)" + _CLOSES + r"\s*\)(?=\s*_)", re.S)
"""A bracket opened invisibly and closed before a subscript, sized as a pair (``\\left. X \\right)_{rel}``) or by
hand (``\\bigl. X \\bigr)_{rel}``)."""
_STARRED = re.compile(r"\\(begin|end)\s*\{([pbBvV]?matrix)\*\}(?:\s*\[[lcr]\])?")
# an arrow over a bold letter, or a bold face around an arrowed one: two marks of one vector
_BOLD_FACE = BOLD + r"\s*"
_NESTED = r"(?:[^{}]|\{(?:[^{}]|\{[^{}]*\})*\})*"     # a group's inside, two levels of braces deep
_ARROW_OVER_BOLD = re.compile(r"\\vec(?![A-Za-z])\s*\{\s*(" + _BOLD_FACE + r"\{" + _NESTED + r"\})\s*\}")
_BOLD_OVER_ARROW = re.compile(r"(" + _BOLD_FACE + r")\{\s*\\vec(?![A-Za-z])\s*\{(" + _NESTED + r")\}\s*\}")


def synonyms(latex: str) -> str:
    """The formula with two spellings of what the reader reads written the usual way: the dotless
    letters ``\\imath`` and ``\\jmath`` as i and j (the letters themselves, set dotless under a hat:
    ``\\hat{\\imath}``, the unit vector î), and mathtools' starred matrices (``bmatrix*``, with or
    without its column alignment ``[r]``) as the plain ones (``bmatrix``), which they only align; and a
    bracket closed with a subscript but opened invisibly, ``\\left. X \\right)_{rel}`` (or sized by hand,
    ``\\bigl. X \\bigr)_{rel}``), as the bracket ``\\left( X \\right)_{rel}`` it draws half of (a derivative
    relative to a frame); the script letter ``\\ell`` as l (a length, set in script to keep it apart
    from the digit 1); and a vector marked twice, an arrow over a bold letter (``\\vec{\\mathbf{H}}_C``) or
    a bold face around an arrowed one (``\\mathbf{\\vec{M_O}}``), as the bold letter alone, which is what
    either mark says; and a comma typed for a thin space between factors (`_STRAY_COMMA`) as a space.

    Parameters
    ----------
    latex : str
        One formula.

    Returns
    -------
    str
        The formula with those spellings replaced.
    """
    latex = _stray_commas(latex)
    latex = _DOTLESS.sub(lambda m: (" " if latex[max(m.start() - 1, 0)].isalpha() else "") + m.group(1), latex)
    latex = _SCRIPT_L.sub(lambda m: (" " if latex[max(m.start() - 1, 0)].isalpha() else "") + "l", latex)
    latex = _HALF_OPEN.sub(lambda m: "\\left(" + m.group(1) + "\\right)", latex)
    latex = _BOLD_OVER_ARROW.sub(lambda m: m.group(1).rstrip() + "{" + m.group(2) + "}", _ARROW_OVER_BOLD.sub(r"\1", latex))
    return _STARRED.sub(lambda m: f"\\{m.group(1)}{{{m.group(2)}}}", latex)


def expand(latex: str, user: dict[str, Macro], active: frozenset = frozenset()) -> str:
    """The formula with each use of the file's macros replaced by its body, arguments
    substituted, and macros in the result expanded in turn.

    Parameters
    ----------
    latex : str
        One formula.
    user : dict
        The file's macros (`definitions`).
    active : frozenset
        The macros being expanded around this text (a use of one of them is a loop).

    Returns
    -------
    str
        The expanded formula; a use without all its arguments is left as written.

    Raises
    ------
    MacroLoop
        A macro's expansion reaches that macro again.
    """
    if not user or "\\" not in latex:
        return latex
    out, i = "", 0
    while i < len(latex):
        m = _WORD.search(latex, i)
        if m is None:
            break
        # a control symbol (\\, \{) is one token: never the start of a control word
        j = m.start()
        if m.group(1) not in user or (j > 0 and latex[j - 1] == "\\" and (j < 2 or latex[j - 2] != "\\")):
            out, i = _join(out, latex[i:m.end()]), m.end()
            continue
        name, macro = m.group(1), user[m.group(1)]
        if name in active:
            raise MacroLoop(name)
        args, k, complete = [], m.end(), True
        if macro.default is not None:
            opt = _group(latex, _skip_space(latex, k), "[", "]")
            if opt is not None:
                args.append(opt[0])
                k = opt[1]
            else:
                args.append(macro.default)
        while len(args) < macro.nargs:
            got = _token(latex, k)
            if got is None:
                complete = False
                break
            args.append(got[0])
            k = got[1]
        if not complete:
            out, i = _join(out, latex[i:m.end()]), m.end()
            continue
        args = [expand(a, user, active) for a in args]
        body = expand(macro.body, user, active | {name})
        body = _substitute(body, args)
        before = out + latex[i:m.start()]
        if _TAKES_IT.search(before) and not _ONE_TOKEN.match(body):
            body = "{" + body + "}"      # \dot\vw: the command's argument is the whole expansion
        out = _join(before, body)
        i = k
    return _join(out, latex[i:])
