"""Integrals over a body's volume read as integrals over its mass (ρ dV = dm).

A uniform density ρ and the volume element dV pair into the mass element: ``\\rho \\int … \\mathrm dV``
(ρ before the integral or inside it, one ρ with each dV) is ``\\int … dm``; so is a density at the
point with the volume element d³r (``\\int \\rho(\\mathbf{r}) … \\mathrm{d}^3 r``), and, under a sum over
the pieces of a body, a piece's ρᵢ ΔVᵢ or Δmᵢ is the particle's mass mᵢ.

A ρ inside the integral that multiplies only some terms of its integrand (``\\int_V \\rho (\\mathbf r
\\cdot \\mathbf r) I_3 - \\mathbf r \\mathbf r^T \\, dV``: the integral runs to dV, the density stops at the
minus) is read as written, never dropped: dV is dm/ρ, so the integrand is bracketed and divided by
ρ, ``\\int (\\rho A - B) \\frac{1}{\\rho} dm`` (ρ spelled :data:`KEPT_DENSITY`), and a term without
the density keeps a 1/ρ the derivation does not have. Mixing ρ-weighted and unweighted terms adds
unlike quantities: a slip of the brackets.

Takes: a statement's LaTeX. Gives: :func:`mass_element`, :func:`pieces`, :data:`INTEGRAL_SIGN`, :data:`KEPT_DENSITY`.

May import: :mod:`derive.lecture.latex_spaces`, :mod:`derive.lecture.latex_spellings`,
:mod:`derive.lecture.statements`.
"""
from __future__ import annotations

import re

from derive.lecture.latex_spaces import SPACE
from derive.lecture.latex_spellings import BOLD
from derive.lecture.statements import top_level

INTEGRAL_SIGN = re.compile(r"\\int(?:\s*\\limits)?(?:\s*_\s*(?:\{(?:[^{}]|\{[^{}]*\})*\}|\\[A-Za-z]+|[^\s\\]))?")
"""∫ with its lower limit (``\\int_V``, ``\\int\\limits_{V}``)."""
_VOLUME = re.compile(r"(?:\\mathrm\s*\{?\s*d\s*\}?|\bd)" + SPACE + r"V\b")
_DENSITY = re.compile(r"\\rho(?![A-Za-z])")
KEPT_DENSITY = r"\rho_{V}"
"""The density as a symbol of its own where it multiplies only part of an integrand (the reader's ρ)."""

# a density at the point, rho(r), and the volume element d^3 r: their product is the mass element dm
_DENSITY_AT = re.compile(r"\\rho\s*(?:\\(?:left|[Bb]igg?l?)\s*)?\(\s*\{?\s*(?:" + BOLD + r"|\\vec)\s*\{?\s*r\s*\}?\s*\}?"
                         r"\s*(?:\\(?:right|[Bb]igg?r?)\s*)?\)")     # rho(r), rho\left(r\right)
_VOLUME_3 = re.compile(r"(?:\\mathrm\s*\{\s*d\s*\}|\bd)\s*\^\s*\{?\s*3\s*\}?" + SPACE +
                       r"(?:(?:" + BOLD + r"|\\vec)\s*\{\s*r\s*\}|\{\s*" + BOLD + r"\s*\{\s*r\s*\}\s*\}|r(?![A-Za-z]))")
_SIGN = re.compile(r"[+\-]")


def mass_element(text: str) -> str:
    """``text`` with each volume integral of a uniform density written over the mass: ρ … dV as
    … dm where ρ multiplies the whole integrand (stands before the integral or in each of its
    terms), as ∫ (…) (1/ρ) dm where it multiplies only some of its terms; ρ(𝐫) … d³r as … dm."""
    at = _VOLUME_3.findall(text)
    if at and len(_DENSITY_AT.findall(text)) == len(at):
        text = _VOLUME_3.sub(" dm", _DENSITY_AT.sub(" ", text))
    done, rest = "", text
    for sign in INTEGRAL_SIGN.finditer(text):
        volume = _VOLUME.search(text, sign.end())
        if volume is None or sign.start() < len(text) - len(rest):
            continue
        integrand = text[sign.end():volume.start()]
        terms = _top_terms(integrand)
        weighted = [len(_DENSITY.findall(t)) for t in terms]
        if len(terms) < 2 or not any(weighted) or (all(weighted) and weighted != [1] * len(terms)):
            continue                # one term, or ρ outside, or twice in a term: paired over the text
        if all(weighted):
            read = _DENSITY.sub(" ", integrand) + " dm"         # ρ in each term: the mass element
        else:
            read = (r" \left(" + _DENSITY.sub(KEPT_DENSITY.replace("\\", "\\\\"), integrand) +
                    r"\right) \frac{1}{" + KEPT_DENSITY + "} dm")
        done += _paired(text[len(text) - len(rest):sign.end()]) + read
        rest = text[volume.end():]
    return done + _paired(rest)


def _paired(text: str) -> str:
    """ρ … dV as … dm where the text has one ρ with each dV (before the integral or inside it)."""
    volumes = _VOLUME.findall(text)
    if not volumes or len(_DENSITY.findall(text)) != len(volumes):
        return text
    return _VOLUME.sub(" dm", _DENSITY.sub(" ", text))


def _top_terms(s: str) -> list[str]:
    """The terms of ``s`` split at its top-level + and − (a leading sign starts the first term)."""
    cuts = [m.start() for m in top_level(s, _SIGN) if s[:m.start()].strip()]
    return [s[i:j] for i, j in zip([0, *cuts], [*cuts, len(s)])]


_SUB = r"(\s*_\s*(?:\{[^{}]*\}|[A-Za-z0-9]))"
_PIECE_MASS = re.compile(r"\\Delta" + SPACE + "m" + _SUB)
_PIECE_DENSITY = re.compile(r"\\rho" + _SUB)
_PIECE_VOLUME = re.compile(r"\\Delta" + SPACE + "V" + _SUB)


def pieces(text: str) -> str:
    """A body cut into pieces (a sum over them): the mass of piece i, ``\\Delta m_i``, and its density
    times its volume, ``\\rho_i … \\Delta V_i`` (one ρᵢ with each ΔVᵢ), are the particle's mass mᵢ."""
    text = _PIECE_MASS.sub(r"m\1", text)
    volumes = _PIECE_VOLUME.findall(text)
    if volumes and sorted(re.sub(r"\s", "", v) for v in _PIECE_DENSITY.findall(text)) == \
            sorted(re.sub(r"\s", "", v) for v in volumes):
        text = _PIECE_VOLUME.sub(r"m\1", _PIECE_DENSITY.sub(" ", text))
    return text
