"""Safe expressions: text a user wrote in a scene (a potential V, a torque's components) read by a
whitelist of syntax and turned into SymPy from that tree, never by ``eval`` or ``sympify``.

The grammar is that of a Python expression restricted to

* numbers (decimal integers and floats, finite as doubles),
* declared names (the caller says which: ``R11`` … ``R33``, the Euler angles, a term's params,
  ``pi``, …),
* ``+ - * / **``, unary ``+`` and ``-``, parentheses,
* calls of the functions in :data:`FUNCTIONS` by plain name (``sin(x)``, ``atan2(y, x)``).

Anything else is refused before any SymPy work, with a :class:`ExpressionError` whose text names
what is at fault (``unknown name 'mu2'``, ``attribute access '.x' is not allowed``, …): undeclared
names, attributes, subscripts, lambdas, comparisons, calls of other names, keyword arguments,
text over :data:`MAX_LENGTH` characters, nesting deeper than :data:`MAX_DEPTH`, and constant
exponents whose product along a path exceeds :data:`MAX_DEGREE` (``9**9**9``, ``x**1000``),
constant parts that are no finite real number (``1/0``, ``x/(2-2)``, ``sqrt(-1)``): the checks
run in time linear in the text, whatever it holds.

:func:`parse` returns a :class:`Parsed` (the checked tree and the names it uses); only
:func:`to_sympy` imports SymPy.
"""
from __future__ import annotations

import ast
import math
import operator
from dataclasses import dataclass

#: Longest expression accepted, in characters.
MAX_LENGTH = 1000
#: Deepest nesting of operations and calls accepted.
MAX_DEPTH = 32
#: Largest product of constant exponents along any path of the tree (x**8 and (x**4)**4 pass,
#: x**100 and 9**9**9 do not): a physical potential needs no more, and a large one would make
#: the derivation's trigonometric reduction expand a polynomial of that degree.
MAX_DEGREE = 64

#: The functions an expression may call, with their number of arguments.
FUNCTIONS = {
    "sin": 1, "cos": 1, "tan": 1, "asin": 1, "acos": 1, "atan": 1, "atan2": 2,
    "sinh": 1, "cosh": 1, "tanh": 1, "exp": 1, "log": 1, "sqrt": 1, "abs": 1,
}

#: Names every expression may use besides the caller's.
CONSTANTS = ("pi",)

#: The binary operators allowed, each with what it computes (on floats and on SymPy alike).
_BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
           ast.Pow: operator.pow}
_UNARY = {ast.UAdd: "+", ast.USub: "-"}

#: What a refused node is called in a message.
_REFUSED = {
    ast.Attribute: "attribute access", ast.Subscript: "subscripts", ast.Lambda: "lambda",
    ast.Compare: "comparisons", ast.BoolOp: "'and'/'or'", ast.IfExp: "'if ... else'",
    ast.List: "lists", ast.Tuple: "tuples", ast.Dict: "dicts", ast.Set: "sets",
    ast.ListComp: "comprehensions", ast.GeneratorExp: "comprehensions",
    ast.DictComp: "comprehensions", ast.SetComp: "comprehensions",
    ast.JoinedStr: "strings", ast.NamedExpr: "':='", ast.Starred: "'*' unpacking",
    ast.Await: "await", ast.Yield: "yield", ast.YieldFrom: "yield", ast.Slice: "slices",
}


class ExpressionError(ValueError):
    """An expression that is not accepted; the text says what is at fault (one line)."""


@dataclass(frozen=True)
class Parsed:
    """A checked expression: the source text, its tree (``ast.Expression``) and the names used."""

    text: str
    tree: ast.Expression
    names: frozenset


def parse(text, names) -> Parsed:
    """Check ``text`` against the whitelist and return its tree.

    Parameters
    ----------
    text : str
        The expression, as written in the scene.
    names : collection of str
        The names it may use (``pi`` is always allowed).

    Returns
    -------
    Parsed

    Raises
    ------
    ExpressionError
        With one line saying what is wrong (the name at fault where there is one).
    """
    if not isinstance(text, str):
        raise ExpressionError(f"must be a string (an expression), got {type(text).__name__}")
    if len(text) > MAX_LENGTH:
        raise ExpressionError(f"is {len(text)} characters long, more than {MAX_LENGTH}")
    if not text.strip():
        raise ExpressionError("is empty (write 0 for no term)")
    bad = next((c for c in text if not (" " <= c <= "~" or c in "\t\n\r")), None)
    if bad is not None:
        # ASCII only: Python would read some other letters as names after NFKC normalisation.
        raise ExpressionError(f"holds the character {bad!r} (U+{ord(bad):04X}); expressions are "
                              f"written in ASCII")
    try:
        # Python's own parser, in "eval" mode (one expression); it builds a tree and runs
        # nothing. Its nesting limit (about 200 parentheses) and the length limit above bound
        # the work; RecursionError and MemoryError are caught all the same.
        tree = ast.parse(text, mode="eval")
    except SyntaxError as exc:
        where = f" at column {exc.offset}" if exc.offset else ""
        raise ExpressionError(f"is not an expression ({exc.msg}{where})") from None
    except (RecursionError, MemoryError, ValueError):
        raise ExpressionError("is not an expression (too deeply nested)") from None
    allowed = frozenset(names) | frozenset(CONSTANTS)
    used = _check(tree.body, allowed)
    _fold(tree.body)
    return Parsed(text, tree, frozenset(used))


