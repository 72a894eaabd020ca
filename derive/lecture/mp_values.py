"""SymPy expressions evaluated with mpmath at points, by walking their trees: what
``sympy.lambdify(symbols, exprs, modules="mpmath")`` computes, without printing and compiling
Python source for each expression (most of the cost of a zero test that evaluates a formula at a
handful of points).

Takes: SymPy expressions. Gives: `evaluator`, a callable ``f(*point) -> list`` of mpmath values,
reading each node as SymPy's mpmath printer writes it (an integer as a Python int, a rational as
``mpf(p)/mpf(q)`` at the working precision of the call, x⁻¹ as ``1/x``, x^½ as ``sqrt(x)``, x^(-½)
as ``1/sqrt(x)``, other powers as ``**``, ``Abs`` as ``fabs``, a function with a ``mpmath_value``
of its own through it); an expression holding anything else is left to ``lambdify``. The values
agree with ``lambdify``'s to the working precision (sums and products may round in another
order), and the same points raise the same errors (a division by zero, a pole); a function
``lambdify`` cannot write raises NotImplementedError.

May import: SymPy, mpmath.
"""
from __future__ import annotations

import mpmath
import sympy as sp

_FUNCTIONS = {
    sp.sin: mpmath.sin, sp.cos: mpmath.cos, sp.tan: mpmath.tan, sp.cot: mpmath.cot,
    sp.sec: mpmath.sec, sp.csc: mpmath.csc, sp.exp: mpmath.exp, sp.log: mpmath.log,
    sp.asin: mpmath.asin, sp.acos: mpmath.acos, sp.atan: mpmath.atan, sp.sinh: mpmath.sinh,
    sp.cosh: mpmath.cosh, sp.tanh: mpmath.tanh, sp.Abs: mpmath.fabs, sp.atan2: mpmath.atan2,
}
_CONSTANTS = {sp.pi: lambda: +mpmath.pi, sp.E: lambda: +mpmath.e}


class _Unread(Exception):
    """A node the walk does not read (then ``lambdify`` evaluates the expressions)."""


def evaluator(symbols, exprs):
    """f(*point) → [each expression at symbols = point] in mpmath (see the module docstring)."""
    exprs = [sp.sympify(e) for e in exprs]
    if any(e.has(sp.zoo, sp.nan) for e in exprs):
        return _pole       # SymPy's infinity, written into a formula, is a value at no point
    f = walker(symbols, exprs)
    return f if f is not None else _lambdified(sp.lambdify(symbols, exprs, modules="mpmath", docstring_limit=0))


def real_values(f, radicands, point):
    """``f(*point)`` in mpmath where every radicand is real and positive there (a square root of a
    negative is no value of the text's formula), else None; a point where ``f`` has no value is None too."""
    try:
        if not all(mpmath.im(b) == 0 and mpmath.re(b) > 0 for b in map(mpmath.mpmathify, radicands(*point))):
            return None
        return [mpmath.mpmathify(v) for v in f(*point)]
    except (ZeroDivisionError, ValueError, TypeError):
        return None


def _pole(*point):
    """The value of a formula holding SymPy's complex infinity or NaN: none, at any point."""
    raise ZeroDivisionError("the formula holds an infinity")


def _lambdified(g):
    """``g`` (a lambdified function), whose call on a function with no numeric meaning (the reader's
    stand-in for a transpose of a name whose shape the text never gave) raises NotImplementedError:
    there is no value to compare, so the formula is left unjudged."""
    def f(*point):
        try:
            return g(*point)
        except NameError as err:
            raise NotImplementedError(f"no numeric value for {err.name}") from None
    return f


def walker(symbols, exprs):
    """The walk of `evaluator` alone: None when an expression holds a node it does not read (a
    symbol not in ``symbols``, an unknown function)."""
    try:
        program, outs = _compile(list(symbols), [sp.sympify(e) for e in exprs])
    except _Unread:
        return None
    return lambda *point: _run(program, outs, point)


def _compile(symbols, exprs):
    """The expressions as straight-line steps (each distinct subexpression once): step k is
    (operation, constant, argument steps); the first steps are the symbols."""
    index = {s: k for k, s in enumerate(symbols)}
    program = [("arg", k, ()) for k in range(len(symbols))]

    def node(e):
        if e in index:
            return index[e]
        if e.is_Integer:
            step = ("const", int(e), ())
        elif e.is_Rational:
            step = ("ratio", (int(e.p), int(e.q)), ())
        elif e.is_Float:
            step = ("float", tuple(map(int, e._mpf_)), ())
        elif e in _CONSTANTS:
            step = ("call0", _CONSTANTS[e], ())
        elif e.is_Add or e.is_Mul:
            step = ("add" if e.is_Add else "mul", None, tuple(node(a) for a in e.args))
        elif e.is_Pow:
            step = _power(e, node)
        elif type(e) in _FUNCTIONS:
            step = ("call", _FUNCTIONS[type(e)], tuple(node(a) for a in e.args))
        elif callable(getattr(type(e), "mpmath_value", None)):
            step = ("call", type(e).mpmath_value, tuple(node(a) for a in e.args))
        else:
            raise _Unread(e)
        program.append(step)
        index[e] = len(program) - 1
        return index[e]

    outs = [node(e) for e in exprs]
    return program, outs


def _power(e, node):
    base, exp = node(e.base), e.exp
    if exp == sp.S.Half:
        return ("sqrt", None, (base,))
    if exp == -sp.S.Half:
        return ("rsqrt", None, (base,))
    if exp == -1:
        return ("recip", None, (base,))
    if exp.is_Integer:
        return ("ipow", int(exp), (base,))
    return ("pow", None, (base, node(exp)))


def _run(program, outs, point):
    mpf = mpmath.mpf
    v = []
    for op, c, args in program:
        if op == "arg":
            x = point[c]
        elif op == "add":
            x = v[args[0]]
            for a in args[1:]:
                x = x + v[a]
        elif op == "mul":
            x = v[args[0]]
            for a in args[1:]:
                x = x * v[a]
        elif op == "const":
            x = c
        elif op == "ratio":
            x = mpf(c[0]) / mpf(c[1])
        elif op == "float":
            x = mpf(c)
        elif op == "ipow":
            x = v[args[0]] ** c
        elif op == "recip":
            x = 1 / v[args[0]]
        elif op == "sqrt":
            x = mpmath.sqrt(v[args[0]])
        elif op == "rsqrt":
            x = 1 / mpmath.sqrt(v[args[0]])
        elif op == "pow":
            x = v[args[0]] ** v[args[1]]
        elif op == "call0":
            x = c()
        else:
            x = c(*(v[a] for a in args))
        v.append(x)
    return [v[k] for k in outs]
