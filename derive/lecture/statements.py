"""A display cut into the statements it makes, as a reader cuts it.

Takes: the LaTeX of one display (normalised by `derive.lecture.source`). Gives: `statements`,
the list of its statements, each a LaTeX string. May import: the standard library,
:mod:`derive.lecture.alignment_arrays`, :mod:`derive.lecture.index_quantifier`, :mod:`derive.lecture.latex_spaces`.

A display is cut into rows at ``\\\\`` (of ``aligned``, ``split``, ``cases``, ``align`` and the
other display environments, which are dropped; an aligned row of column pairs side by side,
``a &= b & c &\\equiv d``, is one row per pair), a row ending in ``+``/``-`` continuing on the
next, a row opening with ``+``/``-`` and stating no relation of its own continuing the row before
it (``&+ \\frac{1}{2}I_2 …``), and one ending in ``=`` on a next that opens with ``=``; a row into pieces at ``\\qquad``,
``\\quad``, ``\\Rightarrow``, ``\\implies``, ``\\Leftrightarrow``, ``\\iff`` and a spaced ``\\text{and}``; a piece at top-level ``;``
and at commas between relations (never inside brackets). A label before a colon (``\\theta:``,
``\\Omega_1 : \\quad``) and words after a statement (``&&\\text{stable}``) are dropped; a case
before a colon (``\\theta = 0: \\omega_z = \\omega_3``) is a statement of its own; an
equation's number written in letters after a quad or a tie (``\\quad~Eq. (1)``) is dropped;
``\\text{const}`` is kept as the constant it names, and so are words after a statement that say
it is a constant (``= E \\quad \\text{(const.)}``: E names a conserved quantity); a relation in
brackets after a statement (``\\dot\\omega_3 = -\\alpha\\gamma_2 \\left(\\alpha = \\frac{Mgx_C}{I_3}\\right)``)
defines a name it uses and is a statement of its own, read first; a ``\\pm`` on a statement's left
side makes it two statements, one for each sign. An ``array`` that is the display's body and states
a relation in its first row is an alignment (`derive.lecture.alignment_arrays`), cut like ``aligned``.
"""
from __future__ import annotations

import functools
import re

from derive.lecture import alignment_arrays, index_quantifier
from derive.lecture.latex_spaces import ONE_SPACING, QUAD, SPACING

_ENVS = ("split", "aligned", "align", "align*", "gathered", "gather", "gather*", "equation", "equation*",
         "multline", "multline*", "eqnarray", "eqnarray*", "cases", "flalign", "flalign*", "alignat", "alignat*",
         "alignedat", "subequations", "displaymath", "math", "numcases", "subnumcases",
         # mathtools' cases: display-style, and with the brace on the right
         "dcases", "dcases*", "rcases", "rcases*", "drcases", "drcases*")

_SYSTEM_OPEN = re.compile(r"\\left\s*(?:\\\{|\\lbrace)\s*(?P<array>\\begin\{array\}\s*\{[^{}]*\})?")
_SYSTEM_ARRAY_END = re.compile(r"\\end\{array\}(?=\s*(?:\\right\s*\.|" + QUAD + "|$))")
_SET_CLOSE = re.compile(r"\\right\s*(?:\\\}|\\rbrace)")


def _system_rows(s: str) -> str:
    """A system brace, ``\\left\\{`` with no closing brace (its ``\\right.`` already dropped), round
    aligned rows or a one-column array: the rows, each ended so that it is cut as one."""
    if _SET_CLOSE.search(s) or not _SYSTEM_OPEN.search(s):
        return s
    arrays = any(m.group("array") for m in _SYSTEM_OPEN.finditer(s))
    s = _SYSTEM_OPEN.sub(" ", s)
    if arrays:
        s = _SYSTEM_ARRAY_END.sub(lambda m: r" \\ ", s)
    return re.sub(r"\\right\s*\.", lambda m: r" \\ ", s)


_GROUPED_ENV = re.compile(r"\{\s*(\\begin\{(" + "|".join(re.escape(e) for e in _ENVS) + r")\}.*?\\end\{\2\})\s*\}", re.S)
"""A display environment inside a brace group, ``{\\begin{aligned} … \\end{aligned}}`` (as an
encyclopaedia renders its displays): the braces only group, and the rows are cut as the bare
environment's."""


