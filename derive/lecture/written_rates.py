"""Rates written d/dt, read as the dots are.

A text writes the rate of a symbol x as ``\\dot x`` or as ``\\frac{d x}{dt}``, ``\\frac{dx}{dt}``,
``\\frac{\\mathrm{d} x}{\\mathrm{d} t}``, ``dx/dt``, ``\\frac{d}{dt} x``, ``\\frac{d}{dt}\\left(x\\right)``,
and its second rate as ``\\ddot x`` or ``\\frac{d^2 x}{dt^2}`` (``d^2x/dt^2``, ``\\frac{d^2}{dt^2} x``).
Such a rate of one symbol is looked up as the dotted atom itself, ``\\dot x`` with as many dots as
the order: the same SymPy symbol (α̇ of an angle, ω̃̇ᵢ, a name the text gives, the text's own ẋ, Ė
for a quantity E), so the equations of motion the checker keeps, the rates a text sets, the
second-order equations and the chains see one rate however it is written. The rate of a constant
of the derivation (p_α, I₁) and of anything else (a product) stays d/dt of it
(`derive.lecture.vocabulary.DT`), which the checker differentiates.

Takes the formula reader's tokens (`derive.lecture.vocabulary.scan`) and its reading of an atom
(`derive.lecture.vocabulary.Vocabulary.resolve`, or a parser's own); gives
:func:`written_rate` (where a rate written d/dt is, among the tokens), :func:`operand_rate` (the operator
d/dt, of what follows it), :func:`rate_of` and
:func:`symbol_rate` (what it reads as), :func:`partial_variable` (a rate as the variable of ∂),
:func:`rate_argument` (a rate in a name's list of arguments), :func:`rate_along` (dx/dy of two of
the text's own symbols, y not the time) and :func:`opens_with_rate` (a statement that gives a rate).

May import: :mod:`derive.lecture.vocabulary`.
"""
from __future__ import annotations

import re

from derive.lecture.vocabulary import DLDT, DT, LVEC, W, Generic, NotRead, Quantity, Tok, Unknown, scan

FRACTIONS = ("frac", "dfrac", "tfrac")


def _plain(tok, base: str) -> bool:
    """Whether ``tok`` is the bare letter ``base`` (the differential d, the time t)."""
    a = tok.value if tok.kind == "atom" else None
    return a is not None and a.base == base and not (a.sub or a.sup or a.dots or a.bold or a.hat or a.tilde
                                                     or a.primes or a.mark)


def _is(toks, j, kind, value=None) -> bool:
    return j < len(toks) and toks[j].kind == kind and (value is None or toks[j].value == value)


def _order(toks, j) -> tuple[int, int]:
    """The power after a d or a dt (``^2``, ``^{2}``): (the order, the index after it); (1, j) when
    there is none, (0, j) when the power is not a whole number the rate can have."""
    if not _is(toks, j, "op", "^"):
        return 1, j
    if _is(toks, j + 1, "num") and toks[j + 1].value in ("2", "3"):
        return int(toks[j + 1].value), j + 2
    if _is(toks, j + 1, "op", "{") and _is(toks, j + 2, "num") and toks[j + 2].value in ("2", "3") \
            and _is(toks, j + 3, "op", "}"):
        return int(toks[j + 2].value), j + 4
    return 0, j


def _dt(toks, j) -> tuple[int, int]:
    """``d t`` with its order at toks[j]: (the order, the index after it), or (0, j)."""
    if not (j + 1 < len(toks) and _plain(toks[j], "d") and _plain(toks[j + 1], "t")):
        return 0, j
    return _order(toks, j + 2)


def written_rate(toks: list, i: int) -> tuple[int | None, int, int] | None:
    """A rate written d/dt starting at ``toks[i]``.

    Parameters
    ----------
    toks : list of Tok
        The formula's tokens.
    i : int
        Where the rate would start: a ``\\frac`` (``\\dfrac``, ``\\tfrac``) command, or the
        differential ``d`` of ``dx/dt``.

    Returns
    -------
    tuple, or None
        ``(x, n, end)``: the index of the differentiated symbol's token (None for the operator
        ``\\frac{d^n}{dt^n}``, which acts on what follows it), the order n (dⁿx/dtⁿ, the numerator's
        and the denominator's powers equal) and the index of the token after the rate. None when
        ``toks[i:]`` is no such rate (a frame's label on t, ``dt_b``, included: that is another
        derivative).
    """
    if _is(toks, i, "cmd") and toks[i].value in FRACTIONS and _is(toks, i + 1, "op", "{") \
            and i + 2 < len(toks) and _plain(toks[i + 2], "d"):
        n, j = _order(toks, i + 3)
        x = None
        if _is(toks, j, "atom"):
            x, j = j, j + 1
        if not (n and _is(toks, j, "op", "}") and _is(toks, j + 1, "op", "{")):
            return None
        m, k = _dt(toks, j + 2)
        return (x, n, k + 1) if m == n and _is(toks, k, "op", "}") else None
    if i < len(toks) and _plain(toks[i], "d"):
        n, j = _order(toks, i + 1)
        if n and _is(toks, j, "atom") and _is(toks, j + 1, "op", "/"):
            m, k = _dt(toks, j + 2)
            return (j, n, k) if m == n else None
    return None