_MATH = {**{name: getattr(math, name) for name in FUNCTIONS if name != "abs"}, "abs": abs}


def _fold(node) -> float | None:
    """The value of a constant subtree in doubles (None where a name other than pi enters), so
    that a constant that is no real number (``1/0``, ``sqrt(-1)``, ``log(0)``, ``asin(2)``) is
    refused here rather than met by the derivation or the C compiler. Runs on a checked tree
    (depth at most MAX_DEPTH, constant powers bounded), so the recursion and the arithmetic
    are bounded."""
    kind = type(node)
    if kind is ast.Constant:
        return float(node.value)
    if kind is ast.Name:
        return math.pi if node.id == "pi" else None
    if kind is ast.UnaryOp:
        x = _fold(node.operand)
        return None if x is None else (-x if type(node.op) is ast.USub else x)
    if kind is ast.BinOp:
        a, b = _fold(node.left), _fold(node.right)
        op = type(node.op)
        if op is ast.Div and b == 0:  # x/0 whatever x is
            raise ExpressionError("divides by zero (a constant part of it)")
        if a is None or b is None:
            return None
        try:
            if op is not ast.Pow:
                x = _BINARY[op](a, b)
            elif a == 0 and b < 0:
                raise ZeroDivisionError
            else:
                x = math.pow(a, b)
        except ZeroDivisionError:
            raise ExpressionError("divides by zero (a constant part of it)") from None
        except ValueError:
            raise ExpressionError("has a constant part that is not a real number "
                                  f"({_fmt(a)})**({_fmt(b)})") from None
        except OverflowError:
            x = math.inf
    else:  # a call
        args = [_fold(arg) for arg in node.args]
        if any(x is None for x in args):
            return None
        name = node.func.id
        if name == "atan2" and args[0] == 0 and args[1] == 0:
            raise ExpressionError("has a constant part that is undefined: atan2(0, 0)")
        try:
            x = _MATH[name](*args)
        except ZeroDivisionError:
            raise ExpressionError(f"divides by zero in {name}()") from None
        except ValueError:
            raise ExpressionError(f"has a constant part that is not a real number: {name}("
                                  + ", ".join(_fmt(a) for a in args) + ")") from None
        except OverflowError:
            x = math.inf
    if not math.isfinite(x):
        raise ExpressionError("has a constant part that is not a finite double")
    return x


def _fmt(x: float) -> str:
    return f"{x:.6g}"


def _check(root, allowed) -> set:
    """Walk the tree without recursion: every node whitelisted, depth and degree bounded."""
    used = set()
    stack = [(root, 1, 1.0)]  # (node, depth, product of constant exponents above it)
    while stack:
        node, depth, degree = stack.pop()
        if depth > MAX_DEPTH:
            raise ExpressionError(f"is nested more than {MAX_DEPTH} deep")
        kind = type(node)
        if kind is ast.Constant:
            value = node.value
            if type(value) not in (int, float):
                raise ExpressionError(f"holds {_what_constant(value)}; only numbers are allowed")
            _finite(value)
        elif kind is ast.Name:
            if node.id in FUNCTIONS:
                raise ExpressionError(f"function {node.id!r} used without arguments")
            if node.id not in allowed:
                raise ExpressionError(f"unknown name {node.id!r}")
            used.add(node.id)
        elif kind is ast.BinOp:
            op = type(node.op)
            if op not in _BINARY:
                raise ExpressionError(f"operator {_op_text(node.op)!r} is not allowed "
                                      f"(+ - * / ** only)")
            if op is ast.Pow:
                exponent = _constant(node.right)
                if exponent is not None:
                    degree *= max(abs(exponent), 1.0)
                    if degree > MAX_DEGREE:
                        raise ExpressionError(f"has a constant power of degree above {MAX_DEGREE}")
            stack.append((node.left, depth + 1, degree))
            stack.append((node.right, depth + 1, 1.0))
        elif kind is ast.UnaryOp:
            if type(node.op) not in _UNARY:
                raise ExpressionError(f"operator {_op_text(node.op)!r} is not allowed")
            stack.append((node.operand, depth + 1, degree))
        elif kind is ast.Call:
            func = node.func
            if type(func) is not ast.Name:
                if type(func) is ast.Attribute:
                    raise ExpressionError(f"attribute access '.{func.attr}' is not allowed")
                raise ExpressionError("calls only the functions "
                                      + " ".join(FUNCTIONS) + " by name")
            if func.id not in FUNCTIONS:
                raise ExpressionError(f"unknown function {func.id!r} (allowed: "
                                      + " ".join(FUNCTIONS) + ")")
            if node.keywords:
                raise ExpressionError(f"{func.id}() takes no keyword arguments")
            n = FUNCTIONS[func.id]
            if len(node.args) != n:
                raise ExpressionError(f"{func.id}() takes {n} argument{'s' if n > 1 else ''}, "
                                      f"got {len(node.args)}")
            for arg in node.args:
                stack.append((arg, depth + 1, 1.0))
        else:
            if kind is ast.Attribute:
                raise ExpressionError(f"attribute access '.{node.attr}' is not allowed")
            what = _REFUSED.get(kind, type(node).__name__)
            raise ExpressionError(f"{what} are not allowed" if what.endswith("s")
                                  else f"{what} is not allowed")
    return used