def _strip_envs(s: str) -> str:
    s = _GROUPED_ENV.sub(r"\1", s)
    s = alignment_arrays.unwrapped(_system_rows(s))
    # alignat's argument is its number of column pairs, not math
    s = re.sub(r"\\begin\{(alignat\*?|alignedat)\}\s*\{\s*\d+\s*\}", " ", s)
    for env in _ENVS:
        s = s.replace(f"\\begin{{{env}}}", " ").replace(f"\\end{{{env}}}", " ")
    return s

def _top_level_split(s: str, seps: tuple, parens: bool = False) -> list[str]:
    """Split at separators outside braces and outside matrix environments (and, with ``parens``,
    outside brackets: the ``;`` of ``V(t; q)`` separates a function's arguments, not statements)."""
    out, depth, env, i, start = [], 0, 0, 0, 0
    opening, closing = ("{([", "})]") if parens else ("{", "}")
    while i < len(s):
        if s.startswith("\\begin{", i):
            env += 1
        elif s.startswith("\\end{", i):
            env -= 1
        ch = s[i]
        if ch in opening and not (ch != "{" and i and s[i - 1] == "\\"):
            depth += 1
        elif ch in closing and not (ch != "}" and i and s[i - 1] == "\\"):
            depth -= 1
        elif depth == 0 and env == 0:
            for sep in seps:
                if s.startswith(sep, i) and not (sep[-1].isalpha() and i + len(sep) < len(s) and s[i + len(sep)].isalpha()):
                    out.append(s[start:i])
                    i += len(sep)
                    start = i
                    break
            else:
                i += 1
                continue
            continue
        i += 1
    out.append(s[start:])
    return out

def _alignment_free(s: str) -> str:
    """Drop the alignment '&' of aligned/split rows, keeping the '&' that separates matrix entries."""
    out, env, i = [], 0, 0
    while i < len(s):
        if s.startswith("\\begin{", i):
            env += 1
        elif s.startswith("\\end{", i):
            env -= 1
        if s[i] == "&" and env == 0 and (i == 0 or s[i - 1] != "\\"):
            out.append(" ")
        else:
            out.append(s[i])
        i += 1
    return "".join(out)

def _column_pairs(row: str) -> list[str]:
    """An aligned row of several column pairs, ``a &= b & c &= d``: each pair that states a relation
    is a statement of its own (cut at the second, fourth, ... top-level '&'); a row whose other
    columns hold words (``a &= b &&\\text{stable}``) stays one row."""
    cuts, depth, env = [], 0, 0
    for i, ch in enumerate(row):
        if row.startswith("\\begin{", i):
            env += 1
        elif row.startswith("\\end{", i):
            env -= 1
        elif ch == "{" and (i == 0 or row[i - 1] != "\\"):
            depth += 1
        elif ch == "}" and (i == 0 or row[i - 1] != "\\"):
            depth -= 1
        elif ch == "&" and depth == 0 and env == 0 and (i == 0 or row[i - 1] != "\\"):
            cuts.append(i)
    if len(cuts) < 3:
        return [row]
    bounds = [0] + [c + 1 for c in cuts[1::2]]
    ends = [c for c in cuts[1::2]] + [len(row)]
    pairs = [row[a:b] for a, b in zip(bounds, ends)]
    if all(RELATION.search(p) for p in pairs) and not any(_CONTINUED.match(p) for p in pairs[1:]):
        return pairs
    return [row]


# a column that goes on with the statement before it (``&&= …``, ``&\rightarrow …``, ``&+ …``)
_CONTINUED = re.compile(r"\s*&*\s*(?:[=<>+\-]|\\(?:rightarrow|Rightarrow|to|implies|iff|Longrightarrow|"
                        r"longrightarrow|Leftrightarrow|leftrightarrow|equiv|approx|simeq|le|ge|leq|geq|neq|"
                        r"cdot|times)(?![A-Za-z]))")

def _text_only(piece: str) -> bool:
    rest = re.sub(r"\\text\{[^{}]*\}", "", piece)
    return not rest.strip(" &,.;:") and "\\text" in piece

_CONST = re.compile(r"\\(?:text|mathrm|rm)\s*\{\s*(?:const|constant|cst|cte|constante|costante|konst|Konstante)\.?"
                    r"(?:\s*(?:\\?\#|no\.)?\s*\d+)?\s*\}")
"""``\\text{const}``; a text numbering its constants writes ``\\text{constant \\#2}``; Spanish, French,
Italian and German texts write ``cte``, ``constante``, ``costante``, ``konst.``, ``Konstante``."""

