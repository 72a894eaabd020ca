"""Jacobi's elliptic functions as texts on the heavy top write them: ``\\sn``, ``\\cn``, ``\\dn``.

Gives: `FUNCTIONS`, the three as SymPy functions of one argument whose parameter m = k² is the
text's modulus k (the usual name: "sn u with modulus k"), with their derivatives (sn′ = cn dn,
cn′ = −sn dn, dn′ = −k² sn cn) and numeric values (mpmath's ``ellipfun``), so that a solution a
text writes with them can be put into its equation of motion and compared at numeric points.
May import: SymPy, mpmath (the caller passes the class of the text's symbols).
"""
from __future__ import annotations

import functools

import mpmath
import sympy as sp
from sympy.core.function import ArgumentIndexError

MODULUS = "k"
"""The text's name for the modulus of sn, cn, dn written with one argument."""


class _Jacobi(sp.Function):
    """f(x, m) with m = k² the parameter; the derivative in x, values from mpmath."""

    nargs = 2
    kind_name = ""

    def _eval_evalf(self, prec):
        return _value(self.kind_name, self.args, prec)

    @classmethod
    def mpmath_value(cls, x, m):
        """The value at mpmath arguments (the reader's numeric zero test, `derive.lecture.mp_values`)."""
        return mpmath.ellipfun(cls.kind_name, x, m=m)

    def _mpmathcode(self, printer):
        """For lambdify with mpmath (the reader's numeric zero test)."""
        x, m = (printer._print(a) for a in self.args)
        return f"{printer._module_format('mpmath.ellipfun')}({self.kind_name!r}, {x}, m={m})"


class JacobiSN(_Jacobi):
    kind_name = "sn"

    def fdiff(self, argindex=1):
        if argindex != 1:
            raise ArgumentIndexError(self, argindex)
        x, m = self.args
        return JacobiCN(x, m) * JacobiDN(x, m)


class JacobiCN(_Jacobi):
    kind_name = "cn"

    def fdiff(self, argindex=1):
        if argindex != 1:
            raise ArgumentIndexError(self, argindex)
        x, m = self.args
        return -JacobiSN(x, m) * JacobiDN(x, m)


class JacobiDN(_Jacobi):
    kind_name = "dn"

    def fdiff(self, argindex=1):
        if argindex != 1:
            raise ArgumentIndexError(self, argindex)
        x, m = self.args
        return -m * JacobiSN(x, m) * JacobiCN(x, m)


@functools.lru_cache(maxsize=4096)
def _value(kind_name: str, args: tuple, prec: int):
    """sn, cn or dn at numeric arguments to ``prec`` bits (None when an argument is not a number):
    kept, since SymPy's evalf asks again for the same value as it raises its working precision."""
    x, m = (sp.sympify(a).evalf(prec) for a in args)
    if not (x.is_number and m.is_number):
        return None
    with mpmath.workprec(prec):
        value = mpmath.ellipfun(kind_name, x._to_mpmath(prec), m=m._to_mpmath(prec))
    return sp.Expr._from_mpmath(value, prec)


def _with_modulus(cls, generic):
    return lambda x: cls(x, generic(MODULUS, real=True) ** 2)


def functions(generic) -> dict:
    """LaTeX name → SymPy function of one argument, the modulus the text's symbol ``generic(k)``."""
    return {"sn": _with_modulus(JacobiSN, generic), "cn": _with_modulus(JacobiCN, generic),
            "dn": _with_modulus(JacobiDN, generic)}
