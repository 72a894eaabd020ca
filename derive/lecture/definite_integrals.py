"""Definite integrals written out: ``\\int_0^h \\mathrm{d} z \\int_0^{dz/h} \\mathrm{d} r \\, z``,
``\\int_0^1 (1 - s^2) \\, \\mathrm{d}s``, ``\\int_0^{\\pi/2} \\frac{\\mathrm{d}\\phi}{\\sqrt{1 - k^2 \\sin^2\\phi}}``.

An integral is read only where both its bounds are written and its differential is found: right
after the bounds (the physicist's order, the integrand the rest of the product, 1 where nothing
follows), as a fraction's numerator ``\\frac{d x}{…}``, or after the integrand. The variable is
bound: it is replaced by a fresh symbol inside the integrand, so the text's φ elsewhere (an Euler
angle) is never the φ integrated over; an integral over the time is not read (the motion's
quantities depend on it without the integrand saying so). SymPy works the integral out where the
integrand is a polynomial in the variable and its sine and cosine; otherwise it stays an integral,
evaluated numerically where it is compared. ``\\int`` without both bounds (over
the body, ``\\int_V``, ``\\int dm``) is not read here: the scanner refuses it, as before.
"""
from __future__ import annotations

import functools
import re

import sympy as sp

# \int with both bounds written, in either order: the only integral the scanner lets through
_BOUND = r"\s*(?:\{(?:[^{}]|\{(?:[^{}]|\{[^{}]*\})*\})*\}|\\[A-Za-z]+|[^\s\\{}])"
DEFINITE = re.compile(r"\\int(?![A-Za-z])\s*(?:_" + _BOUND + r"\s*\^" + _BOUND + r"|\^" + _BOUND + r"\s*_" + _BOUND + ")")


def written_with_bounds(s: str, i: int) -> bool:
    """``s[i:]`` opens an integral with both bounds written (``\\int_0^h``, ``\\int^{b}_{a}``)."""
    return DEFINITE.match(s, i) is not None


def _differential(toks, k) -> bool:
    """toks[k], toks[k+1] are a differential: an upright or italic d alone, then a plain symbol."""
    if k + 1 >= len(toks):
        return False
    d, x = toks[k], toks[k + 1]
    return d.kind == "atom" and d.value.base == "d" and not (d.value.sub or d.value.sup or d.value.dots
                                                            or d.value.bold or d.value.primes) \
        and x.kind == "atom" and not x.value.bold and not x.value.dots


def _end_of_term(toks, k) -> int:
    """The index where the product starting at toks[k] ends: a relation, a closing bracket it did not
    open, or + - at bracket depth 0 (a sign opening the product or a group excepted)."""
    depth, start = 0, k
    while k < len(toks):
        tok = toks[k]
        if tok.kind == "op" and tok.value in "({":
            depth += 1
        elif tok.kind == "op" and tok.value in ")}":
            if depth == 0:
                return k
            depth -= 1
        elif depth == 0 and (tok.kind == "rel" or (tok.kind == "op" and tok.value in "+-" and k > start
                                                   and not (toks[k - 1].kind == "op" and toks[k - 1].value in "^_"))):
            return k
        k += 1
    return k


def definite_integral(parser, env, tok):
    """The integral at ``tok`` (the parser just past ``\\int``): its bounds, its differential and its
    integrand read, the variable bound, the value worked out by SymPy where it can."""
    bounds = {}
    for _ in range(2):
        if parser.at("op", "_") or parser.at("op", "^"):
            mark = parser.take("op").value
            bounds[mark] = parser.group_or_token(env)
    if set(bounds) != {"_", "^"}:
        parser.fail("an integral without both its bounds", tok)
    toks, k = parser.toks, parser.i
    if _differential(toks, k):                      # ∫ dz …: the integrand is the rest of the product
        var_tok = toks[k + 1]
        parser.i = k + 2
        integrand = parser.term(env) if parser._starts_factor() else sp.S.One
    elif (k + 4 < len(toks) and toks[k].kind == "cmd" and toks[k].value in ("frac", "dfrac", "tfrac")
          and toks[k + 1].kind == "op" and toks[k + 1].value == "{" and _differential(toks, k + 2)
          and toks[k + 4].kind == "op" and toks[k + 4].value == "}"):    # ∫ dφ/(…)
        var_tok = toks[k + 3]
        parser.i = k + 5
        integrand = 1 / parser.braced(env)
        if parser._starts_factor():
            integrand = integrand * parser.term(env)
    else:                                           # ∫ f … dx: the differential closes the integrand
        end = _end_of_term(toks, k)
        at = next((j for j in range(end - 1, k, -1) if _differential(toks, j) and j + 2 == end), None)
        if at is None:
            parser.fail("an integral without its differential", tok)
        var_tok = toks[at + 1]
        inner = type(parser)(toks[k:at], parser.vocab, parser.source)
        integrand = inner.expr(env)
        if inner.peek() is not None:
            inner.fail(f"unexpected {inner.peek().value!r}")
        parser.i = end
    var = parser.atom(var_tok, env)
    if not isinstance(var, sp.Symbol) or not var.is_commutative:
        parser.fail("an integral over what is not a scalar", var_tok)
    if var.name == "t":     # the motion's quantities depend on the time without saying so
        parser.fail("an integral over the time", var_tok)
    x = sp.Dummy(var.name, real=True)
    integrand = sp.sympify(integrand).xreplace({var: x})
    if _elementary(integrand, x):
        return _worked(integrand.xreplace({x: _X}), bounds["_"], bounds["^"])
    return sp.Integral(integrand, (x, bounds["_"], bounds["^"]))


_X = sp.Dummy("x", real=True)
"""The variable of every integral worked out, so that a display read again finds its value kept."""


@functools.lru_cache(maxsize=1024)
def _worked(integrand, lower, upper):
    """∫ integrand d`_X` from lower to upper, worked out by SymPy (the value has no `_X` in it)."""
    return sp.Integral(integrand, (_X, lower, upper)).doit()


def _elementary(integrand, x) -> bool:
    """A polynomial in x, sin x and cos x: SymPy works its integral out in a bounded time (any other
    integrand is kept as an integral, compared numerically)."""
    s, c = sp.Dummy(), sp.Dummy()
    return integrand.xreplace({sp.sin(x): s, sp.cos(x): c}).is_polynomial(x, s, c)