_TRAILING_WORDS = re.compile(r"(?:[,;&]|" + ONE_SPACING + r")*\\(?:text|mbox|textrm|hbox)\s*\{[^{}]*\}[\s.,;]*$")

_CONSTANT_WORDS = re.compile(r"\\(?:text|mbox|textrm|hbox)\s*\{\s*[(（]?\s*(?:const|constant|cst|常数|常量|Konstante|constante)\.?\s*[)）]?\s*\}")
"""Words after a statement that say it is a constant, in the languages texts are written in."""

_NAMED_END = re.compile(r"(?<![<>!\\])=\s*\\?[A-Za-z]+(?:_\{?\w+\}?)?\s*$")
"""A statement that ends by naming its value with one symbol (``… = L_Z``): the name of a constant."""

_WHERE = re.compile(r"^(?P<claim>.*?(?<![<>!\\])=.*?)\s*(?:\\left\s*)?\(\s*(?P<name>\\?[A-Za-z]+(?:_\{?\w+\}?)?)\s*="
                    r"(?P<value>[^=]+?)(?:\\right\s*)?\)\s*$", re.S)
"""A statement followed by a bracketed definition of a name: ``… = -\\alpha\\gamma_2 \\left(\\alpha = …\\right)``."""

# a relation sign; a command is matched whole, so that \left( is no \le
RELATION = re.compile(r"(?<![<>\\])=|\\(?:equiv|approx|geq?|leq?|simeq)(?![A-Za-z])|(?<!\\)[<>]")


_SIZED_AROUND = re.compile(r"^\\(?:left|[Bb]igg?l?)\s*\((.*)\\(?:right|[Bb]igg?r?)\s*\)$", re.S)


def _unwrapped(piece: str) -> str:
    """A statement written in parentheses, ``(\\dot\\theta = \\text{const})`` or sized
    ``\\left(0 \\le k^2 \\le 1\\right)``, without them."""
    s = piece.strip()
    s = "(" + sized.group(1) + ")" if (sized := _SIZED_AROUND.match(s)) else s
    if s.startswith("(") and s.endswith(")") and RELATION.search(s):
        depth = 0
        for k, ch in enumerate(s):
            depth += ch == "("
            depth -= ch == ")"
            if depth == 0 and k < len(s) - 1:
                return piece
        return s[1:-1]
    return piece

def _cleaned(piece: str) -> str:
    """A statement without the words after it (``&&\\text{stable}``); ``\\text{const}`` becomes a
    constant of the text's."""
    piece = _CONST.sub(r" \\mathrm{const} ", piece)
    while True:
        cut = _TRAILING_WORDS.sub("", piece)
        if cut == piece or not cut.strip():
            break
        piece = cut
    return piece

def _lists(row: str) -> list[str]:
    """A row that lists statements: cut at top-level ``;`` and at top-level commas between
    relations (``\\theta = 0, \\dot\\theta = 0``), never inside brackets (f(a, b))."""
    pieces = []
    for part in _top_level_split(row, (";",), parens=True):
        if part.rstrip().endswith("\\"):
            pieces.append(part)
            continue
        commas = split_top(part)
        if len(commas) > 1 and not commas[-1].strip():
            commas.pop()                  # a comma that ends the row ends a sentence, it cuts nothing
        if len(commas) > 1 and all(RELATION.search(c) for c in commas):
            pieces.extend(commas)
        else:
            pieces.append(part)
    return [p.replace("\\\x00", "\\;") for p in pieces]

def _where_first(piece: str) -> list[str]:
    """A statement and the bracketed definition after it (`_WHERE`): the definition, then the statement."""
    m = _WHERE.match(piece.strip())
    if m is None or m.group("name") not in m.group("claim"):
        return [piece]
    return [f"{m.group('name')} = {m.group('value')}", m.group("claim")]

def top_level(s: str, pattern: re.Pattern) -> list[re.Match]:
    """The matches of ``pattern`` that start outside every bracket and brace of ``s``, in order."""
    depth, found = 0, []
    for i, ch in enumerate(s):
        depth += (ch in "({[") - (ch in ")}]")
        if depth == 0:
            m = pattern.match(s, i)
            if m:
                found.append(m)
    return found