def reading(parser):
    """atom → what ``parser`` (the formula reader's grammar, or a subclass with symbols of its own)
    reads it as: its ``atom`` method; None when it cannot."""
    def read(atom):
        try:
            return parser.atom(Tok("atom", atom, 0), {})
        except Unknown:
            return None
    return read


def rate_of(read, atom, n: int):
    """What the rate dⁿx/dtⁿ of the symbol written ``atom`` reads as, when x has a rate of its own.

    Parameters
    ----------
    read : callable
        Atom → what the formula reader reads it as (`Vocabulary.resolve`, or a parser's own
        reading of a symbol, so that a grammar with symbols of its own reads ẋ and dx/dt alike);
        None or `NotRead` for an atom it cannot read.
    atom : Atom
        The differentiated symbol as written (a bold letter with a component index, 𝛚₁, is the
        component ω₁).
    n : int
        The order.

    Returns
    -------
    sympy object or None
        What the same atom with n more dots reads as (``\\dot x``, ``\\ddot x``): α̇ for an Euler
        angle α, ω̃̇ᵢ for ω̃ᵢ (ω̃̈ᵢ, the text's own symbol, as ``\\ddot\\omega_i`` is), the rate a
        name the text gives stands for, the text's ẋ for a symbol x of its own or a quantity's (Ė).
        None when x is unknown or a constant whose dotted name the derivation does not give (I₁,
        p_α): its rate is d/dt of it.
    """
    try:
        plain = read(atom)
        value = None if plain is None else read(atom.with_(dots=atom.dots + n))
    except NotRead:
        return None
    # a constant's dotted name (ṗ_α, İ₁) would be a new symbol: d/dt of the constant instead, zero; a
    # quantity's (Ė, L̇) is the text's own symbol, as the dot reads it (d/dt of the derivation's E holds
    # only on the motion); ω̃̈ᵢ is the text's own symbol as \ddot\omega_i is (the second-order equations
    # read it)
    if value is None or (isinstance(value, Generic) and not isinstance(plain, (Generic, Quantity)) and plain not in W):
        return None
    return value


def derivative(value, n: int):
    """dⁿ/dtⁿ of ``value`` as written (`DT` n times), for the checker to differentiate."""
    for _ in range(n):
        value = DT(value)
    return value


def operand_rate(parser, n: int):
    """dⁿ/dtⁿ written as an operator (``\\frac{d}{dt}``), of what follows it at ``parser.i``.

    A bracket right after the operator is its operand, and what follows the bracket multiplies the
    rate (``\\frac{d}{dt}(\\phi) \\sin\\theta`` is φ̇ sin θ); without a bracket the operand is the
    whole product (``\\frac{d}{dt} m \\mathbf{v}``). A rate of one symbol reads as :func:`rate_of`.

    Raises
    ------
    NotRead
        When the operand is unclear: a power after the bracket (of the rate, or inside it), or a
        product without a bracket whose first factor has a rate of its own (``\\frac{d}{dt}\\phi
        \\sin\\theta``: φ̇ sin θ, or the rate of the product).
    """
    toks, start = parser.toks, parser.i
    bracketed = _is(toks, start, "op", "(")
    value = parser.paren({}) if bracketed else parser.term({})
    inner = toks[start + 1:parser.i - 1] if bracketed else toks[start:parser.i]
    if bracketed and _is(toks, parser.i, "op", "^"):
        raise NotRead("a power after the rate of a bracket: of the rate, or inside it")
    first = inner[0] if inner and inner[0].kind == "atom" else None
    rate = rate_of(reading(parser), first.value, n) if first is not None else None
    if rate is not None and len(inner) > 1 and not bracketed and not _is(inner, 1, "op", "^"):
        raise NotRead("d/dt before a product whose first factor has a rate of its own: of it, or of the product")
    return rate if rate is not None and len(inner) == 1 else derivative(value, n)


