"""The arithmetic between the numbers of a chain of equalities in a worked example.

A worked example writes ``I_z = \\frac{1}{2} m R^2 = \\frac{1}{2}(2.50)(0.18)^2 = 0.04050`` (its units
already dropped by `units.plain_numbers`). `arithmetic` judges each link between two neighbouring
members of a chain that are plain numbers: ``=`` and ``≈`` hold when the two agree to the digits
the text writes (the value rounded or cut at the last place it prints: ``= 9`` holds for 9.4 and
9.9, never for 10), fail
when they differ by more than a few per cent, and are left unchecked in between. A chain may end by
stating its value's sign (``= 2.4 - 4.2 = -1.8 < 0``): an inequality between two numbers holds when
true and fails when they stand the other way round by more than the digits written. Two members in
the same symbols that differ by a number, one of them a worked decimal (``\\Omega_0 \\sqrt{0.6}
\\approx 0.7746 \\Omega_0``), are compared by their ratio the same way. The symbols'
values are not used: a text's later "effective" value of a symbol (``L_{\\text{eff}}``) cannot
turn a correct line into a false alarm. A member in symbols the text has set to numbers
(``r = 0.1`` given, then ``d = 2r = 0.2``) is worked out with those values only to confirm its link
to a plain number: the link holds when they agree to the digits written and gets no verdict
otherwise, so a value the text meant differently there can never make it fail.

Takes a formula in the reader's dialect (`source.normalize`) and the reader's parser; gives the
verdicts of the numeric links. Imports nothing of derive but the lecture's LaTeX reader and its statement splitter.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.latex_spaces import QUAD
from derive.lecture.statements import top_level

_LINK = re.compile(r"(?<![<>!])=|\\approx(?![A-Za-z])|\\simeq(?![A-Za-z])|(?<![\\<>])(?<!left)(?<!right)[<>](?!=)"
                   r"|\\(?:leq|geq|le|ge|lt|gt)(?![A-Za-z])")
_SIGN = {"<": "<", ">": ">", r"\lt": "<", r"\gt": ">", r"\le": "≤", r"\leq": "≤", r"\ge": "≥", r"\geq": "≥"}
"""A chain's inequality links: a worked chain may end by stating the sign of its value (``= -1.8 < 0``)."""
_LITERAL = re.compile(r"\s*-?\d*\.?\d+\s*")


def _members(text: str):
    """The top-level members of a chain and the relations between them (None where the chain
    holds anything the split does not follow)."""
    cuts = [(m.start(), m.end(), "=" if m.group(0) == "=" else _SIGN.get(m.group(0), "≈"))
            for m in top_level(text, _LINK)]
    if not cuts:
        return None
    pieces, rels, at = [], [], 0
    for a, b, rel in cuts:
        pieces.append(text[at:a])
        rels.append(rel)
        at = b
    pieces.append(text[at:])
    return pieces, rels


def _value(piece: str, vocab):
    """A member's value when it is a plain number (no symbol in it), else None."""
    if not re.search(r"\d", piece) or re.search(r"\\(?:implies|Rightarrow|text)|" + QUAD + r"|(?<!\\)[,;]", piece):
        return None
    try:
        parsed = lx.parse(piece, vocab)
    except (lx.NotRead, lx.Words, ValueError, TypeError):
        return None
    if len(parsed.members) != 1:
        return None
    value = parsed.members[0].value
    if not isinstance(value, sp.Expr) or value.free_symbols:
        return None
    number = complex(sp.N(value, 30))
    return number.real if abs(number.imag) < 1e-12 else None


def _last_place(piece: str) -> float:
    """One unit in the last place a written number prints (0 for an expression: it is exact)."""
    if not _LITERAL.fullmatch(piece):
        return 0.0
    digits = piece.strip().lstrip("-")
    return 10.0 ** -(len(digits.split(".")[1]) if "." in digits else 0)


def _decimal_place(piece: str) -> float:
    """One unit in the last place of a written decimal (0 for an integer or an expression: exact)."""
    return _last_place(piece) if "." in piece else 0.0


