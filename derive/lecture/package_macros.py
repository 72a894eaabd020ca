"""The semantic commands of a LaTeX package a file loads, read as the package sets them.

Takes: the text of a notes file. Gives: `loaded`, the macros of the packages it loads with
``\\usepackage`` that this module knows, name → `derive.lecture.texmacros.Macro`, for the file's own
definitions to be laid over (a file's ``\\newcommand`` wins). A text that writes its formulas in a
package's commands leaves them out of the file: the package defines them, and a reader that does not
know them cannot read a display that uses one.

What is known, from each package's documentation:

* **semtex** (Robin Leroy's "semantic commands for LaTeX", in the Principia project's notes):
  ``\\pa{x}``, ``\\Associate{x}``, ``\\pascal{x}`` (a bracket for grouping) and ``\\of{x}`` (a
  function's argument) are round brackets, ``\\tuple{a, b}`` too; ``\\abs{x}`` and ``\\norm{x}``
  are bars; ``\\TimeDerivative{m}`` is the dot over m; ``\\DefineAs`` is the definition sign
  ``\\coloneqq``; the named functions ``\\JacobiSN``, ``\\JacobiCN``, ``\\JacobiDN``,
  ``\\JacobiAmplitude``, ``\\HyperbolicSine``, ``\\HyperbolicCosine``, ``\\HyperbolicTangent``,
  ``\\HyperbolicSecant``, ``\\TrigonometricTangent``, ``\\InverseTrigonometricTangent`` and
  ``\\InverseHyperbolicTangent`` are sn, cn, dn, am, sinh, cosh, tanh, sech, tan, arctan and
  artanh. Its letter shortcuts (``\\gl``, ``\\vm``) are left to `derive.lecture.undefined_macros`,
  which reads each as a symbol of its own name.

May import: the standard library, :mod:`derive.lecture.texmacros`.
"""
from __future__ import annotations

import functools
import re

from derive.lecture import texmacros

# the package's commands, restated as definitions the file itself could have written
_SEMTEX = r"""
\newcommand{\pa}[1]{\left(#1\right)}
\newcommand{\Associate}[1]{\left(#1\right)}
\newcommand{\pascal}[1]{\left(#1\right)}
\newcommand{\of}[1]{\left(#1\right)}
\newcommand{\tuple}[1]{\left(#1\right)}
\newcommand{\abs}[1]{\left|#1\right|}
\newcommand{\norm}[1]{\left|#1\right|}
\newcommand{\TimeDerivative}[1]{\dot{#1}}
\newcommand{\DefineAs}{\coloneqq}
\DeclareMathOperator{\JacobiSN}{sn}
\DeclareMathOperator{\JacobiCN}{cn}
\DeclareMathOperator{\JacobiDN}{dn}
\DeclareMathOperator{\JacobiAmplitude}{am}
\DeclareMathOperator{\HyperbolicSine}{sinh}
\DeclareMathOperator{\HyperbolicCosine}{cosh}
\DeclareMathOperator{\HyperbolicTangent}{tanh}
\DeclareMathOperator{\HyperbolicSecant}{sech}
\DeclareMathOperator{\TrigonometricTangent}{tan}
\DeclareMathOperator{\InverseTrigonometricTangent}{arctan}
\DeclareMathOperator{\InverseHyperbolicTangent}{artanh}
"""
_PACKAGES = {"semtex": _SEMTEX}
# \usepackage[options]{a, b}: the packages a file loads (a comment's % ends the line's reading)
_USE = re.compile(r"^[^%\n]*?\\usepackage\s*(?:\[[^\]]*\])?\s*\{([^}]*)\}", re.M)


@functools.lru_cache(maxsize=8)
def _macros(package: str) -> dict:
    return texmacros.definitions(_PACKAGES[package])


def loaded(text: str) -> dict[str, texmacros.Macro]:
    """The macros of the known packages ``text`` loads (see the module docstring), name → `Macro`."""
    found: dict[str, texmacros.Macro] = {}
    for m in _USE.finditer(text):
        for name in (n.strip() for n in m.group(1).split(",")):
            if name in _PACKAGES:
                found.update(_macros(name))
    return found