def split_top(s: str) -> list[str]:
    """``s`` cut at its commas outside brackets and braces (an escaped ``\\,``, a thin space, is
    no cut)."""
    out, depth, start = [], 0, 0
    for i, ch in enumerate(s):
        if ch in "({[":
            depth += 1
        elif ch in ")}]":
            depth -= 1
        elif ch == "," and depth == 0 and (i == 0 or s[i - 1] != "\\"):
            out.append(s[start:i])
            start = i + 1
    out.append(s[start:])
    return out

def statements(latex: str) -> list[str]:
    """The statements of one display (see the module docstring), each a LaTeX string."""
    return list(_statements(latex))


@functools.lru_cache(maxsize=4096)
def _statements(latex: str) -> tuple[str, ...]:
    """`statements`, once per display: a display read again (a second reading, a probe in another
    sequence) is cut as before."""
    body = _AND.sub(r" \\quad ", _EQUATION_NUMBER.sub("", _strip_envs(latex)))
    # a whole display in one pair of parentheses (a sheet's (L = I ω), its aligned rows in \left( … \right)) is what they hold
    body = _unwrapped(body)
    # ∀ i ∈ ℤ₃: one statement per axis, read before a medium space \; is masked (the quantifier may be spaced so)
    body = " \\\\ ".join(index_quantifier.instances(body)).replace("\\;", "\\\x00")
    rows = [_alignment_free(c).strip() for r in _top_level_split(body, ("\\\\",)) for c in _column_pairs(r)]
    # a row that ends with a binary operator continues on the next
    joined: list[str] = []
    for row in rows:
        if not row:
            continue
        if joined and re.search(r"[+\-]\s*$", joined[-1]):
            joined[-1] = joined[-1] + " " + row
        elif joined and re.match(r"[+\-]", _INDENT.sub("", row)) and not RELATION.search(row) \
                and not joined[-1].rstrip().endswith("."):
            joined[-1] = joined[-1] + " " + row      # "&+ \frac{1}{2}I_2 …": a long right side carried over a row
        elif joined and re.search(r"(?<![<>!\\])=\s*$", joined[-1]) and row.startswith("="):
            joined[-1] = joined[-1] + " " + row[1:]      # "A = B =" then "= C": one chain, the = said twice
        else:
            joined.append(row)
    out = []
    for row in joined:
        words = _TRAILING_WORDS.search(row)
        if words and _CONSTANT_WORDS.search(words.group(0)) and _NAMED_END.search(row[:words.start()]):
            row = row[:words.start()] + r" = \mathrm{const}"
        for piece in (p for r in _index_range(row) for p in _colon_parts(r)):
            for part in _spacing_joined(_top_level_split(piece, ("\\qquad", "\\quad", "\\Rightarrow", "\\implies",
                                                                              "\\Leftrightarrow", "\\iff"))):
                for one in [w for p in _lists(part) for w in _where_first(_trimmed(p))]:
                    one = _unwrapped(_cleaned(_trimmed(one)))
                    if _trimmed(one) and not _text_only(one):
                        out.extend(_sign_cases(_trimmed(one)))
    return tuple(out)


# a text without \tag numbers a row in letters after a wide space (``\quad~Eq. (1)``): a name, not a factor
_NUMBER = r"(?:\\(?:left|[Bb]igg?l?)\s*)?\(\s*\d+[a-z]?\s*(?:\\(?:right|[Bb]igg?r?)\s*)?\)"     # (1), \left(1\right)
_EQUATION_NUMBER = re.compile(r"(?:" + QUAD + r"|~)+\s*(?:Eqs?|Eqn|Equation)\.?\s*~?\s*" + _NUMBER +
                              r"|(?:" + QUAD + r"|~)+\s*\\(?:text|mbox|textrm)\s*\{\s*(?:Eqs?|Eqn|Equation)\.?\s*~?\s*"
                              + _NUMBER + r"\s*\}")


# "and" between two statements, spaced with ~ or \quad (``a = b ~~~\text{and}~~~ c = d``): a cut
_AND = re.compile(SPACING + r"\\(?:text|mbox|textrm|mathrm)\s*\{\s*and\s*\}" + SPACING)


# a long sum's next row is indented with spaces and may open with the invisible \left. that answers the row before's \right.
_INDENT = re.compile(r"^(?:" + ONE_SPACING + r"|\s|\\left\s*\.)+")
_OPEN_END = re.compile(r"(?:(?<![<>!\\])=|\+|-|\\times|\\cdot)$")