def _agree(a: float, b: float, place_a: float, place_b: float) -> bool:
    """Whether two values agree to the digits written: one is the other rounded to its last place
    (half a unit either side) or cut there (a truncated value is never larger in size)."""
    slack = 1e-9 * max(abs(a), abs(b), 1.0)
    if abs(a - b) <= (place_a + place_b) / 2 + slack:
        return True
    return any(p > 0 and x * y >= 0 and -slack <= abs(x) - abs(y) < p - slack
               for x, y, p in ((a, b, place_b), (b, a, place_a)))


_WHOLE = re.compile(r"\s*-?\d*[1-9]\s*")


def _whole(left: str, right: str) -> bool:
    """Whether a link is whole-number arithmetic: no decimal point on either side, and one side a
    whole number not ending in zero. Such a value is exact or rounded from an exact one, so it is
    off by more than its rounding only by a slip; a trailing zero may be a rounded place (2000 for
    1940), and a decimal may carry an intermediate rounding."""
    return "." not in left + right and bool(_WHOLE.fullmatch(left) or _WHOLE.fullmatch(right))


def _given(piece: str, vocab, given: dict):
    """A member's value with the numbers the text gave its symbols put in, or None."""
    if not given or not re.search(r"[A-Za-z]", piece):
        return None
    try:
        parsed = lx.parse(piece, vocab)
    except (lx.NotRead, lx.Words, ValueError, TypeError):
        return None
    if len(parsed.members) != 1 or not isinstance(parsed.members[0].value, sp.Expr):
        return None
    value = parsed.members[0].value.xreplace(given)
    if value.free_symbols:
        return None
    number = complex(sp.N(value, 30))
    return number.real if abs(number.imag) < 1e-12 else None


def _sign(shown: str, a: float, b: float, rel: str, ulp: float) -> tuple[str, str]:
    """An inequality between two numbers: it holds when true, fails when the numbers, apart by more
    than the digits written, stand the other way round, and is unchecked when they agree to those digits."""
    gap = a - b if rel in (">", "≥") else b - a
    if gap > ulp or (gap >= 0 and rel in ("≤", "≥")):
        return "holds", f"the arithmetic {shown}: {a:.10g} against {b:.10g}"
    if gap < -ulp:
        return "fails", f"the arithmetic {shown}: {a:.10g} against {b:.10g} stand the other way round"
    return "unchecked", f"the arithmetic {shown}: {a:.10g} against {b:.10g}, equal to the digits written"


_DECIMAL = re.compile(r"(?<![\w.])\d+\.\d+(?![\w.])")


def _expr(piece: str, vocab):
    """A member's value as an expression (None when it does not read as one)."""
    if re.search(r"\\(?:implies|Rightarrow|text)|" + QUAD + r"|(?<!\\)[,;]", piece):
        return None
    try:
        parsed = lx.parse(piece, vocab)
    except (lx.NotRead, lx.Words, ValueError, TypeError):
        return None
    value = parsed.members[0].value if len(parsed.members) == 1 else None
    return value if isinstance(value, sp.Expr) else None


_SCRIPT = re.compile(r"[_^]\s*(?:\{[^{}]*\}|\\[A-Za-z]+|.)")
"""A subscript or a superscript: an index or a power, never a number the member works out."""


def _relative_place(piece: str) -> float:
    """A worked member written as one decimal times symbols (``0.7746 \\Omega_0``): one unit in that
    decimal's last place, relative to it (0 when the member is exact); a ratio holds within half of it.
    A member with any other number (``\\frac{1}{4} M (0.2)^2``), or whose decimal stands in a group or
    a bracket (``\\sqrt{0.6}``, ``(0.2)^2``), works out its data: it is exact."""
    bare = _SCRIPT.sub(" ", piece)
    numbers = re.findall(r"(?<![\w.])\d+(?:\.\d+)?", bare)
    if len(numbers) != 1 or "." not in numbers[0] or float(numbers[0]) == 0 or \
            re.search(r"[{(\[]\s*" + re.escape(numbers[0]), bare):
        return 0.0
    return _last_place(numbers[0]) / abs(float(numbers[0]))