def _what_constant(value) -> str:
    if isinstance(value, bool):
        return f"the boolean {value}"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, complex):
        return "an imaginary number"
    return repr(type(value).__name__)


def _finite(value) -> float:
    try:
        x = float(value)
    except OverflowError:
        x = math.inf
    if not math.isfinite(x):
        raise ExpressionError(f"holds a number that is not a finite double "
                              f"({str(value)[:20]}{'…' if len(str(value)) > 20 else ''})")
    return x


def _constant(node) -> float | None:
    """The value of a constant exponent (a number, signed, or a power or product of numbers),
    bounded: None when the subtree holds a name or a call (a symbolic exponent). Raises for a
    constant too large to be a double (``9**9**9``) without computing it."""
    kind = type(node)
    if kind is ast.Constant and type(node.value) in (int, float):
        return _finite(node.value)
    if kind is ast.UnaryOp and type(node.op) in _UNARY:
        inner = _constant(node.operand)
        return None if inner is None else (-inner if type(node.op) is ast.USub else inner)
    if kind is ast.BinOp and type(node.op) in _BINARY:
        a, b = _constant(node.left), _constant(node.right)
        if a is None or b is None:
            return None
        try:
            if type(node.op) is ast.Pow:
                if abs(b) > MAX_DEGREE and abs(a) != 1.0 and a != 0.0:
                    raise ExpressionError(f"has a constant power of degree above {MAX_DEGREE}")
                value = math.pow(abs(a), b) if a != 0 or b > 0 else math.inf
            else:
                value = math.inf if type(node.op) is ast.Div and b == 0 else _BINARY[type(node.op)](a, b)
        except OverflowError:
            value = math.inf
        if not math.isfinite(value):
            raise ExpressionError("holds a constant that is not a finite double")
        return value
    return None  # a name, a call or anything refused later by _check


def _op_text(op) -> str:
    return {ast.FloorDiv: "//", ast.Mod: "%", ast.MatMult: "@", ast.BitAnd: "&", ast.BitOr: "|",
            ast.BitXor: "^", ast.LShift: "<<", ast.RShift: ">>", ast.Invert: "~",
            ast.Not: "not"}.get(type(op), type(op).__name__)


# ---------------------------------------------------------------------------------------------
# SymPy, from the checked tree


def number(value):
    """A number of the text as SymPy: integers exact; a float that is a short binary fraction
    (0.5, 2.25) exact too, any other float a 53-bit Float (the double the text denotes)."""
    import sympy as sp

    if type(value) is int:
        return sp.Integer(value)
    if (value * 1024).is_integer() and abs(value) < 2.0**40:
        return sp.Rational(value)
    return sp.Float(value, precision=53)


def to_sympy(parsed: Parsed, symbols):
    """The SymPy expression of a checked expression.

    Parameters
    ----------
    parsed : Parsed
        From :func:`parse`.
    symbols : mapping of str to SymPy expression
        A value for every name the expression may use (``pi`` is ``sympy.pi`` unless given).

    Returns
    -------
    sympy.Expr
    """
    import sympy as sp

    funcs = {**{name: getattr(sp, name) for name in FUNCTIONS if name != "abs"}, "abs": sp.Abs}
    env = {"pi": sp.pi, **symbols}

    def build(node):  # depth bounded by MAX_DEPTH: recursion is safe
        kind = type(node)
        if kind is ast.Constant:
            return number(node.value)
        if kind is ast.Name:
            return env[node.id]
        if kind is ast.UnaryOp:
            x = build(node.operand)
            return -x if type(node.op) is ast.USub else x
        if kind is ast.BinOp:
            return _BINARY[type(node.op)](build(node.left), build(node.right))
        if kind is ast.Call:
            return funcs[node.func.id](*(build(arg) for arg in node.args))
        raise ExpressionError(f"{type(node).__name__} is not allowed")  # unreachable after parse

    return build(parsed.tree.body)