def symbol_rate(read, tok, n: int, vocab=None):
    """dⁿx/dtⁿ of the symbol written at ``tok``: :func:`rate_of`, d𝐋/dt of the angular momentum,
    or d/dt of what x stands for. With the text's vocabulary (``vocab``), a bold letter with a
    component index (d𝛚₁/dt) is the component, ω̇₁, read as its scalar; any other bold symbol is not
    read here."""
    component = vocab is not None and tok.value.bold and tok.value.sub in ("1", "2", "3")
    atom = tok.value.with_(bold=False) if component else tok.value
    read = vocab.resolve if component else read
    value = read(atom)
    if value is LVEC and n == 1:
        return DLDT
    if value is None or atom.bold:
        raise NotRead(f"cannot parse at column {tok.pos + 1}: the time derivative of {tok.value.text}", tok.pos + 1)
    rate = rate_of(read, atom, n)
    return rate if rate is not None else derivative(value, n)


def rate_along(read, num: list, den: list):
    """``\\frac{dx}{dy}`` of two of the text's own symbols, y not the time (a variable the text
    substituted, its τ = p t): the rate of x per unit of y along the motion, ẋ/ẏ (`DT` of each),
    never the quotient x/y the letters d would make; None for any other fraction.

    Parameters
    ----------
    read : callable
        The reading of an atom (`derive.lecture.vocabulary.Vocabulary.resolve`).
    num, den : list of Tok
        The tokens of the fraction's numerator and denominator.
    """
    if len(num) != 2 or len(den) != 2 or not (_plain(num[0], "d") and _plain(den[0], "d")):
        return None
    if num[1].kind != "atom" or den[1].kind != "atom" or _plain(den[1], "t"):
        return None
    x, y = read(num[1].value), read(den[1].value)
    if not isinstance(x, Generic) or not isinstance(y, Generic) or x == y:
        return None
    return DT(x) / DT(y)


NOT_PARTIAL = object()
"""What :func:`partial_variable` gives for a denominator that is not ∂ of one variable."""


def partial_variable(read, den: list):
    """The variable of a partial derivative's denominator ``\\partial x`` (``\\partial{x}``): x read
    as an atom, or a rate written d/dt, ``\\partial \\frac{d\\phi}{dt}``, ``\\partial (d\\phi/dt)``, as
    the rate φ̇ (None when that rate is not one of the text's symbols); :data:`NOT_PARTIAL` for any
    other denominator."""
    if not den or den[0].kind != "cmd" or den[0].value != "partial":
        return NOT_PARTIAL
    inner = den[1:]
    if any(t.kind == "atom" and t.value.bold for t in inner):
        # ∂L/∂𝛀, ∂U/∂𝐫: a gradient in a vector, never the scalar partial of a name the vector is not in
        raise NotRead("a partial derivative with respect to a vector", den[0].pos + 1)
    if len(inner) > 2 and (_is(inner, 0, "op", "(") and _is(inner, len(inner) - 1, "op", ")")
                           or _is(inner, 0, "op", "{") and _is(inner, len(inner) - 1, "op", "}")):
        inner = inner[1:-1]                     # ∂(dφ/dt), ∂{θ}
    if len(inner) == 1 and inner[0].kind == "atom":
        return read(inner[0].value)
    rate = written_rate(inner, 0)
    if rate is None or rate[0] is None or rate[2] != len(inner):
        return NOT_PARTIAL
    return rate_of(read, inner[rate[0]].value, rate[1])


def rate_argument(toks: list, j: int) -> tuple[int, int] | None:
    """A rate written d/dt in a list of arguments, ``L(\\alpha, \\frac{d\\alpha}{dt})``, ``L(\\alpha,
    d\\alpha/dt)``: (the index of the differentiated symbol's token, the index of the token after the
    rate), or None."""
    rate = written_rate(toks, j)
    return (rate[0], rate[2]) if rate is not None and rate[0] is not None and rate[1] == 1 else None


# what a statement opening with a rate starts with (a dot, a fraction of d's, d then a symbol): only
# such a statement is scanned
_RATE_START = re.compile(r"\s*&?\s*(?:\\d?dot(?![A-Za-z])|\\[dt]?frac\s*\{\s*(?:\\mathrm\s*\{?\s*)?d(?![A-Za-z])"
                         r"|(?:\\mathrm\s*\{?\s*)?d\s*[\\}A-Za-z])")


def opens_with_rate(latex: str) -> bool:
    """Whether a statement opens with the rate of one symbol and relates it to something:
    ``\\dot\\phi = …``, ``\\frac{d\\phi}{dt} = …``, ``d\\phi/dt = …`` (not the operator
    ``\\frac{d}{dt}(…)``)."""
    if "=" not in latex or not _RATE_START.match(latex):
        return False
    try:
        toks = scan(latex)
    except NotRead:
        return False
    if toks and toks[0].kind == "atom" and toks[0].value.dots:
        return any(t.kind == "rel" and t.value == "=" for t in toks)
    rate = written_rate(toks, 0)
    return rate is not None and rate[0] is not None and any(t.kind == "rel" and t.value == "=" for t in toks[rate[2]:])