def _scaled(left: str, right: str, rel: str, vocab):
    """A link between two members in the same symbols that differ by a number, one of them a worked
    decimal (``\\Omega_0 \\sqrt{0.6} \\approx 0.7746 \\Omega_0``): their ratio against 1, to the digits
    written (verdict, why), or None."""
    if not (_DECIMAL.search(left) or _DECIMAL.search(right)):
        return None
    a, b = _expr(left, vocab), _expr(right, vocab)
    if a is None or b is None or not a.free_symbols or a.free_symbols != b.free_symbols or b == 0:
        return None
    ratio = sp.simplify(a / b)
    if not ratio.is_number:
        return None
    r = complex(sp.N(ratio, 30))
    if abs(r.imag) > 1e-12:
        return None
    gap, place = abs(r.real - 1), _relative_place(left) + _relative_place(right)
    shown = f"{left.strip()} {rel} {right.strip()}"
    if gap <= place / 2 * (1 + 1e-6) + 1e-9:        # the decimal rounded correctly
        return "holds", f"the arithmetic {shown}: the two sides' ratio is {r.real:.10g}, 1 to the digits written"
    if gap > 3 * place and gap > 0.03:
        return "fails", f"the arithmetic {shown}: the two sides' ratio is {r.real:.10g}, not 1"
    return "unchecked", f"the arithmetic {shown}: the two sides' ratio is {r.real:.10g}, not 1 to the digits written"


def arithmetic(text: str, vocab=None, given: dict | None = None) -> list[tuple[str, str]]:
    """The verdicts (verdict, why) of the links between neighbouring numeric members of a chain.

    ``a = b`` and ``a ≈ b`` hold when one side is the other rounded to the last place it prints
    (``|a - b|`` at most half a unit there on each side, plus a relative 1e-9) or cut there (``|b| ≤
    |a| < |b| + 1`` unit, same sign); they fail when the two differ by more than 3 % and by more
    than three such units; in between the link is left unchecked. ``given`` (a symbol → the number
    the text set it to) works out a member in those symbols next to a plain number: such a link
    holds when the two agree to the digits written, and is not judged otherwise. ``<``, ``>``,
    ``\\le``, ``\\ge`` between two numbers hold when true and fail when false (`_sign`). Two
    members in the same symbols that differ by a number, one a worked decimal, are compared by their
    ratio to the digits written (`_scaled`).
    """
    split = _members(text)
    if split is None:
        return []
    pieces, rels = split
    values = [_value(p, vocab) for p in pieces]
    out = []
    for k, rel in enumerate(rels):
        a, b = values[k], values[k + 1]
        if rel in ("<", ">", "≤", "≥"):
            if a is not None and b is not None:
                out.append(_sign(f"{pieces[k].strip()} {rel} {pieces[k + 1].strip()}", a, b, rel,
                                 _decimal_place(pieces[k]) + _decimal_place(pieces[k + 1])))
            continue
        if (a is None) != (b is None):
            worked = _given(pieces[k] if a is None else pieces[k + 1], vocab, given)
            number = b if a is None else a
            if worked is not None and _agree(worked, number, 0.0, _last_place(pieces[k + 1 if a is None else k])):
                shown = f"{pieces[k].strip()} {rel} {pieces[k + 1].strip()}"
                out.append(("holds", f"the arithmetic {shown}: {worked:.10g} with the values the text gave, "
                                     f"against {number:.10g}, to the digits written"))
            continue
        if a is None or b is None:
            scaled = _scaled(pieces[k], pieces[k + 1], rel, vocab)
            if scaled is not None:
                out.append(scaled)
            continue
        place_a, place_b = _last_place(pieces[k]), _last_place(pieces[k + 1])
        ulp, gap = place_a + place_b, abs(a - b)
        shown = f"{pieces[k].strip()} {rel} {pieces[k + 1].strip()}"
        if _agree(a, b, place_a, place_b):
            out.append(("holds", f"the arithmetic {shown}: {a:.10g} against {b:.10g}, to the digits written"))
        elif (gap > 3 * ulp or _whole(pieces[k], pieces[k + 1])) and gap > 0.03 * max(abs(a), abs(b)):
            out.append(("fails", f"the arithmetic {shown}: the left side is {a:.10g}, not {b:.10g}"))
        else:
            out.append(("unchecked", f"the arithmetic {shown}: {a:.10g} against {b:.10g}, closer than a slip "
                                     "but not to the digits written"))
    return out