def _spacing_joined(parts: list[str]) -> list[str]:
    """Parts split at a ``\\quad`` that only spaced one statement (``a = \\quad b + \\quad c``): a
    part that ends with a relation or an operator, or a part that starts with ``=``, is joined to
    its neighbour."""
    out: list[str] = []
    for part in parts:
        t = _trimmed(part)
        if out and (_OPEN_END.search(_trimmed(out[-1])) or t.startswith("=") or _factors_only(t, out[-1])):
            out[-1] = out[-1] + " " + part
        elif out and _factors_only(_trimmed(out[-1]), part) and all(_factors_only(_trimmed(p), part) for p in out):
            out = [" ".join(out + [part])]        # `M \quad g \quad l = …`: factors before the relation
        else:
            out.append(part)
    return out


def _factors_only(part: str, before: str) -> bool:
    """A part with no relation, no words and no bracketed aside after a part with one
    (``\\dot\\alpha \\quad \\sin\\beta``): the factors of the statement the ``\\quad`` only spaced."""
    return bool(part) and _FIRST_RELATION.search(part) is None and _FIRST_RELATION.search(before) is not None \
        and _ASIDE.match(part) is None and _WORDS.search(part) is None


# what a relation-free part after a \quad may be other than factors: words, a quantifier, a label
_ASIDE = re.compile(r"\\(?:mathrm|forall|exists|in|label|tag|dots|ldots|cdots)\b|[,;.:]")
_WORDS = re.compile(r"\\(?:text|mbox|textrm|hbox|textit|textbf)\b")


_PM = re.compile(r"\\(pm|mp)(?![A-Za-z])")
_FIRST_RELATION = re.compile(r"(?<![<>!\\])=|[<>]|\\(le|ge|leq|geq|lt|gt|leqslant|geqslant|equiv|approx)(?![A-Za-z])")


_RANGE = re.compile(r"(?:[,;]|\\[,;:!]|\\q?quad|~|\s)*\(?\s*([ijk])\s*=\s*1\s*,\s*2\s*,\s*3\s*\)?\s*[.,;]?\s*$")


def _index_range(row: str) -> list[str]:
    """``L_i = I_i \\omega_i,\\quad i = 1,2,3``: a statement with a free index and the index's range
    written after it is its three statements (the index put in each subscript ``_i``, ``_{i}``). Left
    as written when the index also sits in a longer subscript (``I_{ij}``), a sum binds it, or it
    subscripts one side only."""
    m = _RANGE.search(row)
    if not m or m.start() == 0:
        return [row]
    body, index = row[:m.start()], m.group(1)
    used = re.compile(r"_\s*(?:\{\s*" + index + r"\s*\}|" + index + r"(?![A-Za-z]))")
    sides = _FIRST_RELATION.split(body, maxsplit=1)
    if len(sides) < 2 or re.search(r"\\(?:sum|prod)(?![A-Za-z])", body) or \
            not all(used.search(side or "") for side in (sides[0], sides[-1])):
        return [row]
    out = [used.sub("_{" + n + "}", body) for n in "123"]
    if any(re.search(r"_\s*\{[^{}]*" + index + r"[^{}]*\}", o) for o in out):
        return [row]                      # the index in a longer subscript (I_{ij}): not this rule's
    return out


def _sign_cases(piece: str) -> list[str]:
    """``G(\\pm 1) = -(\\beta \\mp b)^2``: a ± on the left side states the formula for each sign,
    the upper signs (± → +, ∓ → −) and the lower; each is a statement. A ± only on the right side
    (``x = \\pm\\sqrt{y}``, two roots) is left as written."""
    rel = _FIRST_RELATION.search(piece)
    if rel is None or not _PM.search(piece[:rel.start()]):
        return [piece]
    return [_PM.sub(lambda m: sign if m.group(1) == "pm" else other, piece)
            for sign, other in (("+", "-"), ("-", "+"))]

_LEADING = re.compile(r"^(?:[,.;:]|" + ONE_SPACING + ")+")
_TRAILING = re.compile(r"(?:(?<!\\)[,.;:]|" + ONE_SPACING + ")+$")


def _trimmed(s: str) -> str:
    """Without spacing (quads too) and punctuation at its ends."""
    prev = None
    while prev != s:
        prev = s
        s = _LEADING.sub("", s)
        s = _TRAILING.sub("", s)
    return s

_PROPORTION = re.compile(r"[^=:]*(?<![\\:<>!]):(?![:=])[^=]*(?<![<>!\\])=(?!=)[^=]*(?<![\\:<>!]):(?![:=])[^=]*$")
"""A proportion, colons on both sides of its one ``=``: ``I_{11} : I_{22} : I_{33} = 2.5833 : 0.2550 : 2.8333``."""


def _colon_parts(row: str) -> list[str]:
    """``label: statement`` → the statement; ``case: statement`` (θ = 0: ω_z = ω₃) → both, the case
    first (a statement of a value, read as the case it is); a proportion as written (no label in it)."""
    parts = [p for p in re.split(r"(?<!\\)(?<![:<>!])\s*:(?!=)\s*", row)]
    if len(parts) == 1 or _PROPORTION.match(row):
        return [row]                      # a : b : c = x : y : z is one statement, a proportion
    out = []
    for k, part in enumerate(parts):
        if k < len(parts) - 1 and not RELATION.search(part):
            continue                      # a label (\\Omega_1:, \\theta:)
        out.append(part)
    return out


_MARKS = re.compile(r"\\(label|tag|eqref)\*?\s*\{[^{}]*\}|\\(notag|nonumber)\b")


def continues(before: str, after: str) -> bool:
    """A display that starts with + or − continues the previous one's right side — unless the
    previous one ended its sentence (a full stop) or the new one states a relation of its own
    in its first row (``-\\dot{R} R^T = …``, ``-1 < u_1 < u_2``)."""
    head = _strip_envs(after)
    if not re.match(r"\s*(&\s*)?[+\-]", head):
        return False
    if _MARKS.sub(" ", _strip_envs(before)).rstrip().endswith("."):
        return False
    return not re.search(r"(?<![<>!\\])=|(?<!\\left)(?<!\\right)[<>]|\\(le|ge|leq|geq|lt|gt|approx|equiv)\b",
                         head.split("\\\\")[0])


# prose that says the display after it is the value of the side just written ("this right-hand side is the
# same as", "which equals"): a subject pointing back, then a phrase of equality ending the prose
_RESTATED_SIDE = re.compile(
    r"\b(this|that|it|which|(the\s+)?(right|left)([- ]hand)?\s+side|rhs|lhs)\s+(\w+\s+)?"
    r"\b(is\s+(indeed\s+|just\s+|simply\s+|also\s+)?(the\s+same\s+as|equal\s+to|identical\s+to)|is\s+indeed|equals|coincides\s+with)"
    r"\s*[:,]?\s*$", re.I)


def restates_side(lead: str, after: str) -> bool:
    """A display that states no relation, after prose saying the side just written is the same as it
    (``this right-hand side is the same as``, ``which equals``): it goes on with ``= …`` from the
    statement before, never as more terms of that statement's last side."""
    if not _RESTATED_SIDE.search(lead or ""):
        return False
    body = _MARKS.sub(" ", _strip_envs(after))
    return not re.search(r"(?<![<>!\\])=|(?<!\\left)(?<!\\right)[<>]|\\(le|ge|leq|geq|lt|gt|approx|equiv|propto|sim)\b", body)


_LABEL = re.compile(r"\s*(\\?[A-Za-z]+)\s*_\s*(\{\s*([A-Za-z0-9])\s*\}|([A-Za-z0-9]))\s*=(?!=)")


def repeated_labels(pieces) -> dict:
    """Rows of one block that set one label twice (``I_{x} = …``, ``I_{x} = …``, ``I_{z} = …``): the
    second is a typo for the index the block leaves out. Row → its correction."""
    rows = [(p, _LABEL.match(p)) for p in pieces]
    out = {}
    for base in {m.group(1) for _, m in rows if m}:
        mine = [(p, m) for p, m in rows if m and m.group(1) == base]
        subs = [m.group(3) or m.group(4) for _, m in mine]
        for family in ("123", "xyz"):
            if len(mine) < 3 or not set(subs) <= set(family):
                continue
            left = [x for x in family if x not in subs]
            twice = [k for k in range(len(subs)) if subs[k] in subs[:k]]
            if len(left) == 1 and len(twice) == 1 and mine[twice[0]][0] != mine[subs.index(subs[twice[0]])][0]:
                p, m = mine[twice[0]]
                out[p] = (p[:m.start(2)] + "{" + left[0] + "}" + p[m.end(2):]).strip()
    return out
